//! The scan of one step for the roots of an event function g: which points of the step to
//! evaluate g at so that every sign change of g between them brackets one root, however
//! many roots the step holds.
//!
//! g∘y on the step is interpolated at Chebyshev–Lobatto points along the stepper's own
//! solution ([`Stepper::state_at`](super::Stepper::state_at)): first at degree 4 (the ends,
//! whose values are known, and three inner points), then 8 and 16 while the interpolant's
//! last two Chebyshev coefficients stay above [`TAIL`] times the largest |g| on the piece,
//! then in halves of the piece, down to 2^−[`MAX_SPLITS`] of the step. A piece is passed
//! over as rootless, resolved or not, when its interpolant stays more than 8 error
//! estimates away from 0 and that estimate is at most [`TRUSTED_TAIL`] (10⁻³) of the
//! largest |g| on the piece: a larger one means the points alias g, and its coefficients
//! are no measure of the error. On each resolved piece p, the interpolant, is monotone
//! between its critical points, which are isolated exactly on its Bernstein form
//! ([`super::chebyshev`]); g itself is evaluated at those where p comes within its error
//! estimate of 0 or changes sign, so that between two consecutive points of the returned
//! sequence p has at most one root. Each sign change of g along the sequence is then
//! located on g itself by [`super::events::locate_root`]: an interpolant decides where to
//! look, never what is reported.
//!
//! Cost: on a step where g is slow, three evaluations of the state and of g besides the
//! step's ends (the three shared by every event of the run), and a 5 × 5 transform.

use super::chebyshev::{self, Grid, MAX_DEGREE};
use super::error::OdeError;

/// The decay asked of the interpolant: its last two Chebyshev coefficients together at
/// most this times the largest |g| at its points (an a-posteriori estimate of its error).
pub(crate) const TAIL: f64 = 1e-10;

/// Halvings of a step, at most: a piece is never shorter than 2⁻⁶ of its step, so a step
/// costs at most 64 × 16 + 1 evaluations of g however g behaves.
pub(crate) const MAX_SPLITS: u32 = 6;

/// How many times its error estimate an interpolant must stay away from 0 for its piece
/// to be passed over without resolving it further.
const EXCLUSION_MARGIN: f64 = 8.0;

/// The largest error estimate, as a fraction of the largest |g| at the interpolant's
/// points, that is trusted for passing a piece over. On a g that the points do not resolve
/// (a term of g several periods long across the piece, aliased onto five points) the last
/// coefficients are as large as g's unresolved part unless they happen to cancel, and such
/// a coincidence is what lets a dip between two roots pass as rootless; a g that the
/// points do resolve (slow against the step, the common case) has an estimate far below
/// this and still costs the first pass only.
pub(crate) const TRUSTED_TAIL: f64 = 1e-3;

/// The first pass's inner points on the 16-grid (degree 4: J = 4, 8, 12).
const FIRST: [usize; 3] = [4, 8, 12];

/// The times of the first pass's three inner points on the step [a, b].
pub(crate) fn first_pass_times(a: f64, b: f64) -> [f64; 3] {
    FIRST.map(|j| chebyshev::node(a, b, j))
}

/// Appends to `out` the points (t, g) of the step [a, b] after a, ending with (b, g_b),
/// such that g has at most one root between two consecutive ones wherever its
/// interpolant is resolved. `inner` holds g at [`first_pass_times`]; `eval` computes g at
/// any other time of the step.
///
/// # Errors
/// What `eval` returns.
pub(crate) fn scan_step(
    eval: &mut impl FnMut(f64) -> Result<f64, OdeError>,
    (a, g_a): (f64, f64),
    (b, g_b): (f64, f64),
    inner: [f64; 3],
    out: &mut Vec<(f64, f64)>,
) -> Result<(), OdeError> {
    let mut grid = [0.0; MAX_DEGREE + 1];
    grid[0] = g_a;
    grid[MAX_DEGREE] = g_b;
    for (j, g) in FIRST.into_iter().zip(inner) {
        grid[j] = g;
    }
    scan_piece(eval, (a, b), grid, 0, out)
}

/// One piece [a, b] whose degree-4 points are filled in `grid`.
fn scan_piece(
    eval: &mut impl FnMut(f64) -> Result<f64, OdeError>,
    (a, b): (f64, f64),
    mut grid: Grid,
    depth: u32,
    out: &mut Vec<(f64, f64)>,
) -> Result<(), OdeError> {
    let g_b = grid[MAX_DEGREE];
    let mut n = 4;
    let (c, tail) = loop {
        let c = chebyshev::coefficients(&grid, n);
        let scale = (0..=n).fold(0.0f64, |m, j| m.max(grid[j * MAX_DEGREE / n].abs()));
        let tail = c[n - 1].abs() + c[n].abs();
        // |p| ≥ |c_0| − Σ_{k≥1} |c_k| on [−1, 1]: a piece whose interpolant stays away from
        // 0 by several times its error estimate has no root (the common case of a g far
        // from its roots: the first pass alone), provided the estimate is one. Half of a
        // Taylor step, 0.4 long, over a sum of sines up to 28 rad/s had at degree 4 an
        // estimate 0.049 against max |g| 0.93 and stayed 0.54 from 0, more than 8 × 0.049,
        // over a dip to −0.026 between roots 0.0217 apart: an estimate that large says the
        // points do not resolve g, so it is not trusted (`TRUSTED_TAIL`).
        let spread: f64 = c[1..=n].iter().map(|v| v.abs()).sum();
        if tail <= TRUSTED_TAIL * scale && c[0].abs() - spread > EXCLUSION_MARGIN * tail {
            out.push((b, g_b));
            return Ok(());
        }
        if tail <= TAIL * scale {
            break (c, tail);
        }
        if n < MAX_DEGREE {
            // The points of degree 2n between those of degree n.
            let stride = MAX_DEGREE / (2 * n);
            for j in (stride..MAX_DEGREE).step_by(2 * stride) {
                grid[j] = eval(chebyshev::node(a, b, j))?;
            }
            n *= 2;
            continue;
        }
        let mid = chebyshev::node(a, b, MAX_DEGREE / 2);
        if depth < MAX_SPLITS && a < mid && mid < b {
            let g_mid = grid[MAX_DEGREE / 2];
            for (lo, hi, g_lo, g_hi) in [(a, mid, grid[0], g_mid), (mid, b, g_mid, g_b)] {
                let mut half = [0.0; MAX_DEGREE + 1];
                (half[0], half[MAX_DEGREE]) = (g_lo, g_hi);
                for j in FIRST {
                    half[j] = eval(chebyshev::node(lo, hi, j))?;
                }
                scan_piece(eval, (lo, hi), half, depth + 1, out)?;
            }
            return Ok(());
        }
        // Not resolved at the finest piece (g is noise-dominated, or faster than 16
        // points per 2⁻⁶ of the step): scanned as it is.
        break (c, tail);
    };
    let mut xs = [0.0; MAX_DEGREE];
    let count = chebyshev::critical_points(&c, n, &mut xs);
    let values: [f64; MAX_DEGREE] = core::array::from_fn(|i| chebyshev::clenshaw(&c, n, xs[i]));
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let sign = |v: f64| v < 0.0;
    for i in 0..count {
        // Between two kept points p is monotone or keeps one sign, so a critical point whose
        // p has the sign of both neighbours (and is not within the error of 0) can go.
        let v = values[i];
        let before = if i == 0 { grid[0] } else { values[i - 1] };
        let after = if i + 1 == count { g_b } else { values[i + 1] };
        if v.abs() > tail && sign(v) == sign(before) && sign(v) == sign(after) {
            continue;
        }
        let t = mid + half * xs[i];
        if t > a && t < b && out.last().is_none_or(|&(last, _)| t > last) {
            out.push((t, eval(t)?));
        }
    }
    out.push((b, g_b));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The points the scan of `g` over [a, b] returns, with the number of evaluations.
    fn points(g: impl Fn(f64) -> f64, a: f64, b: f64) -> (Vec<(f64, f64)>, usize) {
        let mut calls = 0;
        let mut eval = |t: f64| {
            calls += 1;
            Ok(g(t))
        };
        let inner = first_pass_times(a, b).map(&g);
        let mut out = vec![(a, g(a))];
        scan_step(&mut eval, (a, g(a)), (b, g(b)), inner, &mut out).unwrap();
        (out, calls)
    }

    fn sign_changes(p: &[(f64, f64)]) -> usize {
        p.windows(2)
            .filter(|w| (w[0].1 < 0.0) != (w[1].1 < 0.0))
            .count()
    }

    #[test]
    fn a_slow_function_costs_the_first_pass_only() {
        let (p, calls) = points(|t| t - 0.3, 0.0, 1.0);
        assert_eq!(calls, 0);
        assert_eq!(sign_changes(&p), 1);
        let (p, calls) = points(|t| (0.1 * t).cos() + 0.5, 0.0, 1.0);
        assert_eq!((calls, p.len()), (0, 2));
    }

    #[test]
    fn every_root_of_a_fast_sine_is_bracketed() {
        // sin(50 t) on [0.01, 1.41] has the 22 roots kπ/50, k = 1 … 22.
        let (p, _) = points(|t| (50.0 * t).sin(), 0.01, 1.41);
        assert_eq!(sign_changes(&p), 22);
        assert!(p.windows(2).all(|w| w[0].0 < w[1].0));
    }

    #[test]
    fn two_roots_with_the_same_sign_at_the_ends_are_bracketed() {
        // (t − 0.4)(t − 0.41) + 0: positive at both ends, two roots 0.01 apart.
        let (p, calls) = points(|t| (t - 0.4) * (t - 0.41), 0.0, 1.0);
        assert_eq!(sign_changes(&p), 2, "{p:?}");
        // Exact at degree 4: one more evaluation, at the critical point.
        assert_eq!(calls, 1);
    }

    /// Σ Aᵢ sin(ωᵢ t + φᵢ) shifted down to dip δ below 0 at a local minimum near `t0`:
    /// the function, the minimum, and the pair of roots around it (bisection on g to
    /// adjacent doubles), or `None` where S stays below S(t_m) + δ for more than 1.
    fn planted_dip(
        amps: [f64; 3],
        omegas: [f64; 3],
        phases: [f64; 3],
        t0: f64,
        depth: f64,
    ) -> Option<(impl Fn(f64) -> f64 + Copy, f64, [f64; 2])> {
        let s = move |t: f64| {
            (0..3)
                .map(|i| amps[i] * (omegas[i] * t + phases[i]).sin())
                .sum::<f64>()
        };
        let ds = move |t: f64| {
            (0..3)
                .map(|i| amps[i] * omegas[i] * (omegas[i] * t + phases[i]).cos())
                .sum::<f64>()
        };
        let mut t = t0;
        while ds(t) > 0.0 {
            t -= 1e-3;
        }
        while ds(t) < 0.0 {
            t += 1e-3;
        }
        let (mut lo, mut hi) = (t - 1e-3, t);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if ds(m) < 0.0 { lo = m } else { hi = m }
        }
        let t_m = 0.5 * (lo + hi);
        let (s_m, delta) = (s(t_m), depth * amps.iter().sum::<f64>());
        let g = move |t: f64| s(t) - s_m - delta;
        let beside = |dir: f64| {
            let mut t = t_m;
            while g(t + dir * 1e-4) < 0.0 {
                t += dir * 1e-4;
                if (t - t_m).abs() > 1.0 {
                    return None;
                }
            }
            let (mut neg, mut pos) = (t, t + dir * 1e-4);
            loop {
                let m = 0.5 * (neg + pos);
                if m == neg || m == pos {
                    return Some(pos);
                }
                if g(m) < 0.0 { neg = m } else { pos = m }
            }
        };
        Some((g, t_m, [beside(-1.0)?, beside(1.0)?]))
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(4096))]

        /// Two roots around a shallow dip (10⁻³ to 3·10⁻² of Σ|A| deep, a few 1e-3 to a
        /// few 1e-2 apart) of a sum of three sines up to 30 rad/s, anywhere in a step of
        /// 0.05 to 1.4 (Taylor's steps on a smooth system are this long): both are
        /// bracketed by a change of sign between consecutive points of the scan. The
        /// degree-4 first pass sees such a g at five points over up to 40 rad of its
        /// fastest term, and passing a step over on that interpolant's error estimate
        /// alone missed about 4 pairs in 1000.
        #[test]
        fn a_close_pair_with_a_shallow_dip_is_bracketed(
            amps in proptest::array::uniform3(0.1f64..1.0),
            omegas in proptest::array::uniform3(0.5f64..30.0),
            phases in proptest::array::uniform3(0.0f64..6.3),
            t0 in 1.0f64..9.0,
            depth in 1e-3f64..3e-2,
            h in 0.05f64..1.4,
            at in 0.0f64..1.0,
        ) {
            let planted = planted_dip(amps, omegas, phases, t0, depth);
            proptest::prop_assume!(planted.is_some());
            let Some((g, _t_m, pair)) = planted else { return Ok(()) };
            // The step [a, a + h] holds the pair, anywhere in it.
            let room = h - (pair[1] - pair[0]);
            proptest::prop_assume!(room > 0.0);
            let a = pair[0] - (0.001 + 0.998 * at) * room;
            let (p, _) = points(g, a, a + h);
            for r in pair {
                let bracketed = p
                    .windows(2)
                    .any(|w| w[0].0 < r && r <= w[1].0 && (w[0].1 < 0.0) != (w[1].1 < 0.0));
                proptest::prop_assert!(bracketed, "root {} of {:?} on [{}, {}]", r, pair, a, a + h);
            }
        }
    }
}
