//! Operation counts, the cost model reports print next to timings.

use std::fmt;

use super::program::{Op, Program};

/// How many floating-point operations of each kind a [`Program`] executes.
///
/// A sine and a cosine of the same argument are counted as one `sin_cos` pair, which is how
/// the emitted code computes them.
#[derive(Clone, Copy, Default, PartialEq, Eq, Debug)]
pub struct OpCount {
    /// Additions and subtractions.
    pub adds: usize,
    /// Multiplications.
    pub muls: usize,
    /// Divisions.
    pub divs: usize,
    /// Negations.
    pub negs: usize,
    /// Square roots.
    pub sqrts: usize,
    /// Real powers (`powf`) and the registered primitives (`exp`): one call of a
    /// transcendental function each (the generated code's macros report these fields).
    pub powfs: usize,
    /// Lone sines or cosines.
    pub trig: usize,
    /// Paired sine-and-cosine evaluations.
    pub sin_cos: usize,
}

impl OpCount {
    /// All operations, each `sin_cos` pair counted once.
    pub fn total(&self) -> usize {
        self.adds
            + self.muls
            + self.divs
            + self.negs
            + self.sqrts
            + self.powfs
            + self.trig
            + self.sin_cos
    }
}

impl OpCount {
    /// A cost in rough multiply-equivalents for choosing between equal forms: divisions and
    /// square roots cost about 4, a sine or cosine or a real power about 15, a paired
    /// `sin_cos` about 20.
    pub fn weighted(&self) -> usize {
        self.adds
            + self.muls
            + self.negs
            + 4 * (self.divs + self.sqrts)
            + 15 * (self.trig + self.powfs)
            + 20 * self.sin_cos
    }
}

impl fmt::Display for OpCount {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ops: {} add, {} mul, {} div, {} neg, {} sqrt, {} powf, {} sin/cos, {} sin_cos",
            self.total(),
            self.adds,
            self.muls,
            self.divs,
            self.negs,
            self.sqrts,
            self.powfs,
            self.trig,
            self.sin_cos
        )
    }
}

impl Program {
    /// The operation count of the program.
    pub fn op_count(&self) -> OpCount {
        let mut c = OpCount::default();
        let mut sin_args = Vec::new();
        let mut cos_args = Vec::new();
        for op in &self.ops {
            match op {
                Op::Const(_) | Op::Input(_) => {}
                Op::Add(..) | Op::Sub(..) => c.adds += 1,
                Op::Mul(..) => c.muls += 1,
                Op::Div(..) => c.divs += 1,
                Op::Neg(_) => c.negs += 1,
                Op::Sqrt(_) => c.sqrts += 1,
                Op::Powf(..) | Op::Func(..) => c.powfs += 1,
                Op::Sin(a) => sin_args.push(*a),
                Op::Cos(a) => cos_args.push(*a),
            }
        }
        let paired = sin_args.iter().filter(|a| cos_args.contains(a)).count();
        c.sin_cos = paired;
        c.trig = sin_args.len() + cos_args.len() - 2 * paired;
        c
    }
}
