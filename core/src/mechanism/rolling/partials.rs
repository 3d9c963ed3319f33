//! The exact Jacobian of a rolling mechanism's free accelerations u̇(q, u).
//!
//! The engine differentiates the pieces of Maggi's equations symbolically
//! ([`RollingDerivation::partials`]: ∂(M a)/∂q at a = q̈, ∂f/∂q, ∂f/∂q̇, ∂A/∂q,
//! ∂(Ȧq̇)/∂q, ∂(Ȧq̇)/∂q̇,
//! lowered to straight-line code by the derive, to a program by [`super::RollingModel`]),
//! and [`jacobian`] carries them through the
//! numerical projection by the product rule, with q̇ = S u and S_I = I:
//!
//! - A S = 0 gives dS_D = −A_D⁻¹ (dA S), so dq̇ = dS u;
//! - A s + Ȧq̇ = 0 with s_I = 0 gives ds_D = −A_D⁻¹ (d(Ȧq̇) + dA s);
//! - K u̇ = r, K = Sᵀ M S, r = Sᵀ (f − M s) gives du̇ = K⁻¹ (dr − dK u̇), with
//!   dK = dSᵀ M S + Sᵀ dM S + Sᵀ M dS and dr = dSᵀ (f − M s) + Sᵀ (df − dM s − M ds).
//!   M's derivative enters only as Sᵀ dM (S u̇ + s) = Sᵀ dM q̈, so the engine gives
//!   ∂(M a)/∂q with a = q̈ (n² entries), not every ∂M/∂q_j (n³).
//!
//! Nothing is differenced; the error is that of the solves with A_D and K.

use nalgebra::{SMatrix, SVector};

use super::derivation::RollingDerivation;
use crate::lagrange::Coordinates;
use crate::lagrange::{Inverted, LagrangeError, Partition, solve};
use crate::sym::{Arena, ExprId, SymError};

/// The first derivatives of a rolling mechanism's M(q), f(t, q, q̇), A(q) and Ȧq̇(q, q̇) at
/// one state, from [`super::RollingDynamics::partials`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollingPartials<const N: usize, const M: usize> {
    /// ∂(M a)/∂q at a = q̈: column j is (∂M/∂q_j) q̈.
    pub mass_times_accelerations: SMatrix<f64, N, N>,
    /// ∂f/∂q: column j is ∂f/∂q_j.
    pub forcing_by_q: SMatrix<f64, N, N>,
    /// ∂f/∂q̇: column j is ∂f/∂q̇_j.
    pub forcing_by_qdot: SMatrix<f64, N, N>,
    /// ∂A/∂q_j, one matrix per coordinate j.
    pub rows: [SMatrix<f64, M, N>; N],
    /// ∂(Ȧq̇)/∂q: column j is ∂(Ȧq̇)/∂q_j.
    pub rate_terms_by_q: SMatrix<f64, M, N>,
    /// ∂(Ȧq̇)/∂q̇.
    pub rate_terms_by_qdot: SMatrix<f64, M, N>,
}

impl<const N: usize, const M: usize> RollingPartials<N, M> {
    /// The number of values [`RollingPartials::from_slice`] reads: 3n² + m n² + 2 m n.
    pub const LEN: usize = 3 * N * N + M * N * N + 2 * M * N;

    /// The partials from the values in the order of [`RollingDerivation::partials`]:
    /// ∂(M q̈)/∂q, ∂f/∂q and ∂f/∂q̇ (row i is f_i), ∂A/∂q_j for each j
    /// (row-major), ∂(Ȧq̇)/∂q and ∂(Ȧq̇)/∂q̇ (row r is row r's term). A value missing from a
    /// short slice reads as NaN, which the Jacobian reports as not finite.
    pub fn from_slice(values: &[f64]) -> RollingPartials<N, M> {
        let at = |i: usize| values.get(i).copied().unwrap_or(f64::NAN);
        let (nn, mn) = (N * N, M * N);
        let forcing = nn;
        let rows = forcing + 2 * nn;
        let rate_terms = rows + N * mn;
        RollingPartials {
            mass_times_accelerations: SMatrix::from_fn(|i, j| at(i * N + j)),
            forcing_by_q: SMatrix::from_fn(|i, j| at(forcing + i * N + j)),
            forcing_by_qdot: SMatrix::from_fn(|i, j| at(forcing + nn + i * N + j)),
            rows: std::array::from_fn(|j| SMatrix::from_fn(|r, c| at(rows + j * mn + r * N + c))),
            rate_terms_by_q: SMatrix::from_fn(|r, j| at(rate_terms + r * N + j)),
            rate_terms_by_qdot: SMatrix::from_fn(|r, j| at(rate_terms + mn + r * N + j)),
        }
    }
}

impl RollingDerivation {
    /// The partial derivatives of M q̈ (q̈ the acceleration symbols), f, A and Ȧq̇ in the
    /// coordinates and rates, differentiated by the engine, in the order
    /// [`RollingPartials::from_slice`] reads.
    pub fn partials(&self, arena: &mut Arena) -> Vec<ExprId> {
        Differentiated {
            coords: self.coordinates().clone(),
            mass: self.equations.mass.clone(),
            forcing: self.equations.forcing.clone(),
            rows: self.constraints.coefficients.clone(),
            rate_terms: self.rate_terms.clone(),
        }
        .partials(arena)
    }
}

/// What [`RollingDerivation::partials`] differentiates: M, f, A, Ȧq̇ and the coordinates,
/// apart from the rest of the derivation, so that the interpreted model can keep them in
/// an arena of their own ([`Differentiated::extract`]) until it differentiates them.
#[derive(Debug)]
pub(super) struct Differentiated {
    pub coords: Coordinates,
    pub mass: Vec<Vec<ExprId>>,
    pub forcing: Vec<ExprId>,
    pub rows: Vec<Vec<ExprId>>,
    pub rate_terms: Vec<ExprId>,
}

impl Differentiated {
    /// The pieces of `derivation` copied into a new arena that holds only what they need
    /// ([`Arena::extract`]), with every symbol under the same id.
    ///
    /// # Errors
    /// [`SymError::ForeignExpression`] for a piece `arena` does not own.
    pub fn extract(
        arena: &Arena,
        derivation: &RollingDerivation,
    ) -> Result<(Arena, Differentiated), SymError> {
        let coords = derivation.coordinates();
        let (mass, rows) = (
            &derivation.equations.mass,
            &derivation.constraints.coefficients,
        );
        let mut roots: Vec<ExprId> = mass.iter().flatten().copied().collect();
        roots.extend(&derivation.equations.forcing);
        roots.extend(rows.iter().flatten());
        roots.extend(&derivation.rate_terms);
        roots.extend(coords.q.iter().chain(&coords.rates).chain(&coords.accels));
        let (copy, moved) = arena.extract(&roots)?;
        let mut moved = moved.into_iter();
        let mut take = |n: usize| -> Vec<ExprId> { moved.by_ref().take(n).collect() };
        let mass = mass.iter().map(|r| take(r.len())).collect();
        let forcing = take(derivation.equations.forcing.len());
        let rows = rows.iter().map(|r| take(r.len())).collect();
        let rate_terms = take(derivation.rate_terms.len());
        let coords = Coordinates {
            q: take(coords.q.len()),
            rates: take(coords.rates.len()),
            accels: take(coords.accels.len()),
        };
        Ok((
            copy,
            Differentiated {
                coords,
                mass,
                forcing,
                rows,
                rate_terms,
            },
        ))
    }

    /// [`RollingDerivation::partials`] of these pieces.
    pub fn partials(&self, arena: &mut Arena) -> Vec<ExprId> {
        let coords = &self.coords;
        let zero = arena.zero();
        let symbols = |arena: &Arena, of: &[ExprId]| -> Vec<_> {
            of.iter().map(|&x| arena.as_symbol(x)).collect()
        };
        let q = symbols(arena, &coords.q);
        let rates = symbols(arena, &coords.rates);
        let d = |arena: &mut Arena, e: ExprId, s: Option<crate::sym::SymbolId>| match s {
            Some(s) => arena.diff(e, s),
            None => zero,
        };
        let mut out = Vec::new();
        for row in &self.mass {
            let terms: Vec<ExprId> = row
                .iter()
                .zip(&coords.accels)
                .map(|(&m, &a)| arena.mul(m, a))
                .collect();
            let product = arena.sum(&terms);
            for &s in &q {
                out.push(d(arena, product, s));
            }
        }
        for by in [&q, &rates] {
            for &e in &self.forcing {
                for &s in by {
                    out.push(d(arena, e, s));
                }
            }
        }
        for &s in &q {
            for &e in self.rows.iter().flatten() {
                out.push(d(arena, e, s));
            }
        }
        for by in [&q, &rates] {
            for &e in &self.rate_terms {
                for &s in by {
                    out.push(d(arena, e, s));
                }
            }
        }
        out
    }
}

/// The pieces at one state (q, u) that the Jacobian starts from, with q̇ = S u.
pub(super) struct AtState<'a, const N: usize, const M: usize> {
    /// M(q).
    pub mass: SMatrix<f64, N, N>,
    /// f.
    pub forcing: SVector<f64, N>,
    /// A(q).
    pub a: SMatrix<f64, M, N>,
    /// Ȧq̇.
    pub rate_terms: SVector<f64, M>,
    /// Their derivatives.
    pub partials: &'a RollingPartials<N, M>,
}

/// (∂u̇/∂q, ∂u̇/∂u) at (q, u) by the product rule through the projection (the module's
/// formulas): K × N and K × K.
///
/// # Errors
/// [`LagrangeError::SingularAtState`] where A_D is singular,
/// [`LagrangeError::SingularReducedMass`] where K is.
#[allow(clippy::type_complexity)]
pub(super) fn jacobian<const N: usize, const M: usize, const K: usize>(
    partition: &Partition<M, K>,
    at: &AtState<'_, N, M>,
    u: &[f64; K],
) -> Result<(SMatrix<f64, K, N>, SMatrix<f64, K, K>), LagrangeError> {
    let (mass, forcing, a, p) = (&at.mass, &at.forcing, &at.a, at.partials);
    let s = partition.rates(a, u)?.projection;
    let u = SVector::<f64, K>::from_column_slice(u);
    let a_d = SMatrix::<f64, M, M>::from_fn(|r, c| a[(r, partition.dependent[c])]);
    let a_d_inv = solve(
        a_d,
        SMatrix::<f64, M, M>::identity(),
        Inverted::DependentBlock,
    )?;
    // A dependent block (M rows) scattered into the coordinates' order.
    let embed = |x: SVector<f64, M>| {
        let mut out = SVector::<f64, N>::zeros();
        for (r, &d) in partition.dependent.iter().enumerate() {
            out[d] = x[r];
        }
        out
    };
    let drift = embed(-(a_d_inv * at.rate_terms));
    let k = s.transpose() * mass * s;
    let k_inv = solve(k, SMatrix::<f64, K, K>::identity(), Inverted::ReducedMass)?;
    let reduced_force = forcing - mass * drift;
    let ud = k_inv * (s.transpose() * reduced_force);

    let mut by_q = SMatrix::<f64, K, N>::zeros();
    for j in 0..N {
        let da = &p.rows[j];
        let mut ds_proj = SMatrix::<f64, N, K>::zeros();
        let ds_d = -(a_d_inv * (da * s));
        for (r, &d) in partition.dependent.iter().enumerate() {
            ds_proj.set_row(d, &ds_d.row(r));
        }
        let dqdot = ds_proj * u;
        let dr = p.rate_terms_by_q.column(j) + p.rate_terms_by_qdot * dqdot;
        let d_drift = embed(-(a_d_inv * (dr + da * drift)));
        let df = p.forcing_by_q.column(j) + p.forcing_by_qdot * dqdot;
        // dr − dK u̇, M's derivative in it gathered as Sᵀ dM q̈.
        let dk_rest = ds_proj.transpose() * mass * s + s.transpose() * mass * ds_proj;
        let dr_rest = ds_proj.transpose() * reduced_force
            + s.transpose() * (df - mass * d_drift - p.mass_times_accelerations.column(j));
        by_q.set_column(j, &(k_inv * (dr_rest - dk_rest * ud)));
    }
    let mut by_u = SMatrix::<f64, K, K>::zeros();
    for j in 0..K {
        let dqdot = s.column(j).into_owned();
        let dr = p.rate_terms_by_qdot * dqdot;
        let d_drift = embed(-(a_d_inv * dr));
        let df = p.forcing_by_qdot * dqdot;
        by_u.set_column(j, &(k_inv * (s.transpose() * (df - mass * d_drift))));
    }
    Ok((by_q, by_u))
}
