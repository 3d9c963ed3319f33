use precess::prelude::*;

// `Hz` is one turn a second to some readers and SI's 1/s to others: a rotor's rate in Hz
// would be silently 2π off for one of them, so it is refused with both readings.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.001, rate = 50 Hz))]
struct Gyrotop;

fn main() {}
