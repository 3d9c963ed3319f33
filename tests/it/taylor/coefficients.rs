//! The interpreted Taylor recurrences against independent values: DETEST B5's coefficients
//! against those of its closed form (Jacobi's sn, cn, dn with m = 0.51) computed by Cauchy's
//! integral formula on a circle in the complex plane (the closed form continued off the real
//! axis by the addition theorems, Abramowitz & Stegun 16.21), and the truncated series
//! against the closed form a step ahead.

use precess::exact::sncndn;
use precess::sym::Arena;
use precess::taylor::{TaylorSystem, TaylorTape};

const M: f64 = 0.51;

/// B5, y1' = y2 y3, y2' = −y1 y3, y3' = −0.51 y1 y2, as a run-time tape.
fn b5(max_order: usize) -> TaylorTape<3> {
    let mut a = Arena::new();
    let y = [a.coordinate("y1"), a.coordinate("y2"), a.coordinate("y3")];
    let m = a.parameter("m");
    let f1 = a.mul(y[1], y[2]);
    let p = a.mul(y[0], y[2]);
    let f2 = a.neg(p);
    let q = a.mul(y[0], y[1]);
    let mq = a.mul(m, q);
    let f3 = a.neg(mq);
    TaylorTape::new(&a, y, [f1, f2, f3], None, &[("m", M)], max_order).unwrap()
}

/// (sn, cn, dn)(x + iy | m) as complex pairs, from the real functions of x (parameter m)
/// and of y (parameter 1 − m): A&S 16.21.1–3.
fn sncndn_complex(x: f64, y: f64) -> [(f64, f64); 3] {
    let (s, c, d) = sncndn(x, 1.0 - M).unwrap();
    let (s1, c1, d1) = sncndn(y, M).unwrap();
    let den = c1 * c1 + M * s * s * s1 * s1;
    [
        (s * d1 / den, c * d * s1 * c1 / den),
        (c * c1 / den, -s * d * s1 * d1 / den),
        (d * c1 * d1 / den, -M * s * c * s1 / den),
    ]
}

/// c_k of (sn, cn, dn) at t0 for k = 0..=order: the mean of f(t0 + r e^{iθ}) e^{−ikθ} / r^k
/// over `points` equally spaced θ (exact for a polynomial of degree < points; the rest
/// aliases in as r^points / R^points, R ≈ 1.8 the distance to the nearest pole).
fn cauchy_coefficients(t0: f64, r: f64, order: usize, points: usize) -> Vec<[f64; 3]> {
    let values: Vec<[(f64, f64); 3]> = (0..points)
        .map(|j| {
            let th = std::f64::consts::TAU * j as f64 / points as f64;
            sncndn_complex(t0 + r * th.cos(), r * th.sin())
        })
        .collect();
    (0..=order)
        .map(|k| {
            let mut acc = [0.0; 3];
            for (j, v) in values.iter().enumerate() {
                let th = std::f64::consts::TAU * (j * k % points) as f64 / points as f64;
                let (co, si) = (th.cos(), -th.sin());
                for (a, &(re, im)) in acc.iter_mut().zip(v) {
                    *a += re * co - im * si;
                }
            }
            acc.map(|a| a / points as f64 / r.powi(k as i32))
        })
        .collect()
}

#[test]
fn the_complex_closed_form_is_sn_cn_dn_on_the_real_axis() {
    // The continuation must reduce to the real functions at y = 0 and satisfy
    // sn² + cn² = 1 off the axis (real part 1, imaginary part 0).
    let [s, c, d] = sncndn_complex(0.7, 0.0);
    let (rs, rc, rd) = sncndn(0.7, 1.0 - M).unwrap();
    assert!((s.0 - rs).abs() < 1e-15 && (c.0 - rc).abs() < 1e-15 && (d.0 - rd).abs() < 1e-15);
    let [s, c, d] = sncndn_complex(0.4, 0.6);
    let sq = |(a, b): (f64, f64)| (a * a - b * b, 2.0 * a * b);
    let (s2, c2, d2) = (sq(s), sq(c), sq(d));
    assert!((s2.0 + c2.0 - 1.0).abs() < 1e-14 && (s2.1 + c2.1).abs() < 1e-14);
    assert!((d2.0 + M * s2.0 - 1.0).abs() < 1e-14 && (d2.1 + M * s2.1).abs() < 1e-14);
}

#[test]
fn b5_coefficients_match_the_jacobi_closed_form() {
    let order = 24;
    let tape = b5(order);
    for t0 in [0.0, 1.3, 5.0, 12.0] {
        let (s, c, d) = sncndn(t0, 1.0 - M).unwrap();
        let mut got = vec![[0.0; 3]; order + 1];
        tape.coefficients(t0, &[s, c, d], order, &mut got);
        let r = 0.8;
        let want = cauchy_coefficients(t0, r, order, 128);
        for (k, (g, w)) in got.iter().zip(&want).enumerate() {
            for i in 0..3 {
                // The circle's rounding, ε·max|f| ≈ 1e-15, grows by 1/r^k in c_k.
                let tol = 2e-14 / r.powi(k as i32);
                assert!(
                    (g[i] - w[i]).abs() <= tol,
                    "t0 = {t0}, k = {k}, y{}: {} vs {} (tol {tol:e})",
                    i + 1,
                    g[i],
                    w[i]
                );
            }
        }
    }
}

#[test]
fn b5_low_orders_match_the_published_series_at_zero() {
    // A&S 16.22: sn u = u − (1+m)u³/3! + (1 + 14m + m²)u⁵/5! − …,
    // cn u = 1 − u²/2! + (1 + 4m)u⁴/4! − …, dn u = 1 − m u²/2! + m(4 + m)u⁴/4! − ….
    let tape = b5(6);
    let mut c = [[0.0; 3]; 6];
    tape.coefficients(0.0, &[0.0, 1.0, 1.0], 5, &mut c);
    let expect = [
        [0.0, 1.0, 1.0],
        [1.0, 0.0, 0.0],
        [0.0, -0.5, -M / 2.0],
        [-(1.0 + M) / 6.0, 0.0, 0.0],
        [0.0, (1.0 + 4.0 * M) / 24.0, M * (4.0 + M) / 24.0],
        [(1.0 + 14.0 * M + M * M) / 120.0, 0.0, 0.0],
    ];
    for (k, (g, e)) in c.iter().zip(&expect).enumerate() {
        for i in 0..3 {
            assert!((g[i] - e[i]).abs() < 1e-16, "k = {k}: {g:?} vs {e:?}");
        }
    }
}

#[test]
fn the_truncated_series_reaches_the_closed_form_a_step_ahead_at_its_order() {
    // Error of the degree-p polynomial ≈ |c_{p+1}| h^{p+1}: halving h divides it by 2^{p+1}.
    let tape = b5(30);
    let t0 = 3.0;
    let (s, c, d) = sncndn(t0, 1.0 - M).unwrap();
    let err = |p: usize, h: f64| {
        let mut co = vec![[0.0; 3]; p + 1];
        tape.coefficients(t0, &[s, c, d], p, &mut co);
        let sum: Vec<f64> = (0..3)
            .map(|i| co.iter().rev().fold(0.0, |acc, ck| acc * h + ck[i]))
            .collect();
        let (es, ec, ed) = sncndn(t0 + h, 1.0 - M).unwrap();
        (sum[0] - es)
            .abs()
            .max((sum[1] - ec).abs())
            .max((sum[2] - ed).abs())
    };
    for p in [4, 6, 8] {
        let ratio = err(p, 0.2) / err(p, 0.1);
        let expect = 2f64.powi(p as i32 + 1);
        assert!(
            ratio > 0.6 * expect && ratio < 1.6 * expect,
            "order {p}: ratio {ratio}, expected ≈ {expect}"
        );
    }
    // At order 24 the step 0.5 is at rounding.
    assert!(err(24, 0.5) < 5e-15, "{}", err(24, 0.5));
}

precess::taylor_system! {
    /// B5 through `taylor_system!`, m a field as the tape's parameter.
    struct B5 { m: f64 }
    state [y1, y2, y3];
    taylor = 24;
    d/dt y1 = y2 * y3;
    d/dt y2 = -(y1 * y3);
    d/dt y3 = -(m * (y1 * y2));
}

precess::taylor_system! {
    /// Products, a quotient and a sine–cosine pair: every kind of sum the emitted code fuses.
    struct Mixed { c: f64 }
    state [x, y, z];
    taylor = 24;
    d/dt x = y * z - x / (c + y);
    d/dt y = -(x * z) + sin(x);
    d/dt z = x * cos(z);
}

/// [`Mixed`] as a run-time tape.
fn mixed(c: f64) -> TaylorTape<3> {
    let mut a = Arena::new();
    let [x, y, z] = [a.coordinate("x"), a.coordinate("y"), a.coordinate("z")];
    let cp = a.parameter("c");
    let yz = a.mul(y, z);
    let den = a.add(cp, y);
    let q = a.div(x, den).unwrap();
    let f1 = a.sub(yz, q);
    let xz = a.mul(x, z);
    let nxz = a.neg(xz);
    let sx = a.sin(x);
    let f2 = a.add(nxz, sx);
    let cz = a.cos(z);
    let f3 = a.mul(x, cz);
    TaylorTape::new(&a, [x, y, z], [f1, f2, f3], None, &[("c", c)], 24).unwrap()
}

/// Whether two jets are the same bits, order by order (the first order that differs).
fn first_difference<const N: usize>(a: &[[f64; N]], b: &[[f64; N]]) -> Option<usize> {
    a.iter()
        .zip(b)
        .position(|(x, y)| x.map(f64::to_bits) != y.map(f64::to_bits))
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]

    /// The emitted code sums an order's dot products side by side in one loop where the
    /// interpreter calls the kernel once a sum; at any point both add the same terms in the
    /// same order, below and above the eight terms where the kernel takes two accumulators.
    #[test]
    fn emitted_sums_are_the_interpreters_bit_for_bit_at_every_order(
        y in proptest::array::uniform3(-1.5f64..1.5),
        c in 2.0f64..4.0,
    ) {
        let (mut generated, mut interpreted) = ([[0.0; 3]; 25], [[0.0; 3]; 25]);
        B5 { m: M }.coefficients(0.0, &y, 24, &mut generated);
        b5(24).coefficients(0.0, &y, 24, &mut interpreted);
        proptest::prop_assert_eq!(first_difference(&generated, &interpreted), None);
        Mixed { c }.coefficients(0.0, &y, 24, &mut generated);
        mixed(c).coefficients(0.0, &y, 24, &mut interpreted);
        proptest::prop_assert_eq!(first_difference(&generated, &interpreted), None);
    }
}
