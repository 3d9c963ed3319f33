//! `taylor_system!` with the time `t` in its equations: the generated recurrences (the time
//! a series t₀ + τ) and the generated `System::rhs` (reading its `t` argument) against the
//! closed forms of two non-autonomous equations, y' = t·y and a forced oscillator, and
//! against the interpreted tape of a third with the time inside functions.

use precess::ode::{AdaptiveConfig, Dop853Pair, System};
use precess::sym::Arena;
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape};

precess::taylor_system! {
    /// y' = t·y: y(t) = y(t₀) exp((t² − t₀²)/2).
    struct Gaussian;
    state [y];
    taylor = 30;
    d/dt y = t * y;
}

precess::taylor_system! {
    /// x'' = −ω² x + cos(Ω t), as a first-order system.
    struct Forced {
        w: f64,
        big_w: f64,
    }
    state [x, v];
    taylor = 24;
    d/dt x = v;
    d/dt v = -w * w * x + (big_w * t).cos();
}

precess::taylor_system! {
    /// The time inside a sine–cosine pair, a square and a quotient.
    struct Mixed {
        k: f64,
    }
    state [x];
    taylor = 16;
    d/dt x = t.sin() * x + k * t * t - x / (2.0 + cos(t));
}

precess::taylor_system! {
    /// The time as an output itself and squared: x = x₀ + (t² − t₀²)/2, y = y₀ + t³ − t₀³.
    struct Clock;
    state [x, y];
    taylor = 6;
    d/dt x = t;
    d/dt y = 3.0 * t * t;
}

const FORCED: Forced = Forced { w: 1.3, big_w: 0.7 };
/// x(0), v(0) of the forced runs.
const X0: [f64; 2] = [0.4, -0.9];

/// The forced oscillator's solution from `X0` at 0 and its derivatives:
/// x = A cos ωt + B sin ωt + cos Ωt / (ω² − Ω²), A = x₀ − 1/(ω² − Ω²), B = v₀/ω; the k-th
/// derivative turns each phase by kπ/2 and scales it by the frequency to the k.
fn forced_derivative(t: f64, k: u32) -> f64 {
    let (w, big_w) = (FORCED.w, FORCED.big_w);
    let d = w * w - big_w * big_w;
    let (a, b) = (X0[0] - 1.0 / d, X0[1] / w);
    let turn = f64::from(k) * std::f64::consts::FRAC_PI_2;
    let wk = w.powi(k as i32);
    a * wk * (w * t + turn).cos()
        + b * wk * (w * t + turn).sin()
        + big_w.powi(k as i32) * (big_w * t + turn).cos() / d
}

fn factorial(k: u32) -> f64 {
    (1..=k).map(f64::from).product()
}

#[test]
fn gaussian_coefficients_are_those_of_its_closed_form() {
    // y(t₀ + τ) = y₀ exp(t₀ τ) exp(τ²/2): the Cauchy product of the two exponential series,
    // c_k = y₀ Σ_{j ≤ k/2} t₀^{k−2j} / ((k − 2j)! j! 2ʲ).
    for (t0, y0) in [(0.0, 1.0), (0.8, -2.5), (-1.7, 0.3)] {
        let mut c = [[0.0; 1]; 31];
        Gaussian.coefficients(t0, &[y0], 30, &mut c);
        for (k, ck) in c.iter().enumerate() {
            let k = k as u32;
            let exact: f64 = (0..=k / 2)
                .map(|j| {
                    let i = k - 2 * j;
                    f64::powi(t0, i as i32) / (factorial(i) * factorial(j) * 2f64.powi(j as i32))
                })
                .sum::<f64>()
                * y0;
            assert!(
                (ck[0] - exact).abs() <= 1e-13 * exact.abs(),
                "t0 = {t0}: coefficient {k}: {} against {exact}",
                ck[0]
            );
        }
    }
    assert_eq!(TaylorSystem::<1>::max_order(&Gaussian), 30);
}

#[test]
fn gaussian_integrated_by_taylor_matches_its_closed_form() {
    let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
    for (t0, t_end) in [(0.0, 3.0), (-2.0, 1.5)] {
        let s = precess::taylor::solve(Gaussian, t0, [1.0], t_end, &[], cfg)
            .expect("Taylor integrates y' = t y");
        let exact = ((t_end * t_end - t0 * t0) / 2.0f64).exp();
        assert!(
            (s.y[0] - exact).abs() <= 1e-12 * exact,
            "from {t0} to {t_end}: {} against {exact}",
            s.y[0]
        );
    }
}

#[test]
fn clock_coefficients_are_the_polynomials_of_the_time() {
    // x(t₀ + τ) = x₀ + t₀ τ + τ²/2; y(t₀ + τ) = y₀ + 3t₀² τ + 3t₀ τ² + τ³: exact in f64.
    for t0 in [0.0, 1.5, -2.25] {
        let mut c = [[f64::NAN; 2]; 7];
        Clock.coefficients(t0, &[0.5, -1.0], 6, &mut c);
        let want = [
            [0.5, -1.0],
            [t0, 3.0 * t0 * t0],
            [0.5, 3.0 * t0],
            [0.0, 1.0],
            [0.0, 0.0],
            [0.0, 0.0],
            [0.0, 0.0],
        ];
        assert_eq!(c, want, "t0 = {t0}");
    }
}

#[test]
fn forced_oscillator_coefficients_are_its_derivatives_over_factorials() {
    for t0 in [0.0, 2.3, -7.1] {
        let y = [forced_derivative(t0, 0), forced_derivative(t0, 1)];
        let mut c = [[0.0; 2]; 25];
        FORCED.coefficients(t0, &y, 24, &mut c);
        for (k, ck) in c.iter().enumerate() {
            let k = k as u32;
            let exact = [
                forced_derivative(t0, k) / factorial(k),
                forced_derivative(t0, k + 1) / factorial(k),
            ];
            for i in 0..2 {
                assert!(
                    (ck[i] - exact[i]).abs() <= 1e-14 * exact[i].abs().max(1.0),
                    "t0 = {t0}, component {i}, coefficient {k}: {} against {}",
                    ck[i],
                    exact[i]
                );
            }
        }
        // The generated right-hand side reads its `t` argument.
        let mut f = [0.0; 2];
        FORCED.rhs(t0, &y, &mut f);
        assert!((f[0] - forced_derivative(t0, 1)).abs() < 1e-14);
        assert!((f[1] - forced_derivative(t0, 2)).abs() < 1e-14);
    }
}

#[test]
fn forced_oscillator_integrated_by_taylor_and_dop853_matches_its_closed_form() {
    let t_end = 20.0;
    let exact = [forced_derivative(t_end, 0), forced_derivative(t_end, 1)];
    let taylor = precess::taylor::solve(
        &FORCED,
        0.0,
        X0,
        t_end,
        &[],
        TaylorConfig::with_tol(1e-15, 1e-15),
    )
    .expect("Taylor integrates the forced oscillator");
    // The pairs call the generated `System::rhs`, which must read the time too.
    let dop = precess::ode::solve::<Dop853Pair, _, 2>(
        &FORCED,
        0.0,
        X0,
        t_end,
        &[],
        AdaptiveConfig::with_tol(1e-13, 1e-13),
    )
    .expect("DOP853 integrates the forced oscillator");
    for (i, want) in exact.into_iter().enumerate() {
        let (ours, pair) = (taylor.y[i], dop.y[i]);
        assert!(
            (ours - want).abs() <= 1e-12 * want.abs().max(1.0),
            "Taylor, component {i}: {ours} against {want}"
        );
        assert!(
            (pair - want).abs() <= 1e-9 * want.abs().max(1.0),
            "DOP853, component {i}: {pair} against {want}"
        );
    }
}

#[test]
fn time_inside_functions_matches_the_interpreted_tape() {
    let k = 0.6;
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let t = a.time();
    let kp = a.parameter("k");
    let (two, sin_t, cos_t) = (a.integer(2), a.sin(t), a.cos(t));
    let growth = a.mul(sin_t, x);
    let kt = a.mul(kp, t);
    let ktt = a.mul(kt, t);
    let den = a.add(two, cos_t);
    let damp = a.div(x, den).expect("2 + cos t is not zero");
    let sum = a.add(growth, ktt);
    let rhs = a.sub(sum, damp);
    let tape = TaylorTape::new(&a, [x], [rhs], Some(t), &[("k", k)], 16).expect("the tape");
    let sys = Mixed { k };
    for (t0, x0) in [(0.0, 1.0), (1.9, -0.4), (-3.2, 2.2)] {
        let mut ours = [[0.0; 1]; 17];
        let mut reference = [[0.0; 1]; 17];
        sys.coefficients(t0, &[x0], 16, &mut ours);
        tape.coefficients(t0, &[x0], 16, &mut reference);
        for j in 0..=16 {
            let (o, r) = (ours[j][0], reference[j][0]);
            assert!(
                (o - r).abs() <= 1e-13 * r.abs().max(1.0),
                "t0 = {t0}, coefficient {j}: {o} against {r}"
            );
        }
        // Order 1 is the right-hand side, here in f64 directly.
        let direct = t0.sin() * x0 + k * t0 * t0 - x0 / (2.0 + t0.cos());
        assert!((ours[1][0] - direct).abs() < 1e-14 * direct.abs().max(1.0));
        let mut f = [0.0];
        sys.rhs(t0, &[x0], &mut f);
        assert!((f[0] - direct).abs() < 1e-14 * direct.abs().max(1.0));
    }
}
