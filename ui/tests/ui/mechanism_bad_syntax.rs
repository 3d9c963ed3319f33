use precess::prelude::*;

#[derive(Mechanism)]
#[body]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0)), extra)]
struct Syntax;

fn main() {}
