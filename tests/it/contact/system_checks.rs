//! A body on a table as an `ode::System`: every stepper over it runs the body's parameter
//! checks before its first step, as for the other scenes, and a contact error becomes the
//! ODE layer's refusal naming the quantity and carrying its value.
//!
//! `ContactSystem::new` checks the body itself, so the system's own `check_parameters` is
//! reached by a system whose body was swapped after it was built (its `body` field is
//! public): without the forwarding, the steppers would start on a body of negative mass.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactError, ContactSystem, Phase, STATE_LEN};
use precess::ode::{AdaptiveConfig, Dop853, FixedStepConfig, OdeError, Rk4, Run, System};
use precess::prelude::*;

/// A marble of mass m (a field, so nothing refuses a bad one at compile time).
#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = 0.01))]
#[contact(surface = sphere(radius = 0.01), law = rolling, gravity = 9.81)]
struct Marble {
    m: f64,
}

const GOOD: Marble = Marble { m: 0.02 };
const BAD: Marble = Marble { m: -1.0 };

/// A marble rolling along x at 0.1 m/s.
fn rolling() -> [f64; STATE_LEN] {
    GOOD.rolling_state(
        [0.0, 0.0],
        &UnitQuaternion::identity(),
        &Vector3::new(0.0, 10.0, 0.0),
    )
    .expect("a placeable rolling state")
}

/// The refusal: the marble's mass, −1, named as a mass.
fn is_negative_mass(e: &OdeError) -> bool {
    matches!(
        e,
        OdeError::InvalidSystemParameter { quantity, value, .. }
            if quantity.ends_with("mass") && *value == -1.0
    )
}

/// A system built on the good marble, then pointed at the bad one.
fn swapped() -> ContactSystem<'static, Marble> {
    let mut sys = ContactSystem::new(&GOOD, Phase::Rolling).expect("a physical marble");
    sys.body = &BAD;
    sys
}

#[test]
fn the_system_forwards_the_bodys_parameter_checks() {
    assert_eq!(GOOD.check_parameters(), Ok(()));
    assert!(
        swapped()
            .check_parameters()
            .is_err_and(|e| is_negative_mass(&e))
    );
    // The good marble's system passes the same hook.
    let sys = ContactSystem::new(&GOOD, Phase::Rolling).expect("a physical marble");
    assert_eq!(System::<STATE_LEN>::check_parameters(&sys), Ok(()));
}

#[test]
fn every_stepper_refuses_a_run_over_an_unphysical_body() {
    let y0 = rolling();
    let dop = Dop853::new(swapped(), 0.0, y0, AdaptiveConfig::default()).map(|_| ());
    assert!(dop.as_ref().is_err_and(is_negative_mass), "{dop:?}");
    let rk4 = Rk4::new(swapped(), 0.0, y0, FixedStepConfig::with_step(1e-3)).map(|_| ());
    assert!(rk4.as_ref().is_err_and(is_negative_mass), "{rk4:?}");
    // The good marble runs: 1 s at 0.1 m/s rolls it 0.1 m along x (v = ω × (R ẑ)).
    let sys = ContactSystem::new(&GOOD, Phase::Rolling).expect("a physical marble");
    let mut dop = Dop853::new(sys, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12))
        .expect("a physical marble starts");
    let out = Run::new(&mut dop, 1.0)
        .sample_none()
        .integrate()
        .expect("the run reaches t = 1");
    assert_eq!(out.t, 1.0);
    assert!((out.state[0] - 0.1).abs() < 1e-12, "{:?}", out.state);
}

#[test]
fn a_contact_error_becomes_the_ode_refusal_naming_its_quantity() {
    let e = ContactError::NegativeCoefficient {
        name: "mu",
        value: -0.25,
    };
    let message = e.to_string();
    assert_eq!(
        e.into_ode_error(),
        OdeError::InvalidSystemParameter {
            quantity: "mu".to_owned(),
            value: -0.25,
            message,
        }
    );
    // A stepper's own error passes through unchanged.
    let ode = OdeError::NonFiniteTime { t: f64::INFINITY };
    assert_eq!(ContactError::Ode(ode.clone()).into_ode_error(), ode);
}
