//! Typed errors of the closed-form theory of the symmetric top.

use thiserror::Error;

use crate::exact::ExactError;

/// Why a closed form of the symmetric top could not be set up or evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum TheoryError {
    /// An input is NaN or infinite.
    #[error("non-finite {quantity}: {value}")]
    NonFinite {
        /// Which input.
        quantity: &'static str,
        /// Its value.
        value: f64,
    },
    /// A moment of inertia is not positive.
    #[error("the moment {moment} = {value} must be > 0")]
    NonPositiveMoment {
        /// Which moment: I1 (transverse, about the pivot) or I3 (axial).
        moment: &'static str,
        /// Its value.
        value: f64,
    },
    /// The two transverse moments differ: the closed forms hold for I1 = I2 only.
    #[error(
        "the transverse moments differ (I1 = {i1}, I2 = {i2}, relative difference \
         {relative:e} above {limit:e}); the closed forms need a symmetric top"
    )]
    NotSymmetric {
        /// I1.
        i1: f64,
        /// I2.
        i2: f64,
        /// |I1 − I2| / max(I1, I2).
        relative: f64,
        /// The largest relative difference taken as equal.
        limit: f64,
    },
    /// M g l = 0: no gravity torque, so the cubic in cos θ degenerates.
    #[error("M g l = 0: the top is torque-free; use TorqueFreeSymmetric for its cones")]
    NoGravity,
    /// At θ = 0 or π the axis is vertical and φ̇ is defined only if p_φ = ±p_ψ there;
    /// otherwise the kinetic energy is unbounded.
    #[error(
        "at θ = {theta} the axis is vertical, which needs p_φ = {sign}p_ψ (got p_φ = {p_phi}, \
         p_ψ = {p_psi}); otherwise the energy is unbounded",
        sign = if *theta < 1.0 { "" } else { "−" }
    )]
    TransverseMomentumAtPole {
        /// θ.
        theta: f64,
        /// p_φ.
        p_phi: f64,
        /// p_ψ.
        p_psi: f64,
    },
    /// A cosine |u| > 1 names no angle.
    #[error("u = cos θ = {u} lies outside [−1, 1]")]
    CosineOutOfRange {
        /// The value.
        u: f64,
    },
    /// The motion never reaches this cos θ: it nutates between u_min and u_max.
    #[error("u = {u} lies outside the nutation band [{u_min}, {u_max}] of this motion")]
    OutsideNutationBand {
        /// The value asked for.
        u: f64,
        /// The lowest cos θ reached (at θ_max).
        u_min: f64,
        /// The highest cos θ reached (at θ_min).
        u_max: f64,
    },
    /// No steady precession exists at this θ for this spin: I1 cos θ Ω² − I3 ω3 Ω + M g l = 0
    /// has no real root (|ω3| is below the smallest spin that allows one).
    #[error(
        "no steady precession at θ = {theta} with ω3 = {omega3}: it needs \
         |ω3| ≥ {min_omega3} (ω3² ≥ 4 I1 M g l cos θ / I3²)"
    )]
    NoSteadyPrecession {
        /// θ.
        theta: f64,
        /// ω3.
        omega3: f64,
        /// The smallest |ω3| with a steady precession at θ.
        min_omega3: f64,
    },
    /// (θ, Ω, ω3) is not a steady precession: the balance I1 cos θ Ω² − I3 ω3 Ω + M g l is
    /// not zero within its rounding.
    #[error(
        "θ = {theta}, Ω = {precession}, ω3 = {omega3} is not a steady precession: \
         I1 cos θ Ω² − I3 ω3 Ω + M g l = {residual:e} (relative {relative:e})"
    )]
    NotSteady {
        /// θ.
        theta: f64,
        /// The precession rate Ω.
        precession: f64,
        /// ω3.
        omega3: f64,
        /// The balance's value.
        residual: f64,
        /// Relative to the sum of its terms' magnitudes.
        relative: f64,
    },
    /// The reduced (Routh) system in θ is singular at sin θ = 0.
    #[error("the reduced system in θ is singular at θ = {theta} (sin θ = 0)")]
    SingularAtPole {
        /// θ.
        theta: f64,
    },
    /// An elliptic function or integral failed (a time too large to reduce, for one).
    #[error(transparent)]
    Exact(#[from] ExactError),
    /// A derived top's description z axis (the axis its Euler angles ride) is not a principal
    /// axis about the pivot: a product of inertia is not zero, so the top is not symmetric
    /// about it.
    #[error(
        "the top's products of inertia about the pivot (Ixy = {ixy}, Ixz = {ixz}, Iyz = \
         {iyz}) are not zero (relative {relative:e} above {limit:e}): the closed forms need a \
         top symmetric about its description z axis"
    )]
    ProductsOfInertia {
        /// Ixy about the pivot, description axes.
        ixy: f64,
        /// Ixz.
        ixz: f64,
        /// Iyz.
        iyz: f64,
        /// The largest |product| over the largest moment.
        relative: f64,
        /// The largest relative value taken as zero.
        limit: f64,
    },
    /// A derived top's centre of mass is off its description z axis through the pivot: the
    /// gravity torque is then not M g l sin θ about the line of nodes.
    #[error(
        "the top's centre of mass lies off its symmetry axis, at x = {x}, y = {y} from it \
         (relative {relative:e} above {limit:e}): the closed forms need it on the axis"
    )]
    CentreOffAxis {
        /// Its x from the pivot, description axes.
        x: f64,
        /// Its y from the pivot.
        y: f64,
        /// √(x² + y²) over its distance from the pivot.
        relative: f64,
        /// The largest relative offset taken as zero.
        limit: f64,
    },
    /// A derived top declares a torque besides gravity: the heavy-top closed forms do not
    /// hold for it.
    #[error(
        "the top also declares {declared}: the heavy-top closed forms hold under gravity alone"
    )]
    OtherTorque {
        /// The setting, as `#[top(...)]` names it (`damping`, `body_torque`, `space_torque`,
        /// `torque`).
        declared: &'static str,
    },
    /// A derived top carries internal rotors (a gyrostat): their momentum h adds to the
    /// spin momentum, so the heavy-top closed forms, written for h = 0, do not hold.
    #[error(
        "the top carries {rotors} rotor(s): the heavy-top closed forms hold for a top without rotors"
    )]
    Rotor {
        /// How many rotors the top declares.
        rotors: usize,
    },
}

/// Rejects NaN and ±∞, naming the input.
pub(crate) fn finite(quantity: &'static str, value: f64) -> Result<f64, TheoryError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(TheoryError::NonFinite { quantity, value })
    }
}
