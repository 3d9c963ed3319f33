use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.2]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81)]
#[contact(surface = sphere(radius = 0.3), law = rolling, gravity = 9.81)]
struct WithTop;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81)]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = 9.81)]
struct WithFree;

fn main() {}
