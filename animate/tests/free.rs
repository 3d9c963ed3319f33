//! A free body's keyframes against its run: each keyframe's rotation, followed through the
//! body's principal frame, is the run's quaternion, and its translation puts the centre of
//! mass where the run's position says.

use precess::animate::{self, Options};
use precess::free::{FreeDynamics, FreeFlight, FreeState, FreeSystem};
use precess::nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess::ode::{AdaptiveConfig, Trajectory};
use precess::prelude::*;

/// A box with a ball on one corner: its centre of mass is off the description origin and
/// its principal axes are turned from the description axes, so neither the offset nor the
/// principal frame can be left out unseen.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]),
    sphere(mass = 0.5, radius = 0.03, at = [0.05, 0.1, 0.15]),
)]
#[free(gravity = 9.81)]
struct Lopsided;

/// Thrown up and tumbling, sampled every 10 ms for 1 s (state arrays, as a run records).
fn throw() -> Trajectory<[f64; 13]> {
    let s0 = FreeState {
        position: Vector3::new(0.0, 0.0, 1.0),
        velocity: Vector3::new(0.5, 0.0, 4.0),
        attitude: UnitQuaternion::from_euler_angles(0.2, -0.1, 0.4),
        omega_principal: Vector3::new(3.0, 7.0, 0.5),
    };
    let cfg = AdaptiveConfig::with_tol(1e-10, 1e-10);
    let mut flight = FreeFlight::new(FreeSystem(&Lopsided), 0.0, &s0, cfg).unwrap();
    let mut run = Trajectory::new(vec![]);
    for k in 0..=100 {
        let t = 0.01 * k as f64;
        flight.advance_to(t).unwrap();
        run.push(t, *flight.y(), &[]).unwrap();
    }
    run
}

#[test]
fn a_free_body_s_keyframes_are_its_run_s_quaternions_and_positions() {
    let body = Lopsided;
    let principal = body.principal_cm();
    // The test is void unless the principal frame is turned and the centre is off the origin.
    let turned = (principal.rotation.matrix() - precess::nalgebra::Matrix3::identity()).norm();
    assert!(turned > 0.1, "principal frame turned by {turned}");
    let c = body.center_of_mass();
    assert!(c.norm() > 0.01);

    let run = throw();
    let animation = animate::free(&body, &run, Options::default()).unwrap();
    let keys = animation.keyframes(0).unwrap();
    assert_eq!(keys.times.len(), run.len());
    let mut turned_far = false;
    for ((y, r), p) in run
        .states()
        .iter()
        .zip(&keys.rotations)
        .zip(&keys.translations)
    {
        // The run's own numbers: q = (w, x, y, z) in slots 6..10 (principal → space), the
        // centre of mass in slots 0..3.
        let q = UnitQuaternion::new_normalize(Quaternion::new(y[6], y[7], y[8], y[9]));
        let x = Vector3::new(y[0], y[1], y[2]);
        let r =
            UnitQuaternion::new_normalize(Quaternion::new(r[3], r[0], r[1], r[2]).cast::<f64>());
        // Each principal axis eᵢ lies along P eᵢ in description axes: the keyframe carries it
        // to where q does.
        for i in 0..3 {
            let e = Vector3::ith(i, 1.0);
            let drawn = r * (principal.rotation * e);
            assert!(
                (drawn - q * e).norm() < 1e-6,
                "axis {i}: {drawn} vs {}",
                q * e
            );
        }
        // The keyframe's map x ↦ p + R x puts the description's centre of mass at X.
        let centre = Vector3::new(p[0], p[1], p[2]).cast::<f64>() + r * c;
        assert!((centre - x).norm() < 1e-6, "{centre} vs {x}");
        turned_far |= q.angle() > 2.0;
    }
    assert!(turned_far, "the run should tumble well away from its start");
    // It flies: the centre of mass's path is drawn (a node of that name in the file).
    let glb = animation.to_glb().unwrap();
    assert!(glb.windows(14).any(|w| w == b"centre of mass"));
}

#[test]
fn a_zero_quaternion_is_a_typed_error() {
    let mut run = Trajectory::new(vec![]);
    run.push(0.0, FreeState::at_rest().to_array(), &[]).unwrap();
    let mut bad = FreeState::at_rest().to_array();
    bad[6..10].copy_from_slice(&[0.0; 4]);
    run.push(0.1, bad, &[]).unwrap();
    let err = animate::free(&Lopsided, &run, Options::default()).unwrap_err();
    assert!(
        matches!(err, animate::AnimateError::NonFinite { index: 1, .. }),
        "{err}"
    );
}

#[test]
fn the_page_s_camera_frames_the_whole_flight() {
    let run = throw();
    let animation = animate::free(&Lopsided, &run, Options::default()).unwrap();
    let camera = animate::Camera::fit(&animation);
    // The sphere the camera frames: 90 % of the height at its distance.
    let framed = camera.distance * 0.9 * (camera.fovy.to_radians() / 2.0).sin();
    let target = Vector3::from(camera.target);
    let keys = animation.keyframes(0).unwrap();
    let mut widest = 0.0f64;
    for (p, r) in keys.translations.iter().zip(&keys.rotations) {
        let p = Vector3::new(p[0], p[1], p[2]).cast::<f64>();
        let r =
            UnitQuaternion::new_normalize(Quaternion::new(r[3], r[0], r[1], r[2]).cast::<f64>());
        let at = |x: Vector3<f64>| p + r * x;
        // The farthest point of the body from the target: a corner of the box, or the far
        // side of the ball (its centre's distance plus its radius).
        let corners = (0..8).map(|k| {
            let s = |bit: usize, half: f64| if k >> bit & 1 == 1 { half } else { -half };
            (at(Vector3::new(s(0, 0.05), s(1, 0.1), s(2, 0.15))) - target).norm()
        });
        let ball = (at(Vector3::new(0.05, 0.1, 0.15)) - target).norm() + 0.03;
        let needed = corners.fold(ball, f64::max);
        // The ball is drawn inscribed in the sphere (16 bands): its mesh may fall short of
        // the far point by up to the chord's sag, 0.03 (1 − cos π/16).
        let sag = 0.03 * (1.0 - (std::f64::consts::PI / 16.0).cos());
        assert!(needed <= framed + sag, "{needed} m past {framed} m");
        widest = widest.max(needed);
    }
    // And not much looser than it needs to be (a bounding sphere of the body's box is a
    // little wider than the body).
    assert!(widest > 0.9 * framed, "{widest} m of {framed} m");
}
