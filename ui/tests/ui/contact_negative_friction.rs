use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(viscous = -0.3), gravity = 9.81)]
struct Viscous;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(coulomb = -0.3), gravity = 9.81)]
struct Coulomb;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = stick_slip(mu = 0.1 - 0.4), gravity = 9.81)]
struct StickSlip;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling(spin_resistance = -1e-4), gravity = 9.81)]
struct Spin;

fn main() {}
