//! The principal frame of a symmetric tensor, chosen deterministically.
//!
//! The eigen-decomposition is a cyclic Jacobi iteration, which is accurate to the last bits
//! for symmetric 3×3 matrices (Rᵀ I R is diagonal to rounding, relative to the largest
//! moment). The frame is then fixed by the conventions of `docs/bodies.md`:
//! - among the 24 proper signed permutations of the eigenvectors, the one closest to the
//!   description axes (largest trace of R, i.e. smallest rotation angle) is taken, so a
//!   diagonal tensor keeps the description axes in their order, unsorted;
//! - R is right-handed (det R = +1);
//! - for a degenerate pair of moments, the description axes projected on the degenerate
//!   plane are kept, so a symmetric top whose axis is the description z keeps it as axis 3.

use nalgebra::{Matrix3, Rotation3, Vector3};

/// Principal moments and the rotation from principal to description axes.
///
/// Column k of `rotation` is principal axis k in description coordinates, and
/// `Rᵀ I R = diag(moments)`.
#[derive(Clone, Copy, PartialEq, Debug)]
pub struct Principal {
    /// Principal moments (I1, I2, I3), in the order of the axes closest to x, y, z.
    pub moments: Vector3<f64>,
    /// From principal to description axes.
    pub rotation: Rotation3<f64>,
}

impl Principal {
    /// A diagonal tensor's frame: the description axes themselves (`moments` a `Vector3`
    /// or `[I1, I2, I3]`).
    pub fn diagonal(moments: impl Into<Vector3<f64>>) -> Principal {
        Principal {
            moments: moments.into(),
            rotation: Rotation3::identity(),
        }
    }

    /// The same frame with moments in ascending order (columns permuted along, and the last
    /// one negated after an odd permutation so it stays right-handed).
    pub fn sorted(&self) -> Principal {
        let mut idx = [0usize, 1, 2];
        idx.sort_by(|&a, &b| self.moments[a].total_cmp(&self.moments[b]));
        let r = self.rotation.matrix();
        let mut m = Matrix3::from_columns(&[r.column(idx[0]), r.column(idx[1]), r.column(idx[2])]);
        let swaps = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .filter(|&&(i, j)| idx[i] > idx[j])
            .count();
        if swaps % 2 == 1 {
            m.set_column(2, &(-m.column(2)));
        }
        Principal {
            moments: Vector3::new(
                self.moments[idx[0]],
                self.moments[idx[1]],
                self.moments[idx[2]],
            ),
            rotation: Rotation3::from_matrix_unchecked(m),
        }
    }

    /// The coefficients of Euler's equations, ((I2 − I3)/I1, (I3 − I1)/I2, (I1 − I2)/I3).
    pub fn euler_coefficients(&self) -> Vector3<f64> {
        let i = &self.moments;
        Vector3::new(
            (i[1] - i[2]) / i[0],
            (i[2] - i[0]) / i[1],
            (i[0] - i[1]) / i[2],
        )
    }
}

/// The principal frame of the symmetric part of `tensor` (see the module docs for the
/// conventions).
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::Matrix3;
/// use precess_core::body::principal_frame;
/// let i = Matrix3::new(2.0, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 0.0, 5.0);
/// let p = principal_frame(&i);
/// let d = p.rotation.matrix().transpose() * i * p.rotation.matrix();
/// assert_relative_eq!(d, Matrix3::from_diagonal(&p.moments), epsilon = 1e-14);
/// assert_relative_eq!(p.moments[2], 5.0);
/// ```
pub fn principal_frame(tensor: &Matrix3<f64>) -> Principal {
    let (d, v) = jacobi(tensor);
    let (mut moments, mut r) = closest_to_axes(d, &v);
    keep_axes_in_degenerate_planes(&mut moments, &mut r);
    Principal {
        moments: Vector3::from(moments),
        rotation: Rotation3::from_matrix_unchecked(r),
    }
}

/// Cyclic Jacobi: eigenvalues and eigenvectors (columns) of the symmetric part of `m`.
fn jacobi(m: &Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    let mut a = [[0.0f64; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            a[i][j] = 0.5 * (m[(i, j)] + m[(j, i)]);
        }
    }
    let mut v = Matrix3::identity();
    for _sweep in 0..64 {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = a[p][q];
            if apq == 0.0 {
                continue;
            }
            let (app, aqq) = (a[p][p], a[q][q]);
            // Negligible: 100 |a_pq| is below the last bit of both diagonal entries.
            let g = 100.0 * apq.abs();
            if app.abs() + g == app.abs() && aqq.abs() + g == aqq.abs() {
                a[p][q] = 0.0;
                a[q][p] = 0.0;
                continue;
            }
            rotated = true;
            // The smaller of the two rotations that zero a_pq (|angle| ≤ 45°).
            let theta = (aqq - app) / (2.0 * apq);
            let t = if theta.abs() > 1e150 {
                0.5 / theta
            } else {
                let sign = if theta < 0.0 { -1.0 } else { 1.0 };
                sign / (theta.abs() + (theta * theta + 1.0).sqrt())
            };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            a[p][p] = app - t * apq;
            a[q][q] = aqq + t * apq;
            a[p][q] = 0.0;
            a[q][p] = 0.0;
            let r = 3 - p - q;
            let (arp, arq) = (a[r][p], a[r][q]);
            a[r][p] = c * arp - s * arq;
            a[p][r] = a[r][p];
            a[r][q] = s * arp + c * arq;
            a[q][r] = a[r][q];
            for k in 0..3 {
                let (vp, vq) = (v[(k, p)], v[(k, q)]);
                v[(k, p)] = c * vp - s * vq;
                v[(k, q)] = s * vp + c * vq;
            }
        }
        if !rotated {
            break;
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

const PERMUTATIONS: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

/// The proper signed permutation of the eigenvectors with the largest trace (the first in a
/// fixed order on ties).
fn closest_to_axes(d: [f64; 3], v: &Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    let mut best: Option<(f64, [f64; 3], Matrix3<f64>)> = None;
    for perm in PERMUTATIONS {
        let mut r =
            Matrix3::from_columns(&[v.column(perm[0]), v.column(perm[1]), v.column(perm[2])]);
        for k in 0..3 {
            if r[(k, k)] < 0.0 {
                r.set_column(k, &(-r.column(k)));
            }
        }
        if r.determinant() < 0.0 {
            // Flip the column that costs the least trace (the last of equals).
            let mut k_min = 0;
            for k in 1..3 {
                if r[(k, k)] <= r[(k_min, k_min)] {
                    k_min = k;
                }
            }
            r.set_column(k_min, &(-r.column(k_min)));
        }
        let trace = r.trace();
        if best.as_ref().is_none_or(|(t, _, _)| trace > *t) {
            best = Some((trace, [d[perm[0]], d[perm[1]], d[perm[2]]], r));
        }
    }
    match best {
        Some((_, m, r)) => (m, r),
        None => (d, *v),
    }
}

/// Replaces the axes of a degenerate pair by the description axes projected on their plane,
/// and makes the pair's moments exactly equal (their mean), so the vanishing coefficient of
/// Euler's equations is exactly zero.
fn keep_axes_in_degenerate_planes(moments: &mut [f64; 3], r: &mut Matrix3<f64>) {
    let scale = moments.iter().fold(0.0f64, |s, m| s.max(m.abs()));
    let tol = 16.0 * f64::EPSILON * scale;
    let same = |i: usize, j: usize| (moments[i] - moments[j]).abs() <= tol;
    let pairs: Vec<(usize, usize, usize)> = [(0, 1, 2), (0, 2, 1), (1, 2, 0)]
        .into_iter()
        .filter(|&(i, j, _)| same(i, j))
        .collect();
    match pairs.as_slice() {
        [] => {}
        [(i, j, k)] => {
            let (i, j, k) = (*i, *j, *k);
            let mean = 0.5 * (moments[i] + moments[j]);
            moments[i] = mean;
            moments[j] = mean;
            let ck: Vector3<f64> = r.column(k).into();
            let mut ei = Vector3::zeros();
            ei[i] = 1.0;
            let proj = ei - ck * ck.dot(&ei);
            if proj.norm() < 1e-8 {
                return;
            }
            let ci = proj.normalize();
            let cyclic = (j == (i + 1) % 3) && (k == (j + 1) % 3);
            let cj = if cyclic { ck.cross(&ci) } else { ci.cross(&ck) };
            r.set_column(i, &ci);
            r.set_column(j, &cj);
        }
        _ => {
            let mean = (moments[0] + moments[1] + moments[2]) / 3.0;
            *moments = [mean; 3];
            *r = Matrix3::identity();
        }
    }
}
