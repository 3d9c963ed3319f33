//! Typed errors of the exact solutions.

use thiserror::Error;

/// Why an exact solution could not be set up or evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum ExactError {
    /// The complementary parameter m_c = 1 − m must lie in [0, 1].
    #[error("complementary parameter m_c = {mc} is outside [0, 1]")]
    ParameterOutOfRange {
        /// The offending m_c.
        mc: f64,
    },
    /// An argument (time, angle, state component) is NaN or infinite.
    #[error("non-finite argument {value} for `{name}`")]
    NonFinite {
        /// Which argument.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// Principal moments of inertia must be finite and positive.
    #[error("principal moments must be finite and > 0, got {inertia:?}")]
    InvalidInertia {
        /// The moments given.
        inertia: [f64; 3],
    },
    /// An elliptic argument (or a phase λt + u₀) too large to reduce modulo 2K accurately.
    #[error(
        "argument {u:e} exceeds {limit:e}, beyond which the reduction modulo 2K loses accuracy"
    )]
    ArgumentTooLarge {
        /// The argument.
        u: f64,
        /// The largest accepted magnitude.
        limit: f64,
    },
    /// R_J's value is beyond f64, or its arguments span more orders of magnitude than one
    /// power-of-two scaling can bring into range together.
    #[error(
        "Carlson integral R_J({x:e}, {y:e}, {z:e}, {p:e}) is outside the range of f64 (the \
         value overflows or the arguments span too many orders of magnitude)"
    )]
    CarlsonRange {
        /// First argument.
        x: f64,
        /// Second argument.
        y: f64,
        /// Third argument.
        z: f64,
        /// Fourth argument.
        p: f64,
    },
    /// F(φ | m) at m = 1 (m_c = 0) diverges at |φ| = π/2, where K = ∞: no value beyond.
    #[error("F(φ | m = 1) diverges for |φ| ≥ π/2 (m_c = 0, K = ∞); got φ = {phi}")]
    Diverges {
        /// The amplitude asked for.
        phi: f64,
    },
    /// An attitude quaternion is not of unit norm (|q| − 1 beyond 1e-6): it is no rotation.
    #[error("attitude quaternion has norm {norm}, not 1: it is no rotation")]
    NotUnitQuaternion {
        /// Its norm.
        norm: f64,
    },
    /// A Carlson integral was called outside its domain.
    #[error("Carlson integral outside its domain: ({x}, {y}, {z})")]
    CarlsonDomain {
        /// First argument.
        x: f64,
        /// Second argument.
        y: f64,
        /// Third argument.
        z: f64,
    },
    /// The rate of the free body's motion, about |m|/I, is beyond the f64 range: the moments
    /// are too small for the angular momentum (the period would be below the smallest
    /// double).
    #[error(
        "the motion's rate |m|/I overflows f64: principal moments {inertia:?} are too small \
         for the angular momentum m(0) = {m0:?}"
    )]
    RateOverflow {
        /// The principal moments given.
        inertia: [f64; 3],
        /// The initial angular momentum given.
        m0: [f64; 3],
    },
}

impl ExactError {
    /// Checks that an attitude quaternion has unit norm (within 1e-6).
    ///
    /// # Errors
    /// [`ExactError::NotUnitQuaternion`].
    pub(crate) fn check_unit(q: &nalgebra::UnitQuaternion<f64>) -> Result<(), ExactError> {
        let norm = q.quaternion().norm();
        if (norm - 1.0).abs() <= 1e-6 {
            Ok(())
        } else {
            Err(ExactError::NotUnitQuaternion { norm })
        }
    }
}

/// Rejects NaN and infinities.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, ExactError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ExactError::NonFinite { name, value })
    }
}
