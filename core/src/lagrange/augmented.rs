//! The same constrained motion by Lagrange multipliers with the augmented system, kept as
//! the second formulation the reduced one is checked and costed against.
//!
//! `M q̈ = f + Aᵀ λ` and the differentiated constraints `A q̈ = −(Ȧ q̇ + ḃ)` together are
//! the symmetric (n + m)-square system `[M Aᵀ; A 0] [q̈; −λ] = [f; −(Ȧ q̇ + ḃ)]`, solved by
//! the same adjugate blocks. It needs every rate (the dependent ones as state too) and
//! keeps the constraints only to the integrator's accuracy: the reduced form
//! ([`EquationsOfMotion::constrain`]) is the one to run.

use super::block_solve::solve_linear;
use super::constraints::Constraints;
use super::equations::EquationsOfMotion;
use super::error::LagrangeError;
use crate::codegen::{OpCount, Program};
use crate::sym::{Arena, ExprId};

impl EquationsOfMotion {
    /// `[q̈₀ … q̈_{n−1}, λ₀ … λ_{m−1}]` from the augmented system, in q and every rate q̇.
    ///
    /// # Errors
    /// [`LagrangeError::ConstraintLength`] for constraints on other coordinates;
    /// [`LagrangeError::SingularMassMatrix`] if the augmented matrix is singular everywhere
    /// (dependent constraints); [`LagrangeError::BlockTooLarge`] when a coupled block of the
    /// n + m unknowns passes [`super::MAX_BLOCK`].
    pub fn augmented(
        &self,
        arena: &mut Arena,
        constraints: &Constraints,
    ) -> Result<Vec<ExprId>, LagrangeError> {
        let (n, m) = (self.coords.len(), constraints.len());
        if let Some(r) = constraints.coefficients.iter().position(|r| r.len() != n) {
            return Err(LagrangeError::ConstraintLength {
                row: r,
                got: constraints.coefficients[r].len(),
                expected: n,
            });
        }
        let a = &constraints.coefficients;
        let mut big = vec![vec![arena.zero(); n + m]; n + m];
        for i in 0..n {
            big[i][..n].copy_from_slice(&self.mass[i]);
            for r in 0..m {
                big[i][n + r] = a[r][i];
                big[n + r][i] = a[r][i];
            }
        }
        let mut rhs = self.forcing.clone();
        for h in constraints.rate_terms(arena, &self.coords) {
            rhs.push(arena.neg(h));
        }
        let solved = solve_linear(arena, &big, &rhs)?;
        let mut out = solved.accel;
        for l in &mut out[n..] {
            *l = arena.neg(*l);
        }
        Ok(out)
    }
}

/// The operations of one evaluation of `outputs` lowered together.
pub fn op_count(arena: &Arena, outputs: &[ExprId]) -> OpCount {
    Program::lower(arena, outputs).op_count()
}
