//! The scan of one step for the roots of an event function g: which points of the step to
//! evaluate g at so that every sign change of g between them brackets one root, however
//! many roots the step holds.
//!
//! g∘y on the step is interpolated at Chebyshev–Lobatto points along the stepper's own
//! solution ([`Stepper::state_at`](super::Stepper::state_at)): first at degree 4 (the ends,
//! whose values are known, and three inner points), then 8 and 16 while the interpolant's
//! last two Chebyshev coefficients stay above [`TAIL`] times the largest |g| on the piece,
//! then in halves of the piece, down to 2^−[`MAX_SPLITS`] of the step.
//!
//! An interpolant is judged only on evidence it did not make: the interpolant of degree
//! n/2 must have predicted g at the points of degree n that it never saw, within
//! [`TRUSTED_TAIL`] (10⁻³) of the largest |g|. Only then is a piece passed over as
//! rootless (its interpolant more than 8 error estimates away from 0, the estimate being
//! the larger of that prediction gap and the last coefficients) or taken as resolved. The
//! coefficients of the points alone are no such evidence: on a g aliased onto five points,
//! or a low polynomial at them that dips between them, they are small or 0 by chance.
//!
//! On each resolved piece p, the interpolant, is monotone between its critical points,
//! which are isolated exactly on its Bernstein form ([`super::chebyshev`]); g itself is
//! evaluated at those where p comes within its error estimate of 0 or changes sign, so that
//! between two consecutive points of the returned sequence p has at most one root. Each
//! sign change of g along the sequence is then located on g itself by
//! [`super::events::locate_root`]: an interpolant decides where to look, never what is
//! reported.
//!
//! What no scan of samples can promise: a g that agrees at 9 points with a polynomial of
//! degree 4 and reaches 0 between them is passed over (the points see nothing else). Any
//! other g, however fast, is split until it is resolved or the piece is 2⁻⁶ of the step.
//!
//! Cost: on a step where g is slow, seven evaluations of the state and of g besides the
//! step's ends (the first pass's three shared by every event of the run, then the four
//! points of degree 8 that confirm them), and a 5 × 5 and a 9 × 9 transform.

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

/// The largest error, as a fraction of the largest |g| at the interpolant's points, that
/// is trusted for judging a piece: both the gap between g at the new points and the
/// previous interpolant's prediction there, and the last coefficients. A g that the points
/// resolve (slow against the step, the common case) is far below this at degree 8 and
/// costs the first pass and its check only.
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
    // How far g at the points added last lay from the previous interpolant: the only
    // error estimate made with values the interpolant did not see (∞ before any).
    let mut gap = f64::INFINITY;
    let (c, tail) = loop {
        let c = chebyshev::coefficients(&grid, n);
        let scale = (0..=n).fold(0.0f64, |m, j| m.max(grid[j * MAX_DEGREE / n].abs()));
        let tail = c[n - 1].abs() + c[n].abs();
        // The points of degree n alone are no evidence that g is resolved: on a g several
        // periods long across the piece, aliased onto them, the last coefficients can be
        // small by chance (a Taylor step 0.8 long over sines of 26 and 27 rad/s had at
        // degree 4 a tail of 6.9e-4 of max |g| and passed as rootless over two roots 7 ms
        // apart), and on a g that is a low polynomial at the points and dips between them
        // they are 0. So a piece is judged only once the interpolant of degree n/2 has
        // predicted g at the new points within `TRUSTED_TAIL` of max |g| (`confirmed`),
        // and its error is taken as the larger of that gap and the tail.
        let confirmed = gap <= TRUSTED_TAIL * scale;
        let error = tail.max(gap);
        // |p| ≥ |c_0| − Σ_{k≥1} |c_k| on [−1, 1]: a piece whose interpolant stays away from
        // 0 by several times its error stays away from 0 itself (the common case of a g far
        // from its roots), provided the error is trusted (`TRUSTED_TAIL`).
        let spread: f64 = c[1..=n].iter().map(|v| v.abs()).sum();
        if confirmed
            && tail <= TRUSTED_TAIL * scale
            && c[0].abs() - spread > EXCLUSION_MARGIN * error
        {
            out.push((b, g_b));
            return Ok(());
        }
        if confirmed && tail <= TAIL * scale {
            break (c, tail);
        }
        if n < MAX_DEGREE {
            // The points of degree 2n between those of degree n, each against p of degree n.
            let stride = MAX_DEGREE / (2 * n);
            gap = 0.0;
            for j in (stride..MAX_DEGREE).step_by(2 * stride) {
                grid[j] = eval(chebyshev::node(a, b, j))?;
                let predicted = chebyshev::clenshaw(&c, n, chebyshev::node_x(j));
                gap = gap.max((grid[j] - predicted).abs());
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
    fn a_slow_function_costs_the_first_pass_and_its_check() {
        // The four points of degree 8 confirm the first pass, even on a line.
        let (p, calls) = points(|t| t - 0.3, 0.0, 1.0);
        assert_eq!(calls, 4);
        assert_eq!(sign_changes(&p), 1);
        let (p, calls) = points(|t| (0.1 * t).cos() + 0.5, 0.0, 1.0);
        assert_eq!((calls, p.len()), (4, 2));
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
        // Exact at degree 4, confirmed by the four points of degree 8, then one more
        // evaluation at the critical point.
        assert_eq!(calls, 5);
    }

    /// Whether each of `roots` lies in a change of sign between consecutive points.
    fn bracketed(p: &[(f64, f64)], roots: &[f64]) -> bool {
        roots.iter().all(|&r| {
            p.windows(2)
                .any(|w| w[0].0 < r && r <= w[1].0 && (w[0].1 < 0.0) != (w[1].1 < 0.0))
        })
    }

    #[test]
    fn a_shallow_pair_in_a_beat_is_bracketed_on_a_long_step() {
        // The step the Taylor integrator took over a dip 1e-3 Σ|A| deep in the beat of
        // 26.0 and 27.1 rad/s (tests/it/ode/event_roots.rs, found by its property test):
        // at degree 4 the last coefficients were 6.9e-4 of max |g| by aliasing, and the
        // step passed as rootless. The roots, by bisection on g to adjacent doubles, are
        // 7.330994629666139 and 7.3383906504342455.
        let amps = [
            0.952_194_053_327_659_2,
            0.834_293_547_233_176_4,
            0.576_247_133_923_987_6,
        ];
        let omegas = [
            6.000_115_648_719_028,
            27.080_348_543_076_33,
            26.038_471_104_595_125,
        ];
        let phases = [
            5.152_946_613_068_597,
            1.281_068_395_400_474_7,
            6.260_217_977_937_406,
        ];
        let Some((g, _, pair)) = planted_dip(amps, omegas, phases, 7.3347, 1e-3) else {
            panic!("the planted dip has two roots");
        };
        assert!((pair[0] - 7.330_994_629_666_139).abs() < 1e-12, "{pair:?}");
        assert!(
            (pair[1] - 7.338_390_650_434_245_5).abs() < 1e-12,
            "{pair:?}"
        );
        let (p, _) = points(g, 7.081_703_052_716_543, 7.878_785_844_311_958);
        assert!(bracketed(&p, &pair), "{p:?}");
    }

    /// q(x) + κ ω(x) on [a, b] (x ∈ [−1, 1]), ω vanishing at the five points of the first
    /// pass: those points see the line q alone.
    fn hidden_dip(q: [f64; 2], kappa: f64, (a, b): (f64, f64)) -> impl Fn(f64) -> f64 + Copy {
        let r2 = core::f64::consts::FRAC_1_SQRT_2.powi(2);
        move |t: f64| {
            let x = (2.0 * t - a - b) / (b - a);
            q[0] + q[1] * x + kappa * x * (x * x - 1.0) * (x * x - r2)
        }
    }

    /// The changes of sign of g over 20 000 equal parts of [a, b], each to 1e-12.
    fn brute_roots(g: impl Fn(f64) -> f64, a: f64, b: f64) -> Vec<f64> {
        let n = 20_000;
        let at = |i: usize| a + (b - a) * i as f64 / n as f64;
        let mut roots = Vec::new();
        for i in 0..n {
            let (mut lo, mut hi) = (at(i), at(i + 1));
            if (g(lo) < 0.0) == (g(hi) < 0.0) {
                continue;
            }
            while hi - lo > 1e-12 {
                let m = 0.5 * (lo + hi);
                if (g(m) < 0.0) == (g(lo) < 0.0) {
                    lo = m
                } else {
                    hi = m
                }
            }
            roots.push(hi);
        }
        roots
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

        /// A line that the first pass's five points see alone, plus a quintic that vanishes
        /// at them and dips through 0 between them: every root is bracketed. Before the
        /// first pass had to be confirmed by points it did not see, its coefficients beyond
        /// the line were 0 and every such step passed as rootless.
        #[test]
        fn a_dip_hidden_between_the_first_points_is_bracketed(
            level in 0.05f64..1.0,
            slope in -0.04f64..0.04,
            kappa in proptest::prop_oneof![-40.0f64..-2.0, 2.0f64..40.0],
            a in -5.0f64..5.0,
            h in 1e-3f64..3.0,
        ) {
            let g = hidden_dip([level, slope], kappa, (a, a + h));
            let roots = brute_roots(g, a, a + h);
            proptest::prop_assume!(!roots.is_empty());
            let (p, _) = points(g, a, a + h);
            proptest::prop_assert!(bracketed(&p, &roots), "{:?} against {:?}", p, roots);
        }
    }
}
