use precess::free::FreeState;
use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81, wrench = push)]
struct Ball;

// A wrench function returns an `AppliedWrench`, which names its frame; a bare vector does not.
fn push(_: &Ball, _: f64, _: &FreeState) -> Vector3<f64> {
    Vector3::new(0.0, 0.0, 1.0)
}

fn main() {}
