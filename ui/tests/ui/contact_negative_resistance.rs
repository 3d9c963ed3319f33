use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(
    surface = sphere(radius = 0.1),
    law = stick_slip(mu = 0.3, rolling_resistance = -1e-4, spin_resistance = -2e-4),
    gravity = 9.81,
)]
struct Resisted;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling(pivoting = -0.002), gravity = 9.81)]
struct Pivoting;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = sliding(normal_viscous = -0.3), gravity = 9.81)]
struct NormalViscous;

/// A pivoting friction is a length (μ_p times the patch's radius), not a rate.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = stick_slip(mu = 0.3, pivoting = 2 rpm), gravity = 9.81)]
struct PivotingUnits;

fn main() {}
