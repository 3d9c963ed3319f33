//! The registry of primitive functions: one file per function holds everything the engine
//! knows about it, as heyoka does it.
//!
//! A primitive `f` is a `Primitive` (a crate-internal trait) in its own file here: its name
//! (the call in user expressions, the plain text, the `f64` method), its value in `f64` and
//! double-double, its exact rules (the canonical form, `exp 0 = 1`), its derivative `f′(u)`,
//! its LaTeX, the Rust tokens of a call, and its Taylor recurrence in the three forms the
//! engine runs (the `f64` interpreter, the double-double low orders of the extended mode,
//! the emitted code of `taylor = K`). The engine's walks treat [`Node::Func`] and every
//! lowered form of it (`Op::Func`, `ScalarOp::Func`, `SeriesOp::Func`) through this trait
//! alone, so adding a primitive is its file plus three lines of registration below (`mod`,
//! `pub use` of its handle, and the entry of `PRIMITIVES`), and the macros see it by name
//! through [`Func::named`].
//!
//! A recurrence may need series of its own besides its output (companions): the output is
//! series `out`, the companions `out + 1 …`. The exponential keeps the derivative of its
//! argument, `d_j = j u_j`, as one; a sine would keep its cosine. A recurrence reads its
//! argument at the current order only (the emitter may keep an argument read once as a
//! `let`, with no row); one that needs the argument's lower orders keeps them in a
//! companion, as the exponential does with `d`.
//!
//! The elementary functions that came before the registry (`sin`, `cos`, `sqrt`, real
//! powers) are still nodes of their own, with the trigonometric rules of the canonical form
//! (`sin² u = 1 − cos² u`) that expansion and cancellation rely on.

mod exp;
mod rows;

pub use exp::EXP;

use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;
use crate::exact::Dd;

pub(crate) use rows::{DdTable, F64Table};

/// A primitive function of the engine; see the module's docs for what each part is for.
pub(crate) trait Primitive: Sync {
    /// The name: the call in user expressions (`exp(x)`, `x.exp()`), the plain text, and
    /// the `f64` method of the generated code.
    fn name(&self) -> &'static str;
    /// The LaTeX command written before the argument (`\exp`).
    fn latex(&self) -> &'static str;
    /// The value in `f64`.
    fn value(&self, x: f64) -> f64;
    /// The value in double-double (the extended mode's constants and order 0).
    fn value_dd(&self, x: Dd) -> Dd;
    /// The exact value of `f(u)` when a rule gives one (`exp 0 = 1`), `None` to keep the
    /// node `f(u)`.
    ///
    /// # Errors
    /// A [`SymError`] for an argument outside the domain.
    fn exact(&self, arena: &mut Arena, u: ExprId) -> Result<Option<ExprId>, SymError>;
    /// `f′(u)`, given `value = f(u)` (which the exponential is its own derivative of).
    fn derivative(&self, arena: &mut Arena, u: ExprId, value: ExprId) -> ExprId;
    /// The number of companion series the recurrence keeps after its output.
    fn companions(&self) -> u32;
    /// Floating-point operations of the recurrence at order `k` (a multiply–add counts two).
    fn flops(&self, k: usize) -> usize;
    /// Writes the output (and companions) at order `k` in `f64`, the argument known to
    /// order `k`, the output to `k − 1`.
    fn series(&self, c: &mut F64Table<'_>, arg: u32, out: u32, k: usize);
    /// As [`Primitive::series`], in double-double.
    fn series_dd(&self, c: &mut DdTable<'_>, arg: u32, out: u32, k: usize);
    /// The emitted code of the recurrence, which must round as [`Primitive::series`] does.
    fn series_code(&self, names: &SeriesNames) -> SeriesCode;
}

/// The identifiers the emitted code of one recurrence step uses.
pub(crate) struct SeriesNames {
    /// The output's row (`row[k]` is its order-k coefficient).
    pub out: Ident,
    /// The `let` that must hold the output's current order once the step has run.
    pub value: Ident,
    /// The companions' rows.
    pub companions: Vec<Ident>,
    /// The argument at order 0.
    pub arg_zero: TokenStream,
    /// The argument at the current order `__k`.
    pub arg_k: TokenStream,
    /// The `let` for the part of the sum that reads lower orders only.
    pub interior: Ident,
    /// The path of [`crate::sym::series::dot_reversed`] in the generated code.
    pub dot: TokenStream,
}

/// The emitted code of one recurrence step: order 0, then at each order `__k ≥ 1` the
/// interior (lower orders only, run before any step of order `__k`) and the value.
pub(crate) struct SeriesCode {
    /// Order 0: binds [`SeriesNames::value`] and writes `out[0]`.
    pub zero: TokenStream,
    /// The interior at order `__k`.
    pub interior: TokenStream,
    /// The value at order `__k`: binds [`SeriesNames::value`] and writes `out[__k]`.
    pub order_k: TokenStream,
}

/// Every primitive, in a fixed order (the index [`Func::index`] gives, which the extended
/// mode's tables store). Registration is an entry here and the `mod` and `pub use` lines
/// above.
static PRIMITIVES: [&dyn Primitive; 1] = [&exp::Exp];

/// A handle on a registered primitive function (see the module's docs); equal, ordered and
/// hashed by name, which the registry keeps unique.
#[derive(Clone, Copy)]
pub struct Func(&'static dyn Primitive);

impl Func {
    /// The primitive called `name`, if one is registered.
    ///
    /// ```
    /// use precess_core::sym::Func;
    /// for f in Func::all() {
    ///     assert_eq!(Func::named(f.name()), Some(f));
    /// }
    /// assert_eq!(Func::named("gamma"), None);
    /// ```
    pub fn named(name: &str) -> Option<Func> {
        Func::all().find(|f| f.name() == name)
    }

    /// Every registered primitive.
    pub fn all() -> impl Iterator<Item = Func> {
        PRIMITIVES.iter().map(|&p| Func(p))
    }

    /// The primitive with index `i` (as [`Func::index`] gives), if there is one.
    pub fn from_index(i: usize) -> Option<Func> {
        PRIMITIVES.get(i).map(|&p| Func(p))
    }

    /// The index in the registry (fixed within one build, for the extended mode's tables).
    pub fn index(self) -> usize {
        PRIMITIVES
            .iter()
            .position(|p| p.name() == self.name())
            .unwrap_or(usize::MAX)
    }

    /// The name, as user expressions call it.
    pub fn name(self) -> &'static str {
        self.0.name()
    }

    /// The LaTeX command written before the argument.
    pub fn latex(self) -> &'static str {
        self.0.latex()
    }

    /// The value at `x` in `f64`.
    pub fn value(self, x: f64) -> f64 {
        self.0.value(x)
    }

    /// The value at `x` in double-double.
    pub fn value_dd(self, x: Dd) -> Dd {
        self.0.value_dd(x)
    }

    /// The Rust tokens of `f(x)`: the `f64` method of the name.
    pub fn call_tokens(self, x: TokenStream) -> TokenStream {
        let f = Ident::new(self.name(), proc_macro2::Span::call_site());
        quote!(f64::#f(#x))
    }

    pub(crate) fn primitive(self) -> &'static dyn Primitive {
        self.0
    }
}

impl PartialEq for Func {
    fn eq(&self, other: &Func) -> bool {
        self.name() == other.name()
    }
}

impl Eq for Func {}

impl Hash for Func {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.name().hash(state);
    }
}

impl PartialOrd for Func {
    fn partial_cmp(&self, other: &Func) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Func {
    fn cmp(&self, other: &Func) -> Ordering {
        self.name().cmp(other.name())
    }
}

impl fmt::Debug for Func {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl Arena {
    /// `f(u)` in canonical form: the exact value when the primitive's rules give one, else
    /// the node.
    ///
    /// # Errors
    /// [`SymError::ForeignExpression`] for an id of another arena; what the primitive's
    /// rules return for an argument outside its domain.
    ///
    /// (Each primitive's handle shows one in use.)
    pub fn apply(&mut self, f: Func, u: ExprId) -> Result<ExprId, SymError> {
        self.check_owned(&[u])?;
        match f.primitive().exact(self, u)? {
            Some(v) => Ok(v),
            None => Ok(self.intern(Node::Func(f, u))),
        }
    }

    /// `d f(u)/ds = f′(u) u′` for the node `e = f(u)`, with `du = ∂u/∂s` known.
    pub(crate) fn diff_func(&mut self, f: Func, u: ExprId, e: ExprId, du: ExprId) -> ExprId {
        if du == self.zero() {
            return du;
        }
        let d = f.primitive().derivative(self, u, e);
        self.mul(d, du)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Rational;
    use proptest::prelude::*;

    /// The highest order the properties compare (the repeated derivatives grow fast).
    const ORDERS: usize = 7;

    /// The coefficients of `f(u(τ))` for `u = p0 + p1 τ + p2 τ²` (quarters), from the
    /// recurrence in f64 and in double-double, and from repeated symbolic derivatives
    /// `(1/k!) dᵏ/dτᵏ f(u)` at τ = 0 (a second formulation: the derivative, not the series).
    fn three_ways(f: Func, p: [i64; 3]) -> [[f64; ORDERS]; 3] {
        let mut a = Arena::new();
        let x = a.coordinate("x");
        let s = a.as_symbol(x).unwrap();
        let quarter = |n: i64| Rational::new(i128::from(n), 4).unwrap();
        let terms: Vec<ExprId> = (0..3)
            .map(|j| {
                let c = a.constant(quarter(p[j]));
                let xj = a.powi(x, j as i64).unwrap();
                a.mul(c, xj)
            })
            .collect();
        let u = a.sum(&terms);
        let mut d = a.apply(f, u).unwrap();
        let mut symbolic = [0.0; ORDERS];
        let mut factorial = 1.0;
        for (k, c) in symbolic.iter_mut().enumerate() {
            if k > 0 {
                factorial *= k as f64;
            }
            *c = a.eval(d, &[0.0]) / factorial;
            d = a.diff(d, s);
        }
        let width = 2 + f.primitive().companions() as usize;
        let mut w = vec![0.0; width * ORDERS];
        let mut t = F64Table {
            c: &mut w,
            st: ORDERS,
        };
        let mut dw = vec![0.0; DdTable::len(width, ORDERS)];
        let mut td = DdTable {
            w: &mut dw,
            st: ORDERS,
        };
        for (j, &pj) in p.iter().enumerate() {
            t.set(0, j, quarter(pj).to_f64());
            td.set(0, j, Dd::from(quarter(pj).to_f64()));
        }
        let (mut series, mut series_dd) = ([0.0; ORDERS], [0.0; ORDERS]);
        for k in 0..ORDERS {
            f.primitive().series(&mut t, 0, 1, k);
            f.primitive().series_dd(&mut td, 0, 1, k);
            series[k] = t.get(1, k);
            series_dd[k] = td.get(1, k).to_f64();
        }
        [symbolic, series, series_dd]
    }

    proptest! {
        /// Every registered primitive's recurrence (f64 and double-double) gives the Taylor
        /// coefficients its derivative gives, on random quadratic arguments.
        #[test]
        fn recurrences_agree_with_repeated_derivatives(p in proptest::array::uniform3(-6i64..=6)) {
            for f in Func::all() {
                let [symbolic, series, series_dd] = three_ways(f, p);
                let scale = symbolic.iter().fold(1.0f64, |m, c| m.max(c.abs()));
                for k in 0..ORDERS {
                    prop_assert!(
                        (series[k] - symbolic[k]).abs() <= 1e-12 * scale,
                        "{} order {k}: series {} vs derivative {}", f.name(), series[k], symbolic[k]
                    );
                    prop_assert!(
                        (series_dd[k] - symbolic[k]).abs() <= 1e-12 * scale,
                        "{} order {k}: double-double {} vs derivative {}", f.name(), series_dd[k], symbolic[k]
                    );
                }
            }
        }

        /// Every registered primitive's derivative matches central differences of its value.
        #[test]
        fn derivatives_match_central_differences(x in -2.0f64..2.0) {
            for f in Func::all() {
                let mut a = Arena::new();
                let u = a.coordinate("u");
                let s = a.as_symbol(u).unwrap();
                let e = a.apply(f, u).unwrap();
                let d = a.diff(e, s);
                let h = 1e-5;
                let fd = (f.value(x + h) - f.value(x - h)) / (2.0 * h);
                let got = a.eval(d, &[x]);
                prop_assert!((got - fd).abs() <= 1e-8 * fd.abs().max(1.0), "{}: {got} vs {fd}", f.name());
            }
        }
    }

    /// Every handle names its own entry, and names are unique (a lookup by name is exact).
    #[test]
    fn handles_and_names_agree() {
        for f in Func::all() {
            assert_eq!(Func::named(f.name()), Some(f));
            assert_eq!(Func::from_index(f.index()), Some(f));
        }
        assert_eq!(Func::from_index(PRIMITIVES.len()), None);
    }
}
