//! The sums of the Taylor recurrences, shared by the code `taylor = K` generates, the
//! interpreter ([`super::TaylorTape`]) and hand-written systems: each is a dot product of
//! one series with another read backwards, the only loop a recurrence has.
//!
//! They are written for the latency of the additions, which bounds a jet: a sum is one
//! chain of dependent additions, and order k + 1 waits on all of order k. In the sum of
//! order k, `Σⱼ₌₀ᵏ a_j b_{k−j}`, only the two boundary terms `a_0 b_k` and `a_k b_0` read a
//! coefficient of order k, which was just computed; the interior `j = 1 … k − 1` reads lower
//! orders only. So the interior is summed first (it can start before order k is done) and
//! the boundary pair is added last: once `a_k` and `b_k` are known the sum is two products
//! and two additions away, not k. This took B5's jet from 110 to 78 ns at order 10 and
//! from 368 to 280 ns at order 20 (`cargo bench --bench taylor -- jet`). The interior is one
//! zipped pass over two slices, one read backwards (no bounds check per term) with one
//! accumulator below eight terms and two interleaved ones (pairs of terms, which the compiler
//! turns into one two-lane multiply and add per pair) from eight on. With the boundary last,
//! the interior's own chain is no longer on the critical path and a jet becomes bound by
//! the number of operations, which the lanes halve; below eight terms their remainder
//! costs more than they save. Measured in one run (`cargo bench --bench taylor -- jet`, then
//! the table), one accumulator → two lanes from eight terms: B5's jet 121 → 113 ns at order
//! 13 and 269 → 227 ns at order 20, the order-10 jet unchanged (75 → 76 ns); whole runs at
//! tol 1e-12: B5 18.9 → 17.2 µs, the (3, 5, 7) body 22.6 → 20.5 µs, the heavy top with events
//! 155 → 142 µs. Four lanes from eight terms, or two lanes at every length, were slower.

pub use crate::sym::series::{LANES_FROM, dot_reversed};

/// `Σⱼ a_j b_{n−1−j}` over `j < n = min(a.len(), b.len())`: the order-(n−1) coefficient of
/// the product of the series `a` and `b` when both start at order 0.
///
/// The interior `0 < j < n − 1` is summed first and the boundary pair
/// `a_0 b_{n−1} + a_{n−1} b_0` added last (see the module's notes: the boundary reads the
/// newest coefficients, so the interior's chain of additions overlaps their computation).
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
    match (a, b) {
        ([a0, a_inner @ .., a_last], [b0, b_inner @ .., b_last]) => {
            dot_reversed(a_inner, b_inner) + (a0 * b_last + a_last * b0)
        }
        ([a0], [b0]) => a0 * b0,
        _ => 0.0,
    }
}

/// `Σⱼ₌₀ᵏ a_j a_{k−j}` for `k = a.len() − 1`, folded on its symmetry (about half the
/// products): the order-k coefficient of `a²`.
///
/// As in [`cauchy`], the interior (`2 Σ_{0<j<k/2} a_j a_{k−j}`, plus `a_{k/2}²` for even
/// k) comes first and the boundary `2 a_0 a_k` last.
///
/// ```
/// use precess_core::taylor::kernels::square;
/// // (1 + 2τ + 3τ²)² at τ²: 2·1·3 + 2².
/// assert_eq!(square(&[1.0, 2.0, 3.0]), 10.0);
/// ```
#[inline]
pub fn square(a: &[f64]) -> f64 {
    match a {
        [first, inner @ .., last] => square_interior(inner) + 2.0 * first * last,
        [a0] => a0 * a0,
        [] => 0.0,
    }
}

/// The interior of [`square`] at order k, given `inner = a_1 … a_{k−1}`:
/// `2 Σ_{0<j<k/2} a_j a_{k−j}`, plus `a_{k/2}²` for even k. It reads orders below k only,
/// so the generated code computes it before order k; `square(a)` adds `2 a_0 a_k` to it.
///
/// ```
/// use precess_core::taylor::kernels::square_interior;
/// // (a_0 + 1τ + 2τ² + 3τ³ + a_4τ⁴)² at τ⁴ less 2 a_0 a_4: 2·1·3 + 2².
/// assert_eq!(square_interior(&[1.0, 2.0, 3.0]), 10.0);
/// ```
#[inline]
pub fn square_interior(inner: &[f64]) -> f64 {
    // The halves of inner pair a_j with a_{k−j}; an odd length leaves the middle a_{k/2}.
    let half = inner.len() / 2;
    let (low, rest) = inner.split_at(half);
    let (middle, high) = rest.split_at(rest.len() - half);
    let folded = 2.0 * dot_reversed(low, high);
    match middle {
        [m] => folded + m * m,
        _ => folded,
    }
}

/// `Σⱼ₌₁ᵏ⁻¹ (r(k − j) − j) a_{k−j} c_j` with `k − 1 = min(a.len(), c.len())`, given
/// `a_1 … a_{k−1}` and `c_1 … c_{k−1}`: the interior of the real power's recurrence
/// `c_k = (1/(k a_0)) Σⱼ₌₀ᵏ⁻¹ (r(k − j) − j) a_{k−j} c_j` for `c = a^r` (from
/// `a c′ = r a′ c`), which reads lower orders only. The weights differ term by term, so it
/// is one plain loop.
///
/// ```
/// use precess_core::taylor::kernels::power_interior;
/// // k = 3, r = 1/2: (2·½ − 1) a₂ c₁ + (½ − 2) a₁ c₂ = 0 − 1.5·2·5.
/// assert_eq!(power_interior(&[2.0, 3.0], &[4.0, 5.0], 0.5), -15.0);
/// ```
#[inline]
pub fn power_interior(a: &[f64], c: &[f64], r: f64) -> f64 {
    let n = a.len().min(c.len());
    let (a, c) = (&a[..n], &c[..n]);
    let k = n + 1;
    let mut acc = 0.0;
    for (i, (cj, ak_j)) in c.iter().zip(a.iter().rev()).enumerate() {
        let j = i + 1;
        acc += (r * (k - j) as f64 - j as f64) * ak_j * cj;
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::{cauchy, square};

    /// The sums in the textbook order, term by term.
    fn direct(a: &[f64], b: &[f64]) -> f64 {
        let n = a.len().min(b.len());
        (0..n).map(|j| a[j] * b[n - 1 - j]).sum()
    }

    #[test]
    fn kernels_match_the_direct_sums_at_every_length() {
        // Small integers: every partial sum is exact, so any order of summation agrees.
        let a: Vec<f64> = (0..30).map(|j| ((7 * j + 3) % 11) as f64 - 5.0).collect();
        let b: Vec<f64> = (0..30).map(|j| ((5 * j + 1) % 13) as f64 - 6.0).collect();
        for n in 0..=a.len() {
            assert_eq!(
                cauchy(&a[..n], &b[..n]),
                direct(&a[..n], &b[..n]),
                "cauchy n = {n}"
            );
            assert_eq!(square(&a[..n]), direct(&a[..n], &a[..n]), "square n = {n}");
        }
        // Unequal lengths: the shorter one sets the order.
        assert_eq!(cauchy(&a[..5], &b[..9]), direct(&a[..5], &b[..5]));
    }
}

/// The same sums behind calls the compiler may not inline, for the code of tapes too large
/// to inline every sum into (`Tape::to_tokens` switches to them past
/// `OUTLINE_KERNELS_FROM_SUMS` sums): a 10-link chain's recurrences call the kernels some
/// 4 000 times in one loop body, and inlining each of them there cost most of two minutes of
/// a release build. A call costs a few cycles beside a sum of k terms; the values are the
/// inlined kernels' bit for bit.
pub mod outlined {
    /// [`super::dot_reversed`], never inlined.
    #[inline(never)]
    pub fn dot_reversed(a: &[f64], b: &[f64]) -> f64 {
        super::dot_reversed(a, b)
    }

    /// [`super::square`], never inlined.
    #[inline(never)]
    pub fn square(a: &[f64]) -> f64 {
        super::square(a)
    }

    /// [`super::square_interior`], never inlined.
    #[inline(never)]
    pub fn square_interior(inner: &[f64]) -> f64 {
        super::square_interior(inner)
    }

    /// [`super::power_interior`], never inlined.
    #[inline(never)]
    pub fn power_interior(a: &[f64], c: &[f64], r: f64) -> f64 {
        super::power_interior(a, c, r)
    }
}
