//! A symmetric heavy top: a brass disk on a steel stem turning on the stem's tip, its
//! Euler-angle equations emitted by `#[top(gravity = 9.81)]`. Its closed forms (the exact
//! nutation, steady precession, the sleeping threshold) are [`crate::top::HeavyTopTheory`],
//! reached through [`crate::top::TopDynamics::theory`].

use crate::prelude::RigidBody;

/// A disk (brass, 0.2 kg, radius 40 mm) 50 mm up a stem (steel, 10 g, radius 3 mm, 80 mm
/// long), turning on the stem's tip at the pivot, under g = 9.81 m/s².
///
/// # Examples
///
/// The sleeping top is stable above ω₃² = 4 M g l I₁ / I₃² (the Maxwell–Klein condition),
/// with M g l and the moments about the pivot as the derive computed them:
///
/// ```
/// use approx::assert_relative_eq;
/// use precess::models::HeavyTop;
/// use precess::prelude::*;
///
/// let (m, l) = (HeavyTop.mass(), HeavyTop.center_of_mass().z);
/// let [i1, _, i3] = HeavyTop.principal().moments.into();
/// let threshold = (4.0 * m * 9.81 * l * i1).sqrt() / i3;
/// assert_relative_eq!(HeavyTop.theory()?.sleeping_threshold(), threshold, max_relative = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, RigidBody)]
#[rigid(
    disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]),
    cylinder(mass = 0.01, radius = 0.003, length = 0.08, at = [0.0, 0.0, 0.04]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
pub struct HeavyTop;
