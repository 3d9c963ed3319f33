use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = x), q = theta,
       parts(rod(mass = -1.0, length = 1.0), pivot = [0.0, 0.0, 0.0]))]
#[body(hand, joint = revolute(axis = x), q = phi, parts(sphere(mass = 1.0, radius = 0.0)))]
struct BadParts;

fn main() {}
