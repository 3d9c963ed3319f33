//! The sums of [`crate::taylor::kernels`] on [`Lanes`]: the same terms in the same order, a
//! lane at a time in each operation, so that lane `l` of a sum is the scalar kernel's sum of
//! the lane-`l` values bit for bit (the lane tests check it on random series). What the code
//! `taylor_system!` emits for the lanes calls.

use super::Lanes;
use crate::taylor::kernels::LANES_FROM;

/// [`crate::taylor::kernels::dot_reversed`] in every lane: `Σⱼ a_j b_{n−1−j}` over
/// `j < n = min(a.len(), b.len())`, one accumulator below [`LANES_FROM`] terms and two
/// (even and odd `j`) from there on, as the scalar kernel.
///
/// ```
/// use precess_core::taylor::batch::{Lanes, kernels::dot_reversed};
/// let a = [Lanes([2.0, 1.0]), Lanes([3.0, 0.0])];
/// let b = [Lanes([6.0, 1.0]), Lanes([7.0, 5.0])];
/// assert_eq!(dot_reversed(&a, &b), Lanes([32.0, 5.0]));
/// ```
#[inline(always)]
pub fn dot_reversed<const L: usize>(a: &[Lanes<L>], b: &[Lanes<L>]) -> Lanes<L> {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    if n < LANES_FROM {
        let mut acc = Lanes::splat(0.0);
        for (x, y) in a.iter().zip(b.iter().rev()) {
            acc += *x * *y;
        }
        return acc;
    }
    let (pairs, odd) = a.as_chunks::<2>();
    let (odd_b, pairs_b) = b.as_rchunks::<2>();
    let mut even_sum = Lanes::splat(0.0);
    let mut odd_sum = Lanes::splat(0.0);
    for (x, y) in pairs.iter().zip(pairs_b.iter().rev()) {
        even_sum += x[0] * y[1];
        odd_sum += x[1] * y[0];
    }
    let rest = match (odd, odd_b) {
        ([x], [y]) => *x * *y,
        _ => Lanes::splat(0.0),
    };
    (even_sum + odd_sum) + rest
}

/// Whether the emitted lanes sum an order's dot products in fused loops (several sums side
/// by side, see the emitter's notes) rather than one kernel call each: only where a value
/// of `L` lanes fills at most two vector registers of the target (a register holds 2 doubles
/// on SSE2, 4 on AVX2, 8 on AVX-512). A wider value takes more registers a sum, and several
/// sums side by side then spill their accumulators to the stack: on the Euler–Poisson heavy
/// top at 1e-10 on SSE2 (1 024 runs, best of 5, load 5.5), fused loops of 4 sums took
/// 0.20 s at 8 lanes where the kernel calls took 0.18 s, and 0.177 s against 0.182 s at 4.
///
/// ```
/// use precess_core::taylor::batch::kernels::fuse_sums;
/// assert!(fuse_sums(4)); // two registers on every x86-64 target
/// assert!(!fuse_sums(64));
/// ```
#[inline(always)]
pub const fn fuse_sums(l: usize) -> bool {
    let width = if cfg!(target_feature = "avx512f") {
        8
    } else if cfg!(target_feature = "avx") {
        4
    } else {
        2
    };
    l <= 2 * width
}

/// [`crate::taylor::kernels::cauchy`] in every lane: the interior first, the boundary pair
/// `a_0 b_{n−1} + a_{n−1} b_0` last.
#[inline(always)]
pub fn cauchy<const L: usize>(a: &[Lanes<L>], b: &[Lanes<L>]) -> Lanes<L> {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    match (a, b) {
        ([a0, a_inner @ .., a_last], [b0, b_inner @ .., b_last]) => {
            dot_reversed(a_inner, b_inner) + (*a0 * *b_last + *a_last * *b0)
        }
        ([a0], [b0]) => *a0 * *b0,
        _ => Lanes::splat(0.0),
    }
}

/// [`crate::taylor::kernels::square`] in every lane.
#[inline(always)]
pub fn square<const L: usize>(a: &[Lanes<L>]) -> Lanes<L> {
    match a {
        [first, inner @ .., last] => square_interior(inner) + 2.0 * *first * *last,
        [a0] => *a0 * *a0,
        [] => Lanes::splat(0.0),
    }
}

/// [`crate::taylor::kernels::square_interior`] in every lane.
#[inline(always)]
pub fn square_interior<const L: usize>(inner: &[Lanes<L>]) -> Lanes<L> {
    let half = inner.len() / 2;
    let (low, rest) = inner.split_at(half);
    let (middle, high) = rest.split_at(rest.len() - half);
    let folded = 2.0 * dot_reversed(low, high);
    match middle {
        [m] => folded + *m * *m,
        _ => folded,
    }
}

/// [`crate::taylor::kernels::power_interior`] in every lane (the weights are the same in
/// every lane: they depend on the order only).
#[inline(always)]
pub fn power_interior<const L: usize>(a: &[Lanes<L>], c: &[Lanes<L>], r: f64) -> Lanes<L> {
    let n = a.len().min(c.len());
    let (a, c) = (&a[..n], &c[..n]);
    let k = n + 1;
    let mut acc = Lanes::splat(0.0);
    for (i, (cj, ak_j)) in c.iter().zip(a.iter().rev()).enumerate() {
        let j = i + 1;
        acc += (r * (k - j) as f64 - j as f64) * *ak_j * *cj;
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::taylor::kernels as scalar;

    /// Values that round differently in every order of summation: each lane's sums must
    /// still be the scalar kernel's bit for bit.
    fn series(seed: u64, n: usize) -> Vec<Lanes<3>> {
        let mut x = seed;
        let mut next = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 10f64.powi((x % 7) as i32 - 3)
        };
        (0..n).map(|_| Lanes([next(), next(), next()])).collect()
    }

    fn lane(v: &[Lanes<3>], l: usize) -> Vec<f64> {
        v.iter().map(|x| x.0[l]).collect()
    }

    #[test]
    fn every_lane_sums_as_the_scalar_kernels_bit_for_bit() {
        let (a, b) = (series(1, 24), series(2, 24));
        for n in 0..=a.len() {
            let (a, b) = (&a[..n], &b[..n]);
            let (d, c, s, si) = (
                dot_reversed(a, b),
                cauchy(a, b),
                square(a),
                square_interior(a),
            );
            let p = power_interior(a, b, 0.37);
            for l in 0..3 {
                let (al, bl) = (lane(a, l), lane(b, l));
                let pairs = [
                    (d.0[l], scalar::dot_reversed(&al, &bl)),
                    (c.0[l], scalar::cauchy(&al, &bl)),
                    (s.0[l], scalar::square(&al)),
                    (si.0[l], scalar::square_interior(&al)),
                    (p.0[l], scalar::power_interior(&al, &bl, 0.37)),
                ];
                for (i, (got, want)) in pairs.into_iter().enumerate() {
                    assert_eq!(
                        got.to_bits(),
                        want.to_bits(),
                        "kernel {i}, n = {n}, lane {l}"
                    );
                }
            }
        }
    }
}
