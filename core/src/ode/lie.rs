//! Lie-group integration on SO(3) × ℝᵏ: the Runge–Kutta–Munthe-Kaas method of order 4.
//!
//! The state is advanced as y = y₀ · exp(Θ) with Θ̇ = dexp⁻¹₋Θ(ξ(y)) solved by classical
//! RK4 in the algebra, so every stage and the result stay on the group: |q| = 1 up to one
//! rounding per step, whatever the step size.

use nalgebra::Vector3;

use super::attitude::{
    Attitude, AttitudeModel, RigidBodyModel, RigidState, check_attitude, check_model_inertia,
    check_rigid, euler_rates, rotate_body,
};
use super::error::{OdeError, check_span};
use super::rk4::equal_steps;
use super::system::Stats;

/// An element of the algebra so(3) × ℝᵏ: a rotation part plus a vector part.
pub trait Tangent: Copy {
    /// The zero element.
    fn zero() -> Self;
    /// self += a · x.
    fn axpy(&mut self, a: f64, x: &Self);
    /// The so(3) part as a body rotation vector.
    fn rot(&self) -> Vector3<f64>;
    /// Replaces the so(3) part.
    fn set_rot(&mut self, r: Vector3<f64>);
}

/// A state on SO(3) × ℝᵏ acted on by its algebra through y · exp(u).
pub trait LieState: Copy {
    /// The algebra.
    type Tangent: Tangent;
    /// y · exp(u): the rotation part by the exponential map, the vector part by addition.
    fn exp_act(&self, u: &Self::Tangent) -> Self;
    /// Checks the initial data.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteInitialState`].
    fn check(&self) -> Result<(), OdeError>;
}

/// A vector field on a [`LieState`]: ξ(t, y) with ẏ = y · ξ.
pub trait LieSystem<Y: LieState> {
    /// The generator at (t, y).
    fn xi(&self, t: f64, y: &Y) -> Y::Tangent;
    /// Checks the model's parameters (inertia, mass).
    ///
    /// # Errors
    /// [`OdeError::InvalidInertia`].
    fn check(&self) -> Result<(), OdeError>;
}

/// dexp⁻¹₋ᵤ(v) on so(3) ≅ ℝ³: v + ½ u × v + c(θ) u × (u × v),
/// c(θ) = (1 − (θ/2) cot(θ/2))/θ², θ = |u|.
pub fn dexpinv_right(u: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
    let th2 = u.norm_squared();
    let c = if th2 < 1e-6 {
        1.0 / 12.0 + th2 / 720.0
    } else {
        let th = th2.sqrt();
        (1.0 - 0.5 * th / (0.5 * th).tan()) / th2
    };
    let uv = u.cross(v);
    v + 0.5 * uv + c * u.cross(&uv)
}

/// Algebra of [`Attitude`]: (body rotation, ω̇).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AttitudeTangent {
    /// Rotation part (body axes).
    pub rot: Vector3<f64>,
    /// Rate of ω.
    pub domega: Vector3<f64>,
}

impl Tangent for AttitudeTangent {
    fn zero() -> Self {
        Self {
            rot: Vector3::zeros(),
            domega: Vector3::zeros(),
        }
    }
    fn axpy(&mut self, a: f64, x: &Self) {
        self.rot += a * x.rot;
        self.domega += a * x.domega;
    }
    fn rot(&self) -> Vector3<f64> {
        self.rot
    }
    fn set_rot(&mut self, r: Vector3<f64>) {
        self.rot = r;
    }
}

impl LieState for Attitude {
    type Tangent = AttitudeTangent;
    fn exp_act(&self, u: &AttitudeTangent) -> Self {
        Attitude {
            q: rotate_body(&self.q, &u.rot),
            omega: self.omega + u.domega,
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_attitude(self)
    }
}

impl<M: AttitudeModel> LieSystem<Attitude> for M {
    fn xi(&self, t: f64, y: &Attitude) -> AttitudeTangent {
        AttitudeTangent {
            rot: y.omega,
            domega: euler_rates(self.inertia(), &y.omega, &self.torque(t, y)),
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_model_inertia(1.0, self.inertia())
    }
}

/// Algebra of [`RigidState`]: (ẋ, v̇, body rotation, ω̇).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidTangent {
    /// Rate of the centre of mass.
    pub dx: Vector3<f64>,
    /// Acceleration of the centre of mass.
    pub dv: Vector3<f64>,
    /// Rotation part (body axes).
    pub rot: Vector3<f64>,
    /// Rate of ω.
    pub domega: Vector3<f64>,
}

impl Tangent for RigidTangent {
    fn zero() -> Self {
        Self {
            dx: Vector3::zeros(),
            dv: Vector3::zeros(),
            rot: Vector3::zeros(),
            domega: Vector3::zeros(),
        }
    }
    fn axpy(&mut self, a: f64, x: &Self) {
        self.dx += a * x.dx;
        self.dv += a * x.dv;
        self.rot += a * x.rot;
        self.domega += a * x.domega;
    }
    fn rot(&self) -> Vector3<f64> {
        self.rot
    }
    fn set_rot(&mut self, r: Vector3<f64>) {
        self.rot = r;
    }
}

impl LieState for RigidState {
    type Tangent = RigidTangent;
    fn exp_act(&self, u: &RigidTangent) -> Self {
        RigidState {
            x: self.x + u.dx,
            v: self.v + u.dv,
            q: rotate_body(&self.q, &u.rot),
            omega: self.omega + u.domega,
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_rigid(self)
    }
}

impl<M: RigidBodyModel> LieSystem<RigidState> for M {
    fn xi(&self, t: f64, y: &RigidState) -> RigidTangent {
        RigidTangent {
            dx: y.v,
            dv: self.force(t, y) / self.mass(),
            rot: y.omega,
            domega: euler_rates(self.inertia(), &y.omega, &self.torque(t, y)),
        }
    }
    fn check(&self) -> Result<(), OdeError> {
        check_model_inertia(self.mass(), self.inertia())
    }
}

/// Settings of [`Rkmk4`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rkmk4Config {
    /// Largest step (default 1e-2); intervals are cut into equal steps so stops are exact.
    pub h: f64,
}

impl Default for Rkmk4Config {
    fn default() -> Self {
        Self { h: 1e-2 }
    }
}

/// Runge–Kutta–Munthe-Kaas of order 4 (RK4 in the algebra with the exact dexp⁻¹ on so(3)).
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::ode::attitude::{Attitude, AttitudeModel};
/// use precess_core::ode::lie::{Rkmk4, Rkmk4Config};
/// struct Sym;
/// impl AttitudeModel for Sym {
///     fn inertia(&self) -> [f64; 3] { [1.0, 1.0, 1.0] }
/// }
/// // A sphere spins uniformly: after t = π about z, q = (0, 0, 0, 1).
/// let s0 = Attitude { q: UnitQuaternion::identity(), omega: Vector3::new(0.0, 0.0, 1.0) };
/// let mut m = Rkmk4::new(Sym, 0.0, s0, Rkmk4Config { h: 0.1 })?;
/// m.advance_to(std::f64::consts::PI)?;
/// approx::assert_relative_eq!(m.state().q.k, 1.0, epsilon = 1e-14);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Rkmk4<S, Y> {
    sys: S,
    h: f64,
    t: f64,
    y: Y,
    stats: Stats,
}

impl<Y: LieState, S: LieSystem<Y>> Rkmk4<S, Y> {
    /// Starts at (t0, y0).
    ///
    /// # Errors
    /// [`OdeError::InvalidStep`], [`OdeError::InvalidInertia`], non-finite t0 or y0.
    pub fn new(sys: S, t0: f64, y0: Y, cfg: Rkmk4Config) -> Result<Self, OdeError> {
        if !(cfg.h.is_finite() && cfg.h > 0.0) {
            return Err(OdeError::InvalidStep { h: cfg.h });
        }
        check_span(t0, t0)?;
        sys.check()?;
        y0.check()?;
        Ok(Self {
            sys,
            h: cfg.h,
            t: t0,
            y: y0,
            stats: Stats::default(),
        })
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> &Y {
        &self.y
    }

    /// Work done so far (`rhs_evals` counts evaluations of ξ).
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// One RKMK4 step of size h, stage times capped at `t_hi` (see [`super::Rk4`]).
    fn step(&mut self, h: f64, t_hi: f64) {
        let (t, y0) = (self.t, self.y);
        let stage = |u: &Y::Tangent, tt: f64| {
            let mut k = self.sys.xi(tt, &y0.exp_act(u));
            k.set_rot(dexpinv_right(&u.rot(), &k.rot()));
            k
        };
        let k1 = self.sys.xi(t, &y0);
        let mut u = Y::Tangent::zero();
        u.axpy(0.5 * h, &k1);
        let k2 = stage(&u, (t + 0.5 * h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(0.5 * h, &k2);
        let k3 = stage(&u, (t + 0.5 * h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(h, &k3);
        let k4 = stage(&u, (t + h).min(t_hi));
        let mut u = Y::Tangent::zero();
        u.axpy(h / 6.0, &k1);
        u.axpy(h / 3.0, &k2);
        u.axpy(h / 3.0, &k3);
        u.axpy(h / 6.0, &k4);
        self.y = y0.exp_act(&u);
        self.stats.steps += 1;
        self.stats.rhs_evals += 4;
    }

    /// Advances to exactly `t_stop` in equal steps no longer than the configured h.
    ///
    /// # Errors
    /// [`OdeError::StopBeforeCurrent`], [`OdeError::NonFiniteTime`],
    /// [`OdeError::MaxStepsExceeded`] before any work; [`OdeError::NonFiniteState`] if the
    /// state blew up.
    pub fn advance_to(&mut self, t_stop: f64) -> Result<(), OdeError> {
        let Some((n, h)) = equal_steps(self.t, t_stop, self.h)? else {
            return Ok(());
        };
        let t0 = self.t;
        for i in 1..=n {
            self.step(h, t_stop.next_down());
            self.t = t0 + i as f64 * h;
        }
        self.t = t_stop;
        if self.y.check().is_err() {
            return Err(OdeError::NonFiniteState { t: t0 });
        }
        Ok(())
    }
}
