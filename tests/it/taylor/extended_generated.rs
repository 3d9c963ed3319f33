//! The extended mode of generated systems (`taylor_system!`, `#[derive(Mechanism)]` with
//! `taylor = K`): their double-double low orders against the interpreted tape's (a second
//! formulation of the same equations), the pendulum against its elliptic solution (mpmath,
//! 40 digits), and Drake's chaotic babyboot at t = 10 s against MotionGenesis's values.
// Reference constants are quoted with all their digits.
#![allow(clippy::excessive_precision)]

use precess::exact::Dd;
use precess::ode::{AdaptiveConfig, Vern9};
use precess::prelude::*;
use precess::sym::{Arena, Rational};
use precess::taylor::{Taylor, TaylorConfig, TaylorSystem, TaylorTape};

precess::taylor_system! {
    /// The pendulum θ'' = −sin θ.
    struct Pendulum;
    state [theta, omega];
    taylor = 40;
    d/dt theta = omega;
    d/dt omega = -sin(theta);
}

precess::taylor_system! {
    /// Every operation without an algebraic recurrence: a sine and a cosine of the state, a
    /// real power of the state and of the time, and the sine of a field.
    struct Mixed {
        k: f64,
    }
    state [x, y];
    taylor = 12;
    d/dt x = powf(x, -0.333333333333333333333333333333333333) + sin(k) * cos(y);
    d/dt y = (1.0 + t).powf(0.25) * sin(y);
}

#[test]
fn generated_low_orders_match_the_interpreted_tape() {
    // The same equations through the arena and the interpreter.
    let mut a = Arena::new();
    let (x, y, t) = (a.coordinate("x"), a.coordinate("y"), a.coordinate("t"));
    let k = a.parameter("k");
    let px = a.powr(x, Rational::new(-1, 3).unwrap()).unwrap();
    let (sk, cy, sy) = (a.sin(k), a.cos(y), a.sin(y));
    let skcy = a.mul(sk, cy);
    let fx = a.add(px, skcy);
    let one = a.one();
    let opt = a.add(one, t);
    let pt = a.powr(opt, Rational::new(1, 4).unwrap()).unwrap();
    let fy = a.mul(pt, sy);
    let tape = TaylorTape::new(&a, [x, y], [fx, fy], Some(t), &[("k", 0.3)], 12).unwrap();
    let (t0, y0) = (
        Dd { hi: 0.5, lo: 1e-18 },
        [
            Dd {
                hi: 1.7,
                lo: -3e-17,
            },
            Dd::from(0.2),
        ],
    );
    let sys = Mixed { k: 0.3 };
    let (mut c1, mut c2) = ([[0.0; 2]; 11], [[0.0; 2]; 11]);
    let (mut l1, mut l2) = ([[Dd::default(); 2]; 8], [[Dd::default(); 2]; 8]);
    assert!(sys.coefficients_extended_into(&mut Vec::new(), t0, &y0, 10, &mut c1, &mut l1));
    assert!(tape.coefficients_extended_into(&mut Vec::new(), t0, &y0, 10, &mut c2, &mut l2));
    for k in 0..8 {
        for i in 0..2 {
            let (g, w) = (l1[k][i], l2[k][i]);
            let e = ((g - w).to_f64() / w.to_f64().abs().max(1e-300)).abs();
            assert!(e < 1e-29, "order {k}, component {i}: {e:e}");
        }
    }
    // The f64 orders are the generated ones, within a few ulps of the interpreter's.
    for k in 0..11 {
        for i in 0..2 {
            assert!((c1[k][i] - c2[k][i]).abs() <= 1e-15 * c2[k][i].abs().max(1e-10));
        }
    }
    // A reused workspace gives the same values (the scratch rows are returned each call).
    let mut ws = Vec::new();
    let mut l3 = [[Dd::default(); 2]; 8];
    for _ in 0..3 {
        assert!(sys.coefficients_extended_into(&mut ws, t0, &y0, 10, &mut c1, &mut l3));
        assert_eq!(l3, l1);
    }
}

#[test]
fn the_generated_pendulum_reaches_its_exact_solution() {
    // mpmath, 40 digits: θ(1000) and θ'(1000) from θ₀ = 1 at rest, 2 asin(k cd(t | k²)).
    let exact = [
        -0.027450162128045934406643177931,
        -0.95845809724610744908616590033,
    ];
    let err = |y: &[f64; 2]| (y[0] - exact[0]).abs().max((y[1] - exact[1]).abs());
    let run = |cfg: TaylorConfig| {
        let mut ode = Taylor::new(Pendulum, 0.0, [1.0, 0.0], cfg).unwrap();
        ode.advance_to(1000.0).unwrap();
        err(ode.y())
    };
    let plain = run(TaylorConfig::with_tol(1e-18, 1e-18));
    let extended = run(TaylorConfig::with_tol(1e-18, 1e-18).extended_orders(6));
    eprintln!("generated pendulum at t = 1000: plain {plain:e}, extended {extended:e}");
    assert!(extended <= 1.2e-16, "extended: {extended:e}");
    assert!(plain >= 1e-15, "plain: {plain:e}");
}

/// Drake's babyboot (examples/babyboot.rs) with its Taylor recurrences.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81, taylor = 24)]
#[body(rod, parent = ground, joint = revolute(axis = x), q = q_a,
       parts(body(mass = 0.01, at = [0.0, 0.0, -0.075],
                  inertia = diag(5.0e-6, 5.0e-6, 1.0e-7))))]
#[body(plate, parent = rod, joint = revolute(axis = z, at = [0.0, 0.0, -0.2]), q = q_b,
       parts(body(mass = 0.1, inertia = diag(2.5e-4, 5.0e-5, 2.0e-4))))]
struct Babyboot;

#[test]
fn the_babyboot_reaches_the_extended_modes_accuracy() {
    // MotionGenesis at t = 10 s (Drake's test; the four runs it quotes agree to ~1e-7).
    let reference = [
        -61.312983340691f64.to_radians(),
        -929.47789677244f64.to_radians(),
        -6.7440081040646,
        -2.7795690128833,
    ];
    let y0 = [90f64.to_radians(), 1f64.to_radians(), 0.0, 0.0];
    let dist = |a: &[f64; 4], b: &[f64; 4]| {
        a.iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    let run = |cfg: TaylorConfig| {
        let mut ode = Taylor::new(Babyboot, 0.0, y0, cfg).unwrap();
        ode.advance_to(10.0).unwrap();
        *ode.y()
    };
    let tol = 1e-18;
    let extended = run(TaylorConfig::with_tol(tol, tol).extended_orders(6));
    let plain = run(TaylorConfig::with_tol(tol, tol));
    // The extended mode's own convergence: at 1e-20 (a higher order, other steps) it moves
    // by the last digits only; the plain mode at the same tolerances stays as far from it
    // as its per-step roundings carry it on this chaotic motion.
    let extended_20 = run(TaylorConfig::with_tol(1e-20, 1e-20).extended_orders(8));
    let mut vern = Vern9::new(Babyboot, 0.0, y0, AdaptiveConfig::with_tol(1e-15, 1e-16)).unwrap();
    vern.advance_to(10.0).unwrap();
    eprintln!(
        "babyboot at t = 10: extended vs reference {:e}, plain vs reference {:e}, extended vs extended at 1e-20 {:e}, plain vs extended {:e}, Vern9 vs extended {:e}",
        dist(&extended, &reference),
        dist(&plain, &reference),
        dist(&extended, &extended_20),
        dist(&plain, &extended_20),
        dist(vern.y(), &extended_20),
    );
    // Measured: extended vs reference 6.6e-7 (MotionGenesis's value is good to about 1e-7
    // relative, and qB ≈ −16 rad), extended at 1e-18 vs at 1e-20 1.9e-13, the plain mode at
    // 1e-18 1.3e-9 from it, Vern9 at 1e-15 1.9e-9.
    assert!(dist(&extended, &reference) < 1e-6);
    assert!(dist(&extended, &extended_20) < 1e-12);
    assert!(dist(&plain, &extended_20) > 100.0 * dist(&extended, &extended_20));
}
