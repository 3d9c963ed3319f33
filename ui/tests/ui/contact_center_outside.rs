use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.02, at = [0.0, 0.0, 0.03]))]
#[contact(surface = sphere(radius = 0.02), law = rolling, gravity = 9.81)]
struct AboveTheBall;

#[derive(RigidBody)]
#[rigid(ellipsoid(mass = 1.0, semi_axes = [0.2, 0.03, 0.02], at = [0.0, 0.04, 0.0]))]
#[contact(surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02]), law = rolling, gravity = 9.81)]
struct BesideTheEllipsoid;

fn main() {}
