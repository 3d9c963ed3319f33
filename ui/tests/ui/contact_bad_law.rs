use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = slidng(viscous = 0.1), gravity = 9.81)]
struct Misspelled;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling(friction = 0.1), gravity = 9.81)]
struct UnknownKey;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding, gravity = 9.81)]
struct NoFriction;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(viscous = 0.1, coulomb = 0.2), gravity = 9.81)]
struct TwoFrictions;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(frictionless = 0.0), gravity = 9.81)]
struct FlagWithValue;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(coulomb), gravity = 9.81)]
struct KeyWithoutValue;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = stick_slip, gravity = 9.81)]
struct NoMu;

fn main() {}
