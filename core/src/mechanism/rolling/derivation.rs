//! From a mechanism and its rolling wheels to the pieces of Maggi's equations: M(q) and
//! f(q, q̇) of the unconstrained tree (Kane's method, [`MechanismScene::kane_equations`]), the constraint rows A(q) q̇ = 0 of the wheels, Ȧq̇,
//! and what a run reports (contact points, their velocities, the energy).
//!
//! Each wheel gives, from its contact point P (ground axes) and the material velocity
//! v_P = v_hub + ω × (P − hub) of the body's point at P:
//!
//! - two nonholonomic rows: the horizontal components of v_P are zero (no slip), each row
//!   the coefficients ∂v_P/∂q̇;
//! - one holonomic row: up·P = 0 (the wheel touches the floor), whose rate is up·v_P (P
//!   slides on the body along the rim's tangent at P, which is horizontal), so its row is
//!   ∂(up·v_P)/∂q̇; none when up·P is identically zero, which happens when the joints already
//!   hold the wheel on the floor (the bicycle's rear wheel hangs from a frame whose origin is
//!   its contact point). Then the vertical component of v_P vanishes with it.
//!
//! v_P, the rows and Ȧq̇ (the rate of each row's value A_r q̇ at q̈ = 0) stay in their
//! shared, unexpanded forms, with their zeros exact ([`Arena::is_zero`]): they are only
//! evaluated, and expanding them multiplies out the rotations of the whole chain above
//! each wheel.
//!
//! The contact point is the shared support map's ([`Surface::support_along`], the geometry of
//! a body on a table): for a disk, hub + r d/|d| with d = −up + (up·n) n, n the axle.
//! [`Rim`] takes |d| exactly when |d|² expands to a monomial square (cos²φ for a wheel
//! whose axle only leans by φ), so that such identities show; otherwise it stays a square
//! root. |d| is the cosine of the wheel's lean from the vertical and is reported as a tilt
//! that must stay above [`crate::rigid::MIN_TILT`].

use super::scene::RollingScene;
use crate::lagrange::{Constraints, Coordinates, EquationsOfMotion};
use crate::mechanism::error::MechanismError;
use crate::mechanism::kinematics::{basis_axis, unit_axis};
use crate::mechanism::routes::kane::{MassEntries, scalar_rate_at_rest, symbols};
use crate::mechanism::scene::MechanismScene;
use crate::rigid::{Rim, Surface, SurfaceError};
use crate::sym::mat3::{cross, dot, mat_vec};
use crate::sym::{Arena, ExprId};

/// Everything derived from a mechanism whose wheels roll.
#[derive(Clone, Debug, PartialEq)]
pub struct RollingDerivation {
    /// The unconstrained equations M q̈ = f of the tree (every coordinate).
    pub equations: EquationsOfMotion,
    /// The time symbol.
    pub time: ExprId,
    /// The wheels' constraint rows A q̇ = 0 (per wheel: the horizontal rows, then the
    /// height row where there is one).
    pub constraints: Constraints,
    /// Ȧq̇, one per row, unexpanded: the rate at q̈ = 0 of each row's value (the contact
    /// point's horizontal velocity, the height's rate), equal to [`Constraints::rate_terms_shared`].
    pub rate_terms: Vec<ExprId>,
    /// The free speeds' coordinates, in the declared order.
    pub independent: Vec<usize>,
    /// The other coordinates, in coordinate order, one per row.
    pub dependent: Vec<usize>,
    /// Each wheel's contact point, ground axes.
    pub contact_points: Vec<[ExprId; 3]>,
    /// Each wheel's contact point's material velocity, ground axes (zero on a rolling
    /// motion: the check of the constraints).
    pub contact_velocities: Vec<[ExprId; 3]>,
    /// Each disk's |d| = cos of its lean from the vertical (1 for a sphere): must be > 0.
    pub tilts: Vec<ExprId>,
    /// T.
    pub kinetic: ExprId,
    /// V (gravity and springs).
    pub potential: ExprId,
    /// Σ Q_i q̇_i of the non-conservative loads.
    pub power: ExprId,
}

impl RollingDerivation {
    /// The number of constraint rows m.
    pub fn rows(&self) -> usize {
        self.constraints.len()
    }
}

impl MechanismScene {
    /// Derives the mechanism with its wheels rolling on the floor.
    ///
    /// # Errors
    /// As [`MechanismScene::validate`]; [`MechanismError::FloorNotAxis`],
    /// [`MechanismError::UnknownWheelBody`], [`MechanismError::UnknownSpeed`],
    /// [`MechanismError::SpeedCount`]; [`MechanismError::Sym`] and
    /// [`MechanismError::Lagrange`] if the engine fails.
    pub fn derive_rolling(
        &self,
        arena: &mut Arena,
        rolling: &RollingScene,
    ) -> Result<RollingDerivation, MechanismError> {
        let Some((up_axis, up_positive)) = basis_axis(arena, &rolling.up) else {
            return Err(MechanismError::FloorNotAxis);
        };
        let (lag, kin) = self.lagrangian(arena)?;
        let coords = lag.coords.clone();
        let n = coords.len();
        let sign = if up_positive { 1 } else { -1 };
        let up = {
            let mut e = [arena.zero(); 3];
            e[up_axis] = arena.integer(sign);
            e
        };
        let horizontal: Vec<usize> = (0..3).filter(|&k| k != up_axis).collect();
        let mut constraints = Constraints::new();
        let mut contact_points = Vec::new();
        let mut contact_velocities = Vec::new();
        let mut tilts = Vec::new();
        // Each row's value A_r q̇ + b_r in a shared form: the horizontal velocity of the
        // contact point it was read from, or the height's rate.
        let mut row_values = Vec::new();
        for wheel in &rolling.wheels {
            let Some(k) = kin.get(wheel.body) else {
                return Err(MechanismError::UnknownWheelBody {
                    body: wheel.body,
                    count: kin.len(),
                });
            };
            // The wheel's surface in ground axes, about its hub: the shared support map for
            // the outward normal −up (rim or ball), its axis the axle turned by the body.
            let (surface, axle) = wheel.surface.surface();
            let down = up.map(|u| arena.neg(u));
            let (center, arm, tilt) = match (surface, axle) {
                (Surface::DiskRim { center, radius }, Some(axle)) => {
                    let local = unit_axis(arena, &axle)?;
                    let axle = mat_vec(arena, &k.rotation, &local).map(|e| arena.expand(e));
                    let rim = Surface::DiskRim {
                        center: [arena.zero(); 3],
                        radius,
                    };
                    let arm = rim.support_along(arena, &down, &axle)?;
                    let tilt = Rim::new(arena, &down, &axle)?.tilt;
                    (center, arm.map(|e| arena.expand(e)), tilt)
                }
                (Surface::Sphere { center, radius }, _) => {
                    let ball = Surface::Sphere {
                        center: [arena.zero(); 3],
                        radius,
                    };
                    (center, ball.support(arena, &down)?, arena.one())
                }
                (other, _) => {
                    return Err(MechanismError::Surface(SurfaceError::NotAxisymmetric {
                        surface: other.name(),
                    }));
                }
            };
            let lever = mat_vec(arena, &k.rotation, &center);
            let hub = [0, 1, 2].map(|i| {
                let t = arena.add(k.origin[i], lever[i]);
                arena.expand(t)
            });
            let point = [0, 1, 2].map(|i| {
                let t = arena.add(hub[i], arm[i]);
                arena.expand(t)
            });
            // v_hub = v_c + ω × (hub − c), ω in ground axes.
            let omega = mat_vec(arena, &k.rotation, &k.omega);
            let from_center = [0, 1, 2].map(|i| arena.sub(hub[i], k.center[i]));
            let spin = cross(arena, &omega, &from_center);
            let v_hub = [0, 1, 2].map(|i| arena.add(k.center_velocity[i], spin[i]));
            // Left in its shared form, and so are the rows' coefficients ∂v_P/∂q̇ and Ȧq̇
            // (read from it below): expanding them multiplies out the rotations of the
            // whole chain above the wheel, for values that are only evaluated. Their zeros
            // stay exact (`Constraints::nonholonomic_shared`).
            let turn = cross(arena, &omega, &arm);
            let velocity = [0, 1, 2].map(|i| arena.add(v_hub[i], turn[i]));
            for &h in &horizontal {
                let row: Vec<ExprId> = coords
                    .rates
                    .iter()
                    .map(|&r| match arena.as_symbol(r) {
                        Some(s) => arena.diff(velocity[h], s),
                        None => arena.zero(),
                    })
                    .collect();
                let zero = arena.zero();
                if constraints.nonholonomic_shared(arena, &coords, &row, zero)? {
                    row_values.push(velocity[h]);
                }
            }
            let height = dot(arena, &up, &point);
            let height = arena.expand(height);
            if height != arena.zero() {
                // d(up·P)/dt = up·v_P: relative to the body, P moves along the rim's tangent at
                // P, which is horizontal there (on a ball it does not move), so the height
                // rises at the vertical velocity of the body's point at P, whose derivatives
                // share those of the horizontal rows.
                let rise = dot(arena, &up, &velocity);
                constraints.holonomic_shared(arena, &coords, height, rise)?;
                row_values.push(rise);
            }
            contact_points.push(point);
            contact_velocities.push(velocity);
            tilts.push(tilt);
        }
        let m = constraints.len();
        let names = self.coordinate_names();
        let mut independent = Vec::with_capacity(rolling.speeds.len());
        for speed in &rolling.speeds {
            let position = names.iter().position(|c| c == speed);
            let repeated = position.is_some_and(|i| independent.contains(&i));
            match position {
                Some(i) if !repeated => independent.push(i),
                _ => {
                    return Err(MechanismError::UnknownSpeed {
                        speed: speed.clone(),
                        repeated,
                        coordinates: names.iter().map(|c| (*c).to_owned()).collect(),
                    });
                }
            }
        }
        if independent.len() + m != n {
            return Err(MechanismError::SpeedCount {
                got: independent.len(),
                coordinates: n,
                rows: m,
            });
        }
        let dependent: Vec<usize> = (0..n).filter(|i| !independent.contains(i)).collect();
        // Ȧq̇ row by row as the rate of the row's value at q̈ = 0 (`scalar_rate_at_rest`):
        // the values of `Constraints::rate_terms_shared`, whose derivatives of each expanded
        // coefficient cost several times more.
        let q = symbols(arena, &coords.q);
        let time = arena.time_symbol();
        let rate_terms = row_values
            .iter()
            .map(|&c| scalar_rate_at_rest(arena, c, &q, &coords.rates, time))
            .collect();
        // Kane's method: the Lagrangian route's expansion of the whole tree's momenta took
        // seconds on the bicycle (see `kane.rs`). M is left unexpanded: `RollingDynamics`
        // solves Maggi's equations numerically and reads no structural zero of M.
        let equations = self.kane_from(arena, &lag, &kin, MassEntries::Unexpanded);
        let power = lag.power(arena);
        Ok(RollingDerivation {
            equations,
            time: lag.time,
            constraints,
            rate_terms,
            independent,
            dependent,
            contact_points,
            contact_velocities,
            tilts,
            kinetic: lag.kinetic,
            potential: lag.potential,
            power,
        })
    }
}

/// The coordinates of a rolling derivation.
impl RollingDerivation {
    /// q, q̇ and q̈ symbols.
    pub fn coordinates(&self) -> &Coordinates {
        &self.equations.coords
    }
}
