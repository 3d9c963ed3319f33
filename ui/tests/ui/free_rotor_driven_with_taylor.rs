use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(taylor = 20, rotor(axis = [0, 0, 1], inertia = 0.0001, torque = motor))]
struct Satellite;

fn motor(_: &Satellite, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
