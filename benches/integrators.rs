//! Integrator benchmarks and work-precision data: DETEST B5 to t = 20 and the I = (3, 5, 9)
//! near-separatrix body to t = 100, for Vern9, DOP853, DOPRI5, RK4, the splittings and the exact
//! solution.
//!
//! `cargo bench -p precess-benches --bench integrators` prints the work-precision table (error, right-hand-side
//! evaluations) and then times each configuration with criterion.
//! `PRECESS_ALLOC_PROBE=<n> valgrind ./integrators-…` runs each stepping loop n times without
//! criterion: the heap-allocation count valgrind reports does not change with n, i.e. the
//! step loops do not allocate.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use std::hint::black_box;
use std::time::Duration;

use criterion::Criterion;
use nalgebra::{UnitQuaternion, Vector3};
use precess_core::exact::{FreeBodyExact, Jacobi};
use precess_core::ode::{
    AdaptiveConfig, Dop853Pair, Dopri5Pair, EmbeddedPair, FixedStepConfig, Rk4, System, Vern9Pair,
    solve,
};
use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
use precess_testkit::systems::{B5, FreeBody, max_diff};

/// DETEST B5 y(20), 30-digit reference.
const B5_Y20: [f64; 3] = [
    -0.939_657_079_872_920_396_19,
    -0.342_117_775_400_074_906_53,
    0.741_412_659_619_995_300_78,
];
const SEP_I: [f64; 3] = [3.0, 5.0, 9.0];
const SEP_M0: [f64; 3] = [0.0, 2.0, 0.01];
const SEP_T: f64 = 100.0;

/// One method at one setting on one problem: returns (final state, rhs evaluations).
#[derive(Clone, Copy)]
enum Method {
    Vern9(f64),
    Dop853(f64),
    Dopri5(f64),
    Rk4(f64),
    Split(SplittingOrder, f64),
    Exact,
}

impl Method {
    fn label(&self) -> String {
        match self {
            Method::Vern9(t) => format!("Vern9 tol {t:.0e}"),
            Method::Dop853(t) => format!("DOP853 tol {t:.0e}"),
            Method::Dopri5(t) => format!("DOPRI5 tol {t:.0e}"),
            Method::Rk4(h) => format!("RK4 h {h}"),
            Method::Split(o, h) => format!("split {o:?} h {h}"),
            Method::Exact => "exact".to_string(),
        }
    }
}

fn adaptive<P: EmbeddedPair, S: System<3>>(
    sys: S,
    y0: [f64; 3],
    t: f64,
    tol: f64,
) -> ([f64; 3], u64) {
    let s = solve::<P, _, 3>(sys, 0.0, y0, t, &[], AdaptiveConfig::with_tol(tol, tol)).unwrap();
    (s.y, s.stats.rhs_evals)
}

fn rk4<S: System<3>>(sys: S, y0: [f64; 3], t: f64, h: f64) -> ([f64; 3], u64) {
    let mut r = Rk4::new(sys, 0.0, y0, FixedStepConfig::with_step(h)).unwrap();
    r.advance_to(t).unwrap();
    (*r.y(), r.stats().rhs_evals)
}

fn run_b5(m: Method) -> ([f64; 3], u64) {
    let y0 = [0.0, 1.0, 1.0];
    match m {
        Method::Vern9(tol) => adaptive::<Vern9Pair, _>(B5, y0, 20.0, tol),
        Method::Dop853(tol) => adaptive::<Dop853Pair, _>(B5, y0, 20.0, tol),
        Method::Dopri5(tol) => adaptive::<Dopri5Pair, _>(B5, y0, 20.0, tol),
        Method::Rk4(h) => rk4(B5, y0, 20.0, h),
        Method::Split(..) => unreachable!("B5 is not a rigid body"),
        Method::Exact => {
            let (s, c, d) = Jacobi::new(0.49).unwrap().sncndn(black_box(20.0));
            ([s, c, d], 0)
        }
    }
}

fn run_sep(m: Method) -> ([f64; 3], u64) {
    match m {
        Method::Vern9(tol) => adaptive::<Vern9Pair, _>(FreeBody(SEP_I), SEP_M0, SEP_T, tol),
        Method::Dop853(tol) => adaptive::<Dop853Pair, _>(FreeBody(SEP_I), SEP_M0, SEP_T, tol),
        Method::Dopri5(tol) => adaptive::<Dopri5Pair, _>(FreeBody(SEP_I), SEP_M0, SEP_T, tol),
        Method::Rk4(h) => rk4(FreeBody(SEP_I), SEP_M0, SEP_T, h),
        Method::Split(order, h) => {
            let s = FreeBodySplitting::new(SEP_I, order).unwrap();
            let mut y = BodyMomentum {
                q: UnitQuaternion::identity(),
                m: Vector3::from(SEP_M0),
            };
            // Equal steps that land on SEP_T exactly.
            let n = (SEP_T / h).round() as u64;
            s.run(&mut y, SEP_T / n as f64, n).unwrap();
            ([y.m.x, y.m.y, y.m.z], 0)
        }
        Method::Exact => (
            FreeBodyExact::new(SEP_I, SEP_M0)
                .unwrap()
                .m_at(black_box(SEP_T))
                .unwrap()
                .into(),
            0,
        ),
    }
}

fn b5_methods() -> Vec<Method> {
    let mut v: Vec<Method> = [1e-6, 1e-8, 1e-10, 1e-12, 1e-14]
        .map(Method::Dop853)
        .to_vec();
    v.extend([1e-8, 1e-10, 1e-12, 1e-14].map(Method::Vern9));
    v.extend([1e-6, 1e-8, 1e-10, 1e-12].map(Method::Dopri5));
    v.extend([0.1, 0.03, 0.01, 0.003].map(Method::Rk4));
    v.push(Method::Exact);
    v
}

fn sep_methods() -> Vec<Method> {
    let mut v: Vec<Method> = [1e-8, 1e-10, 1e-12, 1e-14].map(Method::Dop853).to_vec();
    v.extend([1e-10, 1e-12, 1e-14].map(Method::Vern9));
    v.extend([1e-8, 1e-10, 1e-12].map(Method::Dopri5));
    v.extend([0.1, 0.03, 0.01].map(Method::Rk4));
    for o in [
        SplittingOrder::Two,
        SplittingOrder::Four,
        SplittingOrder::Six,
    ] {
        v.extend([0.1, 0.05, 0.02].map(|h| Method::Split(o, h)));
    }
    v.push(Method::Exact);
    v
}

fn table() {
    println!("work-precision: B5, max-norm error at t = 20 against the 30-digit reference");
    for m in b5_methods() {
        let (y, evals) = run_b5(m);
        println!(
            "  {:<22} error {:9.2e}  rhs evals {evals}",
            m.label(),
            max_diff(&y, &B5_Y20)
        );
    }
    let exact: [f64; 3] = FreeBodyExact::new(SEP_I, SEP_M0)
        .unwrap()
        .m_at(SEP_T)
        .unwrap()
        .into();
    println!(
        "work-precision: I = (3,5,9), m0 = (0,2,0.01), error at t = 100 against the exact solution"
    );
    for m in sep_methods() {
        let (y, evals) = run_sep(m);
        println!(
            "  {:<22} error {:9.2e}  rhs evals {evals}",
            m.label(),
            max_diff(&y, &exact)
        );
    }
}

fn main() {
    if let Ok(n) = std::env::var("PRECESS_ALLOC_PROBE") {
        // Allocation probe: the same loops n times; compare valgrind's counts for two n.
        let n: usize = n.parse().unwrap_or(1);
        for _ in 0..n {
            black_box(run_b5(Method::Dop853(1e-10)));
            black_box(run_b5(Method::Vern9(1e-10)));
            black_box(run_b5(Method::Dopri5(1e-10)));
            black_box(run_b5(Method::Rk4(0.01)));
            black_box(run_sep(Method::Split(SplittingOrder::Four, 0.1)));
            black_box(run_sep(Method::Exact));
        }
        return;
    }
    table();
    let mut c = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .configure_from_args();
    let mut g = c.benchmark_group("b5");
    for m in b5_methods() {
        g.bench_function(m.label(), |b| b.iter(|| run_b5(black_box(m))));
    }
    g.finish();
    let mut g = c.benchmark_group("sep359");
    for m in sep_methods() {
        g.bench_function(m.label(), |b| b.iter(|| run_sep(black_box(m))));
    }
    g.finish();
    c.final_summary();
}
