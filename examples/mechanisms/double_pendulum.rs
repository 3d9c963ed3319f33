//! The double pendulum's struct, shared by the `double_pendulum` example and
//! tests/mechanism_examples.rs (each includes this file with `#[path]`), so the test checks
//! the very mechanism the example derives.

use precess::prelude::*;

/// Two point masses on massless rods swinging about x.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(name = shoulder, axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(name = elbow, axis = x, at = [0.0, 0.0, -l1]),
       q = theta2, parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
pub struct DoublePendulum {
    /// The upper mass [kg].
    pub m1: f64,
    /// The upper rod's length [m].
    pub l1: f64,
    /// The lower mass [kg].
    pub m2: f64,
    /// The lower rod's length [m].
    pub l2: f64,
}
