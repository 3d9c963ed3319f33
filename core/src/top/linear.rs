//! A derived top linearised about a state: the full system in (q, q̇) from the generated
//! Jacobian, and the reduced (Routh) system with the cyclic coordinates' momenta held fixed.

use nalgebra::{DMatrix, DVector};
use thiserror::Error;

use super::checks::check_state;
use super::dynamics::{TopDynamics, angle_state};
use super::error::TopError;
use crate::linalg::{LinalgError, LinearSystem, jacobian};
use crate::rigid::check_chart;

/// Smallest |det| of the cyclic block of the mass matrix, relative to the product of its
/// diagonal, for the cyclic rates to be solvable from the momenta.
pub const MOMENTUM_MAP_TOLERANCE: f64 = 1e-12;

/// Why a linearisation could not be formed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LinearisationError {
    /// The state is not finite or the chart is singular there (see [`TopError`]).
    #[error(transparent)]
    Top(#[from] TopError),
    /// The Jacobian is not finite, or the eigenvalue routine failed.
    #[error(transparent)]
    Linalg(#[from] LinalgError),
    /// The cyclic rates cannot be solved from the conserved momenta here: the cyclic block
    /// of the mass matrix is singular (the chart's gimbal lock, in practice).
    #[error(
        "the cyclic block of the mass matrix is singular at q = {q:?} \
         (|det| = {det:e} relative to its diagonal, below {limit:e})",
        limit = MOMENTUM_MAP_TOLERANCE
    )]
    SingularMomentumMap {
        /// The angles.
        q: [f64; 3],
        /// |det M_cc| / Π |M_ii|.
        det: f64,
    },
}

/// The linear system ẋ = A x of a derived top's angle form about `(q, q̇)` at time t, with
/// x = (δq, δq̇) and A = [[0, I], [∂q̈/∂q, ∂q̈/∂q̇]] from the generated
/// [`TopDynamics::angle_jacobian`] (exact derivatives, no differencing).
///
/// About a steady motion that moves along cyclic coordinates (a steady precession advances
/// φ and ψ), A is the same at every point of the motion, so its spectrum is that motion's:
/// zeros for the cyclic directions and their momenta, and the oscillation of the rest.
///
/// # Errors
/// [`LinearisationError::Top`] for a non-finite state or at the chart's gimbal lock (use a
/// top declared with the other sequence, e.g. ZYX about the vertical);
/// [`LinearisationError::Linalg`] if the Jacobian is not finite.
///
/// # Examples
///
/// Steady precession of the reference top (I1 = 1, I3 = ½, M g l = 1) at 60° with ω3 = 10
/// is linearly stable, its small nutation at ω_n = √((a − 2Ω cos θ)² + Ω² sin²θ):
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::prelude::*;
/// use precess::linalg::Stability;
/// use precess::top::{HeavyTopTheory, angle_linearisation};
///
/// #[derive(RigidBody)]
/// #[rigid(
///     body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
///     pivot = [0.0, 0.0, 0.0],
/// )]
/// #[top(gravity = 1.0)]
/// struct Heavy;
///
/// let theta = std::f64::consts::FRAC_PI_3;
/// let theory = HeavyTopTheory::new(1.0, 0.5, 1.0)?;
/// let steady = theory.steady_precession(theta, 10.0)?;
/// let lin = angle_linearisation(&Heavy, 0.0, &[0.0, theta, 0.0], &steady.rates(steady.slow))?;
/// assert!(matches!(lin.stability()?, Stability::LinearlyStable { .. }));
/// let top_frequency = lin.eigenvalues()?.iter().map(|e| e.im).fold(0.0, f64::max);
/// let w_n = theory.small_nutation_frequency(theta, steady.slow, 10.0)?;
/// assert_relative_eq!(top_frequency, w_n, max_relative = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn angle_linearisation<T: TopDynamics>(
    top: &T,
    t: f64,
    q: &[f64; 3],
    q_dot: &[f64; 3],
) -> Result<LinearSystem, LinearisationError> {
    check_state(&angle_state(q, q_dot))?;
    check_chart(T::SEQUENCE, &top.rate_matrix_in(T::SEQUENCE, q), q).map_err(TopError::from)?;
    let jac = top.angle_jacobian(t, q, q_dot);
    let a = DMatrix::from_fn(6, 6, |r, c| match r {
        0..=2 => f64::from(u8::from(c == r + 3)),
        _ => jac[r - 3][c],
    });
    Ok(LinearSystem::new(a)?)
}

/// The reduced linearisation of [`reduced_linearisation`].
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedLinearisation {
    /// ẋ = A x for x = (δq_k, δq̇_k) over the kept (non-cyclic) coordinates k.
    pub system: LinearSystem,
    /// The indices into q of the kept coordinates, in order.
    pub kept: Vec<usize>,
    /// The momenta held fixed (`Some` for each cyclic coordinate).
    pub momenta: [Option<f64>; 3],
}

/// The top linearised about `(q, q̇)` with its cyclic coordinates reduced (Routh): the
/// momenta p_c = ∂L/∂q̇_c the derivation marks conserved are held at their values, the cyclic
/// rates solved from them, and the remaining coordinates' (q_k, q̇_k) linearised by central
/// differences with Richardson extrapolation ([`crate::linalg::jacobian`]).
///
/// For the symmetric heavy top in ZXZ this is the 2×2 system in (θ, θ̇) at fixed p_φ, p_ψ;
/// about a steady precession its eigenvalues are ±i ω_n (see
/// [`super::HeavyTopTheory::small_nutation_frequency`]), without the zero eigenvalues the
/// cyclic directions add to [`angle_linearisation`].
///
/// The momenta are linear in q̇ (p = M(q) q̇ for a top), so the mass-matrix rows M_c· are read
/// off the generated momenta at unit rates.
///
/// # Errors
/// As [`angle_linearisation`]; [`LinearisationError::SingularMomentumMap`] if the cyclic
/// rates cannot be solved from the momenta at q.
pub fn reduced_linearisation<T: TopDynamics>(
    top: &T,
    t: f64,
    q: &[f64; 3],
    q_dot: &[f64; 3],
) -> Result<ReducedLinearisation, LinearisationError> {
    check_state(&angle_state(q, q_dot))?;
    check_chart(T::SEQUENCE, &top.rate_matrix_in(T::SEQUENCE, q), q).map_err(TopError::from)?;
    let momenta = top.conserved_momenta(q, q_dot);
    let cyclic: Vec<usize> = (0..3).filter(|&i| momenta[i].is_some()).collect();
    let kept: Vec<usize> = (0..3).filter(|&i| momenta[i].is_none()).collect();
    let fixed: Vec<f64> = momenta.iter().flatten().copied().collect();
    check_momentum_map(top, q, &cyclic)?;
    let r = kept.len();
    let field = |z: &[f64], out: &mut [f64]| {
        let (mut qz, mut rates) = (*q, [0.0; 3]);
        for (i, &k) in kept.iter().enumerate() {
            qz[k] = z[i];
            rates[k] = z[r + i];
        }
        match cyclic_rates(top, &qz, &rates, &cyclic, &fixed) {
            Some(rc) => {
                for (&c, v) in cyclic.iter().zip(rc.iter()) {
                    rates[c] = *v;
                }
                let acc = top.accelerations_unchecked(t, &qz, &rates);
                for (i, &k) in kept.iter().enumerate() {
                    out[i] = z[r + i];
                    out[r + i] = acc[k];
                }
            }
            // Reported by the Jacobian's finiteness check.
            None => out.fill(f64::NAN),
        }
    };
    let z0: Vec<f64> = kept
        .iter()
        .map(|&k| q[k])
        .chain(kept.iter().map(|&k| q_dot[k]))
        .collect();
    let system = LinearSystem::new(jacobian(field, &z0)?)?;
    Ok(ReducedLinearisation {
        system,
        kept,
        momenta,
    })
}

/// M_ij = p_i(q, e_j) for the cyclic rows i.
fn mass_row<T: TopDynamics>(top: &T, q: &[f64; 3], i: usize, j: usize) -> f64 {
    let mut unit = [0.0; 3];
    unit[j] = 1.0;
    top.conserved_momenta(q, &unit)[i].unwrap_or(f64::NAN)
}

/// The cyclic rates q̇_c solving M_cc q̇_c = p_c − M_ck q̇_k (`rates` holds q̇_k, zeros at c).
fn cyclic_rates<T: TopDynamics>(
    top: &T,
    q: &[f64; 3],
    rates: &[f64; 3],
    cyclic: &[usize],
    fixed: &[f64],
) -> Option<DVector<f64>> {
    let n = cyclic.len();
    let m_cc = DMatrix::from_fn(n, n, |a, b| mass_row(top, q, cyclic[a], cyclic[b]));
    let rhs = DVector::from_fn(n, |a, _| {
        fixed[a]
            - (0..3)
                .map(|j| mass_row(top, q, cyclic[a], j) * rates[j])
                .sum::<f64>()
    });
    m_cc.lu().solve(&rhs)
}

/// Refuses a cyclic block of M whose determinant vanishes relative to its diagonal.
fn check_momentum_map<T: TopDynamics>(
    top: &T,
    q: &[f64; 3],
    cyclic: &[usize],
) -> Result<(), LinearisationError> {
    let n = cyclic.len();
    if n == 0 {
        return Ok(());
    }
    let m_cc = DMatrix::from_fn(n, n, |a, b| mass_row(top, q, cyclic[a], cyclic[b]));
    let diag: f64 = (0..n).map(|a| m_cc[(a, a)].abs()).product();
    let det = m_cc.determinant().abs() / diag;
    if det >= MOMENTUM_MAP_TOLERANCE {
        Ok(())
    } else {
        Err(LinearisationError::SingularMomentumMap { q: *q, det })
    }
}
