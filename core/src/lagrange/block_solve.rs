//! Solving `M q̈ = f` symbolically, using the structure of M.
//!
//! The coordinates split into the connected blocks of M's non-zero pattern (a top's θ
//! decouples from φ and ψ when it is symmetric). Each block is solved by its adjugate:
//! `q̈_B = adj(M_B) f_B / det M_B`. Adjugate entries and the determinant are expanded, so
//! their cancellations are exact; the products with f are *not* expanded, so the lowered
//! code evaluates f once, the adjugate once, and a single division per block.

use super::equations::EquationsOfMotion;
use super::error::LagrangeError;
use crate::codegen::Program;
use crate::sym::mat3::{adjugate_times, determinant};
use crate::sym::{Arena, ExprId};

/// The largest coupled block solved symbolically (the adjugate grows as n!).
pub const MAX_BLOCK: usize = 6;

/// `q̈ = M⁻¹ f` in closed form, one expression per coordinate.
#[derive(Clone, Debug, PartialEq)]
pub struct Accelerations {
    /// `q̈_i` in terms of q, q̇ and the parameters.
    pub accel: Vec<ExprId>,
    /// The coordinate blocks that were solved together.
    pub blocks: Vec<Vec<usize>>,
    /// The determinant of each block (the expression that vanishes at a singular chart).
    pub determinants: Vec<ExprId>,
}

impl EquationsOfMotion {
    /// Solves for the accelerations.
    ///
    /// # Errors
    /// [`LagrangeError::SingularMassMatrix`] if a block's determinant is identically zero;
    /// [`LagrangeError::BlockTooLarge`] past [`MAX_BLOCK`] coupled coordinates.
    pub fn solve(&self, arena: &mut Arena) -> Result<Accelerations, LagrangeError> {
        solve_linear(arena, &self.mass, &self.forcing)
    }
}

/// Solves `K x = r` symbolically for a symmetric K (a mass matrix, or the reduced one of
/// a constrained system), block by block with adjugates, keeping the cheapest form.
///
/// # Errors
/// [`LagrangeError::SingularMassMatrix`] if a block's determinant is identically zero;
/// [`LagrangeError::BlockTooLarge`] past [`MAX_BLOCK`] coupled unknowns.
pub(crate) fn solve_linear(
    arena: &mut Arena,
    mass: &[Vec<ExprId>],
    forcing: &[ExprId],
) -> Result<Accelerations, LagrangeError> {
    let n = mass.len();
    let blocks = coupled_blocks(arena, mass);
    let mut accel = vec![arena.zero(); n];
    // Each q̈ as numerator and determinant, kept for the cancelled variant.
    let mut quotients = vec![(arena.zero(), arena.one()); n];
    let mut determinants = Vec::with_capacity(blocks.len());
    for block in &blocks {
        if block.len() > MAX_BLOCK {
            return Err(LagrangeError::BlockTooLarge {
                size: block.len(),
                max: MAX_BLOCK,
            });
        }
        let m: Vec<Vec<ExprId>> = block
            .iter()
            .map(|&i| block.iter().map(|&j| mass[i][j]).collect())
            .collect();
        let det = determinant(arena, &m);
        let det = arena.expand(det);
        // Seen through abbreviations: a body's named inertia entries can hide a zero.
        if arena.is_zero(det)? {
            return Err(LagrangeError::SingularMassMatrix {
                block: block.clone(),
            });
        }
        let inv_det = arena.recip(det)?;
        let block_forcing: Vec<ExprId> = block.iter().map(|&coord| forcing[coord]).collect();
        let nums = adjugate_times(arena, &m, &block_forcing);
        for (r, &num) in nums.iter().enumerate() {
            accel[block[r]] = arena.mul(num, inv_det);
            quotients[block[r]] = (num, det);
        }
        determinants.push(det);
    }
    let accel = cheapest_form(arena, &accel, &quotients)?;
    Ok(Accelerations {
        accel,
        blocks,
        determinants,
    })
}

/// The cheapest of three equal forms of the accelerations, judged on the joint program:
/// - as solved: adjugate–forcing products left factored over one shared reciprocal;
/// - each numerator expanded over the determinant, which cancels terms across products;
/// - each numerator expanded and its common factors with the determinant cancelled
///   ([`Arena::cancel`]), which turns `N / (K sin²θ)` into the textbook `N' / (K' sin θ)`.
///
/// # Errors
/// [`LagrangeError::Sym`] if a cancelled denominator vanished (it cannot, being a factor of
/// a non-zero determinant).
pub fn cheapest_form(
    arena: &mut Arena,
    solved: &[ExprId],
    quotients: &[(ExprId, ExprId)],
) -> Result<Vec<ExprId>, LagrangeError> {
    let mut expanded = Vec::with_capacity(solved.len());
    let mut cancelled = Vec::with_capacity(solved.len());
    for &(num, den) in quotients {
        let n = arena.expand(num);
        let inv = arena.recip(den)?;
        expanded.push(arena.mul(n, inv));
        let (cn, cd) = arena.cancel(n, den);
        let inv = arena.recip(cd)?;
        cancelled.push(arena.mul(cn, inv));
    }
    let cost = |a: &Arena, x: &[ExprId]| Program::lower(a, x).op_count().weighted();
    let candidates = [solved.to_vec(), expanded, cancelled];
    let best = candidates
        .into_iter()
        .min_by_key(|c| cost(arena, c))
        .unwrap_or_else(|| solved.to_vec());
    Ok(best)
}

/// Connected components of the graph with an edge i–j where `M_ij ≠ 0`.
fn coupled_blocks(arena: &Arena, m: &[Vec<ExprId>]) -> Vec<Vec<usize>> {
    let n = m.len();
    let mut block_of = vec![usize::MAX; n];
    let mut blocks: Vec<Vec<usize>> = Vec::new();
    for start in 0..n {
        if block_of[start] != usize::MAX {
            continue;
        }
        let id = blocks.len();
        let mut members = vec![start];
        block_of[start] = id;
        let mut k = 0;
        while k < members.len() {
            let i = members[k];
            for j in 0..n {
                let coupled = m[i][j] != arena.zero() || m[j][i] != arena.zero();
                if coupled && block_of[j] == usize::MAX {
                    block_of[j] = id;
                    members.push(j);
                }
            }
            k += 1;
        }
        members.sort_unstable();
        blocks.push(members);
    }
    blocks
}
