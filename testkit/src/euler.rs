//! Euler's equations in their generic form, ω̇ = I⁻¹ (G − ω × I ω) in any axes: what the
//! body tests check the principal-axes right-hand sides against, at 10⁴ random states a
//! body, optimised (unoptimised nalgebra made the check most of those tests' time).
#![warn(missing_docs)]

use precess::nalgebra::{Matrix3, Vector3};

use crate::rng::Rng;

/// ω̇ = I⁻¹ (G − ω × I ω) in the axes of `i`. The tensor is scaled to order one before it
/// is inverted, so bodies of any magnitude pass.
///
/// # Panics
/// If `i` is singular.
pub fn generic_rhs(i: &Matrix3<f64>, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
    let scale = i.abs().max();
    let inverse = (i / scale).try_inverse().expect("invertible") / scale;
    inverse * (g - w.cross(&(i * w)))
}

/// A right-hand side ω̇(ω, G), all three in one body's axes.
pub type Rhs<'a> = &'a dyn Fn(&Vector3<f64>, &Vector3<f64>) -> Vector3<f64>;

/// The worst relative error |ω̇ − ω̇_generic| / max(|ω̇_generic|, 1) of `principal_rhs` (ω and
/// G in principal axes to ω̇ in principal axes) against [`generic_rhs`] of the tensor `i`
/// in description axes, `r` the principal axes in description axes, at 10⁴ states drawn
/// from `seed` (ω in [−10, 10]³, G in [−1, 1]³).
pub fn principal_rhs_error(
    i: &Matrix3<f64>,
    r: &Matrix3<f64>,
    principal_rhs: Rhs<'_>,
    seed: u64,
) -> f64 {
    let mut rng = Rng::new(seed);
    let mut worst = 0.0f64;
    for _ in 0..10_000 {
        let (w, g) = (rng.vector(-10.0, 10.0), rng.vector(-1.0, 1.0));
        let got = principal_rhs(&w, &g);
        let want = r.transpose() * generic_rhs(i, &(r * w), &(r * g));
        worst = worst.max((got - want).norm() / want.norm().max(1.0));
    }
    worst
}
