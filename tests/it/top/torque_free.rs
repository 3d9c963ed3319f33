//! A bare `#[top]` is a top under no declared torque: whatever its centre of mass, it turns
//! about the pivot by Euler's torque-free equations, checked against their closed form and
//! against the exact torque-free motion (Jacobi elliptic functions).

use crate::common;

use approx::assert_relative_eq;
use common::rng::Rng;
use precess::exact::FreeBodyAttitude;
use precess::ode::AdaptiveConfig;
use precess::prelude::*;
use precess::top::TopParameters;

/// The principal moments of [`Tumbler`] about its pivot.
const I: [f64; 3] = [3.0, 5.0, 7.0];

/// An asymmetric body, I = (3, 5, 7) about the pivot, with its centre of mass off the pivot:
/// without a declared gravity the offset exerts no torque.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.1, -0.2, 0.3], inertia = diag(3.0, 5.0, 7.0), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top]
struct Tumbler;

/// Euler's torque-free equations in principal axes: I1 ω̇1 = (I2 − I3) ω2 ω3, cyclic.
fn euler_torque_free(i: [f64; 3], w: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        (i[1] - i[2]) * w[1] * w[2] / i[0],
        (i[2] - i[0]) * w[2] * w[0] / i[1],
        (i[0] - i[1]) * w[0] * w[1] / i[2],
    )
}

#[test]
fn a_bare_top_declares_nothing() {
    assert_eq!(Tumbler.top_parameters(), TopParameters::default());
    assert_eq!(Tumbler.validate_top(), Ok(()));
    assert!(Tumbler.conserved_momenta(&[0.1, 0.7, 0.2], &[0.3, -0.4, 0.5])[0].is_some());
}

#[test]
fn the_eulerian_form_is_eulers_torque_free_equations_at_any_attitude() {
    let mut rng = Rng::new(11);
    for _ in 0..50 {
        let attitude = UnitQuaternion::from_scaled_axis(rng.vector(-2.0, 2.0));
        let w = rng.vector(-3.0, 3.0);
        let t = rng.uniform(0.0, 10.0);
        assert_relative_eq!(
            Tumbler.eulerian_rhs(t, &attitude, &w),
            euler_torque_free(I, &w),
            epsilon = 1e-13,
            max_relative = 1e-13
        );
    }
}

#[test]
fn the_angle_form_follows_the_exact_torque_free_motion() {
    // The body starts at the identity, where the ZXZ chart is singular, so the charted top
    // starts in ZYX.
    let m0 = [2.0, 0.3, 3.0];
    let w0 = Vector3::new(m0[0] / I[0], m0[1] / I[1], m0[2] / I[2]);
    let [zxz, zyx] = TopChart::both(&Tumbler);
    let config = ChartConfig {
        stepper: AdaptiveConfig::with_tol(1e-12, 1e-12),
        ..ChartConfig::default()
    };
    let mut top = ChartedTop::new([&zxz, &zyx], 0.0, &Matrix3::identity(), &w0, config)
        .expect("a regular start");
    assert_eq!(top.sequence(), AngleSequence::Zyx);
    let exact = FreeBodyAttitude::new(I, UnitQuaternion::identity(), m0).expect("a body");
    for t in [1.0, 4.0, 10.0] {
        top.advance_to(t).expect("a torque-free run");
        let (q, m) = exact.at(t).expect("the closed form");
        let w = top.omega();
        let m_top = Vector3::new(I[0] * w[0], I[1] * w[1], I[2] * w[2]);
        assert_relative_eq!(m_top, Vector3::from(m), epsilon = 1e-8);
        assert_relative_eq!(
            top.rotation(),
            *q.to_rotation_matrix().matrix(),
            epsilon = 1e-8
        );
    }
}
