//! The one loop of a Taylor recurrence, kept here because the primitives' own recurrences
//! (the exponential's, in [`super::functions`]) run it as much as the Taylor integrator
//! does, and the symbolic engine sits below the integrator: a dot product of one series
//! with another read backwards. `crate::taylor::kernels` re-exports it beside its other
//! sums and explains, with the measurements, why it is written this way.

/// The length from which [`dot_reversed`] sums in two lanes (see `crate::taylor::kernels`).
pub const LANES_FROM: usize = 8;

/// `Σⱼ a_j b_{n−1−j}` over `j < n = min(a.len(), b.len())`: the interior of the sums, which
/// the generated code and the quotients, square roots and sines call on the lower orders
/// alone (`a_1 … a_{k−1}` against `b_{k−1} … b_1`) before the boundary terms are known.
///
/// ```
/// use precess_core::taylor::kernels::dot_reversed;
/// // The interior of (1 + 2τ + 3τ² + 4τ³)(5 + 6τ + 7τ² + 8τ³) at τ³: 2·7 + 3·6.
/// assert_eq!(dot_reversed(&[2.0, 3.0], &[6.0, 7.0]), 32.0);
/// ```
///
/// Below [`LANES_FROM`] terms the sum is left to right with one accumulator; from there on
/// the terms are taken in pairs into two accumulators (even and odd `j`) added at the end,
/// and an odd last term after them.
#[inline]
pub fn dot_reversed(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    if n < LANES_FROM {
        let mut acc = 0.0;
        for (x, y) in a.iter().zip(b.iter().rev()) {
            acc += x * y;
        }
        return acc;
    }
    // a in pairs from the front meets b in pairs from the back: (a_j, a_{j+1}) against
    // (b_{n−2−j}, b_{n−1−j}); a's odd last term meets b's odd first one.
    let (pairs, odd) = a.as_chunks::<2>();
    let (odd_b, pairs_b) = b.as_rchunks::<2>();
    let mut lanes = [0.0f64; 2];
    for (x, y) in pairs.iter().zip(pairs_b.iter().rev()) {
        lanes[0] += x[0] * y[1];
        lanes[1] += x[1] * y[0];
    }
    let rest = match (odd, odd_b) {
        ([x], [y]) => x * y,
        _ => 0.0,
    };
    (lanes[0] + lanes[1]) + rest
}
