use precess::prelude::*;

// A free joint takes `sequence`, `at` and `name`: it has no axis, and six coordinates.
#[derive(Mechanism)]
#[body(bus, joint = free(axis = x), q = [x, y, z, yaw, pitch, roll],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct FreeWithAnAxis;

#[derive(Mechanism)]
#[body(bus, joint = free(sequence = xyz), q = [x, y, z, yaw, pitch, roll],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct FreeWithABadSequence;

#[derive(Mechanism)]
#[body(bus, joint = free, q = [yaw, pitch, roll], parts(sphere(mass = 1.0, radius = 0.1)))]
struct FreeWithThreeCoordinates;

fn main() {}
