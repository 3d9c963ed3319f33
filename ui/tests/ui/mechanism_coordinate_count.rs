use precess::prelude::*;

#[derive(Mechanism)]
#[body(gimbal, joint = universal(axes = [x, y]), q = alpha, parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(arm, joint = revolute(axis = z), q = [a, b], parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(ball, joint = spherical(sequence = zyx), q = [yaw, pitch],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct Counts;

fn main() {}
