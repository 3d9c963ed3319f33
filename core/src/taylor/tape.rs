//! The Taylor tape: a right-hand side decomposed into elementary operations on truncated
//! power series, the one description the interpreter ([`super::TaylorTape`]) runs and the
//! emitter ([`Tape::to_tokens`]) turns into Rust.
//!
//! Every value of the lowered [`Program`] is either a *scalar*, constant along the solution
//! (a literal, a parameter, or arithmetic on those), or a *series* `x(t₀ + τ) = Σ x_k τᵏ`
//! (a state component, the time, or arithmetic involving one). A scalar has only its order-0
//! coefficient, so a product with it is a scaling and a sum with it touches order 0 only;
//! operations on scalars alone are computed once, before the recurrences.

use crate::codegen::{Op, Program};
use crate::sym::{Arena, ExprId, Func, IdMap, SymbolId};

/// Where a value of the tape lives.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Hash)]
pub enum Value {
    /// The `i`-th scalar (order 0 only).
    Scalar(u32),
    /// The `i`-th series.
    Series(u32),
}

/// An operation on scalars, evaluated once per coefficient call in tape order.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum ScalarOp {
    /// A literal.
    Const(f64),
    /// A symbol constant along the solution (a parameter, a fixed input).
    Symbol(SymbolId),
    /// `a + b`.
    Add(u32, u32),
    /// `a − b`.
    Sub(u32, u32),
    /// `a · b`.
    Mul(u32, u32),
    /// `a / b`.
    Div(u32, u32),
    /// `−a`.
    Neg(u32),
    /// `√a`.
    Sqrt(u32),
    /// `a^r` for a non-integer constant `r`.
    Powf(u32, f64),
    /// `sin a`.
    Sin(u32),
    /// `cos a`.
    Cos(u32),
    /// `f(a)` for a registered primitive `f`.
    Func(Func, u32),
}

/// An operation producing a series (operands: `a`, `b` series, `s` scalar), with its
/// recurrence for the normalised coefficient of order `k ≥ 1`.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum SeriesOp {
    /// `a + b`: `c_k = a_k + b_k`.
    Add(u32, u32),
    /// `a + s`: `c_0 = a_0 + s`, `c_k = a_k`.
    AddScalar(u32, u32),
    /// `a − b`: `c_k = a_k − b_k`.
    Sub(u32, u32),
    /// `a − s`: `c_0 = a_0 − s`, `c_k = a_k`.
    SubScalar(u32, u32),
    /// `s − a`: `c_0 = s − a_0`, `c_k = −a_k`.
    ScalarSub(u32, u32),
    /// `a · b`: `c_k = Σⱼ₌₀ᵏ a_j b_{k−j}` (Cauchy product).
    Mul(u32, u32),
    /// `a²`: the Cauchy product folded on its symmetry, `c_k = 2 Σ_{j<k/2} a_j a_{k−j}
    /// (+ a_{k/2}² for even k)`, about half the products.
    Square(u32),
    /// `s · a`: `c_k = s a_k`.
    Scale(u32, u32),
    /// `a / b`: `c_k = (a_k − Σⱼ₌₁ᵏ b_j c_{k−j}) / b_0`.
    Div(u32, u32),
    /// `a / s`: `c_k = a_k / s`.
    DivScalar(u32, u32),
    /// `s / a`: `c_k = −(Σⱼ₌₁ᵏ a_j c_{k−j}) / a_0`.
    ScalarDiv(u32, u32),
    /// `−a`: `c_k = −a_k`.
    Neg(u32),
    /// `√a`: `c_k = (a_k − Σⱼ₌₁ᵏ⁻¹ c_j c_{k−j}) / (2 c_0)` (the sum folded as in `Square`).
    Sqrt(u32),
    /// `a^r` for a non-integer constant `r`, of a base taken positive: `c_0 = a_0^r`,
    /// `c_k = (1/(k a_0)) Σⱼ₌₀ᵏ⁻¹ (r(k − j) − j) a_{k−j} c_j` (from `a c′ = r a′ c`).
    Powf(u32, f64),
    /// `(sin a, cos a)` as a pair, into the series `out` and `out + 1`, with the
    /// derivative's coefficients d_j = j a_j in `out + 2` (made once, read by both sums):
    /// `s_k = (1/k) Σⱼ₌₁ᵏ d_j c_{k−j}`, `c_k = −(1/k) Σⱼ₌₁ᵏ d_j s_{k−j}`.
    SinCos(u32),
    /// `f(a)` for a registered primitive `f`, by its own recurrence
    /// ([`crate::sym::functions`]), into `out` and its companions `out + 1 …`.
    Func(Func, u32),
}

impl SeriesOp {
    /// The number of series the step writes: its output, and the cosine and the
    /// argument's derivative of a sine–cosine pair or a primitive's companions.
    pub fn width(self) -> u32 {
        match self {
            SeriesOp::SinCos(_) => 3,
            SeriesOp::Func(f, _) => 1 + f.primitive().companions(),
            _ => 1,
        }
    }
}

/// One step of the recurrences: the series it writes and how.
#[derive(Clone, Copy, PartialEq, Debug)]
pub struct SeriesStep {
    /// The series written (for [`SeriesOp::SinCos`], the sine; the cosine is `out + 1`, the
    /// derivative of the argument `out + 2`; for [`SeriesOp::Func`], the value, its
    /// companions following).
    pub out: u32,
    /// The operation.
    pub op: SeriesOp,
}

/// A right-hand side `y' = f(t, y)` decomposed for Taylor's method.
///
/// Series `0 … n − 1` are the state components, series `n` the time if `f` reads it; the
/// [`SeriesStep`]s follow in an order where every operand precedes its use.
#[derive(Clone, Debug, PartialEq)]
pub struct Tape {
    pub(crate) dimension: usize,
    pub(crate) time: Option<u32>,
    pub(crate) scalars: Vec<ScalarOp>,
    pub(crate) steps: Vec<SeriesStep>,
    pub(crate) series_count: u32,
    pub(crate) outputs: Vec<Value>,
}

impl Tape {
    /// Decomposes `rhs` (one expression per component of `state`, each a bare symbol) with
    /// `time` the time symbol, if any. Any other symbol `rhs` reads is a constant along the
    /// solution ([`ScalarOp::Symbol`]). Returns `None` if a state entry is not a bare
    /// symbol or `rhs` and `state` differ in length.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::Tape;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let k = a.parameter("k");
    /// let rhs = a.mul(k, x); // x' = k x
    /// let tape = Tape::new(&a, &[x], None, &[rhs]).unwrap();
    /// assert_eq!(tape.dimension(), 1);
    /// assert_eq!(tape.op_count().scalings, 1); // k x is a scaling, not a Cauchy product
    /// ```
    pub fn new(
        arena: &Arena,
        state: &[ExprId],
        time: Option<SymbolId>,
        rhs: &[ExprId],
    ) -> Option<Tape> {
        if state.len() != rhs.len() {
            return None;
        }
        let state: Vec<SymbolId> = state
            .iter()
            .map(|&e| arena.as_symbol(e))
            .collect::<Option<_>>()?;
        Some(Tape::from_program(
            &Program::lower(arena, rhs),
            &state,
            time,
        ))
    }

    /// Decomposes a lowered program whose outputs are the right-hand side of `state`.
    pub fn from_program(program: &Program, state: &[SymbolId], time: Option<SymbolId>) -> Tape {
        let mut b = Builder {
            tape: Tape {
                dimension: state.len(),
                time: time.map(|_| state.len() as u32),
                scalars: Vec::new(),
                steps: Vec::new(),
                series_count: state.len() as u32 + u32::from(time.is_some()),
                outputs: Vec::new(),
            },
            values: Vec::with_capacity(program.ops().len()),
            sincos: IdMap::default(),
        };
        for op in program.ops() {
            let v = b.op(*op, state, time);
            b.values.push(v);
        }
        b.tape.outputs = program
            .outputs()
            .iter()
            .map(|&s| b.values[s as usize])
            .collect();
        b.tape
    }

    /// The number of state components `n`.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The series of the time, if the right-hand side reads it.
    pub fn time(&self) -> Option<u32> {
        self.time
    }

    /// The scalar operations, in evaluation order.
    pub fn scalars(&self) -> &[ScalarOp] {
        &self.scalars
    }

    /// The series steps, in evaluation order.
    pub fn steps(&self) -> &[SeriesStep] {
        &self.steps
    }

    /// The interpreter's table of every series, `st` coefficients each (`st ≥ 1`), in `ws`
    /// (grown, never shrunk: a longer one keeps what follows), with the state `y` at order 0
    /// and the time series t + τ written whole. The time's row is the only one read beyond
    /// what a pass writes, so it is written whole: the workspace may have served another
    /// tape.
    pub(crate) fn seeded<'a>(
        &self,
        ws: &'a mut Vec<f64>,
        st: usize,
        t: f64,
        y: &[f64],
    ) -> &'a mut [f64] {
        let len = self.series_count() * st;
        if ws.len() < len {
            ws.resize(len, 0.0);
        }
        let c = ws.as_mut_slice();
        for (i, &yi) in y.iter().enumerate() {
            c[i * st] = yi;
        }
        if let Some(ti) = self.time {
            let row = &mut c[ti as usize * st..(ti as usize + 1) * st];
            row.fill(0.0);
            row[0] = t;
            if let Some(one) = row.get_mut(1) {
                *one = 1.0;
            }
        }
        c
    }

    /// The number of series (state, time, and one per step; three for a sine–cosine pair:
    /// sine, cosine and the argument's derivative; one and its companions for a primitive).
    pub fn series_count(&self) -> usize {
        self.series_count as usize
    }

    /// Where each component of the right-hand side is.
    pub fn outputs(&self) -> &[Value] {
        &self.outputs
    }

    /// The symbols read as scalars, in tape order.
    pub fn scalar_symbols(&self) -> impl Iterator<Item = SymbolId> + '_ {
        self.scalars.iter().filter_map(|op| match op {
            ScalarOp::Symbol(s) => Some(*s),
            _ => None,
        })
    }

    /// How many steps of each kind the recurrences run.
    pub fn op_count(&self) -> TapeCount {
        let mut c = TapeCount {
            scalars: self.scalars.len(),
            ..TapeCount::default()
        };
        for step in &self.steps {
            match step.op {
                SeriesOp::Add(..)
                | SeriesOp::AddScalar(..)
                | SeriesOp::Sub(..)
                | SeriesOp::SubScalar(..)
                | SeriesOp::ScalarSub(..)
                | SeriesOp::Neg(_) => c.linear += 1,
                SeriesOp::Scale(..) | SeriesOp::DivScalar(..) => c.scalings += 1,
                SeriesOp::Mul(..) => c.products += 1,
                SeriesOp::Square(_) => c.squares += 1,
                SeriesOp::Div(..) | SeriesOp::ScalarDiv(..) => c.quotients += 1,
                SeriesOp::Sqrt(_) => c.roots += 1,
                SeriesOp::Powf(..) => c.powers += 1,
                SeriesOp::SinCos(_) => c.sin_cos += 1,
                SeriesOp::Func(f, _) => c.functions.push(f),
            }
        }
        c
    }
}

/// The steps of a [`Tape`] by kind: what one order of the recurrences costs.
#[derive(Clone, Default, Debug, PartialEq, Eq)]
pub struct TapeCount {
    /// Operations on scalars (once per call).
    pub scalars: usize,
    /// Sums, differences and negations (one flop per order).
    pub linear: usize,
    /// Products and quotients by a scalar (one flop per order).
    pub scalings: usize,
    /// Cauchy products (k + 1 multiply–adds at order k).
    pub products: usize,
    /// Squares (about k/2 multiply–adds at order k).
    pub squares: usize,
    /// Quotients of series (k multiply–adds and a division at order k).
    pub quotients: usize,
    /// Square roots (about k/2 multiply–adds and a division at order k).
    pub roots: usize,
    /// Sine–cosine pairs (2k multiply–adds at order k).
    pub sin_cos: usize,
    /// Real powers (k weighted multiply–adds and a division at order k).
    pub powers: usize,
    /// The registered primitives, one entry per step (each prices its own recurrence).
    pub functions: Vec<Func>,
}

impl TapeCount {
    /// Floating-point operations of the coefficients up to `order` (a multiply–add counts
    /// two), the model the docs' price table uses.
    pub fn flops(&self, order: usize) -> usize {
        let mut f = self.scalars;
        for k in 0..=order {
            let per = |n: usize, flops: usize| n * flops;
            f += per(self.linear + self.scalings, 1);
            f += per(self.products, 2 * (k + 1));
            f += per(self.squares, k + 2);
            f += per(self.quotients, 2 * k + 1);
            f += per(self.roots, k + 2);
            f += per(self.sin_cos, if k == 0 { 1 } else { 6 * k + 2 });
            f += per(self.powers, if k == 0 { 1 } else { 4 * k + 3 });
            f += self
                .functions
                .iter()
                .map(|g| g.primitive().flops(k))
                .sum::<usize>();
        }
        f
    }
}

struct Builder {
    tape: Tape,
    /// The tape value of each program slot.
    values: Vec<Value>,
    /// The sine–cosine pair already made for a series argument (its sine's series).
    sincos: IdMap<u32, u32>,
}

impl Builder {
    fn scalar(&mut self, op: ScalarOp) -> Value {
        self.tape.scalars.push(op);
        Value::Scalar(self.tape.scalars.len() as u32 - 1)
    }

    fn series(&mut self, op: SeriesOp) -> Value {
        Value::Series(self.series_index(op))
    }

    fn series_index(&mut self, op: SeriesOp) -> u32 {
        let out = self.tape.series_count;
        self.tape.series_count += op.width();
        self.tape.steps.push(SeriesStep { out, op });
        out
    }

    fn op(&mut self, op: Op, state: &[SymbolId], time: Option<SymbolId>) -> Value {
        use Value::{Scalar as C, Series as S};
        let v = |s: u32| self.values[s as usize];
        match op {
            Op::Const(x) => self.scalar(ScalarOp::Const(x)),
            Op::Input(s) => match state.iter().position(|&x| x == s) {
                Some(i) => S(i as u32),
                None if Some(s) == time => S(state.len() as u32),
                None => self.scalar(ScalarOp::Symbol(s)),
            },
            Op::Add(a, b) => match (v(a), v(b)) {
                (C(a), C(b)) => self.scalar(ScalarOp::Add(a, b)),
                (S(a), S(b)) => self.series(SeriesOp::Add(a, b)),
                (S(a), C(s)) | (C(s), S(a)) => self.series(SeriesOp::AddScalar(a, s)),
            },
            Op::Sub(a, b) => match (v(a), v(b)) {
                (C(a), C(b)) => self.scalar(ScalarOp::Sub(a, b)),
                (S(a), S(b)) => self.series(SeriesOp::Sub(a, b)),
                (S(a), C(s)) => self.series(SeriesOp::SubScalar(a, s)),
                (C(s), S(a)) => self.series(SeriesOp::ScalarSub(s, a)),
            },
            Op::Mul(a, b) => match (v(a), v(b)) {
                (C(a), C(b)) => self.scalar(ScalarOp::Mul(a, b)),
                (S(a), S(b)) if a == b => self.series(SeriesOp::Square(a)),
                (S(a), S(b)) => self.series(SeriesOp::Mul(a, b)),
                (S(a), C(s)) | (C(s), S(a)) => self.series(SeriesOp::Scale(a, s)),
            },
            Op::Div(a, b) => match (v(a), v(b)) {
                (C(a), C(b)) => self.scalar(ScalarOp::Div(a, b)),
                (S(a), S(b)) => self.series(SeriesOp::Div(a, b)),
                (S(a), C(s)) => self.series(SeriesOp::DivScalar(a, s)),
                (C(s), S(a)) => self.series(SeriesOp::ScalarDiv(s, a)),
            },
            Op::Neg(a) => match v(a) {
                C(a) => self.scalar(ScalarOp::Neg(a)),
                S(a) => self.series(SeriesOp::Neg(a)),
            },
            Op::Sqrt(a) => match v(a) {
                C(a) => self.scalar(ScalarOp::Sqrt(a)),
                S(a) => self.series(SeriesOp::Sqrt(a)),
            },
            Op::Powf(a, r) => match v(a) {
                C(a) => self.scalar(ScalarOp::Powf(a, r)),
                S(a) => self.series(SeriesOp::Powf(a, r)),
            },
            Op::Func(f, a) => match v(a) {
                C(a) => self.scalar(ScalarOp::Func(f, a)),
                S(a) => self.series(SeriesOp::Func(f, a)),
            },
            Op::Sin(a) | Op::Cos(a) => match v(a) {
                C(a) if matches!(op, Op::Sin(_)) => self.scalar(ScalarOp::Sin(a)),
                C(a) => self.scalar(ScalarOp::Cos(a)),
                S(a) => {
                    // The pair is made once per argument, whichever of the two comes first:
                    // each one's recurrence reads the other.
                    let sin = match self.sincos.get(&a) {
                        Some(&sin) => sin,
                        None => {
                            let sin = self.series_index(SeriesOp::SinCos(a));
                            self.sincos.insert(a, sin);
                            sin
                        }
                    };
                    S(if matches!(op, Op::Sin(_)) {
                        sin
                    } else {
                        sin + 1
                    })
                }
            },
        }
    }
}
