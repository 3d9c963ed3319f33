use precess::prelude::*;

// A sequence that is neither `zxz` nor `zyx` keeps both sets of names, so whichever the
// user meant, only the sequence is an error.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(angles = xyz, gravity = 9.81)]
struct Spinner;

fn main() {
    let _pitch = [0.0_f64; 3][Spinner::PITCH];
    let _theta = [0.0_f64; 3][Spinner::THETA];
}
