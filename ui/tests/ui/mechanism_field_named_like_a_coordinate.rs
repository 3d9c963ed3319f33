use precess::prelude::*;

// The joint's coordinate is `swing`: a field of that name would print as the same symbol.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(arm, parent = ground, joint = revolute(axis = x), q = swing,
       parts(particle(mass = 1, at = [0, 0, -swing])))]
struct Pendulum {
    swing: f64,
}

fn main() {}
