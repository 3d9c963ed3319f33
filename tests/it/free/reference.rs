//! Item 4(e): the published references that apply to a free body, through the run-time
//! scene (the GNI body, I = (2, 1, 2/3), breaks the triangle inequality, so the derive
//! refuses it as a description; the scene takes its moments directly).

use approx::assert_relative_eq;
use precess::free::{FreeFlight, FreeModel, FreeScene, FreeState};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;
use precess::sym::Arena;
use precess_testkit::systems::{GNI_I, GNI_M1, GNI_M10};

#[test]
fn the_gni_body_through_the_scene_matches_its_thirty_digit_values() {
    let mut a = Arena::new();
    let m = a.parameter("M");
    let moments = GNI_I.map(|i| a.float(i).unwrap());
    let mut scene = FreeScene::new(&mut a, m, moments);
    // A throw under gravity does not touch the rotation about the centre of mass.
    let g = a.parameter("g");
    let z = a.zero();
    let down = a.neg(g);
    scene.gravity = Some([z, z, down]);
    let derivation = scene.derive(&mut a).unwrap();
    let model = FreeModel::new(&mut a, &derivation, &[("M", 3.0), ("g", 9.81)]).unwrap();
    let m0 = Vector3::new(1.1f64.cos(), 0.0, 1.1f64.sin());
    let s0 = FreeState {
        velocity: Vector3::new(1.0, 0.0, 20.0),
        omega_principal: m0.component_div(&Vector3::from(GNI_I)),
        ..FreeState::at_rest()
    };
    let mut flight =
        FreeFlight::new(&model, 0.0, &s0, AdaptiveConfig::with_tol(1e-13, 1e-15)).unwrap();
    for (t, want) in [(1.0, GNI_M1), (10.0, GNI_M10)] {
        flight.advance_to(t).unwrap();
        let s = flight.state().unwrap();
        let m = s.omega_principal.component_mul(&Vector3::from(GNI_I));
        assert_relative_eq!(m, Vector3::from(want), epsilon = 1e-11);
        assert_relative_eq!(
            s.position.z,
            20.0 * t - 0.5 * 9.81 * t * t,
            max_relative = 1e-12
        );
    }
    // The energy has only the potential and the kinetic parts: conserved.
    let (e0, e1) = (model.energy(&s0.to_array()), model.energy(flight.y()));
    assert_relative_eq!(e0, e1, max_relative = 1e-12);
}
