//! Symbolic kinematics through the tree: each body's attitude, origin, centre of mass,
//! angular velocity and centre velocity as expressions in q and q̇.
//!
//! For a body b hanging from p by a joint at `a` (in p's frame) with joint rotation J(q)
//! (b's axes to p's axes) and joint translation d(q) (in p's frame):
//!
//! - R_b = R_p J                      (b's axes to ground axes)
//! - o_b = o_p + R_p (a + d)          (b's origin, ground axes)
//! - c_b = o_b + R_b c                (its centre of mass, c in b's axes)
//! - ω_b = Jᵀ ω_p + ω_rel             (angular velocity in b's axes; ω_rel = vee(Jᵀ J̇))
//! - v_c = d c_b / dt                 (the total time derivative, ground axes)
//!
//! Past [`MAX_LAGRANGIAN`] coordinates the velocities come from the same recursion
//! instead of differentiating c_b: with d/dt (R x) = R (ω × x + ẋ) for ω in the axes R maps
//! from,
//!
//! - v_o,b = v_o,p + R_p (ω_p × (a + d) + ȧ + ḋ)
//! - v_c   = v_o,b + R_b (ω_b × c + ċ)
//!
//! The derivative of c_b carries one product-rule term per rotation above the body, so its
//! lowered form grows as the square of the depth and T's as the cube: a 100-link chain's T
//! was 900 000 operations (rustc overflowed its stack building it), the recursion's is a
//! few dozen per body.
//!
//! A revolute about the unit axis n turns by Rodrigues' formula
//! `R = cos q 𝟙 + sin q [n]ₓ + (1 − cos q) n nᵀ` (with n nᵀ = a aᵀ/|a|², so only the
//! sine term carries a square root), except that an axis along x, y or z uses the
//! elementary rotation so the trigonometry stays canonical; its ω_rel is n q̇. A universal
//! joint is two revolutes, a spherical joint the Euler angles of its sequence (the tops'
//! charts), a free joint the translation d = (x, y, z) in the parent's axes followed by the
//! Euler angles of its sequence.

use super::error::MechanismError;
use super::scene::{JointKind, MechanismScene, Parent};
use crate::lagrange::Coordinates;
use crate::rigid::elementary;
use crate::sym::mat3::{Mat3, cross, mat_mul, mat_vec, transpose};
use crate::sym::{Arena, ExprId, SymError};

/// The most coordinates for which [`Route::Auto`](super::Route::Auto) forms the Euler–Lagrange equations and
/// compares the Lagrangian routes with the recursive one. Past it the expanded M and f grow
/// faster than the chain (planar chains: 1,046 weighted operations factored against 454
/// recursive at five coordinates, and five to eight times the derivation time per link),
/// so Auto takes the recursive route without deriving them. It lives here because the
/// kinematics are the first thing it sizes: expanded up to it, shared and unexpanded past it.
pub const MAX_LAGRANGIAN: usize = 3;

/// The motion of one body: every entry expanded to the engine's canonical form for
/// mechanisms of at most [`MAX_LAGRANGIAN`] coordinates (the Lagrangian routes
/// differentiate and compare them), hash-consed but unexpanded past it (see
/// [`MechanismScene::kinematics`]).
#[derive(Clone, Debug, PartialEq)]
pub struct BodyKinematics {
    /// R_b, the body's axes to ground axes.
    pub rotation: Mat3,
    /// The body frame's origin, in ground axes.
    pub origin: [ExprId; 3],
    /// The centre of mass, in ground axes.
    pub center: [ExprId; 3],
    /// The angular velocity ω_b, in the body's axes.
    pub omega: [ExprId; 3],
    /// The centre of mass velocity, in ground axes.
    pub center_velocity: [ExprId; 3],
}

/// The unit vector along `axis`: a signed basis vector when the axis is a constant along x,
/// y or z, otherwise `a / √(a·a)`.
pub(crate) fn unit_axis(arena: &mut Arena, axis: &[ExprId; 3]) -> Result<[ExprId; 3], SymError> {
    if let Some((k, positive)) = basis_axis(arena, axis) {
        let mut e = [arena.zero(); 3];
        e[k] = if positive {
            arena.one()
        } else {
            arena.integer(-1)
        };
        return Ok(e);
    }
    let n2 = norm_squared(arena, axis);
    let n = arena.sqrt(n2)?;
    let inv = arena.recip(n)?;
    Ok(axis.map(|x| arena.mul(x, inv)))
}

/// `(k, sign > 0)` when `axis` is a non-zero constant times the k-th basis vector.
pub(crate) fn basis_axis(arena: &Arena, axis: &[ExprId; 3]) -> Option<(usize, bool)> {
    let zero = arena.zero();
    let nonzero: Vec<usize> = (0..3).filter(|&k| axis[k] != zero).collect();
    let [k] = nonzero.as_slice() else {
        return None;
    };
    let r = arena.as_rational(axis[*k])?;
    Some((*k, !r.is_negative()))
}

fn norm_squared(arena: &mut Arena, v: &[ExprId; 3]) -> ExprId {
    let terms: Vec<ExprId> = v.iter().map(|&x| arena.mul(x, x)).collect();
    let s = arena.sum(&terms);
    arena.expand(s)
}

/// The rotation by `angle` about `axis` (not necessarily unit).
pub(crate) fn axis_rotation(
    arena: &mut Arena,
    axis: &[ExprId; 3],
    angle: ExprId,
) -> Result<Mat3, SymError> {
    if let Some((k, positive)) = basis_axis(arena, axis) {
        let angle = if positive { angle } else { arena.neg(angle) };
        return Ok(elementary(arena, k, angle));
    }
    let (c, s) = (arena.cos(angle), arena.sin(angle));
    let one_minus_c = arena.sub(arena.one(), c);
    let n2 = norm_squared(arena, axis);
    let inv_n2 = arena.recip(n2)?;
    let root = arena.sqrt(n2)?;
    let inv_n = arena.recip(root)?;
    let sn = arena.mul(s, inv_n);
    let mut r = [[arena.zero(); 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            // (1 − cos q) a_i a_j / |a|²
            let aa = arena.product(&[one_minus_c, axis[i], axis[j], inv_n2]);
            let mut terms = vec![aa];
            if i == j {
                terms.push(c);
            } else {
                // sin q [a]ₓ / |a|: [a]ₓ(i, j) = −ε_ijk a_k
                let k = 3 - i - j;
                let sign = if (i + 1) % 3 == j { -1 } else { 1 };
                let t = arena.mul(sn, axis[k]);
                terms.push(if sign < 0 { arena.neg(t) } else { t });
            }
            *e = arena.sum(&terms);
        }
    }
    Ok(r)
}

/// Joint rotation J(q), joint translation d(q) in the parent's frame, and ω_rel in the
/// child's axes, for the joint's coordinates `q` and rates `qd`.
struct JointMotion {
    rotation: Mat3,
    translation: [ExprId; 3],
    omega: [ExprId; 3],
}

fn joint_motion(
    arena: &mut Arena,
    kind: &JointKind,
    q: &[ExprId],
    qd: &[ExprId],
) -> Result<JointMotion, MechanismError> {
    let z = arena.zero();
    let identity = {
        let o = arena.one();
        [[o, z, z], [z, o, z], [z, z, o]]
    };
    Ok(match kind {
        JointKind::Revolute { axis } => {
            let n = unit_axis(arena, axis)?;
            JointMotion {
                rotation: axis_rotation(arena, axis, q[0])?,
                translation: [z; 3],
                omega: n.map(|x| arena.mul(x, qd[0])),
            }
        }
        JointKind::Prismatic { axis } => {
            let n = unit_axis(arena, axis)?;
            JointMotion {
                rotation: identity,
                translation: n.map(|x| arena.mul(x, q[0])),
                omega: [z; 3],
            }
        }
        JointKind::Universal { axes } => {
            let n0 = unit_axis(arena, &axes[0])?;
            let n1 = unit_axis(arena, &axes[1])?;
            let r0 = axis_rotation(arena, &axes[0], q[0])?;
            let r1 = axis_rotation(arena, &axes[1], q[1])?;
            let outer = mat_vec(arena, &transpose(&r1), &n0);
            let omega = [0, 1, 2].map(|k| {
                let a = arena.mul(outer[k], qd[0]);
                let b = arena.mul(n1[k], qd[1]);
                arena.add(a, b)
            });
            JointMotion {
                rotation: mat_mul(arena, &r0, &r1),
                translation: [z; 3],
                omega,
            }
        }
        JointKind::Spherical { sequence } => {
            let coords = Coordinates::from_symbols(arena, q)?;
            JointMotion {
                rotation: sequence.rotation(arena, q),
                translation: [z; 3],
                omega: sequence.body_rates(arena, &coords),
            }
        }
        JointKind::Free { sequence } => {
            let coords = Coordinates::from_symbols(arena, &q[3..6])?;
            JointMotion {
                rotation: sequence.rotation(arena, &q[3..6]),
                translation: [q[0], q[1], q[2]],
                omega: sequence.body_rates(arena, &coords),
            }
        }
    })
}

impl MechanismScene {
    /// The kinematics of every body (indexed as [`MechanismScene::bodies`]), computed in the
    /// topological `order` that [`MechanismScene::validate`] returns, with the body's
    /// coordinates taken from `coords` in [`MechanismScene::coordinate_names`] order.
    ///
    /// Past [`MAX_LAGRANGIAN`] coordinates only the energy reads these (q̈ comes from
    /// the recursive route), so they are left unexpanded: a body's expanded rotation holds
    /// about twice the terms of its parent's, which made the derive of a 15-link 3D chain
    /// take seconds and a 25-link one never finish, while the hash-consed forms grow with the
    /// chain and lower, shared subexpressions and all, to the same values.
    ///
    /// # Errors
    /// [`MechanismError::Sym`] if an axis normalisation divides by an identically zero
    /// length (validation rules that out).
    pub fn kinematics(
        &self,
        arena: &mut Arena,
        order: &[usize],
        coords: &Coordinates,
    ) -> Result<Vec<BodyKinematics>, MechanismError> {
        let offsets = self.coordinate_offsets();
        let expanded = coords.q.len() <= MAX_LAGRANGIAN;
        let expand3 = |arena: &mut Arena, v: [ExprId; 3]| {
            if expanded {
                v.map(|e| arena.expand(e))
            } else {
                v
            }
        };
        let mut out: Vec<Option<BodyKinematics>> = vec![None; self.bodies.len()];
        // The velocity of each body frame's origin, ground axes (the recursive form only).
        let mut origin_velocity: Vec<[ExprId; 3]> = vec![[arena.zero(); 3]; self.bodies.len()];
        let z = arena.zero();
        let o = arena.one();
        let ground = BodyKinematics {
            rotation: [[o, z, z], [z, o, z], [z, z, o]],
            origin: [z; 3],
            center: [z; 3],
            omega: [z; 3],
            center_velocity: [z; 3],
        };
        for &b in order {
            let body = &self.bodies[b];
            let joint = &body.joint;
            let parent = match joint.parent {
                Parent::Ground => &ground,
                Parent::Body(p) => out.get(p).and_then(Option::as_ref).ok_or_else(|| {
                    MechanismError::UnknownParent {
                        body: body.name.clone(),
                        parent: p,
                        count: self.bodies.len(),
                    }
                })?,
            };
            let dof = joint.kind.dof();
            let range = offsets[b]..offsets[b] + dof;
            let motion = joint_motion(
                arena,
                &joint.kind,
                &coords.q[range.clone()],
                &coords.rates[range],
            )?;
            let rotation = mat_mul(arena, &parent.rotation, &motion.rotation);
            let rotation = rotation.map(|row| expand3(arena, row));
            let offset = [0, 1, 2].map(|k| arena.add(joint.at[k], motion.translation[k]));
            let shift = mat_vec(arena, &parent.rotation, &offset);
            let origin = [0, 1, 2].map(|k| arena.add(parent.origin[k], shift[k]));
            let origin = expand3(arena, origin);
            let arm = mat_vec(arena, &rotation, &body.center);
            let center = [0, 1, 2].map(|k| arena.add(origin[k], arm[k]));
            let center = expand3(arena, center);
            let carried = mat_vec(arena, &transpose(&motion.rotation), &parent.omega);
            let omega = [0, 1, 2].map(|k| arena.add(carried[k], motion.omega[k]));
            let omega = expand3(arena, omega);
            let center_velocity = if expanded {
                let v = center.map(|e| arena.dt(e));
                expand3(arena, v)
            } else {
                let parent_velocity = match joint.parent {
                    Parent::Ground => [z; 3],
                    Parent::Body(p) => origin_velocity.get(p).copied().unwrap_or([z; 3]),
                };
                let turning = cross(arena, &parent.omega, &offset);
                let local = [0, 1, 2].map(|k| {
                    let moving = arena.dt(offset[k]);
                    arena.add(turning[k], moving)
                });
                let carried = mat_vec(arena, &parent.rotation, &local);
                let velocity = [0, 1, 2].map(|k| arena.add(parent_velocity[k], carried[k]));
                origin_velocity[b] = velocity;
                let turning = cross(arena, &omega, &body.center);
                let local = [0, 1, 2].map(|k| {
                    let moving = arena.dt(body.center[k]);
                    arena.add(turning[k], moving)
                });
                let arm_velocity = mat_vec(arena, &rotation, &local);
                [0, 1, 2].map(|k| arena.add(velocity[k], arm_velocity[k]))
            };
            out[b] = Some(BodyKinematics {
                rotation,
                origin,
                center,
                omega,
                center_velocity,
            });
        }
        Ok(out
            .into_iter()
            .map(|k| k.unwrap_or_else(|| ground.clone()))
            .collect())
    }

    /// The index of each body's first coordinate in the state.
    pub fn coordinate_offsets(&self) -> Vec<usize> {
        let mut offsets = Vec::with_capacity(self.bodies.len());
        let mut next = 0;
        for b in &self.bodies {
            offsets.push(next);
            next += b.joint.kind.dof();
        }
        offsets
    }
}
