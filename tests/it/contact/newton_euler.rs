//! The derived contact equations against the Newton–Euler reference written out in
//! `reference.rs` (space axes, the contact force as unknowns of a linear solve, the support
//! maps' derivatives by hand), at random states of every surface and law.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, Phase, STATE_LEN};
use proptest::prelude::*;

use super::reference::{
    NumBody, NumLaw, NumSurface, ROLLING, chaplygin_ball, model, newton_euler, offset_sphere,
    rattleback, state, thin_disk,
};

/// The bodies tested: every surface, with offset centres and a product of inertia.
fn bodies() -> Vec<NumBody> {
    let torus = NumBody {
        mass: 0.5,
        center: [0.0, 0.0, 0.002],
        inertia: [[1e-3, 0.0, 0.0], [0.0, 1.1e-3, 1e-5], [0.0, 1e-5, 1.9e-3]],
        surface: NumSurface::Torus {
            c: [0.0; 3],
            big: 0.06,
            tube: 0.01,
        },
        gravity: 9.81,
    };
    let bowl = NumBody {
        mass: 0.3,
        center: [0.001, 0.0, 0.05],
        inertia: [[4e-4, 0.0, 0.0], [0.0, 5e-4, 0.0], [0.0, 0.0, 3e-4]],
        surface: NumSurface::Paraboloid {
            v: [0.0; 3],
            big: 0.2,
        },
        gravity: 9.81,
    };
    vec![
        rattleback(),
        chaplygin_ball(),
        offset_sphere(),
        thin_disk(),
        torus,
        bowl,
    ]
}

/// Compares the model's ω̇, horizontal acceleration and contact force with the reference,
/// relative to the size of each (ω̇ against |ω̇| + |ω|², the force against M g + |F|).
fn compare(body: &NumBody, law: NumLaw, phase: Phase, y: &[f64; STATE_LEN]) -> f64 {
    let m = model(body, law);
    let reference = newton_euler(body, law, y);
    let mut d = [0.0; STATE_LEN];
    m.phase_rhs(phase, 0.0, y, &mut d);
    let omega_dot = Vector3::new(d[8], d[9], d[10]);
    let omega = Vector3::new(y[8], y[9], y[10]);
    let scale_w = reference.omega_dot.norm() + omega.norm_squared() + 1.0;
    let e_w = (omega_dot - reference.omega_dot).norm() / scale_w;
    let accel = Vector3::new(d[2], d[3], 0.0);
    let want = Vector3::new(reference.accel.x, reference.accel.y, 0.0);
    let e_a = (accel - want).norm() / (reference.accel.norm() + body.gravity);
    let f = m.reaction(phase, y).force();
    let e_f = (f - reference.force).norm() / (reference.force.norm() + body.mass * body.gravity);
    e_w.max(e_a).max(e_f)
}

/// An attitude tilted by at most `tilt_max` from upright (or from inverted, `flip`).
fn attitude(yaw: f64, tilt: f64, axis: f64, flip: bool) -> UnitQuaternion<f64> {
    let base = if flip {
        UnitQuaternion::from_euler_angles(std::f64::consts::PI, 0.0, 0.0)
    } else {
        UnitQuaternion::identity()
    };
    let tilt_axis = nalgebra::Unit::new_normalize(Vector3::new(axis.cos(), axis.sin(), 0.0));
    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), yaw)
        * UnitQuaternion::from_axis_angle(&tilt_axis, tilt)
        * base
}

/// One of the worst errors measured is printed by the fixed cases below.
const TOL: f64 = 1e-12;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Rolling: every surface at random attitudes and spins.
    #[test]
    fn rolling_matches_newton_euler(
        which in 0usize..6,
        yaw in -3.0f64..3.0, tilt in 0.05f64..1.2, axis in -3.0f64..3.0,
        w in prop::array::uniform3(-8.0f64..8.0),
    ) {
        let body = bodies()[which];
        // The disk rim and torus stand on edge: tilt them from lying flat.
        let tilt = match body.surface {
            NumSurface::DiskRim { .. } | NumSurface::Torus { .. } => std::f64::consts::FRAC_PI_2 - tilt,
            NumSurface::Paraboloid { .. } => tilt.min(0.6),
            _ => tilt,
        };
        let q = attitude(yaw, tilt, axis, false);
        let m = model(&body, NumLaw::Rolling { cr: Some(1e-3), cs: Some(2e-4) });
        let y = m.rolling_state([0.3, -0.2], &q, &Vector3::from(w)).unwrap();
        let e = compare(&body, NumLaw::Rolling { cr: Some(1e-3), cs: Some(2e-4) }, Phase::Rolling, &y);
        prop_assert!(e < TOL, "relative error {e:e} for body {which}");
    }

    /// Sliding under each friction law: the centre of mass's horizontal velocity free.
    #[test]
    fn sliding_matches_newton_euler(
        which in 0usize..6, law in 0usize..3,
        yaw in -3.0f64..3.0, tilt in 0.05f64..1.2, axis in -3.0f64..3.0,
        w in prop::array::uniform3(-8.0f64..8.0),
        v in prop::array::uniform2(-1.0f64..1.0),
    ) {
        let body = bodies()[which];
        let tilt = match body.surface {
            NumSurface::DiskRim { .. } | NumSurface::Torus { .. } => std::f64::consts::FRAC_PI_2 - tilt,
            NumSurface::Paraboloid { .. } => tilt.min(0.6),
            _ => tilt,
        };
        let law = [NumLaw::Frictionless, NumLaw::Viscous(0.3), NumLaw::Coulomb(0.2)][law];
        let y = state([0.0, 0.0], v, &attitude(yaw, tilt, axis, false), &Vector3::from(w));
        let e = compare(&body, law, Phase::Sliding, &y);
        prop_assert!(e < TOL, "relative error {e:e} for body {which}, {law:?}");
    }
}

/// The rattleback of Kane & Levinson at its release state, and a stick–slip law's two phases
/// (its sliding phase is Coulomb's).
#[test]
fn the_rattleback_and_stick_slip_phases_match_newton_euler() {
    let body = rattleback();
    let tilt = 0.5f64.to_radians();
    let q = UnitQuaternion::from_euler_angles(tilt, tilt, 0.0);
    let w = Vector3::new(0.0, 0.0, -5.0);
    let m = model(&body, ROLLING);
    let y = m.rolling_state([0.0, 0.0], &q, &w).unwrap();
    let e = compare(&body, ROLLING, Phase::Rolling, &y);
    println!("rattleback at release: relative error {e:e}");
    assert!(e < TOL, "{e:e}");
    let ss = model(&body, NumLaw::StickSlip(0.3));
    let mut d_roll = [0.0; STATE_LEN];
    let mut d_ref = [0.0; STATE_LEN];
    ss.phase_rhs(Phase::Rolling, 0.0, &y, &mut d_roll);
    m.phase_rhs(Phase::Rolling, 0.0, &y, &mut d_ref);
    assert_eq!(d_roll, d_ref);
    let mut slipping = y;
    slipping[2] += 0.05;
    let e = compare(&body, NumLaw::Coulomb(0.3), Phase::Sliding, &slipping);
    let mut d_slide = [0.0; STATE_LEN];
    ss.phase_rhs(Phase::Sliding, 0.0, &slipping, &mut d_slide);
    let coulomb = model(&body, NumLaw::Coulomb(0.3));
    coulomb.phase_rhs(Phase::Sliding, 0.0, &slipping, &mut d_ref);
    assert_eq!(d_slide, d_ref);
    assert!(e < TOL, "{e:e}");
}
