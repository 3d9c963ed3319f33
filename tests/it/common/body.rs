//! Independent reference values for the body tests: particle lattices summed directly, the
//! generic tensor formula, and Euler's equations in their generic form I⁻¹ (G − ω × I ω)
//! (all in the testkit, optimised).

use nalgebra::{Matrix3, Vector3};
use precess::body::RigidBody;

use precess_testkit::euler::principal_rhs_error;

pub use precess_testkit::particles::*;

/// Largest entry of |a − b| relative to the largest entry of |b|.
pub fn rel_err(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).abs().max() / b.abs().max()
}

pub use precess_testkit::euler::generic_rhs;

/// Checks `euler_rhs_principal` (principal axes) against the generic form in description
/// axes at 10⁴ random states (the testkit's `euler`); returns the worst relative error.
pub fn check_euler(body: &impl RigidBody, seed: u64) -> f64 {
    let p = body.principal();
    let rhs = |w: &Vector3<f64>, g: &Vector3<f64>| body.euler_rhs_principal(w, g);
    let worst = principal_rhs_error(&body.inertia(), p.rotation.matrix(), &rhs, seed);
    assert!(worst < 1e-12, "euler_rhs_principal off by {worst:e}");
    worst
}

/// The distance between two finite f64 of one sign in units in the last place.
pub fn ulps(a: f64, b: f64) -> u64 {
    assert!(a.is_finite() && b.is_finite() && (a == b || a.signum() == b.signum()));
    a.abs().to_bits().abs_diff(b.abs().to_bits())
}
