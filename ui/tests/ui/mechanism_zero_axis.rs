use precess::prelude::*;

#[derive(Mechanism)]
#[body(slider, joint = prismatic(axis = [0.0, 0.0, 0.0]), q = s, parts(particle(mass = 1.0)))]
#[body(gimbal, joint = universal(axes = [x, [0.0, 0.0 * 2.0, 0.0]]), q = [a, b],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct Slider;

fn main() {}
