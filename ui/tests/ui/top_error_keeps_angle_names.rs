use precess::prelude::*;

// A description with an error still names its angles, so code reading `Spinner::THETA`
// adds no error of its own to the one that matters.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, damping = -0.02)]
struct Spinner;

fn main() {
    let _tilt = [0.0_f64; 3][Spinner::THETA];
}
