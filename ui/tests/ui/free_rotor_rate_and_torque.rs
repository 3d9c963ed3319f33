use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.0001, rate = 300 rpm, torque = motor))]
struct Satellite;

fn motor(_: &Satellite, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
