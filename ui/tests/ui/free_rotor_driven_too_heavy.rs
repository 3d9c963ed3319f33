use precess::prelude::*;

// The wheel's axial moment equals the body's own about z: once it turns freely the body
// keeps no moment about that axis.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 0, 1], inertia = 3.0, torque = motor))]
struct Satellite;

fn motor(_: &Satellite, _t: f64, _y: &[f64]) -> f64 {
    0.01
}

fn main() {}
