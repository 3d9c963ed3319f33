//! Item 4(c): a free body with no force is, about its centre of mass, the torque-free top
//! pivoted there: the top's Euler-angle equations and the free body's quaternion equations
//! (in another frame: principal against description axes) give the same motion.

use approx::assert_relative_eq;
use precess::free::{FreeDynamics, FreeFlight, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;

/// A body whose tensor is not diagonal, so the principal frame is a real rotation away from
/// the description axes; as a top pivoted at its centre of mass.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, inertia = [[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]], about = center),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(angles = zxz)]
struct PivotedAtCenter;

/// The same body, free.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]], about = center))]
#[free]
struct Flying;

#[test]
fn the_free_body_turns_as_the_torque_free_top() {
    let principal = Flying.principal_cm();
    // The frame is tilted: the comparison goes through the constant rotation.
    assert!(principal.rotation.angle() > 0.1);
    // Body x near the vertical and ω mostly about it: θ stays near 90°, far from the ZXZ
    // chart's singularity.
    let q0 = [
        0.3,
        std::f64::consts::FRAC_PI_2 - 0.1,
        std::f64::consts::FRAC_PI_2 - 0.2,
    ];
    let omega0 = Vector3::new(3.0, 0.4, 0.3);
    let rates0 = PivotedAtCenter.rates_from_omega(&q0, &omega0).unwrap();
    let chart = TopChart::declared(&PivotedAtCenter);
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let y0 = precess::top::angle_state(&q0, &rates0);
    let mut top = Dop853::new(&chart, 0.0, y0, tight).unwrap();

    let r0 = PivotedAtCenter.rotation_in(AngleSequence::Zxz, &q0);
    let att0 = precess_testkit::rotations::quaternion_of(&r0);
    let s0 = FreeState::from_description(
        Vector3::zeros(),
        Vector3::zeros(),
        &att0,
        omega0,
        &principal,
    );
    let mut free = FreeFlight::new(FreeSystem(&Flying), 0.0, &s0, tight).unwrap();
    for t in [0.5, 2.0, 5.0] {
        top.advance_to(t).unwrap();
        free.advance_to(t).unwrap();
        let y = top.y();
        let (q, rates) = ([y[0], y[1], y[2]], [y[3], y[4], y[5]]);
        assert!(
            q[1].sin() > 0.5,
            "θ = {} near the chart's singularity",
            q[1]
        );
        let s = free.state().unwrap();
        let r_top = PivotedAtCenter.rotation_in(AngleSequence::Zxz, &q);
        let r_free = s.attitude_description(&principal).to_rotation_matrix();
        assert_relative_eq!(r_free.matrix(), &r_top, epsilon = 1e-10);
        let w_top = PivotedAtCenter.omega_from_rates(&q, &rates);
        assert_relative_eq!(s.omega_description(&principal), w_top, epsilon = 1e-10);
    }
}
