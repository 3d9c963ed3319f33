use precess::prelude::*;

// The names kept are those of the sequence written, here yaw, pitch and roll, even when the
// error is in the same attribute.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(angles = zyx, gravity = 9.81, dampng = 0.02)]
struct Spinner;

fn main() {
    let _pitch = [0.0_f64; 3][Spinner::PITCH];
}
