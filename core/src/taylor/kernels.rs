//! The sums of the Taylor recurrences, shared by the code `taylor = K` generates, the
//! interpreter ([`super::TaylorTape`]) and hand-written systems: each is a dot product of
//! one series with another read backwards, the only loop a recurrence has.
//!
//! They are written for the compiler: a zipped pass over two slices, one read backwards, so
//! that no element access is bounds-checked. At the lengths of double precision (order
//! ≤ 25) one accumulator was measured faster than two, four or eight interleaved ones with
//! their remainder loops (`cargo bench --bench taylor -- jet`): the sums of the different
//! steps of one order are independent and overlap in the processor anyway, and the result
//! is the left-to-right sum, bit for bit.

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
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = 0.0;
    for (x, y) in a.iter().zip(b.iter().rev()) {
        acc += x * y;
    }
    acc
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
    if k.is_multiple_of(2) {
        folded + a[half] * a[half]
    } else {
        folded
    }
}
