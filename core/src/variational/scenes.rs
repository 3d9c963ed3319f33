//! The variational equations of the scenes that have a symbolic right-hand side: a top in
//! angle form and in Eulerian form, and a mechanism.

use super::equations::VariationalEquations;
use super::error::VariationalError;
use crate::mechanism::MechanismDerivation;
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId};
use crate::top::{TopDerivation, TopScene};

/// The parameter symbols called `names`.
///
/// # Errors
/// [`VariationalError::UnknownParameter`] for a name the arena has no parameter of.
fn parameters(arena: &Arena, names: &[&str]) -> Result<Vec<ExprId>, VariationalError> {
    names
        .iter()
        .map(|&name| {
            arena
                .find_parameter(name)
                .map(|s| arena.symbol_expr(s))
                .ok_or_else(|| VariationalError::UnknownParameter {
                    name: name.to_owned(),
                })
        })
        .collect()
}

/// The variational equations of a second-order system q̈ = a(q, q̇), given as
/// `(q, q̇, q̈)`: state (q, q̇), right-hand side (q̇, q̈).
///
/// # Errors
/// [`VariationalError::UnknownParameter`], then as [`VariationalEquations::new`].
fn second_order(
    arena: &mut Arena,
    (q, rates, accel): (&[ExprId], &[ExprId], &[ExprId]),
    tangents: usize,
    sensitivities: &[&str],
) -> Result<VariationalEquations, VariationalError> {
    let p = parameters(arena, sensitivities)?;
    let state: Vec<ExprId> = q.iter().chain(rates).copied().collect();
    let rhs: Vec<ExprId> = rates.iter().chain(accel).copied().collect();
    VariationalEquations::new(arena, &state, &rhs, tangents, &p)
}

impl VariationalEquations {
    /// A top in angle form: state `(q₀, q₁, q₂, q̇₀, q̇₁, q̇₂)` as [`crate::top::TopModel`]
    /// has it, right-hand side `(q̇, q̈)`; sensitivities to the parameters called
    /// `sensitivities`.
    ///
    /// # Errors
    /// [`VariationalError::UnknownParameter`], then as [`VariationalEquations::new`].
    pub fn from_top(
        arena: &mut Arena,
        top: &TopDerivation,
        tangents: usize,
        sensitivities: &[&str],
    ) -> Result<VariationalEquations, VariationalError> {
        let c = top.coords();
        let system = (&c.q[..], &c.rates[..], &top.accelerations.accel[..]);
        second_order(arena, system, tangents, sensitivities)
    }

    /// A mechanism: state `(q, q̇)` in [`crate::mechanism::MechanismScene::coordinate_names`]
    /// order, right-hand side `(q̇, q̈)`; time, if the loads read it, is supplied per call.
    ///
    /// Only binds parameters: the checks [`crate::mechanism::MechanismModel`] makes of mass
    /// properties are not repeated here.
    ///
    /// # Errors
    /// [`VariationalError::UnknownParameter`], then as [`VariationalEquations::new`].
    pub fn from_mechanism(
        arena: &mut Arena,
        mechanism: &MechanismDerivation,
        tangents: usize,
        sensitivities: &[&str],
    ) -> Result<VariationalEquations, VariationalError> {
        let c = &mechanism.coordinates;
        let system = (&c.q[..], &c.rates[..], &mechanism.accelerations[..]);
        second_order(arena, system, tangents, sensitivities)
    }

    /// A top in Eulerian form, free of charts: state `(ω₁, ω₂, ω₃, R₁₁, R₁₂, …, R₃₃)` (body
    /// rates, then the attitude body → space row by row), right-hand side
    /// `(I⁻¹(τ − ω × Iω), R ω̂)`. Twelve entries, of which the six orthonormality conditions
    /// of R are integrals.
    ///
    /// # Errors
    /// [`VariationalError::UnknownParameter`]; in [`VariationalError::Lagrange`], as
    /// [`TopScene::eulerian_rhs`]; then as [`VariationalEquations::new`].
    pub fn from_eulerian_top(
        arena: &mut Arena,
        scene: &TopScene,
        tangents: usize,
        sensitivities: &[&str],
    ) -> Result<VariationalEquations, VariationalError> {
        let p = parameters(arena, sensitivities)?;
        let omega = [1, 2, 3].map(|i| arena.input(&format!("omega_{i}")));
        let mut rotation: Mat3 = [[arena.zero(); 3]; 3];
        for (i, row) in rotation.iter_mut().enumerate() {
            for (j, r) in row.iter_mut().enumerate() {
                *r = arena.input(&format!("R_{}{}", i + 1, j + 1));
            }
        }
        let omega_dot = scene.eulerian_rhs(arena, &rotation, &omega)?;
        // ω̂, the matrix of ω × ·, so that Ṙ = R ω̂ for body rates.
        let z = arena.zero();
        let neg = |a: &mut Arena, e| a.neg(e);
        let hat = [
            [z, neg(arena, omega[2]), omega[1]],
            [omega[2], z, neg(arena, omega[0])],
            [neg(arena, omega[1]), omega[0], z],
        ];
        let mut state: Vec<ExprId> = omega.to_vec();
        let mut rhs: Vec<ExprId> = omega_dot.to_vec();
        for row in &rotation {
            for column in 0..3 {
                let terms: Vec<ExprId> = row
                    .iter()
                    .zip(&hat)
                    .map(|(&r, h)| arena.mul(r, h[column]))
                    .collect();
                rhs.push(arena.sum(&terms));
            }
            state.extend(row);
        }
        VariationalEquations::new(arena, &state, &rhs, tangents, &p)
    }
}
