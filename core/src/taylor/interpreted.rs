//! [`TaylorTape`]: the recurrences of any symbolic system, interpreted at run time.

use thiserror::Error;

use super::recurrence;
use super::recurrence_dd::{self, DdTable};
use super::scalars::bind_scalars;
use super::tape::{Tape, Value};
use super::{MAX_TAYLOR_ORDER, TaylorSystem};
use crate::codegen::{BindingError, Program};
use crate::exact::Dd;
use crate::sym::{Arena, ExprId, SymbolId};

/// Why a [`TaylorTape`] could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TaylorError {
    /// An event on a state component ([`StateEvent`](super::StateEvent)) past the state.
    #[error("event component {index} is outside the state of dimension {dimension}")]
    EventComponentOutOfRange {
        /// The component asked for.
        index: usize,
        /// The state's dimension.
        dimension: usize,
    },
    /// A state entry that is not a bare symbol (a coordinate, a rate, an input).
    #[error("state entry {index} is not a bare symbol")]
    StateNotASymbol {
        /// Its position in the state.
        index: usize,
    },
    /// A maximum order outside `1 ..= MAX_TAYLOR_ORDER`.
    #[error("maximum Taylor order {order} is outside 1..={max}")]
    Order {
        /// The order asked for.
        order: usize,
        /// The largest order allowed ([`MAX_TAYLOR_ORDER`]).
        max: usize,
    },
    /// A parameter named twice, unknown, unset or not finite, or an input the
    /// interpreter cannot supply.
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// A constant of the right-hand side (parameters and numbers combined) that is not
    /// finite for the values given: a square root or real power of a negative value, a
    /// division by zero.
    #[error(
        "{operation} among the right-hand side's constants is {value} for the parameter values given"
    )]
    NonFiniteConstant {
        /// The operation that gave it ("a square root", "a real power", "a quotient", …).
        operation: &'static str,
        /// Its value.
        value: f64,
    },
}

/// The Taylor coefficients of `y' = f(t, y)` for a right-hand side given as expressions,
/// computed by interpreting its [`Tape`].
///
/// Parameters are bound once, at construction. The coefficient table, `series ×
/// (max_order + 1)` values, is the [`TaylorSystem::Workspace`]: sized on the first call
/// into a workspace, then reused, so a call through the integrator allocates nothing.
///
/// # Examples
/// The harmonic oscillator `x' = v`, `v' = −ω² x` from `x = 1`, `v = 0`: `x = cos ωt`.
/// ```
/// use precess_core::sym::Arena;
/// use precess_core::taylor::{TaylorSystem, TaylorTape};
/// let mut a = Arena::new();
/// let x = a.coordinate("x");
/// let v = a.coordinate("v");
/// let w = a.parameter("omega");
/// let w2 = a.mul(w, w);
/// let ax = a.mul(w2, x);
/// let acc = a.neg(ax);
/// let tape = TaylorTape::new(&a, [x, v], [v, acc], None, &[("omega", 2.0)], 10).unwrap();
/// let mut c = [[0.0; 2]; 5];
/// tape.coefficients(0.0, &[1.0, 0.0], 4, &mut c);
/// approx::assert_relative_eq!(c[2][0], -2.0); // −ω²/2!
/// approx::assert_relative_eq!(c[4][0], 16.0 / 24.0); // ω⁴/4!
/// ```
///
/// # Double-double low orders
/// [`TaylorSystem::coefficients_extended_into`] is implemented for every tape: the
/// constants (parameters combined by the scalar operations) are evaluated in double-double
/// too, so that `1/I₃ − 1/I₂` is not rounded once for the whole run, and sines, cosines and
/// real powers take their values from [`Dd::sin_cos`] and [`Dd::powf`].
///
/// # Parameters the equations do not read
/// `values` may bind every parameter of the arena, also those the right-hand side happens
/// not to read (a free body's mass under gravity alone): they are checked for finiteness
/// and otherwise ignored, so that code binding all of a scene's parameters keeps working
/// when a simplification removes one. A name that is no parameter of the arena at all is
/// still a [`BindingError::UnknownParameter`].
#[derive(Debug)]
pub struct TaylorTape<const N: usize> {
    tape: Tape,
    scalars: Vec<f64>,
    /// The scalars in double-double, for the extended mode.
    scalars_dd: Vec<Dd>,
    max_order: usize,
}

impl<const N: usize> TaylorTape<N> {
    /// The recurrences of `y' = rhs(t, y)` for the state symbols `state`, with `time` the
    /// time symbol if `rhs` reads one, parameters bound by name from `values`, up to
    /// `max_order`.
    ///
    /// # Errors
    /// [`TaylorError::StateNotASymbol`], [`TaylorError::Order`], then the binding errors
    /// (a name that is no parameter of the arena, an unset or non-finite parameter, an
    /// input outside the state; a parameter of the arena that `rhs` does not read is
    /// accepted and ignored), then
    /// [`TaylorError::NonFiniteConstant`] for a constant that the parameters make NaN or
    /// infinite (√ or a real power of a negative value, a division by zero).
    pub fn new(
        arena: &Arena,
        state: [ExprId; N],
        rhs: [ExprId; N],
        time: Option<ExprId>,
        values: &[(&str, f64)],
        max_order: usize,
    ) -> Result<Self, TaylorError> {
        let symbols = state_symbols(arena, &state)?;
        if !(1..=MAX_TAYLOR_ORDER).contains(&max_order) {
            return Err(TaylorError::Order {
                order: max_order,
                max: MAX_TAYLOR_ORDER,
            });
        }
        let (tape, scalars, scalars_dd) = bound_tape(arena, symbols, time, &rhs, values)?;
        Ok(TaylorTape {
            tape,
            scalars,
            scalars_dd,
            max_order,
        })
    }

    /// Whether [`TaylorSystem::coefficients_extended_into`] computes the low orders in
    /// double-double for this tape: always, since every operation has its double-double
    /// recurrence (kept for code written when sines and real powers had none).
    pub fn extends(&self) -> bool {
        true
    }

    /// The decomposed right-hand side.
    pub fn tape(&self) -> &Tape {
        &self.tape
    }
}

impl<const N: usize> TaylorSystem<N> for TaylorTape<N> {
    type Workspace = Vec<f64>;

    fn max_order(&self) -> usize {
        self.max_order
    }

    fn coefficients_into(
        &self,
        ws: &mut Vec<f64>,
        t: f64,
        y: &[f64; N],
        order: usize,
        coeffs: &mut [[f64; N]],
    ) {
        let Some(top) = coeffs.len().checked_sub(1) else {
            return;
        };
        let order = order.min(self.max_order).min(top);
        let st = self.max_order + 1;
        // Longer is fine: the extended mode keeps its double-double table after this one.
        let c = self.tape.seeded(ws, st, t, y);
        coeffs[0] = *y;
        // The steps at order k give f's coefficient k, which only order k + 1 reads: the
        // last order needs none.
        for k in 0..order {
            for s in &self.tape.steps {
                recurrence::step(c, st, &self.scalars, s, k);
            }
            let inv = 1.0 / (k + 1) as f64;
            for (i, out) in self.tape.outputs.iter().enumerate() {
                let fk = match *out {
                    Value::Series(x) => c[x as usize * st + k],
                    Value::Scalar(x) if k == 0 => self.scalars[x as usize],
                    Value::Scalar(_) => 0.0,
                };
                c[i * st + k + 1] = fk * inv;
                coeffs[k + 1][i] = fk * inv;
            }
        }
    }

    fn coefficients_extended_into(
        &self,
        ws: &mut Vec<f64>,
        t: Dd,
        y: &[Dd; N],
        order: usize,
        coeffs: &mut [[f64; N]],
        low: &mut [[Dd; N]],
    ) -> bool {
        let sdd = self.scalars_dd.as_slice();
        let Some(top) = coeffs.len().checked_sub(1) else {
            return false;
        };
        self.coefficients_into(ws, t.to_f64(), &y.map(Dd::to_f64), order, coeffs);
        let order = order.min(self.max_order).min(top);
        let Some(last) = low.len().checked_sub(1).map(|l| l.min(order)) else {
            return true;
        };
        // The double-double table, orders 0 ..= last of every series, after the f64 one.
        let base = self.tape.series_count() * (self.max_order + 1);
        let st = last + 1;
        let need = base + DdTable::len(self.tape.series_count(), st);
        if ws.len() < need {
            ws.resize(need, 0.0);
        }
        let mut c = DdTable {
            w: &mut ws[base..need],
            st,
        };
        for (i, &yi) in y.iter().enumerate() {
            c.set(i as u32, 0, yi);
        }
        if let Some(ti) = self.tape.time() {
            for k in 0..st {
                let v = match k {
                    0 => t,
                    1 => Dd::from(1.0),
                    _ => Dd::default(),
                };
                c.set(ti, k, v);
            }
        }
        low[0] = *y;
        for k in 0..last {
            for s in &self.tape.steps {
                recurrence_dd::step(&mut c, &|x| sdd[x as usize], s, k);
            }
            let div = (k + 1) as f64;
            for (i, out) in self.tape.outputs.iter().enumerate() {
                let fk = match *out {
                    Value::Series(x) => c.get(x, k),
                    Value::Scalar(x) if k == 0 => sdd[x as usize],
                    Value::Scalar(_) => Dd::default(),
                };
                let v = fk.div_f64(div);
                c.set(i as u32, k + 1, v);
                low[k + 1][i] = v;
            }
        }
        true
    }
}

/// The symbols of the state entries, in order.
///
/// # Errors
/// [`TaylorError::StateNotASymbol`] for the first entry that is not a bare symbol.
pub(super) fn state_symbols<const N: usize>(
    arena: &Arena,
    state: &[ExprId; N],
) -> Result<Vec<SymbolId>, TaylorError> {
    let mut symbols = Vec::with_capacity(N + 1);
    for (index, &e) in state.iter().enumerate() {
        symbols.push(
            arena
                .as_symbol(e)
                .ok_or(TaylorError::StateNotASymbol { index })?,
        );
    }
    Ok(symbols)
}

/// The tape of `outputs` over the state `symbols` (and `time`'s symbol, if it is one), with
/// its scalars bound from `values` in f64 and in double-double: what a [`TaylorTape`] (the
/// right-hand side) and a [`TaylorEvent`](super::TaylorEvent) (the event function) build
/// once, the same way.
///
/// # Errors
/// The binding errors, then [`TaylorError::NonFiniteConstant`], as [`TaylorTape::new`].
pub(super) fn bound_tape(
    arena: &Arena,
    mut symbols: Vec<SymbolId>,
    time: Option<ExprId>,
    outputs: &[ExprId],
    values: &[(&str, f64)],
) -> Result<(Tape, Vec<f64>, Vec<Dd>), TaylorError> {
    let time = time.and_then(|t| arena.as_symbol(t));
    let program = Program::lower(arena, outputs);
    let tape = Tape::from_program(&program, &symbols, time);
    symbols.extend(time);
    let (scalars, scalars_dd) = bind_scalars(arena, &program, &tape, &symbols, values)?;
    Ok((tape, scalars, scalars_dd))
}
