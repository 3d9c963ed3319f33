use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, parent = ground, parts(particle(mass = 1.0)))]
#[body(hand, parent = arm, joint = revolute(axis = x), parts(particle(mass = 1.0)))]
#[body(joint = revolute(axis = x), q = psi, parts(particle(mass = 1.0)))]
struct Loose;

fn main() {}
