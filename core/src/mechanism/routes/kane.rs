//! M(q) and f(q, q̇) of a mechanism by Kane's method, from the kinematics directly, for
//! trees too large for the Lagrangian route's second differentiation of T.
//!
//! With every body's centre velocity v_b and angular velocity ω_b (body axes) linear in q̇,
//! the partial velocities are v_b,i = ∂v_b/∂q̇_i and ω_b,i = ∂ω_b/∂q̇_i, and the accelerations
//! at q̈ = 0 are a_b = Σ_j ∂v_b/∂q_j q̇_j and α_b = Σ_j ∂ω_b/∂q_j q̇_j (in body axes the
//! derivative of ω is the inertial one, ω × ω being zero). Kane's equations
//! Σ_b [m_b v_b,i · a_b + ω_b,i · (I_b α_b + ω_b × I_b ω_b)] = Q_i then read M q̈ = f with
//!
//! - M_ij = Σ_b m_b v_b,i · v_b,j + ω_b,iᵀ I_b ω_b,j,
//! - f_i = Q_i − ∂V/∂q_i − Σ_b [m_b v_b,i · a_b + ω_b,i · (I_b α_b + ω_b × I_b ω_b)],
//!
//! with Q the non-conservative generalised forces and V the potential of the Lagrangian
//! route (gravity and springs), so both routes describe one mechanism. The partial velocities
//! are expanded with M (they are short); f stays in its shared, unexpanded form, which lowers
//! smaller. M's entries are expanded or not as the caller asks ([`MassEntries`]): expanded,
//! an entry that cancels is exactly zero, which a symbolic solve that splits M into its
//! coupled blocks needs; unexpanded, they cost a fraction of that and lower smaller, which
//! is all a numerical solve of M needs. On the Whipple bicycle (eight coordinates) this takes
//! a fraction of the Lagrangian route's time, which expands the momenta of the whole tree and
//! differentiates them again.

use super::lagrangian::Lagrangian;
use crate::lagrange::EquationsOfMotion;
use crate::mechanism::error::MechanismError;
use crate::mechanism::kinematics::BodyKinematics;
use crate::mechanism::scene::MechanismScene;
use crate::sym::mat3::{cross, dot, mat_vec};
use crate::sym::{Arena, ExprId, SymbolId};

type Vec3 = [ExprId; 3];

/// The form in which Kane's route leaves the mass matrix's entries
/// M_ij = Σ_b m_b v_b,i · v_b,j + ω_b,iᵀ I_b ω_b,j.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MassEntries {
    /// Expanded to sums of distinct monomials, so that an entry whose terms cancel is the
    /// arena's zero: the block adjugate solve (`EquationsOfMotion::solve`) splits M into the
    /// connected blocks of its non-zero pattern and refuses a block whose determinant is
    /// identically zero, and code generated from M skips its zero entries. The expansion is
    /// the costly part of the route on a large tree (the bicycle's 36 entries reach 609
    /// terms each).
    Expanded,
    /// The sums over the bodies of the products of the partial velocities, all left
    /// unexpanded (the partial velocities too): for a caller that solves M numerically at
    /// each state (Maggi's equations of a rolling mechanism), which needs no structural
    /// zero. They share their factors and lower to fewer operations than the expanded
    /// entries.
    Unexpanded,
}

pub(crate) fn symbols(arena: &Arena, exprs: &[ExprId]) -> Vec<Option<SymbolId>> {
    exprs.iter().map(|&e| arena.as_symbol(e)).collect()
}

/// ∂v/∂s for each of the three components, expanded with M's entries.
fn partial(arena: &mut Arena, v: &Vec3, s: Option<SymbolId>, entries: MassEntries) -> Vec3 {
    match s {
        Some(s) => v.map(|e| {
            let d = arena.diff(e, s);
            match entries {
                MassEntries::Expanded => arena.expand(d),
                MassEntries::Unexpanded => d,
            }
        }),
        None => [arena.zero(); 3],
    }
}

/// Σ_j ∂e/∂q_j q̇_j (+ ∂e/∂t): the rate of e(q, q̇, t) at q̈ = 0, unexpanded. For e linear
/// in q̇, e = a(q, t)·q̇ + b(q, t), this is ȧ·q̇ + ḃ.
pub(crate) fn scalar_rate_at_rest(
    arena: &mut Arena,
    e: ExprId,
    q: &[Option<SymbolId>],
    rates: &[ExprId],
    time: Option<SymbolId>,
) -> ExprId {
    let mut terms: Vec<ExprId> = q
        .iter()
        .zip(rates)
        .filter_map(|(&s, &r)| {
            let s = s?;
            let d = arena.diff(e, s);
            Some(arena.mul(d, r))
        })
        .collect();
    if let Some(t) = time {
        terms.push(arena.diff(e, t));
    }
    arena.sum(&terms)
}

/// [`scalar_rate_at_rest`] of each component: Σ_j ∂v/∂q_j q̇_j (+ ∂v/∂t).
fn rate_at_rest(
    arena: &mut Arena,
    v: &Vec3,
    q: &[Option<SymbolId>],
    rates: &[ExprId],
    time: Option<SymbolId>,
) -> Vec3 {
    [0, 1, 2].map(|k| scalar_rate_at_rest(arena, v[k], q, rates, time))
}

impl MechanismScene {
    /// M q̈ = f by Kane's method (see `kane.rs`): the same equations as
    /// [`MechanismScene::mass_matrix`]'s Lagrangian route, M expanded, f shared and
    /// unexpanded, with the momenta M q̇ and the residuals M q̈ − f (T is quadratic in q̇ for
    /// a mechanism's joints).
    ///
    /// # Errors
    /// As [`MechanismScene::validate`].
    pub fn kane_equations(&self, arena: &mut Arena) -> Result<EquationsOfMotion, MechanismError> {
        let (lag, kin) = self.lagrangian(arena)?;
        Ok(self.kane_from(arena, &lag, &kin, MassEntries::Expanded))
    }

    /// [`MechanismScene::kane_equations`] from the Lagrangian's pieces and the kinematics,
    /// M's entries in the form `entries` asks for.
    pub(crate) fn kane_from(
        &self,
        arena: &mut Arena,
        lag: &Lagrangian,
        kin: &[BodyKinematics],
        entries: MassEntries,
    ) -> EquationsOfMotion {
        let coords = &lag.coords;
        let n = coords.len();
        let q = symbols(arena, &coords.q);
        let qd = symbols(arena, &coords.rates);
        let time = arena.time_symbol();
        let mut mass = vec![vec![arena.zero(); n]; n];
        let mut inertial = vec![Vec::new(); n];
        for (body, k) in self.bodies.iter().zip(kin) {
            let pv: Vec<Vec3> = qd
                .iter()
                .map(|&s| partial(arena, &k.center_velocity, s, entries))
                .collect();
            let pw: Vec<Vec3> = qd
                .iter()
                .map(|&s| partial(arena, &k.omega, s, entries))
                .collect();
            let acceleration = rate_at_rest(arena, &k.center_velocity, &q, &coords.rates, time);
            let angular = rate_at_rest(arena, &k.omega, &q, &coords.rates, time);
            let i_alpha = mat_vec(arena, &body.inertia, &angular);
            let i_omega = mat_vec(arena, &body.inertia, &k.omega);
            let gyro = cross(arena, &k.omega, &i_omega);
            let moment: Vec3 = [0, 1, 2].map(|c| arena.add(i_alpha[c], gyro[c]));
            let i_pw: Vec<Vec3> = pw
                .iter()
                .map(|w| mat_vec(arena, &body.inertia, w))
                .collect();
            for i in 0..n {
                let zero = arena.zero();
                if pv[i] == [zero; 3] && pw[i] == [zero; 3] {
                    continue;
                }
                for j in i..n {
                    let lin = dot(arena, &pv[i], &pv[j]);
                    let lin = arena.mul(body.mass, lin);
                    let rot = dot(arena, &pw[i], &i_pw[j]);
                    let entry = arena.add(lin, rot);
                    let total = arena.add(mass[i][j], entry);
                    mass[i][j] = total;
                }
                let lin = dot(arena, &pv[i], &acceleration);
                let lin = arena.mul(body.mass, lin);
                let rot = dot(arena, &pw[i], &moment);
                inertial[i].push(arena.add(lin, rot));
            }
        }
        // Only the upper triangle was summed; expand it if asked, and mirror it.
        for (i, j) in (0..n).flat_map(|i| (i..n).map(move |j| (i, j))) {
            let e = match entries {
                MassEntries::Expanded => arena.expand(mass[i][j]),
                MassEntries::Unexpanded => mass[i][j],
            };
            mass[i][j] = e;
            mass[j][i] = e;
        }
        let forcing: Vec<ExprId> = (0..n)
            .map(|i| {
                let dv = match q[i] {
                    Some(s) => arena.diff(lag.potential, s),
                    None => arena.zero(),
                };
                let mut terms = vec![lag.forces[i], arena.neg(dv)];
                for &t in &inertial[i] {
                    terms.push(arena.neg(t));
                }
                arena.sum(&terms)
            })
            .collect();
        let momenta: Vec<ExprId> = mass
            .iter()
            .map(|row| {
                let terms: Vec<ExprId> = row
                    .iter()
                    .zip(&coords.rates)
                    .map(|(&m, &r)| arena.mul(m, r))
                    .collect();
                arena.sum(&terms)
            })
            .collect();
        let residuals: Vec<ExprId> = mass
            .iter()
            .zip(&forcing)
            .map(|(row, &f)| {
                let mut terms: Vec<ExprId> = row
                    .iter()
                    .zip(&coords.accels)
                    .map(|(&m, &a)| arena.mul(m, a))
                    .collect();
                terms.push(arena.neg(f));
                arena.sum(&terms)
            })
            .collect();
        EquationsOfMotion {
            coords: coords.clone(),
            mass,
            forcing,
            residuals,
            momenta,
        }
    }
}
