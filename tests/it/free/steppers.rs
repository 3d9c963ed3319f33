//! Issue 12 item 2: a free body runs on RK4 (through `FreeSystem`) and, for its torque-free
//! part, on the free-body splitting (through `FreeState::body_momentum`), each against the
//! exact flow of `FreeExact` (the parabola and the elliptic attitude).

use crate::common::free_bodies;

use free_bodies::{T_HANDLE_MOMENTS, THandle, throw};
use precess::free::{FreeDynamics, FreeState, FreeSystem};
use precess::ode::{FixedStepConfig, Rk4};
use precess::prelude::*;
use precess::rigid::{FreeBodySplitting, SplittingOrder};

/// RK4 is fourth order on the whole free body: halving h divides the attitude error by 16.
#[test]
fn rk4_follows_the_exact_flight_at_fourth_order() {
    let (s0, t_end) = (throw(), 2.0);
    let want = THandle.exact(0.0, &s0).unwrap().at(t_end).unwrap();
    let error = |h: f64| {
        let cfg = FixedStepConfig::with_step(h);
        let mut rk4 = Rk4::new(FreeSystem(&THandle), 0.0, s0.to_array(), cfg).unwrap();
        rk4.advance_to(t_end).unwrap();
        let got = FreeState::from_array(rk4.y()).unwrap();
        // Under uniform gravity alone the centre of mass is exact for any Runge–Kutta
        // method (its rhs is constant), to rounding.
        assert!((got.position - want.position).norm() < 1e-12);
        got.attitude.angle_to(&want.attitude)
    };
    let (coarse, fine) = (error(2e-3), error(1e-3));
    let order = (coarse / fine).log2();
    eprintln!("RK4: attitude error {coarse:e} at h = 2e-3, {fine:e} at 1e-3, order {order:.2}");
    assert!(fine < 1e-7, "attitude error {fine:e} at h = 1e-3");
    assert!((order - 4.0).abs() < 0.3, "observed order {order}");
}

/// The torque-free part on the sixth-order free-body splitting: the attitude and ω match
/// the exact flow; the centre of mass is the parabola, in closed form.
#[test]
fn the_splitting_carries_the_rotation_of_a_free_body() {
    let (s0, t_end, n) = (throw(), 2.0, 2000u64);
    let moments = Vector3::from(T_HANDLE_MOMENTS);
    let want = THandle.exact(0.0, &s0).unwrap().at(t_end).unwrap();
    let split = FreeBodySplitting::new(moments, SplittingOrder::Six).unwrap();
    let mut y = s0.body_momentum(&moments);
    split.run(&mut y, t_end / n as f64, n).unwrap();
    let omega = y.m.component_div(&moments);
    eprintln!(
        "splitting order 6, h = 1e-3: attitude {:e} rad, ω {:e} relative",
        y.q.angle_to(&want.attitude),
        (omega - want.omega_principal).norm() / want.omega_principal.norm()
    );
    assert!(
        y.q.angle_to(&want.attitude) < 1e-9,
        "{:e}",
        y.q.angle_to(&want.attitude)
    );
    assert!((omega - want.omega_principal).norm() < 1e-9 * want.omega_principal.norm());
}
