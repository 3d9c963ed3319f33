//! Constraints linear in the rates, `A(q, t) q̇ + b(q, t) = 0`: nonholonomic rows given
//! directly, holonomic rows `φ(q, t) = 0` differentiated symbolically to `J q̇ + ∂φ/∂t = 0`.

use super::equations::Coordinates;
use super::error::LagrangeError;
use crate::sym::{Arena, ExprId, SymbolId, SymbolKind};

/// m constraints `A(q, t) q̇ + b(q, t) = 0` on the coordinates of one derivation.
///
/// Each row remembers the position function φ it came from when it is holonomic, so that
/// the run-time model can pull the coordinates back onto `φ(q) = 0`
/// ([`super::ConstrainedModel::close_loop`]).
///
/// ```
/// use precess_core::{lagrange::{Constraints, Coordinates}, sym::Arena};
/// // A point on the circle x² + y² = ℓ²: one holonomic row 2x ẋ + 2y ẏ = 0.
/// let mut a = Arena::new();
/// let c = Coordinates::new(&mut a, &["x", "y"]);
/// let l = a.parameter("l");
/// let (x2, y2, l2) = (a.mul(c.q[0], c.q[0]), a.mul(c.q[1], c.q[1]), a.mul(l, l));
/// let s = a.add(x2, y2);
/// let phi = a.sub(s, l2);
/// let mut k = Constraints::new();
/// k.holonomic(&mut a, &c, phi)?;
/// let two = a.integer(2);
/// assert_eq!(k.coefficients[0][0], a.mul(two, c.q[0]));
/// assert_eq!(k.offsets[0], a.zero());
/// # Ok::<(), precess_core::lagrange::LagrangeError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Constraints {
    /// `A_rj`, one row per constraint, one entry per coordinate (expanded, except the rows
    /// added by [`Constraints::nonholonomic_shared`] and [`Constraints::holonomic_shared`]).
    pub coefficients: Vec<Vec<ExprId>>,
    /// `b_r` (expanded, except for the rows added by the `_shared` constructors).
    pub offsets: Vec<ExprId>,
    /// `φ_r` for a holonomic row, `None` for a nonholonomic one.
    pub positions: Vec<Option<ExprId>>,
}

impl Constraints {
    /// The index the next row gets, once `row` is checked to have one entry per coordinate.
    fn next_row_of_length(
        &self,
        coords: &Coordinates,
        row: &[ExprId],
    ) -> Result<usize, LagrangeError> {
        let r = self.len();
        if row.len() != coords.len() {
            return Err(LagrangeError::ConstraintLength {
                row: r,
                got: row.len(),
                expected: coords.len(),
            });
        }
        Ok(r)
    }

    /// No constraints yet.
    pub fn new() -> Constraints {
        Constraints::default()
    }

    /// The number of rows m.
    pub fn len(&self) -> usize {
        self.offsets.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.offsets.is_empty()
    }

    /// True when every row is holonomic (the run-time model can close the loop).
    pub fn all_holonomic(&self) -> bool {
        self.positions.iter().all(Option::is_some)
    }

    /// Adds the velocity constraint `Σ_j row_j q̇_j + offset = 0`.
    ///
    /// # Errors
    /// [`LagrangeError::ConstraintLength`] if `row` has not one entry per coordinate;
    /// [`LagrangeError::ConstraintNotLinear`] if an entry or the offset holds a rate or an
    /// acceleration.
    pub fn nonholonomic(
        &mut self,
        arena: &mut Arena,
        coords: &Coordinates,
        row: &[ExprId],
        offset: ExprId,
    ) -> Result<&mut Self, LagrangeError> {
        let r = self.next_row_of_length(coords, row)?;
        for &e in row.iter().chain([&offset]) {
            reject_rates(arena, r, e)?;
        }
        let row: Vec<ExprId> = row.iter().map(|&e| arena.expand(e)).collect();
        self.coefficients.push(row);
        self.offsets.push(arena.expand(offset));
        self.positions.push(None);
        Ok(self)
    }

    /// Adds the velocity constraint `Σ_j row_j q̇_j + offset = 0` with its entries as given,
    /// not expanded: for rows that are only evaluated, lowered or differentiated (the rolling
    /// rows of a mechanism, solved numerically), where expanding products of long shared
    /// factors (a wheel's contact velocity deep in a tree) costs more than all the rest and
    /// lowers larger. An entry that is identically zero is taken as the arena's zero
    /// ([`Arena::is_zero`], exact), so that the zeros of A are still structural, and a row
    /// whose entries and offset all vanish is no constraint: it is not added, and the
    /// answer is `false`.
    ///
    /// # Errors
    /// As [`Constraints::nonholonomic`]; [`LagrangeError::Sym`] if an entry that vanishes at
    /// every point tried is too large to expand.
    pub fn nonholonomic_shared(
        &mut self,
        arena: &mut Arena,
        coords: &Coordinates,
        row: &[ExprId],
        offset: ExprId,
    ) -> Result<bool, LagrangeError> {
        let r = self.next_row_of_length(coords, row)?;
        let mut exact = Vec::with_capacity(row.len() + 1);
        for &e in row.iter().chain([&offset]) {
            reject_rates(arena, r, e)?;
            exact.push(if arena.is_zero(e)? { arena.zero() } else { e });
        }
        if exact.iter().all(|&e| e == arena.zero()) {
            return Ok(false);
        }
        let offset = exact.pop().unwrap_or_else(|| arena.zero());
        self.coefficients.push(exact);
        self.offsets.push(offset);
        self.positions.push(None);
        Ok(true)
    }

    /// Adds the holonomic constraint `φ(q, t) = 0` from its rate given in a shared form:
    /// `rate` is any expression equal to dφ/dt = Σ_j ∂φ/∂q_j q̇_j + ∂φ/∂t (linear in q̇), and
    /// the row is read from it, A_j = ∂rate/∂q̇_j, with the offset ∂φ/∂t, neither expanded
    /// (as in [`Constraints::nonholonomic_shared`], identically zero entries are made the
    /// arena's zero, exactly). For a caller that knows a shorter form of the rate than the
    /// derivatives of φ (a wheel's height on the floor rises at the vertical velocity of the
    /// wheel's material point at the contact) and only evaluates the row. φ is kept, as
    /// given, for the run-time projection.
    ///
    /// # Errors
    /// [`LagrangeError::ConstraintNotLinear`] if φ holds a rate or an acceleration;
    /// [`LagrangeError::Sym`] if an entry that vanishes at every point tried is too large to
    /// expand.
    pub fn holonomic_shared(
        &mut self,
        arena: &mut Arena,
        coords: &Coordinates,
        phi: ExprId,
        rate: ExprId,
    ) -> Result<&mut Self, LagrangeError> {
        let r = self.len();
        reject_rates(arena, r, phi)?;
        // A coordinate φ does not hold has a zero entry, known without testing it (which
        // expands what vanishes); through an abbreviation φ may hold any of them.
        let held = arena.free_symbols(phi);
        let opaque = held
            .iter()
            .any(|&s| arena.symbol(s).kind == SymbolKind::Abbreviation);
        let mut row = Vec::with_capacity(coords.len());
        for (&q, &qd) in coords.q.iter().zip(&coords.rates) {
            if !opaque && !held.contains(&symbol(arena, q)) {
                row.push(arena.zero());
                continue;
            }
            let d = arena.diff(rate, symbol(arena, qd));
            row.push(if arena.is_zero(d)? { arena.zero() } else { d });
        }
        let offset = match arena.time_symbol() {
            Some(t) => {
                let d = arena.diff(phi, t);
                if arena.is_zero(d)? { arena.zero() } else { d }
            }
            None => arena.zero(),
        };
        self.coefficients.push(row);
        self.offsets.push(offset);
        self.positions.push(Some(phi));
        Ok(self)
    }

    /// Adds the holonomic constraint `φ(q, t) = 0` as its derivative
    /// `Σ_j ∂φ/∂q_j q̇_j + ∂φ/∂t = 0`, keeping φ for the run-time projection.
    ///
    /// # Errors
    /// [`LagrangeError::ConstraintNotLinear`] if φ holds a rate or an acceleration.
    pub fn holonomic(
        &mut self,
        arena: &mut Arena,
        coords: &Coordinates,
        phi: ExprId,
    ) -> Result<&mut Self, LagrangeError> {
        let r = self.len();
        reject_rates(arena, r, phi)?;
        let row: Vec<ExprId> = coords
            .q
            .iter()
            .map(|&q| {
                let s = symbol(arena, q);
                let d = arena.diff(phi, s);
                arena.expand(d)
            })
            .collect();
        let offset = match arena.time_symbol() {
            Some(t) => {
                let d = arena.diff(phi, t);
                arena.expand(d)
            }
            None => arena.zero(),
        };
        self.coefficients.push(row);
        self.offsets.push(offset);
        self.positions.push(Some(arena.expand(phi)));
        Ok(self)
    }

    /// `Ȧ q̇ + ḃ`, one per row: what the differentiated constraints `A q̈ + Ȧ q̇ + ḃ = 0`
    /// hold besides the accelerations (expanded, in q and every rate).
    pub fn rate_terms(&self, arena: &mut Arena, coords: &Coordinates) -> Vec<ExprId> {
        self.rate_terms_shared(arena, coords)
            .into_iter()
            .map(|h| arena.expand(h))
            .collect()
    }

    /// [`Constraints::rate_terms`] left unexpanded: the same values, for lowering only. The
    /// expansion multiplies out products that the hash-consed form shares: the Whipple
    /// bicycle's five rows lower to 5 936 operations this way against 11 391 expanded.
    pub fn rate_terms_shared(&self, arena: &mut Arena, coords: &Coordinates) -> Vec<ExprId> {
        self.coefficients
            .iter()
            .zip(&self.offsets)
            .map(|(row, &b)| {
                let mut terms: Vec<ExprId> = row
                    .iter()
                    .zip(&coords.rates)
                    .map(|(&a, &qd)| {
                        let da = arena.dt(a);
                        arena.mul(da, qd)
                    })
                    .collect();
                terms.push(arena.dt(b));
                arena.sum(&terms)
            })
            .collect()
    }

    /// The constraint residuals `A q̇ + b`, one per row (zero on a motion that obeys them).
    pub fn residuals(&self, arena: &mut Arena, coords: &Coordinates) -> Vec<ExprId> {
        (0..self.len())
            .map(|r| {
                let mut terms: Vec<ExprId> = self.coefficients[r]
                    .iter()
                    .zip(&coords.rates)
                    .map(|(&a, &qd)| arena.mul(a, qd))
                    .collect();
                terms.push(self.offsets[r]);
                arena.sum(&terms)
            })
            .collect()
    }
}

/// The symbol of a coordinate expression (a [`Coordinates`] holds only symbols).
pub(super) fn symbol(arena: &Arena, e: ExprId) -> SymbolId {
    arena
        .as_symbol(e)
        .unwrap_or_else(|| unreachable!("Coordinates hold symbols"))
}

/// Refuses an expression that holds a rate or an acceleration of a coordinate.
fn reject_rates(arena: &Arena, row: usize, e: ExprId) -> Result<(), LagrangeError> {
    let rates = arena
        .free_symbols(e)
        .into_iter()
        .any(|s| matches!(arena.symbol(s).kind, SymbolKind::Derivative { .. }));
    if rates {
        return Err(LagrangeError::ConstraintNotLinear {
            row,
            expr: arena.display(e),
        });
    }
    Ok(())
}
