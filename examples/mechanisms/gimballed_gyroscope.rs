//! The gimballed gyroscope's struct, shared by the `gimballed_gyroscope` example and
//! tests/mechanism_examples.rs (each includes this file with `#[path]`), so the test checks
//! the very mechanism the example derives.

use precess::prelude::*;

/// The rotor in an inner and an outer gimbal; the gimbals' masses are fields, so they can
/// be zero.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(outer, parent = ground, joint = revolute(axis = z), q = phi,
       parts(ring(mass = m_outer, radius = 0.08, axis = y)))]
#[body(inner, parent = outer, joint = revolute(axis = x), q = theta,
       parts(ring(mass = m_inner, radius = 0.07, axis = y)))]
#[body(rotor, parent = inner, joint = revolute(axis = z), q = psi,
       parts(disk(mass = 0.4, radius = 0.05, at = [0.0, 0.0, 0.04])))]
pub struct Gyroscope {
    /// The outer gimbal's mass [kg] (zero: massless).
    pub m_outer: f64,
    /// The inner gimbal's mass [kg] (zero: massless).
    pub m_inner: f64,
}
