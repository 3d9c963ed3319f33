use precess::free::{AppliedWrench, FreeState};
use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81, wrench = table, taylor = 20)]
struct Ball;

fn table(_: &Ball, _: f64, _: &FreeState) -> AppliedWrench {
    AppliedWrench::zero()
}

fn main() {}
