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
    // ṁ_p = m_q m_r (1/I_r − 1/I_q) for (p, q, r) cyclic.
    let rate = |a: &mut Arena, q: usize, r: usize| {
        let d = a.sub(inv[r], inv[q]);
        let mm = a.mul(m[q], m[r]);
        a.mul(mm, d)
    };
    let rhs = [rate(&mut a, 1, 2), rate(&mut a, 2, 0), rate(&mut a, 0, 1)];
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
    TaylorTape::new(
        &a,
        y,
        [f1, f2, f3],
        None,
        &[("num", 51.0), ("den", 100.0)],
        40,
    )
    .unwrap()
}

fn max_err(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

fn run(sys: TaylorTape<3>, y0: [f64; 3], t: f64, cfg: TaylorConfig) -> [f64; 3] {
    let mut ode = Taylor::new(sys, 0.0, y0, cfg).unwrap();
    ode.advance_to(t).unwrap();
    *ode.y()
}

const M0: [f64; 3] = [0.0, 2.0, 0.01];

/// The exact m(200) of a body from M0, checked against the value quoted from the bench.
fn exact_at_200(inertia: [f64; 3], quoted: [f64; 3]) -> [f64; 3] {
    let m = FreeBodyExact::new(inertia, M0)
        .unwrap()
        .m_at(200.0)
        .unwrap();
    let m = [m[0], m[1], m[2]];
    assert!(max_err(&m, &quoted) < 1e-15, "{m:?}");
    m
}

#[test]
fn extended_mode_reaches_1e_14_on_the_357_body_where_the_plain_mode_does_not() {
    let inertia = [3.0, 5.0, 7.0];
    let exact = exact_at_200(
        inertia,
        [
            -0.20025294777805186,
            -1.966298347069268,
            0.30605484348211964,
        ],
    );
    for tol in [1e-15, 1e-16, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let ext = max_err(
            &run(free_body(inertia), M0, 200.0, cfg.extended_orders(6)),
            &exact,
        );
        // Measured: 1.8e-15, 5.0e-16, 5.6e-16 (the last digits of m(200) and of the
        // reference); the goal is 1e-14.
        let bound = if tol < 1e-15 { 1e-15 } else { 1e-14 };
        assert!(ext <= bound, "tol {tol:e}: extended {ext:e}");
    }
    // The plain mode at the tightest tolerance: 6e-13 measured (1e-13 – 5e-12 as roundings
    // change), the per-step rounding of c₁ = f(y) gathered into phase.
    let plain = max_err(
        &run(
            free_body(inertia),
            M0,
            200.0,
            TaylorConfig::with_tol(1e-18, 1e-18),
        ),
        &exact,
    );
    assert!(plain > 1e-14, "plain {plain:e}");
}

#[test]
fn extended_mode_reaches_1e_15_on_the_359_body_where_the_plain_mode_does_not() {
    let inertia = [3.0, 5.0, 9.0];
    let exact = exact_at_200(
        inertia,
        [0.5586653843883227, -1.794361298823517, 0.6842956360891311],
    );
    for tol in [1e-16, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol).extended_orders(6);
        let ext = max_err(&run(free_body(inertia), M0, 200.0, cfg), &exact);
        // Measured: 3.3e-16, 5.6e-16.
        assert!(ext <= 1e-15, "tol {tol:e}: extended {ext:e}");
    }
    let plain = max_err(
        &run(
            free_body(inertia),
            M0,
            200.0,
            TaylorConfig::with_tol(1e-18, 1e-18),
        ),
        &exact,
    );
    // Measured 3.8e-12.
    assert!(plain > 1e-14, "plain {plain:e}");
}

#[test]
fn b5_to_t20_in_extended_mode_is_the_reference_rounded() {
    let reference = [
        -0.93965707987292039619,
        -0.34211777540007490653,
        0.74141265961999530078,
    ];
    let y0 = [0.0, 1.0, 1.0];
    for tol in [1e-16, 1e-18] {
        let cfg = TaylorConfig::with_tol(tol, tol).extended_orders(6);
        let ext = max_err(&run(b5(), y0, 20.0, cfg), &reference);
        // One ulp of |y1| ≈ 0.94 is 1.1e-16: the result is the reference to the last bit
        // of a double (measured: 0 at both tolerances, against 1.7e-16 and 4.4e-16 plain).
        assert!(ext <= 1.2e-16, "tol {tol:e}: extended {ext:e}");
    }
}

/// The tape's double-double c₁ and c₂ of the free body from an integer state against their
/// rational values: c₁ = m₂m₃(1/7 − 1/5) = −2m₂m₃/35, which no double holds, and
/// c₂ = ½ d/dt c₁ = −(m₂'m₃ + m₂m₃')/35.
#[test]
fn double_double_coefficients_are_the_rational_ones() {
    let tape = free_body([3.0, 5.0, 7.0]);
    let y = [Dd::from(1.0), Dd::from(2.0), Dd::from(3.0)];
    let mut c = [[0.0; 3]; 4];
    let mut low = [[Dd::default(); 3]; 3];
    assert!(tape.coefficients_extended_into(
        &mut Vec::new(),
        Dd::from(0.0),
        &y,
        3,
        &mut c,
        &mut low
    ));
    // m₁' = m₂m₃(1/7 − 1/5) = −12/35, m₂' = m₃m₁(1/3 − 1/7) = 12/21, m₃' = m₁m₂(1/5 − 1/3)
    // = −4/15; m₁'' coefficient: (m₂'m₃ + m₂m₃')(−2/35)/2.
    let d = |x: f64| Dd::from(x);
    let residuals = [
        low[1][0] * d(35.0) + d(12.0),
        low[1][1] * d(21.0) - d(12.0),
        low[1][2] * d(15.0) + d(4.0),
        // c₂[0]·35·2·21·15 = −2·(12·3·15 + 2·(−4)·21) = −2·372
        low[2][0] * d(35.0 * 2.0 * 21.0 * 15.0) + d(2.0 * 372.0),
    ];
    for r in residuals {
        assert!(r.to_f64().abs() < 1e-27, "{:e}", r.to_f64());
    }
    // The f64 table agrees with the double-double one to its roundings (a few ulps of 0.34).
    assert!((c[1][0] - low[1][0].to_f64()).abs() < 3e-16);
}

#[test]
fn the_extended_mode_is_refused_where_it_cannot_be_had() {
    let cfg = TaylorConfig::with_tol(1e-16, 1e-16).extended_orders(6);
    // A hand-written system that does not implement it: the provided method says no, and
    // the error names the cause, not a parameter's range.
    #[derive(Debug)]
    struct Decay;
    impl TaylorSystem<1> for Decay {
        type Workspace = ();
        fn max_order(&self) -> usize {
            30
        }
        fn coefficients_into(
            &self,
            _: &mut (),
            _: f64,
            y: &[f64; 1],
            order: usize,
            c: &mut [[f64; 1]],
        ) {
            c[0] = *y;
            for k in 1..=order {
                c[k][0] = -c[k - 1][0] / k as f64;
            }
        }
    }
    let err = Taylor::new(Decay, 0.0, [1.0], cfg).unwrap_err();
    assert!(
        matches!(err, OdeError::NoExtendedCoefficients { low: 6 }),
        "{err:?}"
    );
    assert!(
        err.to_string()
            .contains("coefficients_extended_into returns false")
    );
    // No double-double order at all is a configuration error.
    let none = TaylorConfig::with_tol(1e-16, 1e-16).extended_orders(0);
    assert!(
        matches!(none.validate(), Err(OdeError::InvalidParameter { value, .. }) if value == 0.0)
    );
    // Nor more than any order can be: the table of L + 1 rows is never sized from a wild L.
    let wild = TaylorConfig::with_tol(1e-16, 1e-16).extended_orders(usize::MAX);
    assert!(matches!(
        Taylor::new(free_body([3.0, 5.0, 7.0]), 0.0, M0, wild),
        Err(OdeError::InvalidParameter { .. })
    ));
}

/// Tolerances below 1e-16 are taken at their word in the extended mode: the Jorba–Zou order
/// ⌈1 − ½ ln ε⌉ is 22 at 1e-18 and 25 at 1e-20, and the run still lands on the reference.
#[test]
fn tolerances_below_double_precision_set_the_order() {
    let exact = exact_at_200(
        [3.0, 5.0, 7.0],
        [
            -0.20025294777805186,
            -1.966298347069268,
            0.30605484348211964,
        ],
    );
    for (tol, order) in [(1e-18, 22), (1e-20, 25)] {
        let cfg = TaylorConfig::with_tol(tol, tol).extended_orders(6);
        let mut ode = Taylor::new(free_body([3.0, 5.0, 7.0]), 0.0, M0, cfg).unwrap();
        ode.step(200.0).unwrap();
        assert_eq!(ode.last_step().0, order);
        ode.advance_to(200.0).unwrap();
        assert!(max_err(ode.y(), &exact) <= 1e-15);
    }
}

/// The time enters in double-double: for x' = t, c₁ = t keeps the low word given and
/// c₂ = ½.
#[test]
fn the_time_series_is_double_double() {
    let mut a = Arena::new();
    let (x, t) = (a.coordinate("x"), a.coordinate("t"));
    let tape = TaylorTape::new(&a, [x], [t], Some(t), &[], 10).unwrap();
    let mut c = [[0.0; 1]; 4];
    let mut low = [[Dd::default(); 1]; 3];
    let t0 = Dd { hi: 1.0, lo: 1e-20 };
    assert!(tape.coefficients_extended_into(
        &mut Vec::new(),
        t0,
        &[Dd::from(0.0)],
        3,
        &mut c,
        &mut low
    ));
    assert_eq!(low[1][0], t0);
    assert_eq!(low[2][0], Dd::from(0.5));
    assert_eq!(c[3][0], 0.0);
}

/// Dense output in the extended mode is the last step's polynomial on the double-double
/// state (y_hi + y_lo): inside the last step before T = 200 it matches the exact flow as
/// the steps do.
#[test]
fn dense_output_in_the_extended_mode_is_as_accurate_as_the_steps() {
    let inertia = [3.0, 5.0, 7.0];
    let exact = FreeBodyExact::new(inertia, M0).unwrap();
    let cfg = TaylorConfig::with_tol(1e-18, 1e-18).extended_orders(6);
    let mut ode = Taylor::new(free_body(inertia), 0.0, M0, cfg).unwrap();
    ode.advance_to(199.0).unwrap();
    ode.step(1e6).unwrap();
    let (t0, t1) = (ode.last_step_start(), ode.t());
    for theta in [0.0, 0.25, 0.5, 0.75, 1.0] {
        let t = t0 + theta * (t1 - t0);
        let m = exact.m_at(t).unwrap();
        let err = max_err(&ode.dense_at(t).unwrap(), &[m[0], m[1], m[2]]);
        // The state's error there is ~5e-16; the f64 polynomial adds a few ulps.
        assert!(err <= 2e-15, "θ = {theta}: {err:e}");
    }
}
