use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, taylor = 0)]
struct Top;

fn main() {}
