use precess::prelude::*;

// A surface's sizes are lengths, gravity an acceleration, a resistance a torque per rad/s,
// viscous friction a force per m/s and μ a pure number.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 10 cm))]
#[contact(surface = sphere(radius = 100 g), law = rolling(rolling_resistance = 2 N), gravity = 9.81 m)]
struct Sizes;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 10 cm))]
#[contact(surface = sphere(radius = 10 cm, center = [0, 0, 1 s]), law = sliding(viscous = 2 N), gravity = 981 cm/s^2)]
struct Friction;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 10 cm))]
#[contact(surface = sphere(radius = 10 cm), law = stick_slip(mu = 0.5 N), gravity = 9.81)]
struct Coefficient;

fn main() {}
