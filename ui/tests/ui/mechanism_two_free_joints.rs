use precess::prelude::*;

// One base body flies free; a second free joint would be a second mechanism.
#[derive(Mechanism)]
#[body(left, joint = free, q = [x1, y1, z1, a1, b1, c1], parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(right, joint = free, q = [x2, y2, z2, a2, b2, c2], parts(sphere(mass = 1.0, radius = 0.1)))]
struct TwoFreeBodies;

fn main() {}
