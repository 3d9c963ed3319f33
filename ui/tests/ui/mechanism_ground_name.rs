use precess::prelude::*;

#[derive(Mechanism)]
#[body(ground, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0)))]
struct Grounded;

fn main() {}
