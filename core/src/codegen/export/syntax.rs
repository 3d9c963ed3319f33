//! What the C and the Python write differently for one instruction: the locals' prefix, the
//! math functions' namespace, constants, and how the time, the state, the inputs and the
//! parameters are read. The instruction's shape is written once, here.

use super::Exported;
use crate::codegen::program::Op;

/// One language's spelling of an instruction's parts.
pub(super) struct Syntax {
    /// The prefix of the local bound to each instruction (`v`, `_v`).
    pub local: &'static str,
    /// The namespace of the math functions (``, `np.`).
    pub math: &'static str,
    /// A constant.
    pub literal: fn(f64) -> String,
    /// The state entry `k`.
    pub state: fn(usize) -> String,
    /// The input `k`.
    pub input: fn(usize) -> String,
    /// The parameter named so.
    pub parameter: fn(&str) -> String,
}

impl Syntax {
    /// The right-hand side of the local bound to `op`.
    pub(super) fn expression(&self, e: &Exported, op: &Op) -> String {
        let (v, m) = (self.local, self.math);
        let (n, inputs) = (e.state.len(), e.inputs.len());
        match *op {
            Op::Const(c) => (self.literal)(c),
            Op::Input(k) => match k.index() {
                0 => "t".to_owned(),
                k if k <= n => (self.state)(k - 1),
                k if k <= n + inputs => (self.input)(k - 1 - n),
                k => (self.parameter)(&e.parameters[k - 1 - n - inputs]),
            },
            Op::Add(a, b) => format!("{v}{a} + {v}{b}"),
            Op::Sub(a, b) => format!("{v}{a} - {v}{b}"),
            Op::Mul(a, b) => format!("{v}{a} * {v}{b}"),
            Op::Div(a, b) => format!("{v}{a} / {v}{b}"),
            Op::Neg(a) => format!("-{v}{a}"),
            Op::Sqrt(a) => format!("{m}sqrt({v}{a})"),
            Op::Powf(a, r) => {
                // C's `pow` is NumPy's `power`.
                let pow = if m.is_empty() { "pow" } else { "power" };
                format!("{m}{pow}({v}{a}, {})", (self.literal)(r))
            }
            Op::Sin(a) => format!("{m}sin({v}{a})"),
            Op::Cos(a) => format!("{m}cos({v}{a})"),
            Op::Func(g, a) => format!("{m}{}({v}{a})", g.name()),
        }
    }
}
