//! Real powers `x^r` (a non-integer rational `r`) from the symbolic engine to the Taylor
//! integrator: the derivative against the closed form, the lowered program against `powf`,
//! and y' = y^(3/2), y(0) = 1, whose solution is y = (1 − t/2)^(−2), through the generated
//! recurrences of `taylor_system!` and through the interpreted tape.

use precess::codegen::Program;
use precess::sym::{Arena, Rational, SymError};
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape};

precess::taylor_system! {
    /// y' = y^(3/2): y = (1 − t/2)^(−2) from y(0) = 1, blowing up at t = 2.
    struct Blowup;
    state [y];
    taylor = 30;
    d/dt y = y.powf(1.5);
}

precess::taylor_system! {
    /// x' = x^(−1/3) as a call with a negative exponent, y' = (1 + t)^(1/4) · y.
    struct Mixed;
    state [x, y];
    taylor = 12;
    d/dt x = powf(x, -0.333333333333333333333333333333333333);
    d/dt y = (1.0 + t).powf(0.25) * y;
}

precess::taylor_system! {
    /// y' = k^(3/2) y, the power of a field a constant along the solution: y = e^(k^(3/2) t).
    struct Growth {
        k: f64,
    }
    state [y];
    taylor = 16;
    d/dt y = k.powf(1.5) * y;
}

fn three_halves() -> Rational {
    Rational::new(3, 2).unwrap()
}

#[test]
fn derivative_of_a_real_power_is_its_closed_form() {
    // d/dx x^(3/2) = (3/2) x^(1/2); d/dx (1 + x²)^(−1/3) = −(2/3) x (1 + x²)^(−4/3).
    let mut a = Arena::new();
    let x = a.parameter("x");
    let p = a.powr(x, three_halves()).unwrap();
    let s = a.as_symbol(x).unwrap();
    let dp = a.diff(p, s);
    let x2 = a.powi(x, 2).unwrap();
    let one = a.one();
    let base = a.add(one, x2);
    let q = a.powr(base, Rational::new(-1, 3).unwrap()).unwrap();
    let dq = a.diff(q, s);
    for v in [0.3, 1.0, 2.7, 40.0] {
        let want = 1.5 * f64::sqrt(v);
        assert!((a.eval(dp, &[v]) - want).abs() <= 1e-15 * want);
        let want = -2.0 / 3.0 * v * (1.0 + v * v).powf(-4.0 / 3.0);
        assert!((a.eval(dq, &[v]) - want).abs() <= 1e-15 * want.abs());
    }
}

#[test]
fn real_power_constructor_folds_and_refuses() {
    let mut a = Arena::new();
    let x = a.parameter("x");
    // An integer exponent is the integer power, one half the square root.
    assert_eq!(a.powr(x, Rational::integer(3)), a.powi(x, 3));
    assert_eq!(a.powr(x, Rational::new(1, 2).unwrap()), a.sqrt(x));
    let minus_two = a.integer(-2);
    assert!(matches!(
        a.powr(minus_two, three_halves()),
        Err(SymError::RealPowerUndefined { .. })
    ));
    let zero = a.zero();
    assert_eq!(a.powr(zero, three_halves()), Ok(zero));
    assert!(a.powr(zero, -three_halves()).is_err());
}

#[test]
fn lowered_real_power_is_powf() {
    let mut a = Arena::new();
    let x = a.parameter("x");
    let y = a.parameter("y");
    let r = Rational::new(-7, 3).unwrap();
    let sum = a.add(x, y);
    let e = a.powr(sum, r).unwrap();
    let p = Program::lower(&a, &[e]);
    for (xv, yv) in [(0.4, 1.1), (3.0, 5.5)] {
        let got = p.eval(&[xv, yv])[0];
        let want = (xv + yv).powf(-7.0 / 3.0);
        assert!((got - want).abs() <= 1e-15 * want);
    }
    assert_eq!(p.op_count().powfs, 1);
    let code = p.to_tokens(&mut |_| Default::default());
    assert!(code.lets.to_string().contains("powf"));
    assert_eq!(
        precess::codegen::latex(&a, e),
        "{\\left(x + y\\right)}^{-7/3}"
    );
}

/// The coefficients of y = (1 − t/2)^(−2) about t₀: with u = τ/(2 − t₀),
/// y = (2/(2 − t₀))² (1 − u)^(−2) = (2/(2 − t₀))² Σ (k + 1) uᵏ.
fn blowup_coefficient(t0: f64, k: usize) -> f64 {
    let h = 2.0 - t0;
    (2.0 / h).powi(2) * (k + 1) as f64 / h.powi(k as i32)
}

#[test]
fn generated_power_coefficients_are_the_closed_form() {
    for t0 in [0.0, 0.7] {
        let y0 = blowup_coefficient(t0, 0);
        let mut c = [[0.0; 1]; 31];
        Blowup.coefficients(t0, &[y0], 30, &mut c);
        for (k, ck) in c.iter().enumerate() {
            let want = blowup_coefficient(t0, k);
            assert!(
                (ck[0] - want).abs() <= 1e-13 * want,
                "t0 = {t0}, order {k}: {} against {want}",
                ck[0]
            );
        }
    }
}

#[test]
fn blowup_integrated_by_taylor_matches_its_closed_form() {
    let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
    let exact = 4.0; // (1 − 1/2)^(−2)
    let generated =
        precess::taylor::solve(Blowup, 0.0, [1.0], 1.0, &[], cfg).expect("generated recurrences");
    assert!(
        (generated.y[0] - exact).abs() <= 1e-12 * exact,
        "{}",
        generated.y[0]
    );
    let mut a = Arena::new();
    let y = a.coordinate("y");
    let rhs = a.powr(y, three_halves()).unwrap();
    let tape = TaylorTape::new(&a, [y], [rhs], None, &[], 30).unwrap();
    let interpreted =
        precess::taylor::solve(&tape, 0.0, [1.0], 1.0, &[], cfg).expect("interpreted tape");
    assert!(
        (interpreted.y[0] - exact).abs() <= 1e-12 * exact,
        "{}",
        interpreted.y[0]
    );
}

#[test]
fn generated_and_interpreted_real_powers_agree() {
    // The same system through the tape: the emitted code runs the interpreter's sums in
    // the same order, so the two agree bit for bit.
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let y = a.coordinate("y");
    let t = a.time();
    let third = precess::sym::parse_decimal("-0.333333333333333333333333333333333333").unwrap();
    let fx = a.powr(x, third).unwrap();
    let one = a.one();
    let base = a.add(one, t);
    let root = a.powr(base, Rational::new(1, 4).unwrap()).unwrap();
    let fy = a.mul(root, y);
    let tape = TaylorTape::new(&a, [x, y], [fx, fy], Some(t), &[], 12).unwrap();
    let (mut c, mut d) = ([[0.0; 2]; 13], [[0.0; 2]; 13]);
    Mixed.coefficients(0.3, &[1.7, 0.9], 12, &mut c);
    tape.coefficients(0.3, &[1.7, 0.9], 12, &mut d);
    for (k, (ck, dk)) in c.iter().zip(&d).enumerate() {
        for i in 0..2 {
            assert!(
                ck[i].to_bits() == dk[i].to_bits(),
                "order {k}, component {i}: {} against {}",
                ck[i],
                dk[i]
            );
        }
    }
    // Order 1 is the right-hand side itself.
    assert!((c[1][0] - 1.7f64.powf(-1.0 / 3.0)).abs() < 1e-15);
    assert!((c[1][1] - 1.3f64.powf(0.25) * 0.9).abs() < 1e-15);
}

#[test]
fn real_power_of_a_field_is_a_constant_rate() {
    // c_j = λ^j / j! with λ = k^(3/2) = 0.8.
    let growth = Growth {
        k: 0.8f64.powf(2.0 / 3.0),
    };
    let mut c = [[0.0; 1]; 17];
    growth.coefficients(0.0, &[1.0], 16, &mut c);
    let mut want = 1.0;
    for (j, cj) in c.iter().enumerate() {
        if j > 0 {
            want *= 0.8 / j as f64;
        }
        assert!(
            (cj[0] - want).abs() <= 1e-14 * want,
            "order {j}: {} against {want}",
            cj[0]
        );
    }
}

#[test]
fn a_constant_made_non_finite_by_its_parameters_is_a_typed_error() {
    // y' = k^(3/2) y with k a parameter: a negative k has no real power, which must be an
    // error at construction, not NaN coefficients; a positive k builds and gives e^(k^1.5 t).
    let mut a = Arena::new();
    let y = a.coordinate("y");
    let k = a.parameter("k");
    let rate = a.powr(k, three_halves()).unwrap();
    let rhs = a.mul(rate, y);
    let err = TaylorTape::new(&a, [y], [rhs], None, &[("k", -4.0)], 10).unwrap_err();
    match err {
        precess::taylor::TaylorError::NonFiniteConstant { operation, value } => {
            assert_eq!(operation, "a real power");
            assert!(value.is_nan());
        }
        other => panic!("expected NonFiniteConstant, got {other:?}"),
    }
    let tape = TaylorTape::new(&a, [y], [rhs], None, &[("k", 4.0)], 10).unwrap();
    let mut c = [[0.0; 1]; 3];
    tape.coefficients(0.0, &[1.0], 2, &mut c);
    // 4^(3/2) = 8: c₁ = 8, c₂ = 8²/2.
    assert_eq!(c[1][0], 8.0);
    assert_eq!(c[2][0], 32.0);
}
