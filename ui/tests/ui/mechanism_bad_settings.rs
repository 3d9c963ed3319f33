use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0)))]
#[mechanism(route = fastest, gravity = [0.0, 0.0])]
#[mechanism(gravity = 9.81, gravity = 1.0)]
struct Settings;

fn main() {}
