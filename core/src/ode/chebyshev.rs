//! Chebyshev interpolants of g on a piece of a step, for the event scan ([`super::scan`]):
//! coefficients from values at Chebyshev–Lobatto points, Clenshaw evaluation, the
//! derivative, and the critical points of the interpolant isolated exactly on its Bernstein
//! form (Descartes' rule of signs with de Casteljau subdivision).
//!
//! A piece [a, b] is mapped onto x ∈ [−1, 1] by t = (a + b)/2 + x (b − a)/2. The points are
//! x_J = −cos(Jπ/16), J = 0, …, 16 (ascending in t): degree n ∈ {4, 8, 16} uses every
//! (16/n)-th of them, so doubling the degree keeps every value already computed.

/// The highest degree of one piece's interpolant, and the size of its grid of points.
pub(crate) const MAX_DEGREE: usize = 16;

/// Values of one piece on the 16-grid (entries off the current degree's points unused).
pub(crate) type Grid = [f64; MAX_DEGREE + 1];

/// cos(mπ/16), m = 0, …, 16 (the rest by symmetry), with cos(π/2) exactly 0 so that the
/// middle point is the piece's exact midpoint.
const COS16: [f64; 17] = [
    1.0,
    0.980_785_280_403_230_4,
    0.923_879_532_511_286_7,
    0.831_469_612_302_545_2,
    core::f64::consts::FRAC_1_SQRT_2,
    0.555_570_233_019_602_2,
    0.382_683_432_365_089_8,
    0.195_090_322_016_128_27,
    0.0,
    -0.195_090_322_016_128_27,
    -0.382_683_432_365_089_8,
    -0.555_570_233_019_602_2,
    -core::f64::consts::FRAC_1_SQRT_2,
    -0.831_469_612_302_545_2,
    -0.923_879_532_511_286_7,
    -0.980_785_280_403_230_4,
    -1.0,
];

/// cos(mπ/16) for any m ≥ 0.
const fn cos16(m: usize) -> f64 {
    let m = m % 32;
    COS16[if m <= 16 { m } else { 32 - m }]
}

/// The DCT-I of degree n = M − 1 as a matrix: c_k = Σ_j D_kj f_j for the values f_j at
/// x_j = −cos(jπ/n), with T_k(−cos θ) = (−1)ᵏ cos kθ and the ends weighted ½. Built at
/// compile time, so a step's first pass costs one 5 × 5 product.
const fn dct<const M: usize>() -> [[f64; M]; M] {
    let n = M - 1;
    let stride = MAX_DEGREE / n;
    let mut d = [[0.0; M]; M];
    let mut k = 0;
    while k <= n {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        let end = if k == 0 || k == n { 0.5 } else { 1.0 };
        let mut j = 0;
        while j <= n {
            let w = if j == 0 || j == n { 0.5 } else { 1.0 };
            d[k][j] = sign * end * 2.0 / n as f64 * w * cos16(j * k * stride);
            j += 1;
        }
        k += 1;
    }
    d
}

const DCT4: [[f64; 5]; 5] = dct::<5>();
const DCT8: [[f64; 9]; 9] = dct::<9>();
const DCT16: [[f64; 17]; 17] = dct::<17>();

/// c = D f on the points of stride 16/(M − 1) of `grid`.
fn apply<const M: usize>(d: &[[f64; M]; M], grid: &Grid) -> Grid {
    let stride = MAX_DEGREE / (M - 1);
    let mut c = [0.0; MAX_DEGREE + 1];
    for (ck, row) in c.iter_mut().zip(d) {
        *ck = row
            .iter()
            .enumerate()
            .map(|(j, djk)| djk * grid[j * stride])
            .sum();
    }
    c
}

/// Binomial coefficients C(n, k) for n ≤ 32, exact as integers.
const BINOM: [[u64; 33]; 33] = pascal();

const fn pascal() -> [[u64; 33]; 33] {
    let mut c = [[0u64; 33]; 33];
    let mut n = 0;
    while n <= 32 {
        c[n][0] = 1;
        let mut k = 1;
        while k <= n {
            c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
            k += 1;
        }
        n += 1;
    }
    c
}

fn binom(n: usize, k: usize) -> f64 {
    // Every coefficient used is below 2⁵³, so the conversion is exact.
    BINOM
        .get(n)
        .and_then(|row| row.get(k))
        .copied()
        .unwrap_or(0) as f64
}

/// The time of point J of the 16-grid on [a, b]; the ends are a and b exactly.
pub(crate) fn node(a: f64, b: f64, j: usize) -> f64 {
    match j {
        0 => a,
        MAX_DEGREE => b,
        _ => {
            let t = 0.5 * (a + b) - 0.5 * (b - a) * cos16(j);
            t.clamp(a, b)
        }
    }
}

/// The abscissa x_J = −cos(Jπ/16) ∈ [−1, 1] of point J of the 16-grid.
pub(crate) fn node_x(j: usize) -> f64 {
    -cos16(j)
}

/// The interpolant's Chebyshev coefficients c_0 … c_n (p(x) = Σ c_k T_k(x)) from the
/// values at the degree-n points of `grid`, n ∈ {4, 8, 16} (16 for any other n).
pub(crate) fn coefficients(grid: &Grid, n: usize) -> Grid {
    match n {
        4 => apply(&DCT4, grid),
        8 => apply(&DCT8, grid),
        _ => apply(&DCT16, grid),
    }
}

/// p(x) = Σ_{k≤n} c_k T_k(x) by Clenshaw's recurrence.
pub(crate) fn clenshaw(c: &Grid, n: usize, x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for ck in c[1..=n].iter().rev() {
        (b1, b2) = (ck + 2.0 * x * b1 - b2, b1);
    }
    c[0] + x * b1 - b2
}

/// The coefficients of p′(x) (degree n − 1).
pub(crate) fn derivative(c: &Grid, n: usize) -> Grid {
    let mut d = [0.0; MAX_DEGREE + 2];
    for k in (1..=n).rev() {
        d[k - 1] = d[k + 1] + 2.0 * k as f64 * c[k];
    }
    d[0] *= 0.5;
    let mut out = [0.0; MAX_DEGREE + 1];
    out.copy_from_slice(&d[..=MAX_DEGREE]);
    out
}

/// The Bernstein coefficients of p on s = (x + 1)/2 ∈ [0, 1]: T_k has the coefficients
/// Σ_j (−1)^(k−j) C(2k, 2j) C(n−k, i−j) / C(n, i) (Rababah 2003), integer sums computed
/// exactly.
fn bernstein(c: &Grid, n: usize) -> Grid {
    let mut b = [0.0; MAX_DEGREE + 1];
    for (i, bi) in b.iter_mut().enumerate().take(n + 1) {
        let mut s = 0.0;
        for (k, ck) in c.iter().enumerate().take(n + 1) {
            let mut m = 0.0;
            for j in (i + k).saturating_sub(n)..=i.min(k) {
                let term = binom(2 * k, 2 * j) * binom(n - k, i - j);
                m += if (k - j) % 2 == 0 { term } else { -term };
            }
            s += ck * m;
        }
        *bi = s / binom(n, i);
    }
    b
}

/// Sign changes along `b`, zeros skipped.
fn variations(b: &[f64]) -> usize {
    let mut last = 0.0f64;
    let mut count = 0;
    for &v in b {
        if v != 0.0 {
            if last != 0.0 && (v < 0.0) != (last < 0.0) {
                count += 1;
            }
            last = v;
        }
    }
    count
}

/// Subdivisions after which an interval that still shows several sign variations is taken
/// as one point (2⁻²⁴ of the piece: a cluster of critical points, or rounding noise).
const MAX_ISOLATION_DEPTH: u32 = 24;

/// Bisections that refine one isolated critical point (to 2⁻²⁴ of the piece: its value is
/// then the extremum's to second order).
const REFINE_STEPS: u32 = 24;

/// The critical points of p inside (−1, 1), ascending, at most `MAX_DEGREE` of them: the
/// sign changes of p′, isolated on its Bernstein form (Descartes: a Bernstein polynomial with
/// v sign variations has v − 2j roots in the interval, so 0 means none and 1 means one) and
/// refined by bisection on p′. Returns how many were written.
pub(crate) fn critical_points(c: &Grid, n: usize, out: &mut [f64; MAX_DEGREE]) -> usize {
    if n < 2 {
        return 0;
    }
    let d = derivative(c, n);
    let bd = bernstein(&d, n - 1);
    let mut intervals = [(0.0, 0.0); MAX_DEGREE];
    let mut count = 0;
    isolate(&bd[..n], (0.0, 1.0), 0, &mut intervals, &mut count);
    let slope = |s: f64| clenshaw(&d, n - 1, 2.0 * s - 1.0);
    for (o, &(lo, hi)) in out.iter_mut().zip(&intervals[..count]) {
        *o = 2.0 * refine(slope, lo, hi) - 1.0;
    }
    count
}

/// Appends the intervals of s ∈ `(lo, hi)` that each hold one sign change of the Bernstein
/// polynomial `b` (or, at the depth limit, a cluster).
fn isolate(
    b: &[f64],
    (lo, hi): (f64, f64),
    depth: u32,
    out: &mut [(f64, f64); MAX_DEGREE],
    count: &mut usize,
) {
    let v = variations(b);
    if v == 0 || *count >= out.len() {
        return;
    }
    if v == 1 || depth >= MAX_ISOLATION_DEPTH {
        out[*count] = (lo, hi);
        *count += 1;
        return;
    }
    let m = b.len() - 1;
    let mut w = [0.0; MAX_DEGREE + 1];
    w[..=m].copy_from_slice(b);
    let (mut left, mut right) = ([0.0; MAX_DEGREE + 1], [0.0; MAX_DEGREE + 1]);
    (left[0], right[m]) = (w[0], w[m]);
    for r in 1..=m {
        for i in 0..=m - r {
            w[i] = 0.5 * (w[i] + w[i + 1]);
        }
        (left[r], right[m - r]) = (w[0], w[m - r]);
    }
    let mid = 0.5 * (lo + hi);
    isolate(&left[..=m], (lo, mid), depth + 1, out, count);
    if left[m] == 0.0 && *count < out.len() {
        // A root exactly at the split, which neither half counts.
        out[*count] = (mid, mid);
        *count += 1;
    }
    isolate(&right[..=m], (mid, hi), depth + 1, out, count);
}

/// The sign change of `f` in [lo, hi] by bisection (the midpoint if the ends agree in sign).
fn refine(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let f_lo = f(lo);
    if (f_lo < 0.0) == (f(hi) < 0.0) {
        return 0.5 * (lo + hi);
    }
    for _ in 0..REFINE_STEPS {
        let mid = 0.5 * (lo + hi);
        if (f(mid) < 0.0) == (f_lo < 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid_of(f: impl Fn(f64) -> f64, a: f64, b: f64) -> Grid {
        core::array::from_fn(|j| f(node(a, b, j)))
    }

    #[test]
    fn the_cosine_table_is_cos() {
        for m in 0..40 {
            let exact = (m as f64 * core::f64::consts::PI / 16.0).cos();
            // The reference's own argument kπ/16 is rounded: 1e-15 covers it.
            assert!((cos16(m) - exact).abs() < 1e-15, "{m}");
        }
    }

    #[test]
    fn a_polynomial_is_reproduced_at_every_degree() {
        // p(t) = t³ − 2t + 0.5 on [1, 3] is exact at degrees ≥ 3.
        let p = |t: f64| t * t * t - 2.0 * t + 0.5;
        let grid = grid_of(p, 1.0, 3.0);
        for n in [4, 8, 16] {
            let c = coefficients(&grid, n);
            assert!(c[4..=n].iter().all(|v| v.abs() < 1e-13), "{c:?}");
            for t in [1.0, 1.3, 2.0, 2.71, 3.0] {
                let x = t - 2.0;
                assert!((clenshaw(&c, n, x) - p(t)).abs() < 1e-13);
                // p′(t) = 3t² − 2, and dx/dt = 1 here.
                let d = derivative(&c, n);
                assert!((clenshaw(&d, n - 1, x) - (3.0 * t * t - 2.0)).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn the_bernstein_form_has_the_same_values() {
        // De Casteljau on the Bernstein coefficients against Clenshaw on the Chebyshev ones.
        let f = |t: f64| (3.0 * t).sin() + 0.3 * t * t;
        let grid = grid_of(f, -1.0, 1.0);
        for n in [4, 8, 16] {
            let c = coefficients(&grid, n);
            let b = bernstein(&c, n);
            for s in [0.0, 0.1, 0.37, 0.5, 0.93, 1.0] {
                let mut w = b;
                for r in 1..=n {
                    for i in 0..=n - r {
                        w[i] = (1.0 - s) * w[i] + s * w[i + 1];
                    }
                }
                let x = 2.0 * s - 1.0;
                assert!(
                    (w[0] - clenshaw(&c, n, x)).abs() < 1e-12,
                    "n = {n}, s = {s}"
                );
            }
        }
    }

    #[test]
    fn critical_points_of_a_cosine_are_its_extrema() {
        // cos(20 t − 0.5) on [0, 1]: extrema at t = (kπ + 0.5)/20 for k = 0 … 6, resolved
        // at degree 16.
        let grid = grid_of(|t| (20.0 * t - 0.5).cos(), 0.0, 1.0);
        let c = coefficients(&grid, 16);
        let mut out = [0.0; MAX_DEGREE];
        let count = critical_points(&c, 16, &mut out);
        assert_eq!(count, 7, "{:?}", &out[..count]);
        for (k, x) in out[..count].iter().enumerate() {
            let t = 0.5 + 0.5 * x;
            let exact = (k as f64 * core::f64::consts::PI + 0.5) / 20.0;
            assert!((t - exact).abs() < 1e-4, "{t} against {exact}");
        }
    }

    #[test]
    fn two_close_extrema_are_told_apart() {
        // (t − 0.5)(t − 0.5001)(t − 2): critical points 1e-4 apart are both found.
        let p = |t: f64| (t - 0.5) * (t - 0.5001) * (t - 2.0);
        let grid = grid_of(p, 0.0, 1.0);
        let c = coefficients(&grid, 4);
        let mut out = [0.0; MAX_DEGREE];
        let count = critical_points(&c, 4, &mut out);
        assert_eq!(count, 1);
        let t = 0.5 + 0.5 * out[0];
        // p′ = 0 at 0.50005 − 1e-8/(3·1.5) + … from the nearer pair.
        assert!((t - 0.50005).abs() < 1e-6, "{t}");
    }
}
