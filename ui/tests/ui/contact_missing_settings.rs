use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact]
struct Bare;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = 9.81, friction = 0.3)]
struct UnknownKey;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling, law = sliding(frictionless), gravity = 9.81)]
struct TwoLaws;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = 9.81, taylor = 10)]
struct NoTaylor;

fn main() {}
