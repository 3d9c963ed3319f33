//! Elimination of the dependent speeds (Maggi's equations, Kane's with the independent
//! rates as generalised speeds) and the multipliers from the dependent rows.
//!
//! With the coordinates split into independent I (k of them) and dependent D (m, one per
//! constraint), the constraints `A_I q̇_I + A_D q̇_D + b = 0` give, with Δ = det A_D and
//! C̃ = adj(A_D)(−A_I), ĉ = adj(A_D)(−b) (polynomials, no division):
//!
//! - `q̇_D = (C̃ u + ĉ)/Δ` with u = q̇_I the free speeds;
//! - `q̈_D = (C̃ u̇ − H)/Δ` with H = adj(A_D)(Ȧ q̇ + ḃ), from the differentiated constraint;
//! - with S = [I; C̃/Δ] the projection onto the motions the constraints allow,
//!   `Sᵀ M S u̇ = Sᵀ (f − M s)`, scaled by Δ² so every entry is a polynomial:
//!   `K = Δ² M_II + Δ (C̃ᵀ M_DI + M_ID C̃) + C̃ᵀ M_DD C̃`,
//!   `r = Δ² f_I + Δ (M_ID H + C̃ᵀ f_D) + C̃ᵀ M_DD H`, solved by adjugate blocks;
//! - the multipliers from the dependent rows of `M q̈ = f + Aᵀ λ`:
//!   `λ = adj(A_D)ᵀ (M q̈ − f)_D / Δ`.

use super::block_solve::{Accelerations, solve_linear};
use super::constraints::{Constraints, symbol};
use super::equations::EquationsOfMotion;
use super::error::LagrangeError;
use crate::sym::mat3::{cofactor, determinant};
use crate::sym::{Arena, ExprId, SymbolId};

/// The equations of motion under constraints, reduced to the free speeds.
///
/// Every expression reads the coordinates q, the free speeds u = q̇_I (the rate symbols of
/// the independent coordinates), the parameters and possibly time; the dependent rates
/// never appear.
#[derive(Clone, Debug, PartialEq)]
pub struct ConstrainedEquations {
    /// The unconstrained equations the reduction started from.
    pub equations: EquationsOfMotion,
    /// The constraints.
    pub constraints: Constraints,
    /// Indices of the independent coordinates, whose rates are the free speeds u.
    pub independent: Vec<usize>,
    /// Indices of the dependent coordinates, one per constraint.
    pub dependent: Vec<usize>,
    /// `q̇_D` in terms of q and u, one per dependent coordinate.
    pub dependent_rates: Vec<ExprId>,
    /// `u̇ = q̈_I`, one per independent coordinate; its blocks index into `independent`.
    pub accelerations: Accelerations,
    /// `q̈_D` in terms of q and u.
    pub dependent_accelerations: Vec<ExprId>,
    /// The multipliers λ: the generalised constraint force is `Aᵀ λ`, so `λ_r` is the
    /// reaction of constraint r measured along its row (a force for a row of lengths, a
    /// moment for a row of angles).
    pub multipliers: Vec<ExprId>,
    /// The reduced mass matrix `K = Δ² Sᵀ M S` (symmetric, polynomial).
    pub reduced_mass: Vec<Vec<ExprId>>,
    /// The reduced forcing `r = Δ² Sᵀ (f − M s)`.
    pub reduced_forcing: Vec<ExprId>,
    /// `Δ = det A_D`, which vanishes where the chosen dependent coordinates fail.
    pub determinant: ExprId,
}

impl ConstrainedEquations {
    /// The right-hand side the run-time model evaluates: the dependent rates `q̇_D` then
    /// the free accelerations `u̇`, one program.
    pub fn rhs_outputs(&self) -> Vec<ExprId> {
        let mut out = self.dependent_rates.clone();
        out.extend(&self.accelerations.accel);
        out
    }
}

impl EquationsOfMotion {
    /// Reduces the equations by the constraints, with the dependent coordinates `dependent`
    /// (one per constraint), or chosen automatically when `None`: the last m coordinates
    /// whose block of A is not identically singular, trying later coordinates first.
    ///
    /// # Errors
    /// [`LagrangeError::TooManyConstraints`] for m ≥ n; [`LagrangeError::ConstraintLength`]
    /// for constraints built on other coordinates; [`LagrangeError::DependentChoice`] for
    /// indices that are not m distinct coordinates; [`LagrangeError::SingularConstraintBlock`]
    /// if A_D is singular everywhere; [`LagrangeError::DependentConstraints`] if no choice
    /// works; then the errors of the block solve ([`LagrangeError::SingularMassMatrix`],
    /// [`LagrangeError::BlockTooLarge`]).
    pub fn constrain(
        &self,
        arena: &mut Arena,
        constraints: &Constraints,
        dependent: Option<&[usize]>,
    ) -> Result<ConstrainedEquations, LagrangeError> {
        let (n, m) = (self.coords.len(), constraints.len());
        if m >= n {
            return Err(LagrangeError::TooManyConstraints {
                constraints: m,
                coordinates: n,
            });
        }
        if let Some(r) = constraints.coefficients.iter().position(|r| r.len() != n) {
            return Err(LagrangeError::ConstraintLength {
                row: r,
                got: constraints.coefficients[r].len(),
                expected: n,
            });
        }
        let dependent = match dependent {
            Some(d) => {
                let mut sorted = d.to_vec();
                sorted.sort_unstable();
                sorted.dedup();
                if sorted.len() != m || d.len() != m || sorted.iter().any(|&i| i >= n) {
                    return Err(LagrangeError::DependentChoice {
                        dependent: d.to_vec(),
                        constraints: m,
                        coordinates: n,
                    });
                }
                if block_determinant(arena, constraints, d).is_none() {
                    return Err(LagrangeError::SingularConstraintBlock {
                        dependent: d.to_vec(),
                    });
                }
                d.to_vec()
            }
            None => choose_dependent(arena, constraints, n)?,
        };
        self.reduce(arena, constraints, dependent)
    }

    fn reduce(
        &self,
        arena: &mut Arena,
        constraints: &Constraints,
        dependent: Vec<usize>,
    ) -> Result<ConstrainedEquations, LagrangeError> {
        let n = self.coords.len();
        let m = dependent.len();
        let independent: Vec<usize> = (0..n).filter(|i| !dependent.contains(i)).collect();
        let a = &constraints.coefficients;
        let a_d: Vec<Vec<ExprId>> = (0..m)
            .map(|r| dependent.iter().map(|&j| a[r][j]).collect())
            .collect();
        let delta = determinant(arena, &a_d);
        let delta = arena.expand(delta);
        // adj[i][j] = cofactor (j, i) of A_D.
        let adj: Vec<Vec<ExprId>> = (0..m)
            .map(|i| {
                (0..m)
                    .map(|j| {
                        let c = cofactor(arena, &a_d, j, i);
                        arena.expand(c)
                    })
                    .collect()
            })
            .collect();
        // C̃ = adj (−A_I) and ĉ = adj (−b).
        let neg_a_i: Vec<Vec<ExprId>> = (0..m)
            .map(|r| independent.iter().map(|&j| arena.neg(a[r][j])).collect())
            .collect();
        let neg_b: Vec<ExprId> = constraints.offsets.iter().map(|&b| arena.neg(b)).collect();
        let c_t = mat_mat(arena, &adj, &neg_a_i);
        let c_hat = mat_vec(arena, &adj, &neg_b);
        let inv_delta = arena.recip(delta)?;
        let rates = &self.coords.rates;
        let u: Vec<ExprId> = independent.iter().map(|&i| rates[i]).collect();
        let mut dependent_rates = Vec::with_capacity(m);
        for d in 0..m {
            let mut terms: Vec<ExprId> = (0..independent.len())
                .map(|j| arena.mul(c_t[d][j], u[j]))
                .collect();
            terms.push(c_hat[d]);
            let num = arena.sum(&terms);
            let num = arena.expand(num);
            dependent_rates.push(arena.mul(num, inv_delta));
        }
        let rate_map: Vec<(SymbolId, ExprId)> = dependent
            .iter()
            .zip(&dependent_rates)
            .map(|(&d, &e)| (symbol(arena, rates[d]), e))
            .collect();
        // h = Ȧ q̇ + ḃ with the dependent rates put in, then H = adj h.
        let h: Vec<ExprId> = constraints
            .rate_terms(arena, &self.coords)
            .into_iter()
            .map(|hr| arena.subs(hr, &rate_map))
            .collect::<Result<_, _>>()?;
        let big_h = mat_vec(arena, &adj, &h);
        let big_h: Vec<ExprId> = big_h.iter().map(|&e| arena.expand(e)).collect();
        let mm = &self.mass;
        let f: Vec<ExprId> = self
            .forcing
            .iter()
            .map(|&e| arena.subs(e, &rate_map))
            .collect::<Result<_, _>>()?;
        let delta2 = arena.mul(delta, delta);
        let k = independent.len();
        let mut reduced_mass = vec![vec![arena.zero(); k]; k];
        let mut reduced_forcing = Vec::with_capacity(k);
        for (a_row, &i) in independent.iter().enumerate() {
            for (b_col, &j) in independent.iter().enumerate() {
                let mut terms = vec![arena.mul(delta2, mm[i][j])];
                for (dr, &d) in dependent.iter().enumerate() {
                    // Δ (C̃ᵀ M_DI + M_ID C̃)
                    let t1 = arena.product(&[delta, c_t[dr][a_row], mm[d][j]]);
                    let t2 = arena.product(&[delta, mm[i][d], c_t[dr][b_col]]);
                    terms.extend([t1, t2]);
                    for (er, &e) in dependent.iter().enumerate() {
                        let t = arena.product(&[c_t[dr][a_row], mm[d][e], c_t[er][b_col]]);
                        terms.push(t);
                    }
                }
                let s = arena.sum(&terms);
                reduced_mass[a_row][b_col] = arena.expand(s);
            }
            let mut terms = vec![arena.mul(delta2, f[i])];
            for (dr, &d) in dependent.iter().enumerate() {
                terms.push(arena.product(&[delta, mm[i][d], big_h[dr]]));
                terms.push(arena.product(&[delta, c_t[dr][a_row], f[d]]));
                for (er, &e) in dependent.iter().enumerate() {
                    terms.push(arena.product(&[c_t[dr][a_row], mm[d][e], big_h[er]]));
                }
            }
            let s = arena.sum(&terms);
            reduced_forcing.push(arena.expand(s));
        }
        let accelerations = solve_linear(arena, &reduced_mass, &reduced_forcing)?;
        let u_dot = &accelerations.accel;
        // q̈_D = (C̃ u̇ − H)/Δ
        let mut dependent_accelerations = Vec::with_capacity(m);
        for d in 0..m {
            let mut terms: Vec<ExprId> = (0..k).map(|j| arena.mul(c_t[d][j], u_dot[j])).collect();
            terms.push(arena.neg(big_h[d]));
            let num = arena.sum(&terms);
            dependent_accelerations.push(arena.mul(num, inv_delta));
        }
        let mut q_ddot = vec![arena.zero(); n];
        for (j, &i) in independent.iter().enumerate() {
            q_ddot[i] = u_dot[j];
        }
        for (j, &d) in dependent.iter().enumerate() {
            q_ddot[d] = dependent_accelerations[j];
        }
        // E_D = (M q̈ − f)_D, then λ = adjᵀ E_D / Δ.
        let e_d: Vec<ExprId> = dependent
            .iter()
            .map(|&d| {
                let mut terms: Vec<ExprId> =
                    (0..n).map(|j| arena.mul(mm[d][j], q_ddot[j])).collect();
                terms.push(arena.neg(f[d]));
                arena.sum(&terms)
            })
            .collect();
        let multipliers = (0..m)
            .map(|i| {
                let terms: Vec<ExprId> = (0..m).map(|j| arena.mul(adj[j][i], e_d[j])).collect();
                let s = arena.sum(&terms);
                arena.mul(s, inv_delta)
            })
            .collect();
        Ok(ConstrainedEquations {
            equations: self.clone(),
            constraints: constraints.clone(),
            independent,
            dependent,
            dependent_rates,
            accelerations,
            dependent_accelerations,
            multipliers,
            reduced_mass,
            reduced_forcing,
            determinant: delta,
        })
    }
}

/// `det A_D` expanded, or `None` when it is identically zero.
fn block_determinant(arena: &mut Arena, c: &Constraints, dependent: &[usize]) -> Option<ExprId> {
    let a_d: Vec<Vec<ExprId>> = c
        .coefficients
        .iter()
        .map(|row| dependent.iter().map(|&j| row[j]).collect())
        .collect();
    let d = determinant(arena, &a_d);
    let d = arena.expand(d);
    match arena.is_zero(d) {
        Ok(false) => Some(d),
        _ => None,
    }
}

/// The first m-subset of the coordinates, latest first, whose constraint block is not
/// singular everywhere.
fn choose_dependent(
    arena: &mut Arena,
    c: &Constraints,
    n: usize,
) -> Result<Vec<usize>, LagrangeError> {
    let m = c.len();
    // Subsets as index lists, walked in the order (n−m … n−1) first, then earlier ones.
    let mut idx: Vec<usize> = (0..m).map(|i| n - m + i).collect();
    loop {
        if block_determinant(arena, c, &idx).is_some() {
            return Ok(idx);
        }
        // Step to the previous combination in lexicographic order.
        let Some(p) = (0..m)
            .rev()
            .find(|&p| idx[p] > if p == 0 { 0 } else { idx[p - 1] + 1 })
        else {
            return Err(LagrangeError::DependentConstraints { constraints: m });
        };
        idx[p] -= 1;
        for (q, slot) in idx.iter_mut().enumerate().skip(p + 1) {
            *slot = n - m + q;
        }
    }
}

fn mat_mat(arena: &mut Arena, a: &[Vec<ExprId>], b: &[Vec<ExprId>]) -> Vec<Vec<ExprId>> {
    let cols = b.first().map_or(0, Vec::len);
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| {
                    let terms: Vec<ExprId> = row
                        .iter()
                        .zip(b)
                        .map(|(&x, brow)| arena.mul(x, brow[j]))
                        .collect();
                    let s = arena.sum(&terms);
                    arena.expand(s)
                })
                .collect()
        })
        .collect()
}

fn mat_vec(arena: &mut Arena, a: &[Vec<ExprId>], v: &[ExprId]) -> Vec<ExprId> {
    a.iter()
        .map(|row| {
            let terms: Vec<ExprId> = row.iter().zip(v).map(|(&x, &y)| arena.mul(x, y)).collect();
            let s = arena.sum(&terms);
            arena.expand(s)
        })
        .collect()
}
