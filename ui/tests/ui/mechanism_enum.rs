use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0)))]
enum Arm {
    Up,
}

fn main() {}
