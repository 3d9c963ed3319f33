use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(name = hinge, axis = x), q = theta, parts(particle(mass = 1.0)))]
#[body(arm, parent = ground, joint = revolute(axis = y), q = phi, parts(particle(mass = 1.0)))]
#[body(hand, parent = ground, joint = revolute(name = hinge, axis = z), q = Theta,
       parts(particle(mass = 1.0)))]
struct Twins;

fn main() {}
