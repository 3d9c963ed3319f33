//! The sums of the Taylor recurrences, shared by the code `taylor = K` generates, the
//! interpreter ([`super::TaylorTape`]) and hand-written systems: each is a dot product of
//! one series with another read backwards, the only loop a recurrence has.
//!
//! They are written for the compiler: four independent accumulators over chunks of four, so
//! the additions do not wait on each other and LLVM keeps them in vector registers (it may
//! not reassociate one floating-point sum by itself), and slices whose lengths are checked
//! once per call, not per element. The rounding differs from a left-to-right sum by a few
//! ulps of the largest term, as any summation order does.

/// `Σⱼ a_j b_{n−1−j}` over `j < n = min(a.len(), b.len())`: the order-(n−1) coefficient of
/// the product of the series `a` and `b` when both start at order 0.
///
/// ```
/// use precess_core::taylor::kernels::cauchy;
/// // (1 + 2τ + 3τ²)(4 + 5τ + 6τ²) at τ²: 1·6 + 2·5 + 3·4.
/// assert_eq!(cauchy(&[1.0, 2.0, 3.0], &[4.0, 5.0, 6.0]), 28.0);
/// ```
#[inline]
pub fn cauchy(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (Some(a), Some(b)) = (a.get(..n), b.get(..n)) else {
        return 0.0;
    };
    let (head, tail) = (a.chunks_exact(4), b.rchunks_exact(4));
    let (a_rest, b_rest) = (head.remainder(), tail.remainder());
    let mut acc = [0.0f64; 4];
    for (x, y) in head.zip(tail) {
        acc[0] += x[0] * y[3];
        acc[1] += x[1] * y[2];
        acc[2] += x[2] * y[1];
        acc[3] += x[3] * y[0];
    }
    let mut rest = 0.0;
    for (x, y) in a_rest.iter().zip(b_rest.iter().rev()) {
        rest += x * y;
    }
    ((acc[0] + acc[2]) + (acc[1] + acc[3])) + rest
}

/// `Σⱼ₌₀ᵏ a_j a_{k−j}` for `k = a.len() − 1`, folded on its symmetry (about half the
/// products): the order-k coefficient of `a²`.
///
/// ```
/// use precess_core::taylor::kernels::square;
/// // (1 + 2τ + 3τ²)² at τ²: 2·1·3 + 2².
/// assert_eq!(square(&[1.0, 2.0, 3.0]), 10.0);
/// ```
#[inline]
pub fn square(a: &[f64]) -> f64 {
    let Some(k) = a.len().checked_sub(1) else {
        return 0.0;
    };
    let half = a.len() / 2;
    let folded = 2.0 * cauchy(&a[..half], &a[a.len() - half..]);
    if k % 2 == 0 {
        folded + a[half] * a[half]
    } else {
        folded
    }
}
