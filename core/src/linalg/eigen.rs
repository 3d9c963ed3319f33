//! Eigenvalues of a general real matrix by a method that always returns: balancing,
//! Householder reduction to upper Hessenberg form, and the Francis double-shift QR iteration
//! with deflation, exceptional shifts and an iteration cap (Golub & Van Loan, Matrix
//! Computations, 4th ed., §7.5).
//!
//! Each sweep either deflates (the active block shrinks) or spends one of at most
//! 30·max(n, 10) iterations, so the routine terminates; on the (unobserved) exhaustion of the
//! cap it reports [`LinalgError::NoConvergence`] instead of looping.

use nalgebra::{Complex, DMatrix, Dim, Matrix, Storage};

use super::balance::{isolate, scale};
use super::error::{LinalgError, check_finite};

/// Iterations allowed per unit of matrix size (LAPACK's `dlahqr` uses the same 30).
const ITERATIONS_PER_ROW: usize = 30;

/// The eigenvalues of a real square matrix, complex pairs adjacent (positive imaginary part
/// first), sorted by decreasing real part.
///
/// Balancing isolates the eigenvalues a permutation exposes (a zero column, as a cyclic
/// coordinate gives a Jacobian, yields an exact 0) and scales by powers of two; the rest
/// come from the Francis double-shift QR iteration on the Hessenberg form. Backward stable:
/// the eigenvalues are exact for a matrix within a few ε‖A‖ of A, so a simple eigenvalue is
/// accurate to about ε‖A‖ times its condition number, and a k×k Jordan block's to
/// (ε‖A‖)^{1/k}; their mean stays accurate to ε‖A‖.
///
/// # Errors
/// [`LinalgError::NotSquare`]; [`LinalgError::NonFinite`] for a NaN or infinite entry;
/// [`LinalgError::NoConvergence`] if the iteration cap is reached.
///
/// # Examples
///
/// The companion matrix of (x − 1)(x² + 4) = x³ − x² + 4x − 4 has eigenvalues 1 and ±2i:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::linalg::eigenvalues;
/// use precess_core::nalgebra::Matrix3;
///
/// let companion = Matrix3::new(
///     0.0, 0.0, 4.0, //
///     1.0, 0.0, -4.0, //
///     0.0, 1.0, 1.0,
/// );
/// let eig = eigenvalues(&companion)?;
/// assert_relative_eq!(eig[0].re, 1.0, epsilon = 1e-14);
/// assert_relative_eq!(eig[1].im, 2.0, epsilon = 1e-14);
/// assert_relative_eq!(eig[2].im, -2.0, epsilon = 1e-14);
/// # Ok::<(), precess_core::linalg::LinalgError>(())
/// ```
pub fn eigenvalues<R: Dim, C: Dim, S: Storage<f64, R, C>>(
    a: &Matrix<f64, R, C, S>,
) -> Result<Vec<Complex<f64>>, LinalgError> {
    let (rows, cols) = a.shape();
    if rows != cols {
        return Err(LinalgError::NotSquare { rows, cols });
    }
    check_finite("matrix entry", rows, |r, c| a[(r, c)], cols)?;
    let full = DMatrix::from_fn(rows, cols, |r, c| a[(r, c)]);
    let mut eig = Vec::with_capacity(rows);
    let mut h = isolate(&full, &mut eig);
    scale(&mut h);
    hessenberg(&mut h);
    francis_qr(&mut h, &mut eig)?;
    sort(&mut eig);
    Ok(eig)
}

/// Decreasing real part; within a conjugate pair the positive imaginary part first.
fn sort(eig: &mut [Complex<f64>]) {
    eig.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
}

/// Reduces `h` in place to upper Hessenberg form by Householder similarity transformations.
fn hessenberg(h: &mut DMatrix<f64>) {
    let n = h.nrows();
    for k in 0..n.saturating_sub(2) {
        let norm = (k + 1..n).map(|i| h[(i, k)].powi(2)).sum::<f64>().sqrt();
        if norm == 0.0 {
            continue;
        }
        // v = x − α e₁ with α = −sign(x₀)‖x‖: no cancellation in v₀.
        let alpha = if h[(k + 1, k)] >= 0.0 { -norm } else { norm };
        let mut v: Vec<f64> = (k + 1..n).map(|i| h[(i, k)]).collect();
        v[0] -= alpha;
        let vtv: f64 = v.iter().map(|x| x * x).sum();
        // H = I − 2 v vᵀ / vᵀv, applied from the left to rows k+1.. and the right to
        // columns k+1...
        for j in k..n {
            let s: f64 = v
                .iter()
                .enumerate()
                .map(|(r, vr)| vr * h[(k + 1 + r, j)])
                .sum();
            let s = 2.0 * s / vtv;
            for (r, vr) in v.iter().enumerate() {
                h[(k + 1 + r, j)] -= s * vr;
            }
        }
        for i in 0..n {
            let s: f64 = v
                .iter()
                .enumerate()
                .map(|(c, vc)| vc * h[(i, k + 1 + c)])
                .sum();
            let s = 2.0 * s / vtv;
            for (c, vc) in v.iter().enumerate() {
                h[(i, k + 1 + c)] -= s * vc;
            }
        }
        h[(k + 1, k)] = alpha;
        for i in k + 2..n {
            h[(i, k)] = 0.0;
        }
    }
}

/// The Householder reflector `P = I − τ v vᵀ`, v = (1, v₁, v₂), that maps (x, y, z) to a
/// multiple of e₁; τ = 0 when (y, z) already vanish.
fn reflector3(x: f64, y: f64, z: f64) -> (f64, f64, f64) {
    // Scaling by |x| + |y| + |z| keeps the squares from overflowing or underflowing.
    let scale = x.abs() + y.abs() + z.abs();
    if scale == 0.0 || (y == 0.0 && z == 0.0) {
        return (0.0, 0.0, 0.0);
    }
    let (x, y, z) = (x / scale, y / scale, z / scale);
    let norm = (x * x + y * y + z * z).sqrt();
    let alpha = if x >= 0.0 { -norm } else { norm };
    let v0 = x - alpha;
    ((alpha - x) / alpha, y / v0, z / v0)
}

/// Francis double-shift QR iteration on an upper Hessenberg matrix, pushing its eigenvalues
/// onto `eig`. Only the active diagonal block is updated: eigenvalues need no Schur vectors.
fn francis_qr(h: &mut DMatrix<f64>, eig: &mut Vec<Complex<f64>>) -> Result<(), LinalgError> {
    let n = h.nrows();
    let norm = h.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let cap = ITERATIONS_PER_ROW * n.max(10);
    let (mut total, mut since_deflation) = (0, 0);
    // The active block is rows and columns l..hi (hi exclusive).
    let mut hi = n;
    while hi > 0 {
        let last = hi - 1;
        let l = deflation_point(h, last, norm);
        if l == last {
            eig.push(Complex::new(h[(last, last)], 0.0));
            hi -= 1;
            since_deflation = 0;
            continue;
        }
        if l + 1 == last {
            let [a, b, c, d] = [h[(l, l)], h[(l, last)], h[(last, l)], h[(last, last)]];
            eig.extend(eigenvalues_2x2(a, b, c, d));
            hi -= 2;
            since_deflation = 0;
            continue;
        }
        if total >= cap {
            return Err(LinalgError::NoConvergence {
                iterations: total,
                unconverged: hi,
            });
        }
        total += 1;
        since_deflation += 1;
        let (trace, det) = shifts(h, l, last, since_deflation);
        double_shift_sweep(h, l, hi, trace, det);
    }
    Ok(())
}

/// The smallest l ≤ last such that the subdiagonal entries l+1..=last are not negligible:
/// an entry is set to zero when below ε times its diagonal neighbours.
fn deflation_point(h: &mut DMatrix<f64>, last: usize, norm: f64) -> usize {
    let mut l = last;
    while l > 0 {
        let mut s = h[(l - 1, l - 1)].abs() + h[(l, l)].abs();
        if s == 0.0 {
            s = norm;
        }
        if h[(l, l - 1)].abs() <= f64::EPSILON * s {
            h[(l, l - 1)] = 0.0;
            break;
        }
        l -= 1;
    }
    l
}

/// The trace and determinant of the shift pair: the trailing 2×2 block's eigenvalues,
/// replaced every tenth iteration without deflation by an exceptional pair that breaks the
/// cycles the standard shifts can fall into (a cyclic permutation matrix, for one).
fn shifts(h: &DMatrix<f64>, l: usize, last: usize, since_deflation: usize) -> (f64, f64) {
    if since_deflation.is_multiple_of(10) {
        // Built from the size of the last (or, alternately, first) subdiagonal entries.
        let (w, diag) = if since_deflation.is_multiple_of(20) {
            (h[(l + 1, l)].abs() + h[(l + 2, l + 1)].abs(), h[(l, l)])
        } else {
            (
                h[(last, last - 1)].abs() + h[(last - 1, last - 2)].abs(),
                h[(last, last)],
            )
        };
        let centre = 0.75 * w + diag;
        return (2.0 * centre, centre * centre + 0.4375 * w * w);
    }
    let (a, b, c, d) = (
        h[(last - 1, last - 1)],
        h[(last - 1, last)],
        h[(last, last - 1)],
        h[(last, last)],
    );
    (a + d, a * d - b * c)
}

/// One implicit double-shift sweep over the block l..hi: the bulge made by the first column
/// of H² − trace·H + det·I is chased down the subdiagonal by 3×3 reflectors.
fn double_shift_sweep(h: &mut DMatrix<f64>, l: usize, hi: usize, trace: f64, det: f64) {
    let last = hi - 1;
    let mut x = h[(l, l)] * h[(l, l)] + h[(l, l + 1)] * h[(l + 1, l)] - trace * h[(l, l)] + det;
    let mut y = h[(l + 1, l)] * (h[(l, l)] + h[(l + 1, l + 1)] - trace);
    let mut z = h[(l + 1, l)] * h[(l + 2, l + 1)];
    for k in l..last - 1 {
        let (tau, v1, v2) = reflector3(x, y, z);
        if tau != 0.0 {
            let first_col = if k > l { k - 1 } else { l };
            for j in first_col..hi {
                let s = tau * (h[(k, j)] + v1 * h[(k + 1, j)] + v2 * h[(k + 2, j)]);
                h[(k, j)] -= s;
                h[(k + 1, j)] -= s * v1;
                h[(k + 2, j)] -= s * v2;
            }
            for i in l..(k + 4).min(hi) {
                let s = tau * (h[(i, k)] + v1 * h[(i, k + 1)] + v2 * h[(i, k + 2)]);
                h[(i, k)] -= s;
                h[(i, k + 1)] -= s * v1;
                h[(i, k + 2)] -= s * v2;
            }
            if k > l {
                h[(k + 1, k - 1)] = 0.0;
                h[(k + 2, k - 1)] = 0.0;
            }
        }
        x = h[(k + 1, k)];
        y = h[(k + 2, k)];
        if k + 3 <= last {
            z = h[(k + 3, k)];
        }
    }
    // The last 2×2 reflector on rows last−1, last removes the bulge's final entry.
    let k = last - 1;
    let (tau, v1, _) = reflector3(x, y, 0.0);
    if tau != 0.0 {
        for j in k - 1..hi {
            let s = tau * (h[(k, j)] + v1 * h[(k + 1, j)]);
            h[(k, j)] -= s;
            h[(k + 1, j)] -= s * v1;
        }
        for i in l..hi {
            let s = tau * (h[(i, k)] + v1 * h[(i, k + 1)]);
            h[(i, k)] -= s;
            h[(i, k + 1)] -= s * v1;
        }
        h[(k + 1, k - 1)] = 0.0;
    }
}

/// The eigenvalues of [[a, b], [c, d]], without cancellation in the real case.
fn eigenvalues_2x2(a: f64, b: f64, c: f64, d: f64) -> [Complex<f64>; 2] {
    // Scaled so the squares cannot overflow.
    let s = a.abs().max(b.abs()).max(c.abs()).max(d.abs());
    if s == 0.0 {
        return [Complex::new(0.0, 0.0); 2];
    }
    let (a, b, c, d) = (a / s, b / s, c / s, d / s);
    let p = 0.5 * (a - d);
    let disc = p * p + b * c;
    if disc >= 0.0 {
        let r = disc.sqrt();
        let z = if p >= 0.0 { p + r } else { p - r };
        if z == 0.0 {
            return [Complex::new(d * s, 0.0); 2];
        }
        // λ₁ = d + z, λ₂ = d − bc/z: the second from the product, not the difference.
        [
            Complex::new((d + z) * s, 0.0),
            Complex::new((d - b * c / z) * s, 0.0),
        ]
    } else {
        let (re, im) = (0.5 * (a + d) * s, (-disc).sqrt() * s);
        [Complex::new(re, im), Complex::new(re, -im)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_by_two_real_roots_keep_small_ones() {
        // x² − 1e8 x + 1 = 0: roots 1e8 and 1e-8, the small one from the product.
        let e = eigenvalues_2x2(1e8, -1.0, 1.0, 0.0);
        let mut re = [e[0].re, e[1].re];
        re.sort_by(f64::total_cmp);
        assert!((re[0] - 1e-8).abs() < 1e-22 && (re[1] - 1e8).abs() < 1e-7);
    }

    #[test]
    fn hessenberg_keeps_the_trace_and_zeros_below() {
        let mut h = DMatrix::from_fn(5, 5, |i, j| ((i * 7 + j * 3) % 5) as f64 - 1.5);
        let trace = h.trace();
        hessenberg(&mut h);
        assert!((h.trace() - trace).abs() < 1e-13);
        for j in 0..5 {
            for i in j + 2..5 {
                assert_eq!(h[(i, j)], 0.0);
            }
        }
    }
}
