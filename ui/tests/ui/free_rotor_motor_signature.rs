use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.0001, torque = motor))]
struct Satellite;

// The motor takes the whole state as a slice and returns the torque about the wheel's axis.
fn motor(_: &Satellite, _t: f64) -> f64 {
    0.01
}

fn main() {}
