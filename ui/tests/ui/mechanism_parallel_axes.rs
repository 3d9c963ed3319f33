use precess::prelude::*;

// A universal joint's two axes must not be parallel, opposite or a multiple of each other:
// the same rule `check_parameters` applies to axes of fields at run time.
#[derive(Mechanism)]
#[body(gimbal, joint = universal(axes = [x, x]), q = [a, b], parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(cardan, parent = gimbal, joint = universal(axes = [[0.0, 2.0, 0.0], -y]), q = [c, d],
       parts(sphere(mass = 1.0, radius = 0.1)))]
#[body(tiny, parent = cardan, joint = revolute(axis = [1e-160, 0.0, 0.0]), q = e,
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct Gimbal;

fn main() {}
