//! The constants of a tape: its scalars (the parameters and numbers of the right-hand side
//! and what they combine into), bound by name and evaluated once in `f64` and in
//! double-double, the two read from one meaning of each [`ScalarOp`].

use core::ops::{Add, Div, Mul, Neg, Sub};

use super::interpreted::TaylorError;
use super::tape::{ScalarOp, Tape};
use crate::codegen::{BindingError, Bindings, Program, check_distinct};
use crate::exact::Dd;
use crate::sym::{Arena, Func, SymbolId};

/// The values of `tape`'s scalars (lowered from `program`, whose inputs are `symbols` and
/// parameters), in f64 and in double-double, with the parameters bound by name from
/// `values`.
///
/// # Errors
/// The binding errors, then [`TaylorError::NonFiniteConstant`], as
/// [`TaylorTape::new`](super::TaylorTape::new).
pub(super) fn bind_scalars(
    arena: &Arena,
    program: &Program,
    tape: &Tape,
    symbols: &[SymbolId],
    values: &[(&str, f64)],
) -> Result<(Vec<f64>, Vec<Dd>), TaylorError> {
    // A parameter of the arena that the program does not read is bound by code that
    // binds a whole scene: judged for finiteness, then left out of what Bindings sees.
    let inputs = program.inputs();
    let read = |name: &str| inputs.iter().any(|&s| arena.symbol(s).name == name);
    // A name given twice is refused before any is judged, read or not.
    check_distinct(values)?;
    let mut used = Vec::with_capacity(values.len());
    for &(name, value) in values {
        if read(name) || arena.find_parameter(name).is_none() {
            used.push((name, value));
        } else if !value.is_finite() {
            return Err(BindingError::NonFinite {
                name: name.to_owned(),
                value,
            }
            .into());
        }
    }
    // Bindings judges the names and values; the values are then read here by name.
    Bindings::new(arena, std::slice::from_ref(program), symbols, &used)?;
    let value_of = |s| {
        let name = &arena.symbol(s).name;
        values
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map_or(f64::NAN, |&(_, v)| v)
    };
    let mut scalars: Vec<f64> = Vec::with_capacity(tape.scalars.len());
    for op in &tape.scalars {
        let v = scalar_value(op, &scalars, &value_of);
        if !v.is_finite() {
            return Err(TaylorError::NonFiniteConstant {
                operation: operation_name(op),
                value: v,
            });
        }
        scalars.push(v);
    }
    let scalars_dd = scalars_in_dd(tape, &value_of);
    Ok((scalars, scalars_dd))
}

/// How [`TaylorError::NonFiniteConstant`] names a scalar operation.
fn operation_name(op: &ScalarOp) -> &'static str {
    match op {
        ScalarOp::Const(_) => "a number",
        ScalarOp::Symbol(_) => "a parameter",
        ScalarOp::Add(..) => "a sum",
        ScalarOp::Sub(..) => "a difference",
        ScalarOp::Mul(..) => "a product",
        ScalarOp::Div(..) => "a quotient",
        ScalarOp::Neg(_) => "a negation",
        ScalarOp::Sqrt(_) => "a square root",
        ScalarOp::Powf(..) => "a real power",
        ScalarOp::Sin(_) => "a sine",
        ScalarOp::Cos(_) => "a cosine",
        ScalarOp::Func(f, _) => f.name(),
    }
}

/// The tape's scalars in double-double; `value_of` gives a symbol's bound value.
fn scalars_in_dd(tape: &Tape, value_of: &dyn Fn(SymbolId) -> f64) -> Vec<Dd> {
    let mut out: Vec<Dd> = Vec::with_capacity(tape.scalars.len());
    for op in &tape.scalars {
        let v = scalar_value(op, &out, value_of);
        out.push(v);
    }
    out
}

/// The value of the scalar operation `op` in `T`, from the values of the scalars before it
/// (`done`, in tape order) and the bound parameters (`value_of`): the one reading of a
/// [`ScalarOp`] that the `f64` constants and their double-double twins share, so the two
/// tables cannot disagree on what an operation means.
fn scalar_value<T: ScalarValue>(
    op: &ScalarOp,
    done: &[T],
    value_of: &dyn Fn(SymbolId) -> f64,
) -> T {
    let x = |i: u32| done[i as usize];
    match *op {
        ScalarOp::Const(c) => T::from(c),
        ScalarOp::Symbol(s) => T::from(value_of(s)),
        ScalarOp::Add(a, b) => x(a) + x(b),
        ScalarOp::Sub(a, b) => x(a) - x(b),
        ScalarOp::Mul(a, b) => x(a) * x(b),
        ScalarOp::Div(a, b) => x(a) / x(b),
        ScalarOp::Neg(a) => -x(a),
        ScalarOp::Sqrt(a) => x(a).sqrt(),
        ScalarOp::Powf(a, r) => x(a).powf(r),
        ScalarOp::Sin(a) => x(a).sin(),
        ScalarOp::Cos(a) => x(a).cos(),
        ScalarOp::Func(f, a) => x(a).func(f),
    }
}

/// A number the tape's scalars are evaluated in (`f64`, [`Dd`]): the arithmetic of its
/// operators, and the functions of a [`ScalarOp`] as that type computes them. Each method
/// calls the type's inherent one of the same name, which a path names before a trait's.
trait ScalarValue:
    Copy
    + From<f64>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// √x.
    fn sqrt(self) -> Self;
    /// xʳ.
    fn powf(self, r: f64) -> Self;
    /// sin x.
    fn sin(self) -> Self;
    /// cos x.
    fn cos(self) -> Self;
    /// f(x) for a registered primitive `f`.
    fn func(self, f: Func) -> Self;
}

impl ScalarValue for f64 {
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    fn powf(self, r: f64) -> f64 {
        f64::powf(self, r)
    }
    fn sin(self) -> f64 {
        f64::sin(self)
    }
    fn cos(self) -> f64 {
        f64::cos(self)
    }
    fn func(self, f: Func) -> f64 {
        f.value(self)
    }
}

impl ScalarValue for Dd {
    fn sqrt(self) -> Dd {
        Dd::sqrt(self)
    }
    fn powf(self, r: f64) -> Dd {
        Dd::powf(self, r)
    }
    // Dd computes the two together; the tape keeps sin and cos as separate scalars.
    fn sin(self) -> Dd {
        self.sin_cos().0
    }
    fn cos(self) -> Dd {
        self.sin_cos().1
    }
    fn func(self, f: Func) -> Dd {
        f.value_dd(self)
    }
}
