use precess::prelude::*;

// A word alone among a body's parts: the part form is what it lacks (a mechanism body has no
// pivot and no `taylor` key of its own to suggest).
#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0]), rod))]
struct Arm;

fn main() {}
