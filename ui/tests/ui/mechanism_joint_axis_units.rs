use precess::prelude::*;

// A joint's axis is a direction: its components are pure numbers, so a unit on one is a slip
// (a length typed where the hinge point `at` was meant, say).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(arm, joint = revolute(axis = [0.0, 0.0, 1 cm]), q = theta, parts(particle(mass = 1.0)))]
struct Hinge;

fn main() {}
