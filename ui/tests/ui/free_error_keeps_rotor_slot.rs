use precess::free::FreeDynamics;
use precess::prelude::*;

// The misspelt key is the one error: the rotor's slot `Satellite::ROTOR_0` and the 14-slot
// state stay defined, so the code using them adds none.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravty = 9.81, rotor(axis = [0, 0, 1], inertia = 0.0001, torque = motor))]
struct Satellite;

fn motor(_: &Satellite, _t: f64, y: &[f64]) -> f64 {
    0.01 * y[Satellite::ROTOR_0]
}

fn main() {
    let y = [0.0; 14];
    let _ = Satellite.energy(&y);
    assert_eq!(Satellite::coordinate("rotor_0"), Some(Satellite::ROTOR_0));
}
