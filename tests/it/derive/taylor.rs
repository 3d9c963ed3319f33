//! `taylor = K` on `#[top]` and `#[free]`: the generated `impl TaylorSystem` against the
//! interpreted tape of the same scene built at run time, against the scene's own generated
//! right-hand side at order 1, and (the free body) the truncated series against the exact
//! torque-free flight a step ahead.

use crate::common::free_bodies;

use free_bodies::throw;
use precess::free::FreeDynamics;
use precess::prelude::*;
use precess::taylor::TaylorSystem;
use precess::top::TopDynamics;
use precess_testkit::systems::{SpinningTop, interpreted_top};

/// An asymmetric top with a centre off its axis and a field for g: every recurrence kind
/// but the square root (products, quotients, sin–cos pairs, scalings by a field).
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 0.3, size = [0.12, 0.05, 0.02], at = [0.01, -0.005, 0.06]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, taylor = 24)]
struct Brick {
    g: f64,
}

/// The T-handle of `free_bodies`, with its recurrences.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x, at = [0.0, 0.0, 0.1]),
    cylinder(mass = 0.2, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.0]),
)]
#[free(gravity = 9.81, taylor = 20)]
struct TaylorHandle;

/// Generated against interpreted, order by order, relative to the order's largest entry.
fn agree<const N: usize>(
    generated: &impl TaylorSystem<N>,
    interpreted: &impl TaylorSystem<N>,
    y: &[f64; N],
    tol: f64,
) {
    let order = generated.max_order();
    assert_eq!(order, interpreted.max_order());
    let mut g = vec![[0.0; N]; order + 1];
    let mut i = vec![[0.0; N]; order + 1];
    generated.coefficients(0.0, y, order, &mut g);
    interpreted.coefficients(0.0, y, order, &mut i);
    for k in 0..=order {
        let scale = i[k].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for n in 0..N {
            assert!(
                (g[k][n] - i[k][n]).abs() <= tol * scale,
                "order {k}, component {n}: {} vs {} (scale {scale:e})",
                g[k][n],
                i[k][n]
            );
        }
    }
}

#[test]
fn the_generated_top_recurrences_agree_with_the_interpreted_tape() {
    let y = [0.3, 0.5, -0.2, 0.8, -0.4, 60.0];
    agree(
        &SpinningTop,
        &interpreted_top(&SpinningTop, 9.81, 20),
        &y,
        1e-11,
    );
    let brick = Brick { g: 9.81 };
    let y = [0.1, 1.1, 2.0, 1.5, 0.7, -3.0];
    agree(&brick, &interpreted_top(&brick, 9.81, 24), &y, 1e-11);
}

#[test]
fn the_first_coefficient_is_the_generated_right_hand_side() {
    let brick = Brick { g: 3.7 };
    let y = [0.4, 0.9, -1.0, 0.2, 1.3, -2.0];
    let mut c = [[0.0; 6]; 2];
    brick.coefficients(0.0, &y, 1, &mut c);
    let accel = brick.accelerations_unchecked_in(Brick::SEQUENCE, 0.0, &y);
    assert_eq!(c[0], y);
    for k in 0..3 {
        assert!((c[1][k] - y[k + 3]).abs() == 0.0);
        assert!(
            (c[1][k + 3] - accel[k]).abs() <= 1e-13 * accel[k].abs().max(1.0),
            "{c:?} {accel:?}"
        );
    }
}

#[test]
fn the_free_body_series_reaches_the_exact_flight_a_step_ahead() {
    let s0 = throw();
    let exact = TaylorHandle.exact(0.0, &s0).unwrap();
    let y0 = s0.to_array();
    let step = |p: usize, h: f64| {
        let mut c = vec![[0.0; 13]; p + 1];
        TaylorHandle.coefficients(0.0, &y0, p, &mut c);
        let sum: Vec<f64> = (0..13)
            .map(|i| c.iter().rev().fold(0.0, |acc, ck| acc * h + ck[i]))
            .collect();
        let want = exact.at(h).unwrap().to_array();
        // The quaternion q and −q are one attitude: compare with the sign that fits.
        let sign = if (6..10).map(|i| sum[i] * want[i]).sum::<f64>() < 0.0 {
            -1.0
        } else {
            1.0
        };
        (0..13)
            .map(|i| {
                let w = if (6..10).contains(&i) {
                    sign * want[i]
                } else {
                    want[i]
                };
                (sum[i] - w).abs() / w.abs().max(1.0)
            })
            .fold(0.0f64, f64::max)
    };
    // |ω| ≈ 20: at h = 0.01 the order-20 series is at rounding.
    let e = step(20, 0.01);
    assert!(e < 1e-13, "order 20: {e:e}");
    // The error of the degree-p polynomial falls as h^{p+1}.
    for p in [3, 5] {
        let ratio = step(p, 0.004) / step(p, 0.002);
        let expect = 2f64.powi(p as i32 + 1);
        assert!(
            ratio > 0.6 * expect && ratio < 1.6 * expect,
            "order {p}: {ratio} vs {expect}"
        );
    }
}

#[test]
fn the_orders_are_bounded_by_the_key_and_the_buffer() {
    assert_eq!(TaylorSystem::<6>::max_order(&SpinningTop), 20);
    assert_eq!(TaylorSystem::<13>::max_order(&TaylorHandle), 20);
    // A buffer shorter than the order asked for is filled as far as it goes.
    let y = [0.3, 0.5, -0.2, 0.8, -0.4, 60.0];
    let mut short = [[f64::NAN; 6]; 3];
    SpinningTop.coefficients(0.0, &y, 20, &mut short);
    assert!(short.iter().flatten().all(|v| v.is_finite()));
    let mut long = [[0.0; 6]; 21];
    SpinningTop.coefficients(0.0, &y, 20, &mut long);
    assert_eq!(short[..], long[..3]);
}

#[test]
fn a_workspace_kept_across_calls_gives_what_a_fresh_one_gives() {
    // The integrator keeps one workspace for every step: what a call leaves in it must not
    // reach the next call's coefficients, at any order, even when the next asks fewer.
    let top = interpreted_top(&SpinningTop, 9.81, 20);
    let mut ws = Vec::new();
    let mut kept = [[0.0; 6]; 21];
    let mut fresh = [[0.0; 6]; 21];
    let states = [
        [0.3, 0.5, -0.2, 0.8, -0.4, 60.0],
        [1.1, 0.2, 0.7, -3.0, 2.0, 150.0],
        [0.3, 0.5, -0.2, 0.8, -0.4, 60.0],
    ];
    for (y, order) in states.iter().zip([20, 20, 9]) {
        SpinningTop.coefficients_into(&mut ws, 0.0, y, order, &mut kept);
        top.coefficients(0.0, y, order, &mut fresh);
        for k in 0..=order {
            let scale = fresh[k].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for n in 0..6 {
                assert!(
                    (kept[k][n] - fresh[k][n]).abs() <= 1e-12 * scale,
                    "order {k}, component {n}: {} vs {}",
                    kept[k][n],
                    fresh[k][n]
                );
            }
        }
    }
}
