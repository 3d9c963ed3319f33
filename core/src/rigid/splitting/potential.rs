//! A rigid body under a potential as a splitting: free flow plus kicks m ← m + h G(q), with G
//! the body torque of the potential.

use nalgebra::{UnitQuaternion, Vector3};

use super::free::{FreeBodySplitting, check_step};
use crate::exact::{array, free_body_flow_attitude};
use crate::ode::{OdeError, check_inertia};
use crate::rigid::state::{BodyMomentum, check_momentum, momentum_is_finite};

/// A potential on the attitude for the kick steps.
pub trait Potential {
    /// Potential energy V(q).
    fn energy(&self, q: &UnitQuaternion<f64>) -> f64;
    /// Body-frame torque G(q) = −(dV) expressed as a body vector.
    fn torque(&self, q: &UnitQuaternion<f64>) -> Vector3<f64>;
    /// Checks the potential's parameters before a splitting steps with it (default: none to
    /// check).
    ///
    /// # Errors
    /// [`OdeError::InvalidParameter`] naming the offending parameter.
    fn check(&self) -> Result<(), OdeError> {
        Ok(())
    }
}

/// Uniform gravity on a body pivoted at the space origin: V = M g (R c)·ẑ,
/// G = c × (Rᵀ(−M g ẑ)), with c the centre of mass in body axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gravity {
    /// M g (weight).
    pub weight: f64,
    /// Centre of mass in body (principal) axes, from the pivot.
    pub c: Vector3<f64>,
}

impl Potential for Gravity {
    fn energy(&self, q: &UnitQuaternion<f64>) -> f64 {
        self.weight * (q * self.c).z
    }
    fn torque(&self, q: &UnitQuaternion<f64>) -> Vector3<f64> {
        let down = q.inverse() * Vector3::new(0.0, 0.0, -self.weight);
        self.c.cross(&down)
    }
    /// The weight and the lever must be finite.
    fn check(&self) -> Result<(), OdeError> {
        let named = [
            ("weight", self.weight),
            ("c.x", self.c.x),
            ("c.y", self.c.y),
            ("c.z", self.c.z),
        ];
        match named.into_iter().find(|(_, v)| !v.is_finite()) {
            Some((name, value)) => Err(OdeError::InvalidParameter { name, value }),
            None => Ok(()),
        }
    }
}

/// A free-body flow usable as the kinetic part of a splitting.
pub trait FreeFlow {
    /// Principal moments.
    fn inertia(&self) -> Vector3<f64>;
    /// Advances (q, m) by the free motion over `h`.
    ///
    /// # Errors
    /// [`OdeError::Exact`] if an exact flow cannot be evaluated (a non-finite state).
    fn flow(&self, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError>;
}

impl FreeFlow for FreeBodySplitting {
    fn inertia(&self) -> Vector3<f64> {
        FreeBodySplitting::inertia(self)
    }
    fn flow(&self, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        // The splitting that calls this checks h and the state around it.
        self.step_unchecked(y, h);
        Ok(())
    }
}

/// The exact free-body flow (elliptic functions and the third-kind integral) as the
/// kinetic part of a splitting: no error from the free motion at any step size, leaving only
/// the kick-splitting error (for a symmetric body the axis splitting is already exact).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactFreeFlow {
    inertia: [f64; 3],
}

impl ExactFreeFlow {
    /// The exact flow for principal moments `inertia`.
    ///
    /// # Errors
    /// [`OdeError::InvalidInertia`].
    pub fn new(inertia: impl Into<Vector3<f64>>) -> Result<Self, OdeError> {
        let inertia = array(inertia);
        check_inertia(1.0, inertia)?;
        Ok(Self { inertia })
    }
}

impl FreeFlow for ExactFreeFlow {
    fn inertia(&self) -> Vector3<f64> {
        self.inertia.into()
    }
    fn flow(&self, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        let (q, m) = free_body_flow_attitude(self.inertia, y.q, y.m, h)?;
        y.q = q;
        y.m = m;
        Ok(())
    }
}

/// Strang splitting of a body under a potential: kick(h/2) ∘ free(h) ∘ kick(h/2)
/// (order 2, symplectic, energy error bounded), with the free flow `F` either
/// [`FreeBodySplitting`] or [`ExactFreeFlow`].
///
/// ```
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::rigid::{BodyMomentum, ExactFreeFlow, Gravity, PotentialSplitting};
/// // A top (I₁ = I₂ = 1, I₃ = 0.5 about the pivot, Mgl = 1) spinning at ω₃ = 50 from 60°.
/// let top = PotentialSplitting {
///     free: ExactFreeFlow::new([1.0, 1.0, 0.5])?,
///     potential: Gravity { weight: 1.0, c: Vector3::new(0.0, 0.0, 1.0) },
/// };
/// let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 60f64.to_radians());
/// let mut y = BodyMomentum { q, m: Vector3::new(0.0, 0.0, 25.0) };
/// let e0 = top.energy(&y);
/// top.run(&mut y, 0.01, 1000)?;
/// approx::assert_relative_eq!(top.energy(&y), e0, max_relative = 1e-6);
/// # Ok::<(), precess_core::ode::OdeError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PotentialSplitting<P, F = FreeBodySplitting> {
    /// The free-body part (moments about the pivot).
    pub free: F,
    /// The potential.
    pub potential: P,
}

impl<P: Potential, F: FreeFlow> PotentialSplitting<P, F> {
    /// Total energy T + V.
    pub fn energy(&self, y: &BodyMomentum) -> f64 {
        let i = self.free.inertia();
        0.5 * (y.m.x * y.m.x / i[0] + y.m.y * y.m.y / i[1] + y.m.z * y.m.z / i[2])
            + self.potential.energy(&y.q)
    }

    /// One step of size h.
    ///
    /// # Errors
    /// As [`Self::run`] for one step.
    pub fn step(&self, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        self.run(y, h, 1)
    }

    /// `n` steps of size `h`.
    ///
    /// # Errors
    /// Before any work: [`OdeError::InvalidStep`] for h ≤ 0 or non-finite,
    /// [`OdeError::NonFiniteInitialState`] or [`OdeError::NotUnitQuaternion`] for a bad `y`,
    /// [`OdeError::InvalidParameter`] from [`Potential::check`] (a NaN weight). While
    /// stepping: [`OdeError::NonFiniteState`] at the first step whose kick or free flow is not
    /// finite (an overflowing weight; t = i·h from the start of the call), or the free flow's
    /// error; `y` is then left at the last finite state.
    pub fn run(&self, y: &mut BodyMomentum, h: f64, n: u64) -> Result<(), OdeError> {
        check_step(h)?;
        check_momentum(y)?;
        self.potential.check()?;
        for i in 0..n {
            let t = i as f64 * h;
            let mut z = *y;
            // Each stage is checked before the next uses it, so the error names the stage's
            // start rather than a non-finite argument of the exact flow downstream.
            self.kick(&mut z, 0.5 * h, t)?;
            self.free.flow(&mut z, h)?;
            if !momentum_is_finite(&z) {
                return Err(OdeError::NonFiniteState { t });
            }
            self.kick(&mut z, 0.5 * h, t)?;
            *y = z;
        }
        Ok(())
    }

    /// m ← m + τ G(q); `t` names the step in the error.
    fn kick(&self, y: &mut BodyMomentum, tau: f64, t: f64) -> Result<(), OdeError> {
        y.m += tau * self.potential.torque(&y.q);
        if y.m.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(OdeError::NonFiniteState { t })
        }
    }
}
