use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravty = 9.81)]
#[body(arm, parnet = ground, joint = revolut(axis = x), q = theta, parts(particle(mass = 1.0)))]
#[body(hand, joint = revolute(axis = x, att = [0.0, 0.0, 1.0]), q = phi, sprig(k = 1.0),
       parts(particle(mass = 1.0)))]
#[body(foot, joint = revolute(axis = x), q = psi, spring(k = 1.0, reset = 0.5),
       parts(partcle(mass = 1.0)))]
struct Typos;

fn main() {}
