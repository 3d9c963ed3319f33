use precess::prelude::*;

// One angle, and the arm's tip pinned to the ground: two rows (x and y) on one coordinate.
#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = z), q = theta,
       parts(rod(mass = 1.0, length = 1.0, axis = x, at = [0.5, 0.0, 0.0])),
       closes = ground(at = [1.0, 0.0, 0.0], to = [1.0, 0.0, 0.0]))]
struct Pinned;

fn main() {}
