//! Independent reference values for the body tests: particle lattices summed directly, the
//! generic tensor formula, and Euler's equations in their generic form I⁻¹ (G − ω × I ω).

use nalgebra::{Matrix3, Vector3};
use precess::body::RigidBody;

use super::rng::Rng;

pub use precess_testkit::particles::*;

/// Largest entry of |a − b| relative to the largest entry of |b|.
pub fn rel_err(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).abs().max() / b.abs().max()
}

/// Euler's equations in their generic form, ω̇ = I⁻¹ (G − ω × I ω), any axes. The tensor is
/// scaled to order one before it is inverted, so bodies of any magnitude pass.
pub fn generic_rhs(i: &Matrix3<f64>, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
    let scale = i.abs().max();
    let inverse = (i / scale).try_inverse().expect("invertible") / scale;
    inverse * (g - w.cross(&(i * w)))
}

/// Checks `euler_rhs_principal` (principal axes) against the generic form in description axes at 10⁴
/// random states; returns the worst relative error.
pub fn check_euler(body: &impl RigidBody, seed: u64) -> f64 {
    let mut rng = Rng::new(seed);
    let p = body.principal();
    let r = *p.rotation.matrix();
    let i = body.inertia();
    let mut worst = 0.0f64;
    for _ in 0..10_000 {
        let (w, g) = (rng.vector(-10.0, 10.0), rng.vector(-1.0, 1.0));
        let got = body.euler_rhs_principal(&w, &g);
        let want = r.transpose() * generic_rhs(&i, &(r * w), &(r * g));
        worst = worst.max((got - want).norm() / want.norm().max(1.0));
    }
    assert!(worst < 1e-12, "euler_rhs_principal off by {worst:e}");
    worst
}

/// The distance between two finite f64 of one sign in units in the last place.
pub fn ulps(a: f64, b: f64) -> u64 {
    assert!(a.is_finite() && b.is_finite() && (a == b || a.signum() == b.signum()));
    a.abs().to_bits().abs_diff(b.abs().to_bits())
}
