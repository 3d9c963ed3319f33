//! Taylor recurrences for the scenes beyond tops and free bodies: `taylor = K` on
//! `#[mechanism]` against the interpreted tape of the same mechanism built at run time by
//! hand (another route of the engine), against finite differences of q̈ along an accurate
//! DOP853 run, and integrated against DOP853 with its energy; `taylor_system!` against the
//! interpreted tape of the same equations and against B5's closed form.

use crate::common::mechanism::double_pendulum;
use precess::mechanism::{MechanismDynamics, Route};
use precess::ode::{AdaptiveConfig, Dop853Pair};
use precess::prelude::*;
use precess::sym::Arena;
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape};

/// The double pendulum of `examples/double_pendulum.rs` (relative angles, point masses),
/// with its recurrences to order 20.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 20)]
#[body(upper, parent = ground, joint = revolute(name = shoulder, axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(name = elbow, axis = x, at = [0.0, 0.0, -l1]),
       q = theta2, parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct DoublePendulum {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
}

/// The same on the recursive route (q̈ by the articulated-body recursion: divisions by the
/// articulated inertias in the tape), with a damper on the elbow and literal values.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, route = recursive, taylor = 12)]
#[body(upper, parent = ground, joint = revolute(name = shoulder, axis = x), q = theta1,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(name = elbow, axis = x, at = [0.0, 0.0, -0.9]),
       q = theta2, damper = 0.2, parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct DampedRecursive;

const PENDULUM: DoublePendulum = DoublePendulum {
    m1: 1.3,
    l1: 0.9,
    m2: 0.7,
    l2: 0.6,
};

const VALUES: [(&str, f64); 5] = [
    ("m0", 1.3),
    ("m1", 0.7),
    ("l0", 0.9),
    ("l1", 0.6),
    ("g", 9.81),
];

/// |a − b| ≤ tol · max(1, |b|) for every coefficient up to `order`.
fn assert_coefficients_close<const N: usize>(
    ours: &[[f64; N]],
    reference: &[[f64; N]],
    order: usize,
    tol: f64,
) {
    for k in 0..=order {
        for i in 0..N {
            let (x, r) = (ours[k][i], reference[k][i]);
            assert!(
                (x - r).abs() <= tol * r.abs().max(1.0),
                "coefficient {k} of component {i}: {x} against {r}"
            );
        }
    }
}

#[test]
fn derived_mechanism_coefficients_match_the_interpreted_tape_of_another_route() {
    let states = [
        [0.3, -0.2, 1.1, -0.4],
        [2.5, 1.9, -3.0, 2.2],
        [-1.0, 0.01, 0.0, 0.0],
    ];
    for route in [Route::Symbolic, Route::Factored, Route::Recursive] {
        let mut a = Arena::new();
        let scene = double_pendulum(&mut a, None);
        let tape: TaylorTape<4> = scene
            .taylor_tape(&mut a, route, &VALUES, 20)
            .expect("the double pendulum's tape builds");
        for y in states {
            let mut ours = [[0.0; 4]; 21];
            let mut reference = [[0.0; 4]; 21];
            PENDULUM.coefficients(0.0, &y, 20, &mut ours);
            tape.coefficients(0.0, &y, 20, &mut reference);
            assert_coefficients_close(&ours, &reference, 20, 1e-11);
        }
    }
    // The recursive route's divisions, a damper, literal values.
    let mut a = Arena::new();
    let scene = double_pendulum(&mut a, Some("c"));
    let mut values = VALUES.to_vec();
    values.push(("c", 0.2));
    let tape: TaylorTape<4> = scene
        .taylor_tape(&mut a, Route::Symbolic, &values, 12)
        .expect("the damped pendulum's tape builds");
    for y in states {
        let mut ours = [[0.0; 4]; 13];
        let mut reference = [[0.0; 4]; 13];
        DampedRecursive.coefficients(0.0, &y, 12, &mut ours);
        tape.coefficients(0.0, &y, 12, &mut reference);
        assert_coefficients_close(&ours, &reference, 12, 1e-11);
    }
    assert_eq!(TaylorSystem::<4>::max_order(&PENDULUM), 20);
    assert_eq!(TaylorSystem::<4>::max_order(&DampedRecursive), 12);
}

/// The state of an accurate DOP853 run at each of `times` (ascending, from 0).
fn dop853_states(y0: [f64; 4], times: &[f64]) -> Vec<[f64; 4]> {
    times
        .iter()
        .map(|&t| {
            if t == 0.0 {
                return y0;
            }
            let cfg = AdaptiveConfig::with_tol(1e-14, 1e-15);
            precess::ode::solve::<Dop853Pair, _, 4>(&PENDULUM, 0.0, y0, t, &[], cfg)
                .expect("DOP853 integrates the pendulum")
                .y
        })
        .collect()
}

#[test]
fn derived_mechanism_coefficients_match_finite_differences_of_its_accelerations() {
    // q̈ at five points h apart along the solution; the five-point stencils give q⃛ and q⁗
    // at the middle one to O(h⁴), independently of the recurrences.
    let h = 1e-3;
    let times: Vec<f64> = (0..5).map(|i| i as f64 * h).collect();
    let states = dop853_states([0.4, -0.7, 0.9, 1.6], &times);
    let accel: Vec<[f64; 2]> = states
        .iter()
        .map(|y| {
            PENDULUM
                .accelerations(0.0, &[y[0], y[1]], &[y[2], y[3]])
                .expect("a regular state")
        })
        .collect();
    let mid = states[2];
    let mut c = [[0.0; 4]; 21];
    PENDULUM.coefficients(2.0 * h, &mid, 20, &mut c);
    for i in 0..2 {
        let a: Vec<f64> = accel.iter().map(|x| x[i]).collect();
        let third = (a[0] - 8.0 * a[1] + 8.0 * a[3] - a[4]) / (12.0 * h);
        let fourth = (-a[0] + 16.0 * a[1] - 30.0 * a[2] + 16.0 * a[3] - a[4]) / (12.0 * h * h);
        // c₁ = q̇, c₂ = q̈/2, c₃ = q⃛/6, c₄ = q⁗/24 for q; one order lower for q̇.
        assert!((c[1][i] - mid[2 + i]).abs() < 1e-14);
        assert!((c[2][i] - a[2] / 2.0).abs() < 1e-12 * a[2].abs().max(1.0));
        assert!((c[1][2 + i] - a[2]).abs() < 1e-12 * a[2].abs().max(1.0));
        assert!(
            (c[3][i] - third / 6.0).abs() < 1e-7 * third.abs().max(1.0),
            "q⃛/6 of {i}: {} against {}",
            c[3][i],
            third / 6.0
        );
        assert!((c[2][2 + i] - third / 2.0).abs() < 1e-7 * third.abs().max(1.0));
        assert!(
            (c[4][i] - fourth / 24.0).abs() < 1e-5 * fourth.abs().max(1.0),
            "q⁗/24 of {i}: {} against {}",
            c[4][i],
            fourth / 24.0
        );
    }
}

#[test]
fn derived_mechanism_integrated_by_taylor_matches_dop853_and_keeps_its_energy() {
    let y0 = [0.8, -0.5, 0.0, 1.2];
    let t_end = 10.0;
    let energy = |y: &[f64; 4]| {
        PENDULUM.kinetic(&[y[0], y[1]], &[y[2], y[3]]) + PENDULUM.potential(&[y[0], y[1]])
    };
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let taylor = precess::taylor::solve(&PENDULUM, 0.0, y0, t_end, &[], cfg)
        .expect("Taylor integrates the pendulum");
    let dop = precess::ode::solve::<Dop853Pair, _, 4>(
        &PENDULUM,
        0.0,
        y0,
        t_end,
        &[],
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )
    .expect("DOP853 integrates the pendulum");
    for i in 0..4 {
        assert!(
            (taylor.y[i] - dop.y[i]).abs() < 1e-8,
            "component {i}: Taylor {} against DOP853 {}",
            taylor.y[i],
            dop.y[i]
        );
    }
    let (e0, e1) = (energy(&y0), energy(&taylor.y));
    assert!(
        (e1 - e0).abs() < 1e-11 * e0.abs(),
        "energy drifts from {e0} to {e1}"
    );
}

precess::taylor_system! {
    /// DETEST B5: from (0, 1, 1), Jacobi's (sn, cn, dn)(t | m = 0.51).
    #[derive(Clone, Copy, Debug)]
    struct B5;
    state [y1, y2, y3];
    taylor = 24;
    d/dt y1 = y2 * y3;
    d/dt y2 = -y1 * y3;
    d/dt y3 = -0.51 * y1 * y2;
}

precess::taylor_system! {
    /// Every function and operator the macro reads, with parameters from the fields.
    struct Everything {
        k: f64,
        w: f64,
    }
    state [x, v, r];
    taylor = 16;
    d/dt x = v;
    d/dt v = -w * w * x.sin() + k * cos(v) / (2.0 + x.powi(2));
    d/dt r = (1.0 + r * r).sqrt() - sqrt(2.0 + x.powi(-2)) + v.powi(3) / 7;
}

/// B5's right-hand side built by hand in the engine, interpreted.
fn b5_tape() -> TaylorTape<3> {
    let mut a = Arena::new();
    let y = ["y1", "y2", "y3"].map(|n| a.coordinate(n));
    let k = a.number("0.51").expect("a decimal");
    let p13 = a.mul(y[0], y[2]);
    let p12 = a.mul(y[0], y[1]);
    let kp12 = a.mul(k, p12);
    let rhs = [a.mul(y[1], y[2]), a.neg(p13), a.neg(kp12)];
    TaylorTape::new(&a, y, rhs, None, &[], 24).expect("B5's tape builds")
}

#[test]
fn taylor_system_coefficients_match_the_interpreted_tape() {
    let tape = b5_tape();
    for y in [[0.0, 1.0, 1.0], [0.7, -0.3, 0.9], [-1.2, 2.0, 0.1]] {
        let mut ours = [[0.0; 3]; 25];
        let mut reference = [[0.0; 3]; 25];
        B5.coefficients(0.0, &y, 24, &mut ours);
        tape.coefficients(0.0, &y, 24, &mut reference);
        assert_coefficients_close(&ours, &reference, 24, 1e-13);
    }
    assert_eq!(TaylorSystem::<3>::max_order(&B5), 24);
    assert_eq!(B5::STATE, ["y1", "y2", "y3"]);
}

#[test]
fn taylor_system_series_sums_to_the_jacobi_elliptic_solution() {
    // sn, cn, dn at t = 0.2 for m = 0.51: mpmath's ellipfun at 30 digits
    // (0.198008803111523742608706987144, 0.980200241731423888668744580586,
    // 0.989951605930347653258504149191), rounded to f64.
    let exact = [
        0.198_008_803_111_523_75,
        0.980_200_241_731_423_8,
        0.989_951_605_930_347_7,
    ];
    let mut c = [[0.0; 3]; 25];
    B5.coefficients(0.0, &[0.0, 1.0, 1.0], 24, &mut c);
    let h: f64 = 0.2;
    for i in 0..3 {
        let sum: f64 = (0..=24).rev().fold(0.0, |acc, k| acc * h + c[k][i]);
        assert!(
            (sum - exact[i]).abs() < 1e-15,
            "component {i}: {sum} against {}",
            exact[i]
        );
    }
}

#[test]
fn taylor_system_functions_and_fields_match_the_interpreted_tape() {
    let (k, w) = (0.3, 1.7);
    let sys = Everything { k, w };
    let mut a = Arena::new();
    let [x, v, r] = ["x", "v", "r"].map(|n| a.coordinate(n));
    let (kp, wp) = (a.parameter("k"), a.parameter("w"));
    let (one, two, seven) = (a.integer(1), a.integer(2), a.integer(7));
    // v' = −w² sin x + k cos v / (2 + x²)
    let w2 = a.mul(wp, wp);
    let sx = a.sin(x);
    let gravity = a.mul(w2, sx);
    let cv = a.cos(v);
    let kcv = a.mul(kp, cv);
    let x2 = a.mul(x, x);
    let den = a.add(two, x2);
    let push = a.div(kcv, den).expect("non-zero");
    let vdot = a.sub(push, gravity);
    // r' = √(1 + r²) − √(2 + x⁻²) + v³/7
    let r2 = a.mul(r, r);
    let under = a.add(one, r2);
    let root = a.sqrt(under).expect("a root");
    let xm2 = a.powi(x, -2).expect("a power");
    let under2 = a.add(two, xm2);
    let root2 = a.sqrt(under2).expect("a root");
    let v3 = a.powi(v, 3).expect("a power");
    let v37 = a.div(v3, seven).expect("non-zero");
    let diff = a.sub(root, root2);
    let rdot = a.add(diff, v37);
    let tape = TaylorTape::new(
        &a,
        [x, v, r],
        [v, vdot, rdot],
        None,
        &[("k", k), ("w", w)],
        16,
    )
    .expect("the tape builds");
    for y in [[0.4, -0.2, 0.3], [1.5, 0.9, -2.0]] {
        let mut ours = [[0.0; 3]; 17];
        let mut reference = [[0.0; 3]; 17];
        sys.coefficients(0.0, &y, 16, &mut ours);
        tape.coefficients(0.0, &y, 16, &mut reference);
        assert_coefficients_close(&ours, &reference, 16, 1e-12);
        // Order 1 is the right-hand side, evaluated here directly in f64.
        let mut f = [0.0; 3];
        precess::ode::System::rhs(&sys, 0.0, &y, &mut f);
        let [x, v, r] = y;
        let direct = [
            v,
            -w * w * x.sin() + k * v.cos() / (2.0 + x * x),
            (1.0 + r * r).sqrt() - (2.0 + x.powi(-2)).sqrt() + v.powi(3) / 7.0,
        ];
        for i in 0..3 {
            assert!((f[i] - direct[i]).abs() < 1e-14 * direct[i].abs().max(1.0));
            assert!((ours[1][i] - direct[i]).abs() < 1e-14 * direct[i].abs().max(1.0));
        }
    }
}
