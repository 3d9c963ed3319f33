//! Item 5 at run time: bad states and parameters are typed errors naming the quantity.

use precess::codegen::BindingError;
use precess::free::{
    FreeDynamics, FreeError, FreeExact, FreeFlight, FreeModel, FreeScene, FreeState, FreeSystem,
};
use precess::ode::{AdaptiveConfig, OdeError};
use precess::prelude::*;
use precess::sym::Arena;

#[derive(Debug, RigidBody)]
#[rigid(sphere(mass = m, radius = 0.1))]
#[free(gravity = 9.81, drag = c)]
struct Ball {
    m: f64,
    c: f64,
}

#[test]
fn a_zero_or_non_finite_quaternion_is_refused_by_name() {
    let mut y = FreeState::at_rest().to_array();
    y[6..10].copy_from_slice(&[0.0; 4]);
    assert!(matches!(
        FreeState::from_array(&y),
        Err(FreeError::ZeroQuaternion { .. })
    ));
    y[6] = f64::NAN;
    assert!(matches!(
        FreeState::from_array(&y),
        Err(FreeError::NonFinite {
            quantity: "attitude quaternion",
            ..
        })
    ));
    // A tiny quaternion still names its attitude.
    y[6..10].copy_from_slice(&[1e-300, 0.0, 0.0, 0.0]);
    assert_eq!(
        FreeState::from_array(&y).unwrap().attitude,
        UnitQuaternion::identity()
    );
}

#[test]
fn a_non_finite_state_is_refused_by_part() {
    let mut y = FreeState::at_rest().to_array();
    y[4] = f64::INFINITY;
    let e = FreeState::from_array(&y).unwrap_err();
    assert!(
        matches!(
            e,
            FreeError::NonFinite {
                quantity: "velocity",
                ..
            }
        ),
        "{e}"
    );
    let s = FreeState {
        omega_principal: Vector3::new(0.0, f64::NAN, 0.0),
        ..FreeState::at_rest()
    };
    let ball = Ball { m: 1.0, c: 0.1 };
    let e = FreeFlight::new(FreeSystem(&ball), 0.0, &s, AdaptiveConfig::default()).unwrap_err();
    assert!(e.to_string().contains("ω"), "{e}");
}

#[test]
fn a_non_finite_field_is_named() {
    let ball = Ball {
        m: 1.0,
        c: f64::NAN,
    };
    let e = ball.check_parameters().unwrap_err();
    assert!(
        matches!(&e, FreeError::NonFiniteParameter { name, .. } if name == "c"),
        "{e}"
    );
    // Integrating it fails at the start, naming the field, rather than computing NaN (the
    // integrator's parameter hook; before it, the first f came out NaN: NonFiniteState).
    let e = FreeFlight::new(
        FreeSystem(&ball),
        0.0,
        &FreeState::at_rest(),
        AdaptiveConfig::default(),
    );
    assert!(
        matches!(
            &e,
            Err(FreeError::Ode(OdeError::InvalidSystemParameter { quantity, value, .. }))
                if quantity == "c" && value.is_nan()
        ),
        "{e:?}"
    );
    // A negative mass breaks the body's rules.
    let e = Ball { m: -1.0, c: 0.1 }.check_parameters().unwrap_err();
    assert!(matches!(e, FreeError::Body(_)), "{e}");
    // A field drag meets the rule a literal meets at compile time (tests/ui/free_negative_drag).
    let e = Ball { m: 1.0, c: -0.1 }.check_parameters().unwrap_err();
    assert!(
        matches!(e, FreeError::NegativeCoefficient { name: "drag", value } if value == -0.1),
        "{e}"
    );
    assert!(Ball { m: 1.0, c: 0.0 }.check_parameters().is_ok());
}

#[test]
fn the_exact_flow_is_refused_under_other_forces() {
    let ball = Ball { m: 1.0, c: 0.1 };
    let e = ball.exact(0.0, &FreeState::at_rest()).unwrap_err();
    assert_eq!(e, FreeError::NotExact { declared: "drag" });
    let bad = FreeExact::new(
        &Vector3::new(1.0, -1.0, 1.0),
        &Vector3::zeros(),
        0.0,
        &FreeState::at_rest(),
    );
    assert!(matches!(bad, Err(FreeError::InvalidInertia { .. })));
}

#[test]
fn the_interpreted_model_names_its_parameters() {
    let mut a = Arena::new();
    let (m, i) = (a.parameter("M"), a.parameter("I"));
    let mut scene = FreeScene::new(&mut a, m, [i, i, i]);
    scene.drag = Some(a.parameter("c"));
    let d = scene.derive(&mut a).unwrap();
    let e = FreeModel::new(&mut a, &d, &[("M", 1.0), ("I", 1.0)]).unwrap_err();
    assert!(
        matches!(&e, FreeError::Binding(BindingError::UnsetParameter { name, .. }) if name == "c"),
        "{e}"
    );
    let e = FreeModel::new(
        &mut a,
        &d,
        &[("M", 1.0), ("I", 1.0), ("c", 0.1), ("k", 2.0)],
    )
    .unwrap_err();
    assert!(
        matches!(&e, FreeError::Binding(BindingError::UnknownParameter { name, .. }) if name == "k"),
        "{e}"
    );
    let e = FreeModel::new(&mut a, &d, &[("M", 1.0), ("I", f64::NAN), ("c", 0.1)]).unwrap_err();
    assert!(
        matches!(&e, FreeError::Binding(BindingError::NonFinite { name, .. }) if name == "I"),
        "{e}"
    );
    // A zero mass has no equations.
    let z = a.zero();
    let e = FreeScene::new(&mut a, z, [i, i, i])
        .derive(&mut a)
        .unwrap_err();
    assert_eq!(e, FreeError::ZeroInertia { quantity: "mass" });
}

/// `max_steps` bounds each call of `advance_to`, as it bounds each run of the other drivers:
/// a flight advanced in many short legs never exhausts it, and one call that needs more
/// still fails by name.
#[test]
fn the_step_budget_of_a_flight_is_per_call() {
    let ball = Ball { m: 1.0, c: 0.1 };
    let start = FreeState {
        omega_principal: Vector3::new(0.0, 0.0, 5.0),
        ..FreeState::at_rest()
    };
    let cfg = AdaptiveConfig {
        max_steps: 20,
        ..AdaptiveConfig::default()
    };
    let mut flight = FreeFlight::new(FreeSystem(&ball), 0.0, &start, cfg).unwrap();
    for leg in 1..=100 {
        flight.advance_to(f64::from(leg) * 0.05).unwrap();
    }
    let done = flight.stats();
    assert!(done.steps + done.rejections > 20, "{done:?}");
    let e = flight.advance_to(1e6).unwrap_err();
    assert!(
        matches!(
            e,
            FreeError::Ode(OdeError::MaxStepsExceeded { max_steps: 20, .. })
        ),
        "{e}"
    );
}

/// A driven wheel whose J is the body's moment about its axis to 10⁻¹⁵: I − J â âᵀ keeps
/// 10⁻¹⁵ I₃ there, rounding's size, and is refused as the driven rotor's error (it passed,
/// and a run failed later with a non-finite state). One whose J leaves a real moment (10⁻⁶
/// of I₃) passes; the top's check is the same rule.
#[test]
fn a_driven_inertia_singular_to_rounding_is_refused() {
    let i3 = 0.02;
    let inertia = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(0.05, 0.05, i3));
    let wheel = |j: f64| [(0usize, [0.0, 0.0, 1.0], j)];
    let j = i3 * (1.0 - 1e-15);
    assert!(matches!(
        FreeError::check_driven_inertia(&inertia, &wheel(j)),
        Err(FreeError::DrivenInertia { rotor: 0, smallest }) if smallest.abs() < 1e-16
    ));
    assert!(matches!(
        precess::top::TopError::check_driven_inertia(&inertia, &wheel(j)),
        Err(precess::top::TopError::DrivenInertia { rotor: 0, .. })
    ));
    assert_eq!(
        FreeError::check_driven_inertia(&inertia, &wheel(i3 * (1.0 - 1e-6))),
        Ok(())
    );
}
