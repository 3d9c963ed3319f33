use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, parent = ground, joint = revolute(axis = x), q = q0, parts(particle(mass = 1.0)))]
#[body(a, parent = a, joint = revolute(axis = x), q = q1, parts(particle(mass = 1.0)))]
struct OwnParent;

fn main() {}
