//! Internal rotors: symmetric wheels spinning at a constant rate relative to the body about a
//! body-fixed axis, which make the body a gyrostat (free bodies and tops alike).
//!
//! A wheel symmetric about its axis a and spun at the relative rate Ω carries the relative
//! angular momentum h = J Ω â (J its axial moment, â = a/|a|), constant in the body. The
//! body's own inertia I includes the wheel as if it were locked (its transverse and axial
//! moments about the centre of mass are part of the body's parts), so the total angular
//! momentum is I ω + h and Euler's equations become the Volterra–Zhukovsky equations of the
//! gyrostat,
//!
//! I ω̇ = τ − ω × (I ω + h).
//!
//! The motor that holds Ω constant does work on the wheel, so the wheel's own kinetic energy
//! is not the conserved one; ½ ωᵀ I ω is (its rate is ω·τ, the term ω·(ω × h) vanishing).
//!
//! # Driven rotors
//!
//! A [`DrivenRotor`] k is turned by a motor torque uₖ instead: its relative rate Ωₖ is a state
//! variable, the motor's reaction −uₖ âₖ acts on the body, and with I still the inertia with
//! every wheel locked, h = Σ Jₖ Ωₖ âₖ and τ the external torque (body axes),
//!
//! (I − Σ Jₖ âₖ âₖᵀ) ω̇ = τ − ω × (I ω + h) − Σ uₖ âₖ,   Ω̇ₖ = uₖ/Jₖ − âₖ·ω̇.
//!
//! (The wheel's axial spin is ω·â + Ω and J (ω̇·â + Ω̇) = u; the body's momentum balance with
//! the wheel's axial part taken out gives the first line.) I − Σ Jₖ âₖ âₖᵀ is the inertia of
//! the body without its free wheels' axial moments, and must be positive definite. The
//! kinetic energy is the true total,
//!
//! T = ½ ωᵀ I ω + Σ Jₖ Ωₖ âₖ·ω + ½ Σ Jₖ Ωₖ²,   dT/dt = ω·τ + Σ uₖ Ωₖ,
//!
//! and the total angular momentum R (I ω + h) in space is conserved when τ = 0, whatever the
//! motors do (their torques are internal).

use nalgebra::{Matrix3, Vector3};

use crate::ode::OdeError;
use crate::sym::mat3::dot;
use crate::sym::{Arena, ExprId, SymError};

/// A symmetric wheel spinning at a constant rate relative to the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotor {
    /// Its spin axis, fixed in the body, description axes (any non-zero length: it is
    /// normalised).
    pub axis: [ExprId; 3],
    /// Its moment of inertia J about its own axis.
    pub inertia: ExprId,
    /// Its spin rate Ω relative to the body (rad/s, signed about `axis`).
    pub rate: ExprId,
}

impl Rotor {
    /// Its relative angular momentum h = J Ω a/|a|, description axes.
    ///
    /// # Errors
    /// [`SymError`] (a division by zero) if the axis is identically zero.
    pub fn momentum(&self, arena: &mut Arena) -> Result<[ExprId; 3], SymError> {
        let a2 = dot(arena, &self.axis, &self.axis);
        let norm = arena.sqrt(a2)?;
        let scale = arena.mul(self.inertia, self.rate);
        let scale = arena.div(scale, norm)?;
        Ok(self.axis.map(|c| arena.mul(scale, c)))
    }
}

/// A symmetric wheel turned by a motor: its relative rate is a state variable, its
/// acceleration set by the motor torque (see the module's equations).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrivenRotor {
    /// Its spin axis, fixed in the body, description axes (any non-zero length: it is
    /// normalised).
    pub axis: [ExprId; 3],
    /// Its moment of inertia J about its own axis.
    pub inertia: ExprId,
    /// The motor torque u on the wheel about `axis` (N m; the body feels −u â): a constant,
    /// a parameter, or an input symbol a user function supplies.
    pub torque: ExprId,
}

impl DrivenRotor {
    /// Its unit axis â = a/|a|, description axes.
    ///
    /// # Errors
    /// [`SymError`] (a division by zero) if the axis is identically zero.
    pub fn unit_axis(&self, arena: &mut Arena) -> Result<[ExprId; 3], SymError> {
        let a2 = dot(arena, &self.axis, &self.axis);
        let norm = arena.sqrt(a2)?;
        let inv = arena.recip(norm)?;
        Ok(self.axis.map(|c| arena.mul(inv, c)))
    }

    /// The wheel at the relative rate `rate` as a [`Rotor`], for its momentum J Ω â.
    pub fn at_rate(&self, rate: ExprId) -> Rotor {
        Rotor {
            axis: self.axis,
            inertia: self.inertia,
            rate,
        }
    }
}

/// The rotors' total relative angular momentum Σₖ hₖ in description axes, or `None` without
/// rotors (so a body without one derives exactly the expressions it did before).
///
/// # Errors
/// The index of the first rotor whose axis is identically zero, with its [`SymError`].
pub fn total_momentum(
    arena: &mut Arena,
    rotors: &[Rotor],
) -> Result<Option<[ExprId; 3]>, (usize, SymError)> {
    if rotors.is_empty() {
        return Ok(None);
    }
    let mut parts: Vec<[ExprId; 3]> = Vec::with_capacity(rotors.len());
    for (k, r) in rotors.iter().enumerate() {
        parts.push(r.momentum(arena).map_err(|e| (k, e))?);
    }
    Ok(Some(std::array::from_fn(|i| {
        let terms: Vec<ExprId> = parts.iter().map(|p| p[i]).collect();
        arena.sum(&terms)
    })))
}

/// How far above zero the smallest moment of I − Σ J â âᵀ must stand, as a fraction of the
/// body's largest moment: 64 ε. Below it the matrix is singular to rounding — J = I₃(1 − 10⁻¹⁵)
/// leaves 10⁻¹⁵ I₃, a few ulps, whose sign and size are the rounding's — and solving with it
/// gives an ω̇ of 10¹⁵ and a non-finite state a few steps later instead of this refusal.
pub const DRIVEN_ROUNDING: f64 = 64.0 * f64::EPSILON;

/// The first driven rotor k (an index into `rotors`) for which the body's inertia once the
/// wheels up to k turn freely, I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ, is not positive definite beyond rounding
/// (its smallest eigenvalue at most [`DRIVEN_ROUNDING`] times the largest of `inertia`), with
/// that matrix's smallest eigenvalue (NaN if an entry is not finite). `inertia` is about the
/// centre of mass; each rotor is (its axis, its J) in the same axes, an axis of any non-zero
/// length.
///
/// ```
/// use nalgebra::Matrix3;
/// use precess_core::rigid::first_singular_driven;
///
/// let i = Matrix3::from_diagonal(&[2.0, 2.0, 1.0].into());
/// assert_eq!(first_singular_driven(&i, &[([0.0, 0.0, 3.0], 0.5)]), None);
/// // A wheel as heavy about the axis as the whole body leaves it no moment there.
/// let (rotor, smallest) = first_singular_driven(&i, &[([1.0, 0.0, 0.0], 0.5), ([0.0, 0.0, 1.0], 1.0)]).unwrap();
/// assert_eq!(rotor, 1);
/// assert!(smallest.abs() < 1e-15);
/// ```
pub fn first_singular_driven(
    inertia: &Matrix3<f64>,
    rotors: &[([f64; 3], f64)],
) -> Option<(usize, f64)> {
    let mut a = *inertia;
    // The scale rounding is measured against: the body's largest moment (its spectral norm,
    // for a positive definite I).
    let scale = inertia.symmetric_eigenvalues().amax();
    for (k, (axis, j)) in rotors.iter().enumerate() {
        let axis = Vector3::from(*axis);
        a -= (*j / axis.norm_squared()) * axis * axis.transpose();
        if let Some(smallest) = singular_driven_step(&a, scale) {
            return Some((k, smallest));
        }
    }
    None
}

/// The smallest eigenvalue of one step I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ of [`first_singular_driven`] if
/// that step is not positive definite beyond rounding (the eigenvalue at most
/// [`DRIVEN_ROUNDING`] times `scale`, the body's largest moment; NaN if an entry is not
/// finite), `None` if it is: the one criterion, for steps computed here or by a scene's
/// interpreted model.
pub fn singular_driven_step(step: &Matrix3<f64>, scale: f64) -> Option<f64> {
    if !step.iter().all(|v| v.is_finite()) {
        return Some(f64::NAN);
    }
    let smallest = step.symmetric_eigenvalues().min();
    (smallest.is_nan() || smallest <= DRIVEN_ROUNDING * scale).then_some(smallest)
}

/// The driven rotors' rule as both scenes state it: `inertia` (the whole body's, every wheel
/// locked, about the centre of mass for a free body or the pivot for a top) stays positive
/// definite beyond rounding as each wheel's axial moment is taken out,
/// I − Σⱼ≤ₖ Jⱼ âⱼ âⱼᵀ ([`first_singular_driven`]). Each rotor is (its index among every
/// rotor declared, its axis, its J); `refuse` builds the scene's error from the index of the
/// first rotor at which the rule fails and that matrix's smallest eigenvalue, so
/// `TopError::DrivenInertia` and `FreeError::DrivenInertia` come from this one rule.
///
/// ```
/// use nalgebra::Matrix3;
/// use precess_core::rigid::check_driven_inertia;
///
/// let i = Matrix3::from_diagonal(&[2.0, 2.0, 1.0].into());
/// let refuse = |rotor: usize, smallest: f64| (rotor, smallest);
/// assert_eq!(check_driven_inertia(&i, &[(4, [0.0, 0.0, 3.0], 0.5)], refuse), Ok(()));
/// // The body's own moment about the wheel's axis, less 10⁻¹⁵ of it: singular to rounding.
/// let (rotor, _) = check_driven_inertia(&i, &[(4, [0.0, 0.0, 1.0], 1.0 - 1e-15)], refuse).unwrap_err();
/// assert_eq!(rotor, 4);
/// ```
///
/// # Errors
/// `refuse(rotor, smallest)` for the first rotor at which the rule fails (`smallest` NaN if an
/// entry is not finite).
pub fn check_driven_inertia<E>(
    inertia: &Matrix3<f64>,
    rotors: &[(usize, [f64; 3], f64)],
    refuse: impl FnOnce(usize, f64) -> E,
) -> Result<(), E> {
    let wheels: Vec<([f64; 3], f64)> = rotors.iter().map(|&(_, a, j)| (a, j)).collect();
    match first_singular_driven(inertia, &wheels) {
        Some((k, smallest)) => Err(refuse(rotors.get(k).map_or(k, |r| r.0), smallest)),
        None => Ok(()),
    }
}

/// What an integrator's refusal of a rotor's numbers names (the quantity and its value, for
/// [`crate::ode::OdeError::InvalidSystemParameter`]): a rotor with a finite positive axial
/// moment `inertia` was refused for its axis (`rotor axis`, |axis|), any other for its inertia
/// (`rotor inertia`, J).
pub fn rotor_quantity(inertia: f64, axis_norm: f64) -> (String, f64) {
    if inertia.is_finite() && inertia > 0.0 {
        ("rotor axis".to_owned(), axis_norm)
    } else {
        ("rotor inertia".to_owned(), inertia)
    }
}

/// The first driven rotor whose motor torque `torques[k]` is NaN or ±∞, as its name in
/// `rotors` (`rotor_j`), its motor function's in `motors` and the value (a name missing from
/// a list reads `?`).
///
/// ```
/// use precess_core::rigid::first_non_finite_motor;
/// let bad = first_non_finite_motor(&["rotor_0", "rotor_2"], &["hold", "spin_up"], &[1.0, f64::INFINITY]);
/// assert_eq!(bad, Some(("rotor_2", "spin_up", f64::INFINITY)));
/// ```
pub fn first_non_finite_motor(
    rotors: &[&'static str],
    motors: &[&'static str],
    torques: &[f64],
) -> Option<(&'static str, &'static str, f64)> {
    let k = torques.iter().position(|u| !u.is_finite())?;
    let name = |names: &[&'static str]| names.get(k).copied().unwrap_or("?");
    Some((name(rotors), name(motors), torques[k]))
}

/// A motor's NaN or infinite torque as the integrators report it:
/// [`OdeError::NonFiniteInput`] naming the motor function and its rotor (the free body's and
/// the top's `NonFiniteMotor` both map to it).
///
/// ```
/// use precess_core::ode::OdeError;
/// use precess_core::rigid::motor_input_error;
/// let e = motor_input_error("rotor_1", "spin_up", 0.75, f64::NAN);
/// assert!(e.to_string().starts_with("the motor `spin_up` of rotor_1 returned NaN at t = 0.75"));
/// assert!(matches!(e, OdeError::NonFiniteInput { t, .. } if t == 0.75));
/// ```
pub fn motor_input_error(rotor: &str, motor: &str, t: f64, value: f64) -> OdeError {
    OdeError::NonFiniteInput {
        input: format!("the motor `{motor}` of {rotor}"),
        t,
        value,
    }
}
