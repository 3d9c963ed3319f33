//! A body on a table, derived: Kane's method with the body angular velocity ω as the
//! generalised speeds, in body (description) axes, with the Poisson vector γ = Rᵀ ẑ.
//!
//! r(γ) = s(−γ) − c runs from the centre of mass to the contact point (s the surface's
//! support map); the centre of mass stands at height z = −r·γ, and since s(n) is where the
//! normal is n, ṙ·γ = 0 and ż = −r·γ̇ with γ̇ = γ × ω (the envelope property of the support
//! function). The contact force F (body axes) obeys M(v̇ + ω × v) = F − M g γ and
//! I ω̇ + ω × I ω = r × F + τ.
//!
//! - Rolling: v = r × ω, so v̇ = ṙ × ω + r × ω̇; putting F into Euler's equation gives the
//!   symmetric positive definite system
//!   (I + M(|r|² 1 − r rᵀ)) ω̇ = −ω × I ω + M r × (ṙ × ω + ω × v + g γ) + τ,
//!   solved by its adjugate; F follows.
//! - Sliding: (vx, vy) are states and vz = −r·γ̇; F = F₀ + N e (viscous F₀ = −c u, e = γ;
//!   Coulomb F₀ = 0, e = γ − μ u/|u|; u the slip velocity of the contact point). The
//!   constraint z̈ = −ṙ·γ̇ − r·(γ̇ × ω) + (γ × r)·ω̇ = N/M − g is linear in N once
//!   ω̇ = I⁻¹(−ω × I ω + r × F₀) + N I⁻¹(r × e) is put in: N is solved for, then ω̇.
//!
//! Every law's horizontal acceleration is the horizontal part of R F / M.

use super::error::ContactError;
use super::scene::{ContactLaw, ContactScene, ContactTorques, Friction};
use super::state::STATE_LEN;
use super::torques::{Applied, applied};
use crate::rigid::{quaternion_rate, rotation_of_quaternion};
use crate::sym::mat3::{Mat3, cross, determinant, dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId, Rational, SymbolId};

/// The equations of one phase of the contact, as expressions in the state symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactEquations {
    /// The right-hand side ẏ of the state of [`super::layout`].
    pub rhs: [ExprId; STATE_LEN],
    /// The normal force N.
    pub normal: ExprId,
    /// The friction force, space axes (horizontal).
    pub friction: [ExprId; 3],
    /// The energy ½ M |v|² + ½ ωᵀ I ω + M g z with this phase's velocity.
    pub energy: ExprId,
    /// The linear momentum M v, space axes.
    pub linear_momentum: [ExprId; 3],
    /// The angular momentum about the contact point, K = R(I ω − M r × v), space axes.
    pub angular_momentum_contact: [ExprId; 3],
}

/// Everything derived from a [`ContactScene`], as expressions in the state symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactDerivation {
    /// The scene derived (its parameters are what an interpreted model checks).
    pub scene: ContactScene,
    /// The torques beyond the law's friction, a rolling law's own resistances among them.
    pub torques: ContactTorques,
    /// The state symbols, in the order of [`super::layout`].
    pub state: [ExprId; STATE_LEN],
    /// The rolling equations (the rolling and stick–slip laws).
    pub rolling: Option<ContactEquations>,
    /// The sliding equations (the sliding law; Coulomb sliding for stick–slip).
    pub sliding: Option<ContactEquations>,
    /// γ = Rᵀ ẑ, the space vertical in body axes.
    pub gamma: [ExprId; 3],
    /// r, from the centre of mass to the contact point, body axes.
    pub contact_body: [ExprId; 3],
    /// The contact point in space, (x, y, z) + R r.
    pub contact_space: [ExprId; 3],
    /// The height of the centre of mass, z = −r·γ.
    pub height: ExprId,
    /// The velocity of the body's point at the contact from the state's (vx, vy, vz) and ω,
    /// space axes: the slip velocity u.
    pub contact_velocity: [ExprId; 3],
    /// Jellett's quantity λ = −(I ω)·r.
    pub jellett: ExprId,
    /// The angular momentum about the centre of mass, R I ω, space axes.
    pub angular_momentum_center: [ExprId; 3],
}

/// What a phase's equations are built from: the kinematics shared by the phases.
struct Kinematics {
    q: [ExprId; 4],
    rotation: Mat3,
    omega: [ExprId; 3],
    gamma: [ExprId; 3],
    gamma_dot: [ExprId; 3],
    r: [ExprId; 3],
    r_dot: [ExprId; 3],
    i_omega: [ExprId; 3],
    /// −ω × I ω.
    gyroscopic: [ExprId; 3],
    height: ExprId,
    /// The space velocity from the state, (vx, vy, −r·γ̇).
    velocity: [ExprId; 3],
}

impl ContactScene {
    /// Derives the equations of each phase of the law, the reaction, the contact point and
    /// its velocity, the energy, Jellett's quantity and the momenta, over fresh input symbols
    /// for the state.
    ///
    /// # Errors
    /// [`ContactError::Sym`] if a division or root of the derivation is refused (a surface
    /// length or the mass identically zero).
    pub fn derive(&self, arena: &mut Arena) -> Result<ContactDerivation, ContactError> {
        self.derive_with(arena, &ContactTorques::default())
    }

    /// As [`ContactScene::derive`], under the further `torques` (resistances, pivoting
    /// friction, a user couple) in every phase the law derives. A rolling law's own
    /// resistances join them.
    ///
    /// # Errors
    /// As [`ContactScene::derive`]; [`ContactError::DeclaredTwice`] for a resistance both the
    /// rolling law and `torques` declare.
    pub fn derive_with(
        &self,
        arena: &mut Arena,
        torques: &ContactTorques,
    ) -> Result<ContactDerivation, ContactError> {
        const NAMES: [&str; STATE_LEN] = [
            "x", "y", "v_x", "v_y", "q_w", "q_x", "q_y", "q_z", "omega_1", "omega_2", "omega_3",
        ];
        let state: [ExprId; STATE_LEN] = std::array::from_fn(|k| arena.input(NAMES[k]));
        let k = self.kinematics(arena, &state)?;
        let torques = self.merged(torques)?;
        let tau = applied(arena, &k.omega, &k.gamma, &torques)?;
        let (rolling, sliding) = match self.law {
            ContactLaw::Rolling { .. } => (Some(self.rolling(arena, &k, &tau)?), None),
            ContactLaw::Sliding(friction) => (None, Some(self.sliding(arena, &k, friction, &tau)?)),
            ContactLaw::StickSlip { mu } => (
                Some(self.rolling(arena, &k, &tau)?),
                Some(self.sliding(arena, &k, Friction::Coulomb(mu), &tau)?),
            ),
        };
        let lever = mat_vec(arena, &k.rotation, &k.r);
        let contact_space = [
            arena.add(state[0], lever[0]),
            arena.add(state[1], lever[1]),
            arena.add(k.height, lever[2]),
        ];
        let spin = cross(arena, &k.omega, &k.r);
        let spin_space = mat_vec(arena, &k.rotation, &spin);
        let contact_velocity: [ExprId; 3] =
            std::array::from_fn(|j| arena.add(k.velocity[j], spin_space[j]));
        let l_dot_r = dot(arena, &k.i_omega, &k.r);
        let jellett = arena.neg(l_dot_r);
        let angular_momentum_center = mat_vec(arena, &k.rotation, &k.i_omega);
        Ok(ContactDerivation {
            scene: self.clone(),
            torques,
            state,
            rolling,
            sliding,
            gamma: k.gamma,
            contact_body: k.r,
            contact_space,
            height: k.height,
            contact_velocity,
            jellett,
            angular_momentum_center,
        })
    }

    /// γ, r(γ) and ṙ = (∂r/∂γ) γ̇, with r differentiated in γ before γ is written in the
    /// quaternion (the support maps are short in γ, long in q).
    fn kinematics(
        &self,
        arena: &mut Arena,
        state: &[ExprId; STATE_LEN],
    ) -> Result<Kinematics, ContactError> {
        let q = [state[4], state[5], state[6], state[7]];
        let omega = [state[8], state[9], state[10]];
        let rotation = rotation_of_quaternion(arena, q)?;
        let gamma = rotation[2];
        let g_symbols: [ExprId; 3] =
            std::array::from_fn(|j| arena.input(&format!("contact_gamma_{}", j + 1)));
        let g_ids: [SymbolId; 3] = std::array::from_fn(|j| {
            arena
                .as_symbol(g_symbols[j])
                .unwrap_or_else(|| unreachable!("a fresh input is a symbol"))
        });
        let down = g_symbols.map(|g| arena.neg(g));
        let s = self.surface.support(arena, &down)?;
        let r_of_g: [ExprId; 3] = std::array::from_fn(|j| arena.sub(s[j], self.center[j]));
        let gamma_dot = cross(arena, &gamma, &omega);
        let map: Vec<(SymbolId, ExprId)> = g_ids.iter().copied().zip(gamma).collect();
        let mut r = [arena.zero(); 3];
        let mut r_dot = [arena.zero(); 3];
        for j in 0..3 {
            r[j] = arena.subs(r_of_g[j], &map)?;
            let mut terms = Vec::with_capacity(3);
            for (m, &id) in g_ids.iter().enumerate() {
                let partial = arena.diff(r_of_g[j], id);
                let partial = arena.subs(partial, &map)?;
                terms.push(arena.mul(partial, gamma_dot[m]));
            }
            r_dot[j] = arena.sum(&terms);
        }
        let i_omega = mat_vec(arena, &self.inertia, &omega);
        let gyro = cross(arena, &omega, &i_omega);
        let gyroscopic = gyro.map(|c| arena.neg(c));
        let r_gamma = dot(arena, &r, &gamma);
        let height = arena.neg(r_gamma);
        let r_gamma_dot = dot(arena, &r, &gamma_dot);
        let vz = arena.neg(r_gamma_dot);
        Ok(Kinematics {
            q,
            rotation,
            omega,
            gamma,
            gamma_dot,
            r,
            r_dot,
            i_omega,
            gyroscopic,
            height,
            velocity: [state[2], state[3], vz],
        })
    }

    /// The rolling phase under the extra torques `tau`.
    ///
    /// A torque N κ proportional to the normal force (pivoting friction) makes the system
    /// (I + M(|r|² 1 − r rᵀ)) ω̇ = b + N κ implicit, since under rolling N = F·γ =
    /// N₀ + n·ω̇ with N₀ = M γ·(ṙ × ω + ω × v + g γ) and n = M (γ × r); it is solved as
    /// (I + M(|r|² 1 − r rᵀ) − κ nᵀ) ω̇ = b + N₀ κ, by the same adjugate.
    fn rolling(
        &self,
        arena: &mut Arena,
        k: &Kinematics,
        tau: &Applied,
    ) -> Result<ContactEquations, ContactError> {
        let m = self.mass;
        let v = cross(arena, &k.r, &k.omega);
        // The symmetric matrix I + M(|r|² 1 − r rᵀ).
        let r2 = dot(arena, &k.r, &k.r);
        let mut a: Vec<Vec<ExprId>> = (0..3)
            .map(|i| {
                (0..3)
                    .map(|j| {
                        let rr = arena.mul(k.r[i], k.r[j]);
                        let shifted = if i == j {
                            arena.sub(r2, rr)
                        } else {
                            arena.neg(rr)
                        };
                        let mt = arena.mul(m, shifted);
                        arena.add(self.inertia[i][j], mt)
                    })
                    .collect()
            })
            .collect();
        let rdot_w = cross(arena, &k.r_dot, &k.omega);
        let w_v = cross(arena, &k.omega, &v);
        let g_gamma = k.gamma.map(|c| arena.mul(self.gravity, c));
        let inner: [ExprId; 3] =
            std::array::from_fn(|j| arena.sum(&[rdot_w[j], w_v[j], g_gamma[j]]));
        let r_inner = cross(arena, &k.r, &inner);
        let mut b: [ExprId; 3] = std::array::from_fn(|j| {
            let t = arena.mul(m, r_inner[j]);
            arena.sum(&[k.gyroscopic[j], t, tau.fixed[j]])
        });
        if let Some(kappa) = tau.per_normal {
            let g_inner = dot(arena, &k.gamma, &inner);
            let n0 = arena.mul(m, g_inner);
            let g_r = cross(arena, &k.gamma, &k.r);
            let n = g_r.map(|c| arena.mul(m, c));
            for i in 0..3 {
                for j in 0..3 {
                    let kn = arena.mul(kappa[i], n[j]);
                    a[i][j] = arena.sub(a[i][j], kn);
                }
                let kn0 = arena.mul(kappa[i], n0);
                b[i] = arena.add(b[i], kn0);
            }
        }
        let omega_dot = solve3(arena, &a, &b)?;
        let r_wd = cross(arena, &k.r, &omega_dot);
        let v_dot: [ExprId; 3] = std::array::from_fn(|j| arena.add(rdot_w[j], r_wd[j]));
        // F = M(v̇ + ω × v) + M g γ, body axes.
        let force: [ExprId; 3] = std::array::from_fn(|j| {
            let s = arena.sum(&[v_dot[j], w_v[j], g_gamma[j]]);
            arena.mul(m, s)
        });
        self.equations(arena, k, &omega_dot, &force, &v)
    }

    /// The sliding phase under `friction` and the extra torques `tau` (a torque N κ
    /// joins the part of ω̇ proportional to N: β = I⁻¹(r × e + κ)).
    fn sliding(
        &self,
        arena: &mut Arena,
        k: &Kinematics,
        friction: Friction,
        tau: &Applied,
    ) -> Result<ContactEquations, ContactError> {
        let m = self.mass;
        let to_body = transpose(&k.rotation);
        let v = mat_vec(arena, &to_body, &k.velocity);
        let w_r = cross(arena, &k.omega, &k.r);
        let u: [ExprId; 3] = std::array::from_fn(|j| arena.add(v[j], w_r[j]));
        let zero = [arena.zero(); 3];
        let (f0, e) = match friction {
            Friction::Frictionless => (zero, k.gamma),
            Friction::Viscous(c) => {
                let nc = arena.neg(c);
                (u.map(|x| arena.mul(nc, x)), k.gamma)
            }
            Friction::Coulomb(mu) => {
                let u2 = dot(arena, &u, &u);
                let speed = arena.sqrt(u2)?;
                let scale = arena.div(mu, speed)?;
                let e: [ExprId; 3] = std::array::from_fn(|j| {
                    let t = arena.mul(scale, u[j]);
                    arena.sub(k.gamma[j], t)
                });
                (zero, e)
            }
            Friction::NormalViscous(mu) => {
                let e: [ExprId; 3] = std::array::from_fn(|j| {
                    let t = arena.mul(mu, u[j]);
                    arena.sub(k.gamma[j], t)
                });
                (zero, e)
            }
        };
        let inv = inverse3(arena, &self.inertia)?;
        let r_f0 = cross(arena, &k.r, &f0);
        let free: [ExprId; 3] =
            std::array::from_fn(|j| arena.sum(&[k.gyroscopic[j], r_f0[j], tau.fixed[j]]));
        let alpha = mat_vec(arena, &inv, &free);
        let mut r_e = cross(arena, &k.r, &e);
        if let Some(kappa) = tau.per_normal {
            r_e = std::array::from_fn(|j| arena.add(r_e[j], kappa[j]));
        }
        let beta = mat_vec(arena, &inv, &r_e);
        // z̈ = A + b·ω̇ with A = −ṙ·γ̇ − r·(γ̇ × ω), b = γ × r.
        let rd_gd = dot(arena, &k.r_dot, &k.gamma_dot);
        let gd_w = cross(arena, &k.gamma_dot, &k.omega);
        let r_gdw = dot(arena, &k.r, &gd_w);
        let b = cross(arena, &k.gamma, &k.r);
        let b_alpha = dot(arena, &b, &alpha);
        let b_beta = dot(arena, &b, &beta);
        let (nrd, nrg) = (arena.neg(rd_gd), arena.neg(r_gdw));
        let numerator = arena.sum(&[self.gravity, nrd, nrg, b_alpha]);
        let numerator = arena.mul(m, numerator);
        let mbb = arena.mul(m, b_beta);
        let one = arena.one();
        let denominator = arena.sub(one, mbb);
        let normal = arena.div(numerator, denominator)?;
        let omega_dot: [ExprId; 3] = std::array::from_fn(|j| {
            let t = arena.mul(normal, beta[j]);
            arena.add(alpha[j], t)
        });
        let force: [ExprId; 3] = std::array::from_fn(|j| {
            let t = arena.mul(normal, e[j]);
            arena.add(f0[j], t)
        });
        self.equations(arena, k, &omega_dot, &force, &v)
    }

    /// A phase's right-hand side and outputs from its ω̇, its contact force F and its
    /// centre-of-mass velocity v (body axes).
    fn equations(
        &self,
        arena: &mut Arena,
        k: &Kinematics,
        omega_dot: &[ExprId; 3],
        force: &[ExprId; 3],
        v: &[ExprId; 3],
    ) -> Result<ContactEquations, ContactError> {
        let m = self.mass;
        let f_space = mat_vec(arena, &k.rotation, force);
        let inv_m = arena.recip(m)?;
        let q_dot = quaternion_rate(arena, k.q, k.omega);
        let v_space = mat_vec(arena, &k.rotation, v);
        let mut rhs = [arena.zero(); STATE_LEN];
        rhs[0] = v_space[0];
        rhs[1] = v_space[1];
        rhs[2] = arena.mul(inv_m, f_space[0]);
        rhs[3] = arena.mul(inv_m, f_space[1]);
        rhs[4..8].copy_from_slice(&q_dot);
        rhs[8..].copy_from_slice(omega_dot);
        let half = arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE));
        let v2 = dot(arena, v, v);
        let two_t = dot(arena, &k.omega, &k.i_omega);
        let kinetic = arena.mul(m, v2);
        let kinetic = arena.add(kinetic, two_t);
        let kinetic = arena.mul(half, kinetic);
        let potential = arena.product(&[m, self.gravity, k.height]);
        let energy = arena.add(kinetic, potential);
        let linear_momentum = v_space.map(|c| arena.mul(m, c));
        let r_v = cross(arena, &k.r, v);
        let k_body: [ExprId; 3] = std::array::from_fn(|j| {
            let t = arena.mul(m, r_v[j]);
            arena.sub(k.i_omega[j], t)
        });
        let angular_momentum_contact = mat_vec(arena, &k.rotation, &k_body);
        Ok(ContactEquations {
            rhs,
            normal: f_space[2],
            friction: [f_space[0], f_space[1], arena.zero()],
            energy,
            linear_momentum,
            angular_momentum_contact,
        })
    }
}

/// x = A⁻¹ b by the adjugate: one division by det A, shared.
fn solve3(
    arena: &mut Arena,
    a: &[Vec<ExprId>],
    b: &[ExprId; 3],
) -> Result<[ExprId; 3], ContactError> {
    let det = determinant(arena, a);
    let inv_det = arena.recip(det)?;
    let mut out = [arena.zero(); 3];
    for (i, o) in out.iter_mut().enumerate() {
        // adj(A)ᵢⱼ = cofactor(j, i).
        let terms: Vec<ExprId> = (0..3)
            .map(|j| {
                let c = crate::sym::mat3::cofactor(arena, a, j, i);
                arena.mul(c, b[j])
            })
            .collect();
        let s = arena.sum(&terms);
        *o = arena.mul(s, inv_det);
    }
    Ok(out)
}

/// I⁻¹ by the adjugate.
fn inverse3(arena: &mut Arena, m: &Mat3) -> Result<Mat3, ContactError> {
    let rows: Vec<Vec<ExprId>> = m.iter().map(|r| r.to_vec()).collect();
    let det = determinant(arena, &rows);
    let inv_det = arena.recip(det)?;
    let mut out = [[arena.zero(); 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            let c = crate::sym::mat3::cofactor(arena, &rows, j, i);
            *e = arena.mul(c, inv_det);
        }
    }
    Ok(out)
}
