//! Balancing before the QR iteration: isolate the eigenvalues a permutation exposes, then
//! scale rows and columns by powers of two (Parlett and Reinsch, Numer. Math. 13, 1969; the
//! scheme of LAPACK's `dgebal`).
//!
//! Both steps are similarity transformations that change no eigenvalue. Isolation matters
//! for the tops: a cyclic coordinate gives the Jacobian an exactly zero column, whose zero
//! eigenvalue is then returned exactly instead of being smeared by rounding into a
//! Jordan-block cluster of size √ε. Scaling by powers of two is exact and reduces the norm
//! the QR iteration's rounding is proportional to.

use nalgebra::{Complex, DMatrix};

/// Splits off the eigenvalues that a symmetric permutation exposes and returns the rest.
///
/// If row i has no non-zero entry off the diagonal within the remaining indices, then
/// `e_iᵀ A = a_ii e_iᵀ`, so a_ii is an eigenvalue and the others are those of A with row
/// and column i deleted; the same holds for a column. Repeats until no row or column
/// qualifies, pushing the isolated eigenvalues onto `isolated`.
pub(crate) fn isolate(a: &DMatrix<f64>, isolated: &mut Vec<Complex<f64>>) -> DMatrix<f64> {
    let mut keep: Vec<usize> = (0..a.nrows()).collect();
    loop {
        let lone = keep.iter().position(|&i| {
            let row_zero = keep.iter().all(|&j| j == i || a[(i, j)] == 0.0);
            let col_zero = keep.iter().all(|&j| j == i || a[(j, i)] == 0.0);
            row_zero || col_zero
        });
        match lone {
            Some(pos) => {
                let i = keep.remove(pos);
                isolated.push(Complex::new(a[(i, i)], 0.0));
            }
            None => break,
        }
    }
    DMatrix::from_fn(keep.len(), keep.len(), |r, c| a[(keep[r], keep[c])])
}

/// Most sweeps of the scaling; each accepted change lowers the norm by at least 5 %, so
/// the loop stops well before this on any finite matrix.
const MAX_SWEEPS: usize = 64;

/// Scales row i by 1/f and column i by f (f a power of two) until each row and column have
/// comparable off-diagonal norms.
pub(crate) fn scale(a: &mut DMatrix<f64>) {
    let n = a.nrows();
    for _ in 0..MAX_SWEEPS {
        let mut changed = false;
        for i in 0..n {
            let col: f64 = (0..n).filter(|&j| j != i).map(|j| a[(j, i)].abs()).sum();
            let row: f64 = (0..n).filter(|&j| j != i).map(|j| a[(i, j)].abs()).sum();
            if col == 0.0 || row == 0.0 {
                continue;
            }
            let total = col + row;
            let (mut c, mut f) = (col, 1.0_f64);
            // Powers of two: f² moves c towards r by factors of 4, with no rounding.
            while c < row / 2.0 {
                c *= 4.0;
                f *= 2.0;
            }
            while c >= row * 2.0 {
                c /= 4.0;
                f /= 2.0;
            }
            // After scaling the sums are c/f (column, c = C f²) and R/f (row).
            if (c + row) / f < 0.95 * total {
                changed = true;
                for j in 0..n {
                    a[(i, j)] /= f;
                    a[(j, i)] *= f;
                }
            }
        }
        if !changed {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_column_is_isolated_exactly() {
        // Column 0 is zero apart from the diagonal: 0 is an eigenvalue, exactly.
        let a = DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 2.0, 0.0, 3.0, 4.0, 0.0, 5.0, 6.0]);
        let mut iso = Vec::new();
        let rest = isolate(&a, &mut iso);
        assert_eq!(iso, vec![Complex::new(0.0, 0.0)]);
        assert_eq!(rest, DMatrix::from_row_slice(2, 2, &[3.0, 4.0, 5.0, 6.0]));
    }

    #[test]
    fn scaling_keeps_the_trace_and_balances_norms() {
        let mut a = DMatrix::from_row_slice(2, 2, &[1.0, 1e6, 1e-6, 2.0]);
        scale(&mut a);
        assert_eq!(a[(0, 0)] + a[(1, 1)], 3.0);
        assert!(a[(0, 1)].abs() < 10.0 && a[(1, 0)].abs() < 10.0, "{a}");
    }
}
