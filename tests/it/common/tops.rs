//! The reference top of the published heavy-top values, shared by the tests that check the
//! derived equations, the closed forms and the linearisation against them.

use precess::prelude::*;

/// I1 = I2 = 1, I3 = ½ about the pivot, M g l = 1 (M = 1, l = 1, g = 1), in ZXZ.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
pub struct ReferenceTop;
