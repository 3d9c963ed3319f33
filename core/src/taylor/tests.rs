//! Each recurrence against the closed-form series of a scalar equation that exercises it.

use approx::assert_relative_eq;

use super::{SeriesOp, TaylorError, TaylorSystem, TaylorTape};
use crate::codegen::BindingError;
use crate::sym::{Arena, ExprId};

/// The coefficients of the scalar `x' = f(t, x)` from `x(t0) = x0`, up to `order`.
fn coefficients(
    build: impl FnOnce(&mut Arena, ExprId, ExprId) -> ExprId,
    t0: f64,
    x0: f64,
    order: usize,
) -> Vec<f64> {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let t = a.time();
    let rhs = build(&mut a, x, t);
    let values: &[(&str, f64)] = match a.find_parameter("k") {
        Some(_) => &[("k", 0.75)],
        None => &[],
    };
    let tape = TaylorTape::new(&a, [x], [rhs], Some(t), values, 30).unwrap();
    let mut c = vec![[0.0]; order + 1];
    tape.coefficients(t0, &[x0], order, &mut c);
    c.into_iter().map(|[v]| v).collect()
}

#[test]
fn square_gives_the_geometric_series() {
    // x' = x², x(0) = a: x = a/(1 − a t), c_k = a^{k+1}.
    let c = coefficients(|a, x, _| a.mul(x, x), 0.0, 0.7, 20);
    for (k, ck) in c.iter().enumerate() {
        assert_relative_eq!(*ck, 0.7f64.powi(k as i32 + 1), max_relative = 1e-14);
    }
}

#[test]
fn scaling_by_a_parameter_gives_the_exponential() {
    // x' = k x: c_j = x0 k^j / j!.
    let c = coefficients(
        |a, x, _| {
            let k = a.parameter("k");
            a.mul(k, x)
        },
        0.0,
        2.0,
        20,
    );
    let mut expect = 2.0;
    for (j, cj) in c.iter().enumerate() {
        if j > 0 {
            expect *= 0.75 / j as f64;
        }
        assert_relative_eq!(*cj, expect, max_relative = 1e-14);
    }
}

#[test]
fn quotient_and_square_root_match_their_closed_forms() {
    // x' = 1/x, x(0) = 1: x = √(1 + 2t), c_k = binom(1/2, k) 2^k.
    let c = coefficients(
        |a, x, _| {
            let one = a.one();
            a.div(one, x).unwrap()
        },
        0.0,
        1.0,
        20,
    );
    let mut b = 1.0;
    for (k, ck) in c.iter().enumerate() {
        if k > 0 {
            b *= (0.5 - (k - 1) as f64) / k as f64 * 2.0;
        }
        assert_relative_eq!(*ck, b, max_relative = 1e-13);
    }
    // x' = √x, x(0) = 1: x = (1 + t/2)², c = (1, 1, 1/4, 0, …).
    let c = coefficients(|a, x, _| a.sqrt(x).unwrap(), 0.0, 1.0, 12);
    assert_relative_eq!(c[1], 1.0, max_relative = 1e-15);
    assert_relative_eq!(c[2], 0.25, max_relative = 1e-15);
    for ck in &c[3..] {
        assert!(ck.abs() < 1e-15, "{c:?}");
    }
}

#[test]
fn sine_and_cosine_of_time_and_state() {
    // x' = cos t: x = sin t + const, from t0 = 0.3.
    let t0: f64 = 0.3;
    let c = coefficients(|a, _, t| a.cos(t), t0, 0.0, 16);
    let mut fact = 1.0;
    for (k, ck) in c.iter().enumerate().skip(1) {
        fact *= k as f64;
        // d^k sin t/dt^k = sin(t + kπ/2).
        let d = (t0 + k as f64 * std::f64::consts::FRAC_PI_2).sin();
        assert_relative_eq!(*ck, d / fact, max_relative = 1e-12, epsilon = 1e-18);
    }
    // x' = sin x from x(0) = π/2: x = 2 atan(eᵗ), whose series is x = π/2 + t − t³/6 + t⁵/24 − 61 t⁷/5040.
    let c = coefficients(|a, x, _| a.sin(x), 0.0, std::f64::consts::FRAC_PI_2, 7);
    let expect = [1.0, 0.0, -1.0 / 6.0, 0.0, 1.0 / 24.0, 0.0, -61.0 / 5040.0];
    for (ck, e) in c[1..].iter().zip(expect) {
        assert_relative_eq!(*ck, e, epsilon = 1e-15);
    }
}

#[test]
fn a_product_with_a_constant_is_a_scaling_and_sin_cos_a_pair() {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let v = a.coordinate("v");
    let k = a.parameter("k");
    let kx = a.mul(k, x);
    let s = a.sin(x);
    let acc = a.add(kx, s);
    let tape = TaylorTape::new(&a, [x, v], [v, acc], None, &[("k", 1.0)], 20).unwrap();
    let steps: Vec<SeriesOp> = tape.tape().steps().iter().map(|s| s.op).collect();
    assert!(steps.iter().any(|op| matches!(op, SeriesOp::Scale(..))));
    assert!(steps.iter().any(|op| matches!(op, SeriesOp::SinCos(_))));
    assert!(!steps.iter().any(|op| matches!(op, SeriesOp::Mul(..))));
}

#[test]
fn bad_input_is_refused_with_the_numbers() {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let k = a.parameter("k");
    let rhs = a.mul(k, x);
    let e = TaylorTape::new(&a, [x], [rhs], None, &[("k", 1.0)], 0).unwrap_err();
    assert_eq!(e, TaylorError::Order { order: 0, max: 100 });
    let e = TaylorTape::new(&a, [x], [rhs], None, &[], 20).unwrap_err();
    assert!(
        matches!(e, TaylorError::Binding(BindingError::UnsetParameter { ref name, .. }) if name == "k")
    );
    let e = TaylorTape::new(&a, [x], [rhs], None, &[("k", f64::NAN)], 20).unwrap_err();
    assert!(matches!(
        e,
        TaylorError::Binding(BindingError::NonFinite { .. })
    ));
    let e = TaylorTape::new(&a, [rhs], [rhs], None, &[("k", 1.0)], 20).unwrap_err();
    assert_eq!(e, TaylorError::StateNotASymbol { index: 0 });
    let u = a.input("u");
    let rhs = a.mul(u, x);
    let e = TaylorTape::new(&a, [x], [rhs], None, &[], 20).unwrap_err();
    assert!(matches!(
        e,
        TaylorError::Binding(BindingError::RunTimeInput { .. })
    ));
}

#[test]
fn a_parameter_given_twice_is_refused_read_or_not() {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let k = a.parameter("k");
    a.parameter("unread");
    let rhs = a.mul(k, x);
    let twice = |name: &'static str| {
        let values = [("k", 1.0), ("unread", 2.0), (name, 3.0)];
        TaylorTape::new(&a, [x], [rhs], None, &values, 20).unwrap_err()
    };
    for name in ["k", "unread"] {
        assert_eq!(
            twice(name),
            TaylorError::Binding(BindingError::DuplicateParameter {
                name: name.into(),
                first: if name == "k" { 1.0 } else { 2.0 },
                second: 3.0
            })
        );
    }
}

#[test]
fn the_kernels_match_closed_form_sums() {
    use super::kernels::{cauchy, square};
    for n in 1..30usize {
        let ones = vec![1.0; n];
        // Σ 1·1 over n terms.
        assert_eq!(cauchy(&ones, &ones), n as f64);
        // Σⱼ (j + 1)(n − j) = n(n + 1)(n + 2)/6.
        let ramp: Vec<f64> = (1..=n).map(|j| j as f64).collect();
        let want = (n * (n + 1) * (n + 2) / 6) as f64;
        assert_eq!(cauchy(&ramp, &ramp), want);
        // The square of the geometric series rʲ at order k = n − 1: (k + 1) rᵏ.
        let r = 0.5f64;
        let geo: Vec<f64> = (0..n).map(|j| r.powi(j as i32)).collect();
        let k = n - 1;
        assert_relative_eq!(
            square(&geo),
            (k + 1) as f64 * r.powi(k as i32),
            max_relative = 1e-15
        );
    }
    // Unequal lengths: the shorter decides, the longer is read from its end's order.
    assert_eq!(cauchy(&[1.0, 2.0, 3.0], &[4.0, 5.0]), 1.0 * 5.0 + 2.0 * 4.0);
    assert_eq!(cauchy(&[], &[1.0]), 0.0);
    assert_eq!(square(&[]), 0.0);
}

#[test]
fn a_workspace_that_served_another_tape_gives_the_same_coefficients() {
    // Two tapes with the same number of series and the same order share a workspace type
    // and size: x' = x² leaves x²'s coefficients in row 1, which is the time's row of
    // x' = t. The time's row must be rewritten whole, or x's coefficients past order 2
    // pick up x²'s.
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let t = a.time();
    let sq = a.mul(x, x);
    let squares = TaylorTape::new(&a, [x], [sq], None, &[], 12).unwrap();
    let clock = TaylorTape::new(&a, [x], [t], Some(t), &[], 12).unwrap();
    assert_eq!(squares.tape().series_count(), clock.tape().series_count());
    let mut ws = Vec::new();
    let mut c = [[0.0; 1]; 13];
    squares.coefficients_into(&mut ws, 0.0, &[0.5], 12, &mut c);
    clock.coefficients_into(&mut ws, 2.0, &[1.0], 12, &mut c);
    // x(2 + τ) = 1 + 2τ + τ²/2.
    assert_eq!(c[..3], [[1.0], [2.0], [0.5]]);
    assert!(c[3..].iter().all(|ck| ck[0] == 0.0), "{c:?}");
}

#[test]
fn the_emitted_code_keeps_rows_only_for_series_read_over_their_orders() {
    // B5: y' = (y2 y3, −y1 y3, −m y1 y2). Each product and its sign or scaling is read once,
    // at its own order, so only the three state rows remain; a quotient reads its own past
    // and keeps its row.
    let mut a = Arena::new();
    let y: [ExprId; 3] = [a.coordinate("y1"), a.coordinate("y2"), a.coordinate("y3")];
    let m = a.parameter("m");
    let f1 = a.mul(y[1], y[2]);
    let p = a.mul(y[0], y[2]);
    let f2 = a.neg(p);
    let q = a.mul(y[0], y[1]);
    let mq = a.mul(m, q);
    let f3 = a.neg(mq);
    let b5 = super::Tape::new(&a, &y, None, &[f1, f2, f3]).unwrap();
    assert_eq!(b5.series_count(), 9);
    assert_eq!(b5.emitted(20).series, 3);
    let quotient = a.div(y[1], y[2]).unwrap();
    let tape = super::Tape::new(&a, &y, None, &[quotient, f2, f3]).unwrap();
    assert_eq!(tape.emitted(20).series, 4);
}

/// `binom(r, k) = r (r − 1) ⋯ (r − k + 1) / k!`, by its product directly.
fn binomial(r: f64, k: usize) -> f64 {
    (0..k).map(|i| (r - i as f64) / (i + 1) as f64).product()
}

#[test]
fn real_power_of_the_time_gives_the_binomial_series() {
    // x' = (1 + t)^(3/2), x(0) = 0: x_{k+1} = binom(3/2, k)/(k + 1), the series of
    // (1 + t)^(3/2) integrated once; the power's base is the series 1 + τ.
    let c = coefficients(
        |a, _, t| {
            let one = a.one();
            let base = a.add(one, t);
            a.powr(base, crate::sym::Rational::new(3, 2).unwrap())
                .unwrap()
        },
        0.0,
        0.0,
        20,
    );
    assert_eq!(c[0], 0.0);
    for k in 0..20 {
        let want = binomial(1.5, k) / (k + 1) as f64;
        assert_relative_eq!(c[k + 1], want, max_relative = 1e-13, epsilon = 1e-17);
    }
}

#[test]
fn real_power_of_the_state_gives_the_binomial_series() {
    // x' = x^(−1/3), x(0) = 1: (3/4) x^(4/3) = t + 3/4, x = (1 + 4t/3)^(3/4), whose
    // coefficients are binom(3/4, k) (4/3)^k.
    let c = coefficients(
        |a, x, _| {
            a.powr(x, crate::sym::Rational::new(-1, 3).unwrap())
                .unwrap()
        },
        0.0,
        1.0,
        24,
    );
    for (k, ck) in c.iter().enumerate() {
        let want = binomial(0.75, k) * (4.0f64 / 3.0).powi(k as i32);
        assert_relative_eq!(*ck, want, max_relative = 1e-12, epsilon = 1e-17);
    }
    // From another point: x(0) = 2.5, x = (2.5^(4/3) + 4t/3)^(3/4), coefficients
    // binom(3/4, k) (4/3)^k 2.5^(1 − 4k/3).
    let c = coefficients(
        |a, x, _| {
            a.powr(x, crate::sym::Rational::new(-1, 3).unwrap())
                .unwrap()
        },
        0.0,
        2.5,
        16,
    );
    for (k, ck) in c.iter().enumerate() {
        let want = binomial(0.75, k)
            * (4.0f64 / 3.0).powi(k as i32)
            * 2.5f64.powf(1.0 - 4.0 * k as f64 / 3.0);
        assert_relative_eq!(*ck, want, max_relative = 1e-12, epsilon = 1e-17);
    }
}
