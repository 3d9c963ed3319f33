use precess::prelude::*;

// A free joint's first three coordinates are lengths, its last three angles: an effort of
// one newton on all six is a force on the translations and wrong on the rotations.
#[derive(Mechanism)]
#[body(bus, joint = free, q = [x, y, z, yaw, pitch, roll],
       effort = [1 N, 0.0, 0.0, 1 N, 0.0, 0.0], parts(sphere(mass = 1.0, radius = 0.1)))]
struct Thrown;

fn main() {}
