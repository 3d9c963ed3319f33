//! The scan of one step for the roots of an event function g: which points of the step to
//! evaluate g at so that every sign change of g between them brackets one root, however
//! many roots the step holds.
//!
//! g∘y on the step is interpolated at Chebyshev–Lobatto points along the stepper's own
//! solution ([`Stepper::state_at`](super::Stepper::state_at)): first at degree 4 (the ends,
//! whose values are known, and three inner points), then 8 and 16 while the interpolant's
//! last two Chebyshev coefficients stay above [`TAIL`] times the largest |g| on the piece,
//! then in halves of the piece, down to 2^−[`MAX_SPLITS`] of the step. On each resolved
//! piece p, the interpolant, is monotone between its critical points, which are isolated
//! exactly on its Bernstein form ([`super::chebyshev`]); g itself is evaluated at those
//! where p comes within its error estimate of 0 or changes sign, so that between two
//! consecutive points of the returned sequence p has at most one root. Each sign change of
//! g along the sequence is then located on g itself by [`super::events::locate_root`]: an
//! interpolant decides where to look, never what is reported.
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
        // 0 by several times its error estimate has no root, resolved or not (the common
        // case of a g far from its roots: the first pass alone).
        let spread: f64 = c[1..=n].iter().map(|v| v.abs()).sum();
        if c[0].abs() - spread > EXCLUSION_MARGIN * tail {
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
}
