use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, parent = ground, joint = revolute(axis = x), q = theta)]
#[body(hand, parent = arm, joint = revolute(axis = x), q = phi, parts())]
struct Ghost;

fn main() {}
