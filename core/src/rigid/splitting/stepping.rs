//! The splittings as fixed-step methods, so that a [`FixedStepper`](crate::ode::FixedStepper)
//! runs them with trajectories, observers and events; and their state as CSV columns.
//!
//! Inside a step the solution is the splitting's own partial step from the step's start: a
//! splitting of order p gives events accurate to O(hᵖ), like its steps.
//!
//! ```
//! use approx::assert_relative_eq;
//! use nalgebra::{UnitQuaternion, Vector3};
//! use precess_core::ode::{Event, FixedStepConfig, FixedStepper, Run};
//! use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
//! // A symmetric body (I1 = I2 = 1, I3 = 2): m turns about the body axis 3 at
//! // (1/I3 − 1/I1) m3 = −0.5 rad/s, and the axis splitting is exact for it.
//! let split = FreeBodySplitting::new([1.0, 1.0, 2.0], SplittingOrder::Two)?;
//! let y0 = BodyMomentum { q: UnitQuaternion::identity(), m: Vector3::new(1.0, 0.0, 1.0) };
//! let mut s = FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(0.1))?;
//! // m2 = sin(0.5 t) starts rising through 0 and falls through 0 at t = 2π.
//! let out = Run::new(&mut s, 7.0)
//!     .event(Event::new("m2 falls").falling(), |_t, y| y.m.y)
//!     .integrate()?;
//! assert_relative_eq!(out.events[0].t, std::f64::consts::TAU, max_relative = 1e-14);
//! # Ok::<(), precess_core::ode::OdeError>(())
//! ```

use super::free::FreeBodySplitting;
use super::potential::{FreeFlow, Potential, PotentialSplitting};
use crate::ode::{FixedStepMethod, OdeError, StateColumns};
use crate::rigid::state::{BodyMomentum, check_momentum};

impl FixedStepMethod for FreeBodySplitting {
    type State = BodyMomentum;

    fn check_state(&self, y: &BodyMomentum) -> Result<(), OdeError> {
        check_momentum(y)
    }

    fn advance(&self, _t: f64, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        self.step(y, h)
    }
}

impl<P: Potential, F: FreeFlow> FixedStepMethod for PotentialSplitting<P, F> {
    type State = BodyMomentum;

    fn check_state(&self, y: &BodyMomentum) -> Result<(), OdeError> {
        check_momentum(y)?;
        self.potential.check()
    }

    fn advance(&self, _t: f64, y: &mut BodyMomentum, h: f64) -> Result<(), OdeError> {
        self.step(y, h)
    }
}

/// Columns `q_w, q_x, q_y, q_z` (the attitude quaternion, body to space) and `m_1, m_2, m_3`
/// (the body angular momentum).
impl StateColumns for BodyMomentum {
    fn column_count() -> usize {
        7
    }

    fn column_name(i: usize) -> String {
        ["q_w", "q_x", "q_y", "q_z", "m_1", "m_2", "m_3"]
            .get(i)
            .map_or_else(String::new, |s| (*s).to_string())
    }

    fn column(&self, i: usize) -> f64 {
        let q = self.q.quaternion();
        match i {
            0 => q.w,
            1 => q.i,
            2 => q.j,
            3 => q.k,
            4..=6 => self.m[i - 4],
            _ => f64::NAN,
        }
    }
}
