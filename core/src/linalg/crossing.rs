//! Where a stability boundary lies along a parameter: the parameter p at which the largest
//! real part of an eigenvalue of A(p) (the spectral abscissa α(p) = max Re λ) crosses zero,
//! found by Brent's method (Brent, Algorithms for Minimization without Derivatives, 1973,
//! ch. 4) on a bracket where α changes sign.
//!
//! α is continuous in p wherever A is (eigenvalues are continuous in the entries), though
//! not smooth where two modes exchange the lead; Brent's method keeps a bracket and falls
//! back to bisection whenever its interpolation would not shrink it enough, so it
//! converges on such a kink as on a smooth root, to the tolerance asked.

use std::convert::Infallible;

use nalgebra::{Complex, DMatrix};
use thiserror::Error;

use super::eigen::eigenvalues;
use super::error::LinalgError;

/// The default tolerance on the parameter, relative to max(|p|, 1).
pub const CROSSING_TOLERANCE: f64 = 1e-13;

/// Most evaluations Brent's method may spend: bisection alone halves the bracket 1074
/// times before it reaches the smallest double, and Brent's method takes at most about
/// twice bisection's count, so a finite function never reaches this.
const MAX_EVALUATIONS: usize = 2200;

/// A located crossing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// The parameter at which the function is zero (within the tolerance).
    pub parameter: f64,
    /// The width of the final bracket, which holds the exact crossing.
    pub bracket_width: f64,
    /// The function's value at `parameter`.
    pub value: f64,
    /// The evaluations spent, the two ends of the bracket included.
    pub evaluations: usize,
}

/// Why no crossing was located. `E` is the error of the caller's model (a mechanism that
/// refuses a state, say); [`Infallible`] for a model that cannot fail.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CrossingError<E: std::error::Error + 'static = Infallible> {
    /// The bracket is not a finite interval lo < hi.
    #[error("the bracket [{lo}, {hi}] must be finite with lo < hi")]
    InvalidBracket {
        /// Its lower end.
        lo: f64,
        /// Its upper end.
        hi: f64,
    },
    /// The tolerance must be finite and > 0.
    #[error("the tolerance {value} must be finite and > 0")]
    InvalidTolerance {
        /// The value given.
        value: f64,
    },
    /// The function has the same sign at both ends: no crossing is bracketed (there may be
    /// none in the range, or an even number).
    #[error(
        "no crossing in [{lo}, {hi}]: the function is {at_lo:e} at {lo} and {at_hi:e} at {hi}, \
         of the same sign"
    )]
    NoCrossing {
        /// The lower end.
        lo: f64,
        /// The upper end.
        hi: f64,
        /// The function's value there.
        at_lo: f64,
        /// The function's value there.
        at_hi: f64,
    },
    /// The function was NaN or infinite at a parameter.
    #[error("the function is {value} at parameter {parameter}")]
    NonFinite {
        /// Where.
        parameter: f64,
        /// The value.
        value: f64,
    },
    /// The bracket did not shrink to the tolerance within the evaluation cap (never seen
    /// on a finite function; the cap exists so the search always returns).
    #[error(
        "no convergence after {evaluations} evaluations: the bracket about {parameter} is \
         {bracket_width:e} wide"
    )]
    NotConverged {
        /// The best estimate.
        parameter: f64,
        /// The bracket's width.
        bracket_width: f64,
        /// The evaluations spent.
        evaluations: usize,
    },
    /// The eigenvalues of A(p) could not be computed.
    #[error("at parameter {parameter}: {source}")]
    Linalg {
        /// Where.
        parameter: f64,
        /// Why.
        source: LinalgError,
    },
    /// The caller's model failed at a parameter.
    #[error("the model failed at parameter {parameter}: {source}")]
    Model {
        /// Where.
        parameter: f64,
        /// Why.
        source: E,
    },
}

/// The largest real part of the eigenvalues, −∞ for none.
pub fn spectral_abscissa(eig: &[Complex<f64>]) -> f64 {
    eig.iter().map(|e| e.re).fold(f64::NEG_INFINITY, f64::max)
}

/// Where the spectral abscissa α(p) = max Re λ(A(p)) crosses zero in [lo, hi]: the
/// parameter at which the linear system ẋ = A(p) x gains or loses stability. `matrix(p)`
/// gives A(p); `tol` is the tolerance on p relative to max(|p|, 1)
/// ([`CROSSING_TOLERANCE`] is a good default).
///
/// # Errors
/// [`CrossingError::InvalidBracket`], [`CrossingError::InvalidTolerance`];
/// [`CrossingError::NoCrossing`] if α has the same sign at lo and hi;
/// [`CrossingError::NonFinite`]; [`CrossingError::Linalg`] where the eigenvalues fail (a
/// non-finite entry of A); [`CrossingError::Model`] where `matrix` fails.
///
/// # Examples
///
/// The damped oscillator ẍ + (p − 1) ẋ + x = 0 is stable for p > 1:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::linalg::{CROSSING_TOLERANCE, stability_crossing};
/// use precess_core::nalgebra::DMatrix;
///
/// let a = |p: f64| Ok::<_, std::convert::Infallible>(DMatrix::from_row_slice(
///     2, 2, &[0.0, 1.0, -1.0, 1.0 - p],
/// ));
/// let c = stability_crossing(a, 0.0, 3.0, CROSSING_TOLERANCE)?;
/// assert_relative_eq!(c.parameter, 1.0, epsilon = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn stability_crossing<E: std::error::Error + 'static>(
    mut matrix: impl FnMut(f64) -> Result<DMatrix<f64>, E>,
    lo: f64,
    hi: f64,
    tol: f64,
) -> Result<Crossing, CrossingError<E>> {
    find_crossing(
        |p| {
            let a = matrix(p).map_err(|source| CrossingError::Model {
                parameter: p,
                source,
            })?;
            let eig = eigenvalues(&a).map_err(|source| CrossingError::Linalg {
                parameter: p,
                source,
            })?;
            Ok(spectral_abscissa(&eig))
        },
        lo,
        hi,
        tol,
    )
}

/// Where a continuous scalar function g changes sign in [lo, hi], by Brent's method, to
/// `tol` relative to max(|p|, 1) (a mode's own real part, for example, rather than the
/// spectral abscissa of [`stability_crossing`]).
///
/// # Errors
/// As [`stability_crossing`]; the errors `g` returns are passed on as they are.
///
/// # Examples
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::linalg::{CrossingError, find_crossing};
///
/// let c = find_crossing(|p| Ok::<_, CrossingError>(p.cos()), 1.0, 2.0, 1e-14)?;
/// assert_relative_eq!(c.parameter, std::f64::consts::FRAC_PI_2, epsilon = 1e-13);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn find_crossing<E: std::error::Error + 'static>(
    mut g: impl FnMut(f64) -> Result<f64, CrossingError<E>>,
    lo: f64,
    hi: f64,
    tol: f64,
) -> Result<Crossing, CrossingError<E>> {
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(CrossingError::InvalidBracket { lo, hi });
    }
    if !(tol.is_finite() && tol > 0.0) {
        return Err(CrossingError::InvalidTolerance { value: tol });
    }
    let mut evaluations = 0;
    let mut eval = |p: f64, count: &mut usize| -> Result<f64, CrossingError<E>> {
        *count += 1;
        let value = g(p)?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(CrossingError::NonFinite {
                parameter: p,
                value,
            })
        }
    };
    let (mut a, mut b) = (lo, hi);
    let (mut fa, mut fb) = (eval(a, &mut evaluations)?, eval(b, &mut evaluations)?);
    if fa == 0.0 || fb == 0.0 {
        let (parameter, value) = if fa == 0.0 { (a, fa) } else { (b, fb) };
        return Ok(Crossing {
            parameter,
            bracket_width: 0.0,
            value,
            evaluations: 2,
        });
    }
    if (fa > 0.0) == (fb > 0.0) {
        return Err(CrossingError::NoCrossing {
            lo,
            hi,
            at_lo: fa,
            at_hi: fb,
        });
    }
    // Brent's zero: b is the best estimate, a the previous one, c the other end of the
    // bracket [b, c] (or [c, b]); d the last step and e the one before.
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..MAX_EVALUATIONS {
        if (fb > 0.0) == (fc > 0.0) {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let scale = tol * b.abs().max(1.0);
        let t = 2.0 * f64::EPSILON * b.abs() + 0.5 * scale;
        let m = 0.5 * (c - b);
        if m.abs() <= t || fb == 0.0 {
            return Ok(Crossing {
                parameter: b,
                bracket_width: (c - b).abs(),
                value: fb,
                evaluations,
            });
        }
        if e.abs() < t || fa.abs() <= fb.abs() {
            // The last steps were too small: bisect.
            d = m;
            e = m;
        } else {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                // Secant.
                (2.0 * m * s, 1.0 - s)
            } else {
                // Inverse quadratic interpolation.
                let (qa, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0)),
                    (qa - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (t * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        }
        (a, fa) = (b, fb);
        b += if d.abs() > t { d } else { t.copysign(m) };
        fb = eval(b, &mut evaluations)?;
    }
    // Unreachable for a finite function (see MAX_EVALUATIONS); reported, not looped.
    Err(CrossingError::NotConverged {
        parameter: b,
        bracket_width: (c - b).abs(),
        evaluations,
    })
}
