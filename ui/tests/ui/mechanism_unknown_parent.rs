use precess::prelude::*;

#[derive(Mechanism)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
#[body(lower, parent = uper, joint = revolute(axis = x, at = [0.0, 0.0, -1.0]), q = theta2,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct DoublePendulum;

fn main() {}
