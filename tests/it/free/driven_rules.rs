//! The driven-rotor rules at run time, as the interpreted model meets them: the body's
//! inertia I − Σ J â âᵀ left once the wheels turn freely must be positive definite beyond
//! rounding, the same rule (`precess::rigid::first_singular_driven`) the derived bodies and
//! tops apply.

use precess::free::{DrivenRotor, FreeError, FreeModel, FreeScene, FreeState};
use precess::ode::{AdaptiveConfig, Dop853, OdeError};
use precess::sym::Arena;

/// A run-time body of principal moments (1, 2, 3) with one driven wheel of axial moment `j`
/// on its 3-axis, interpreted.
fn wheel_on_axis_3(j: f64) -> FreeModel {
    let mut ar = Arena::new();
    let (m, i) = (ar.integer(1), [ar.integer(1), ar.integer(2), ar.integer(3)]);
    let mut scene = FreeScene::new(&mut ar, m, i);
    let (z, o, inertia) = (ar.zero(), ar.one(), ar.parameter("J"));
    scene.driven.push(DrivenRotor {
        axis: [z, z, o],
        inertia,
        torque: z,
    });
    let d = scene.derive(&mut ar).unwrap();
    FreeModel::new(&mut ar, &d, &[("J", j)]).unwrap()
}

/// J = I₃(1 − 10⁻¹⁵) leaves the body 3·10⁻¹⁵ kg m² about its 3-axis, a few ulps of I₃ whose
/// sign and size are rounding's: the model refuses it as the driven rotor's error (it passed
/// the model's check, which asked only for a moment above zero, and a run would divide by
/// the rounding), and the integrators refuse to start. A J that leaves a real moment
/// (10⁻⁶ of I₃) passes.
#[test]
fn the_run_time_model_refuses_a_driven_inertia_singular_to_rounding() {
    let i3 = 3.0;
    let model = wheel_on_axis_3(i3 * (1.0 - 1e-15));
    match model.check_driven() {
        Err(FreeError::DrivenInertia { rotor: 0, smallest }) => {
            assert!(smallest.abs() < 1e-14, "{smallest}");
        }
        other => panic!("expected DrivenInertia, got {other:?}"),
    }
    let y0: [f64; 14] = {
        let mut y = [0.0; 14];
        y[..13].copy_from_slice(&FreeState::at_rest().to_array());
        y
    };
    let refused = Dop853::new(&model, 0.0, y0, AdaptiveConfig::default());
    assert!(
        matches!(
            refused.err(),
            Some(OdeError::InvalidSystemParameter { ref quantity, .. }) if quantity == "rotor inertia"
        ),
        "the integrator started"
    );
    assert_eq!(wheel_on_axis_3(i3 * (1.0 - 1e-6)).check_driven(), Ok(()));
}
