use precess::prelude::*;

#[derive(Mechanism)]
#[body(arm, joint = revolute(axis = x), q = theta, damper = -0.5, spring(rest = 0.1),
       parts(particle(mass = 1.0)))]
#[body(gimbal, joint = universal(axes = [x, y]), q = [a, b], damper = c, effort = [1.0],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct Loads {
    c: f64,
}

fn main() {}
