use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(at = [0.0, 0.0, 1.0]), q = theta, parts(particle(mass = 1.0)))]
#[body(hand, joint = universal(axes = x), q = [a, b], parts(particle(mass = 1.0)))]
#[body(ball, joint = spherical(sequence = xyz), q = [p, t, s], parts(particle(mass = 1.0)))]
#[body(wrist, joint = revolute(axis = w), q = w, parts(particle(mass = 1.0)))]
struct Joints;

fn main() {}
