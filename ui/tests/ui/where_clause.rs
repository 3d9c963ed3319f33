use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = 0.1))]
struct Body
where
    Self: Sized,
{
    m: f64,
}

fn main() {}
