use precess::free::FreeState;
use precess::prelude::*;

fn push(_: &Ball, _: f64, _: &FreeState) -> Vector3<f64> {
    Vector3::zeros()
}

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(taylor = 20, force = push)]
struct Ball;

fn main() {}
