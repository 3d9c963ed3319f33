//! The extended mode on sines, cosines and real powers, against independent values: the
//! double-double coefficients of sin(a + τ) and (a + τ)^(3/2) against their closed forms,
//! the pendulum θ'' = −sin θ against its Jacobi-elliptic solution computed to 40 digits with
//! mpmath (θ = 2 asin(k cd(t | k²)), k = sin(θ₀/2)), and the binding of parameters the
//! equations do not read.
// Reference constants are quoted with all their digits.
#![allow(clippy::excessive_precision)]

use precess::codegen::BindingError;
use precess::exact::Dd;
use precess::sym::Arena;
use precess::taylor::{Taylor, TaylorConfig, TaylorError, TaylorSystem, TaylorTape};

/// The double-double coefficients of `y' = f(x)` with `x' = 1` from (x₀, 0): low[k + 1][1]
/// is the order-k coefficient of f(x₀ + τ) divided by k + 1.
fn series_of(
    f: impl Fn(&mut Arena, precess::sym::ExprId) -> precess::sym::ExprId,
    x0: f64,
) -> Vec<[Dd; 2]> {
    let mut a = Arena::new();
    let (x, y) = (a.coordinate("x"), a.coordinate("y"));
    let one = a.one();
    let fx = f(&mut a, x);
    let tape = TaylorTape::new(&a, [x, y], [one, fx], None, &[], 20).unwrap();
    let mut c = [[0.0; 2]; 13];
    let mut low = vec![[Dd::default(); 2]; 13];
    let ok = tape.coefficients_extended_into(
        &mut Vec::new(),
        Dd::from(0.0),
        &[Dd::from(x0), Dd::from(0.0)],
        12,
        &mut c,
        &mut low,
    );
    assert!(ok, "the tape computes no double-double coefficients");
    // The f64 table agrees with the double-double one to its roundings.
    for k in 1..13 {
        let (f, d) = (c[k][1], low[k][1].to_f64());
        assert!(
            (f - d).abs() <= 4e-16 * d.abs().max(1e-3),
            "order {k}: {f} vs {d}"
        );
    }
    low
}

/// (k + 1)! as a double-double (exact: below 2¹⁰⁶ for k ≤ 12).
fn factorial(n: usize) -> Dd {
    (1..=n).fold(Dd::from(1.0), |acc, i| acc * Dd::from(i as f64))
}

#[test]
fn sine_series_matches_its_closed_form_to_30_digits() {
    // sin(a + τ) = Σ sin(a + kπ/2) τᵏ/k!, a = 0.7 (the double), sin a and cos a from mpmath.
    let sin_a = Dd {
        hi: 0.644217687237691,
        lo: 2.8740567927338755e-18,
    };
    let cos_a = Dd {
        hi: 0.7648421872844885,
        lo: -4.013780434022238e-17,
    };
    let low = series_of(|a, x| a.sin(x), 0.7);
    for k in 0..12 {
        let want = [sin_a, cos_a, -sin_a, -cos_a][k % 4];
        let got = low[k + 1][1] * factorial(k + 1);
        let e = (got - want).to_f64();
        assert!(e.abs() < 1e-30, "order {k}: {e:e}");
    }
    // The cosine of the same pair: cos(a + τ) = Σ cos(a + kπ/2) τᵏ/k!.
    let low = series_of(|a, x| a.cos(x), 0.7);
    for k in 0..12 {
        let want = [cos_a, -sin_a, -cos_a, sin_a][k % 4];
        let e = (low[k + 1][1] * factorial(k + 1) - want).to_f64();
        assert!(e.abs() < 1e-30, "cos order {k}: {e:e}");
    }
}

#[test]
fn real_power_series_matches_the_binomial_series_to_30_digits() {
    // (2 + τ)^(3/2) = 2√2 Σ C(3/2, k) (τ/2)ᵏ, C(r, k) = C(r, k − 1)(r − k + 1)/k; √2 from the
    // double-double square root, independent of the power.
    let r = precess::sym::Rational::new(3, 2).unwrap();
    let low = series_of(|ar, x| ar.powr(x, r).unwrap(), 2.0);
    let mut want = Dd::from(2.0).sqrt() * Dd::from(2.0);
    for k in 0..12 {
        if k > 0 {
            want = (want * Dd::from(1.5 - (k - 1) as f64)).div_f64(2.0 * k as f64);
        }
        let got = low[k + 1][1] * Dd::from((k + 1) as f64);
        let e = ((got - want).to_f64() / want.to_f64()).abs();
        assert!(e < 1e-30, "order {k}: {e:e}");
    }
}

#[test]
fn a_sine_of_a_parameter_is_a_double_double_constant() {
    // y' = sin(k) y from y = 1: c₁ = sin 1 to 32 digits (mpmath).
    let mut a = Arena::new();
    let y = a.coordinate("y");
    let k = a.parameter("k");
    let s = a.sin(k);
    let rhs = a.mul(s, y);
    let tape = TaylorTape::new(&a, [y], [rhs], None, &[("k", 1.0)], 10).unwrap();
    let mut c = [[0.0; 1]; 3];
    let mut low = [[Dd::default(); 1]; 3];
    assert!(tape.coefficients_extended_into(
        &mut Vec::new(),
        Dd::from(0.0),
        &[Dd::from(1.0)],
        2,
        &mut c,
        &mut low
    ));
    let sin1 = Dd {
        hi: 0.8414709848078965,
        lo: 1.776845092935536e-18,
    };
    assert!((low[1][0] - sin1).to_f64().abs() < 1e-32);
}

/// The pendulum θ'' = −sin θ from θ₀ = 1, at rest.
fn pendulum() -> TaylorTape<2> {
    let mut a = Arena::new();
    let (th, w) = (a.coordinate("theta"), a.coordinate("omega"));
    let s = a.sin(th);
    let acc = a.neg(s);
    TaylorTape::new(&a, [th, w], [w, acc], None, &[], 40).unwrap()
}

#[test]
fn the_pendulum_reaches_its_exact_solution_in_the_extended_mode() {
    // mpmath, 40 digits: θ(1000) and θ'(1000) from 2 asin(k cd(t | k²)).
    let exact = [
        -0.027450162128045934406643177931,
        -0.95845809724610744908616590033,
    ];
    let err = |y: &[f64; 2]| (y[0] - exact[0]).abs().max((y[1] - exact[1]).abs());
    let run = |cfg: TaylorConfig| {
        let mut ode = Taylor::new(pendulum(), 0.0, [1.0, 0.0], cfg).unwrap();
        ode.advance_to(1000.0).unwrap();
        (err(ode.y()), ode.stats().steps)
    };
    // At tol 1e-18 the truncation is below the double's resolution (at 1e-16 it is not:
    // 2.4e-15 in either mode). Measured: the extended mode lands within an ulp (2.1e-17),
    // the plain mode at 6.2e-14 after the same 3274 steps of order 22, its roundings of the
    // state and of f accumulated.
    let tol = 1e-18;
    let (plain, steps) = run(TaylorConfig::with_tol(tol, tol));
    let (extended, _) = run(TaylorConfig::with_tol(tol, tol).extended_orders(6));
    eprintln!("pendulum at t = 1000: plain {plain:e} ({steps} steps), extended {extended:e}");
    assert!(extended <= 1.2e-16, "extended: {extended:e}");
    assert!(plain >= 1e-15, "plain {plain:e} vs extended {extended:e}");
}

#[test]
fn parameters_the_equations_do_not_read_are_accepted() {
    // A free fall: v' = −g, x' = v. The mass is a parameter of the scene the equations do not
    // read; code that binds every parameter of the scene must still work.
    let mut a = Arena::new();
    let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    let g = a.parameter("g");
    let _mass = a.parameter("m");
    let acc = a.neg(g);
    let bound = [("g", 9.81), ("m", 2.0)];
    let tape = TaylorTape::new(&a, [x, v], [v, acc], None, &bound, 10).unwrap();
    let mut c = [[0.0; 2]; 3];
    tape.coefficients(0.0, &[0.0, 0.0], 2, &mut c);
    assert_eq!(c[2][0], -9.81 / 2.0);
    // An unread parameter is still judged: NaN is refused.
    let nan = TaylorTape::new(
        &a,
        [x, v],
        [v, acc],
        None,
        &[("g", 9.81), ("m", f64::NAN)],
        10,
    );
    assert!(
        matches!(nan, Err(TaylorError::Binding(BindingError::NonFinite { ref name, .. })) if name == "m")
    );
    // A name the scene does not know is refused.
    let bogus = TaylorTape::new(
        &a,
        [x, v],
        [v, acc],
        None,
        &[("g", 9.81), ("mass", 2.0)],
        10,
    );
    assert!(
        matches!(bogus, Err(TaylorError::Binding(BindingError::UnknownParameter { ref name, .. })) if name == "mass")
    );
}

mod properties {
    use precess::exact::Dd;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// sin² + cos² = 1 to 2⁻¹⁰⁰, and the double-double values round to the double ones,
        /// over the range the reduction by π/2 serves.
        #[test]
        fn sine_and_cosine_are_consistent(x in -1.0e6f64..1.0e6, lo in -1.0f64..1.0) {
            let x = Dd::from(x) + Dd::from(lo * 1e-17 * x.abs().max(1e-300));
            let (s, c) = x.sin_cos();
            let one = (Dd::dot([(s, s), (c, c)]) - Dd::from(1.0)).to_f64();
            prop_assert!(one.abs() < 4e-31, "{one:e}");
            // sin(hi + lo) ≈ sin hi + lo cos hi, to the double's precision.
            let first_order = x.hi.sin() + x.lo * x.hi.cos();
            prop_assert!((s.to_f64() - first_order).abs() < 2e-15);
        }

        /// (a^(p/q))^q = a^p to 2⁻⁹⁵ relative, for rational exponents of small denominator.
        #[test]
        fn rational_powers_invert(a in 0.01f64..100.0, p in -7i64..8, q in 2i64..8) {
            let r = p as f64 / q as f64;
            let got = Dd::from(a).powf(r).powi(q);
            let want = Dd::from(a).powi(p);
            let e = ((got - want).to_f64() / want.to_f64()).abs();
            prop_assert!(e < 1e-28, "{a}^({p}/{q}): {e:e}");
        }
    }
}
