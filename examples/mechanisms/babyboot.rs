//! The babyboot's struct, shared by the `babyboot` example and tests/mechanism_examples.rs
//! (each includes this file with `#[path]`), so the test checks the very mechanism the
//! example derives.

use precess::prelude::*;

/// Rod A on a horizontal hinge, plate B on a hinge along A.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(rod, parent = ground, joint = revolute(axis = x), q = q_a,
       parts(body(mass = 0.01, at = [0.0, 0.0, -0.075],
                  inertia = diag(5.0e-6, 5.0e-6, 1.0e-7))))]
#[body(plate, parent = rod, joint = revolute(axis = z, at = [0.0, 0.0, -0.2]), q = q_b,
       parts(body(mass = 0.1, inertia = diag(2.5e-4, 5.0e-5, 2.0e-4))))]
pub struct Babyboot;
