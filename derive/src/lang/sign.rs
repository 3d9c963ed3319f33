//! The sign rules every attribute holds its values to where they are constants: a size, a
//! magnitude or a moment positive, a coefficient zero or positive. A value that reads a
//! field is judged at run time by the scene's `check_parameters`; one written in numbers is
//! judged here, once for every attribute, its error spanned on the value as written.

use precess_core::sym::ExprId;
use syn::Expr;

use super::check::Checker;

/// What a value must be.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Bound {
    /// Greater than zero.
    Positive,
    /// Zero or greater.
    NonNegative,
}

impl Bound {
    /// Whether `x` keeps the bound (NaN keeps none).
    fn holds(self, x: f64) -> bool {
        match self {
            Bound::Positive => x > 0.0,
            Bound::NonNegative => x >= 0.0,
        }
    }

    /// The rule as the message states it.
    fn rule(self) -> &'static str {
        match self {
            Bound::Positive => "positive",
            Bound::NonNegative => "zero or positive",
        }
    }
}

impl Checker<'_> {
    /// `value` as a scalar that must be positive where it is a constant; `what` names it in
    /// the error (``the rotor's `inertia` ``), `why` says why, if the rule needs saying.
    pub fn positive(&mut self, value: &Expr, what: &str, why: Option<&str>) -> Option<ExprId> {
        let v = self.scalar(value)?;
        self.bounded(value, v, Bound::Positive, what, why)
            .then_some(v)
    }

    /// `value` as a scalar that must be zero or positive where it is a constant (a
    /// coefficient of friction or damping), as [`Checker::positive`].
    pub fn non_negative(&mut self, value: &Expr, what: &str, why: Option<&str>) -> Option<ExprId> {
        let v = self.scalar(value)?;
        self.bounded(value, v, Bound::NonNegative, what, why)
            .then_some(v)
    }

    /// `value` as a vector `[a, b, c]` each of whose constant components must be positive
    /// (the semi-axes of an ellipsoid), the error on the component.
    pub fn positive_vector(&mut self, value: &Expr, what: &str) -> Option<[ExprId; 3]> {
        let v = self.vector(value)?;
        let mut ok = true;
        if let Expr::Array(a) = value {
            for (k, (&e, tokens)) in v.iter().zip(&a.elems).enumerate() {
                let place = format!("{what} in place {}", k + 1);
                ok &= self.bounded(tokens, e, Bound::Positive, &place, None);
            }
        }
        ok.then_some(v)
    }

    /// True if `v`, the value of the tokens `value`, is positive or not a constant; else
    /// records the error on `value` (a density, already read, that must be positive).
    pub fn positive_constant(&self, value: &Expr, v: ExprId, what: &str) -> bool {
        self.bounded(value, v, Bound::Positive, what, None)
    }

    /// True if `v` keeps `bound` or reads a field; else records why on `value`.
    fn bounded(
        &self,
        value: &Expr,
        v: ExprId,
        bound: Bound,
        what: &str,
        why: Option<&str>,
    ) -> bool {
        if !self.arena.free_symbols(v).is_empty() {
            return true;
        }
        let x = self.arena.eval(v, &[]);
        if bound.holds(x) {
            return true;
        }
        let why = why.map(|w| format!(" ({w})")).unwrap_or_default();
        self.cx.error_spanned_by(
            value,
            format!("{what} is {x}: it must be {}{why}", bound.rule()),
        );
        false
    }
}

#[cfg(test)]
mod tests {
    use super::Bound;

    #[test]
    fn the_bounds_refuse_nan_and_keep_their_edge() {
        assert!(Bound::Positive.holds(1e-300));
        assert!(!Bound::Positive.holds(0.0));
        assert!(!Bound::Positive.holds(f64::NAN));
        assert!(Bound::NonNegative.holds(0.0));
        assert!(!Bound::NonNegative.holds(-1e-300));
        assert!(!Bound::NonNegative.holds(f64::NAN));
    }
}
