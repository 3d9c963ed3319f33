use precess::prelude::*;

// `a` hangs from `b` and `b` from `a`: no chain reaches the ground.
#[derive(Mechanism)]
#[body(a, parent = b, joint = revolute(axis = x), q = qa, parts(particle(mass = 1.0)))]
#[body(b, parent = a, joint = revolute(axis = x), q = qb, parts(particle(mass = 1.0)))]
struct Loop;

fn main() {}
