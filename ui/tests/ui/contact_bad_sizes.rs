use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = -0.1), law = rolling, gravity = 9.81)]
struct NegativeRadius;

#[derive(RigidBody)]
#[rigid(ellipsoid(mass = 1.0, semi_axes = [0.2, 0.03, 0.02]))]
#[contact(surface = ellipsoid(semi_axes = [0.2, 0.0, 0.02]), law = rolling, gravity = 9.81)]
struct FlatEllipsoid;

#[derive(RigidBody)]
#[rigid(disk(mass = 1.0, radius = 0.1))]
#[contact(surface = torus(radius = 0.05, tube = 0.06), law = rolling, gravity = 9.81)]
struct FatTorus;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = -9.81)]
struct Upward;

fn main() {}
