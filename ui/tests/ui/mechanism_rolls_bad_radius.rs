// A rolling radius that is zero or negative, written as a literal.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.0, axle = y))]
struct ZeroRadius;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(sphere(mass = 1.0, radius = 0.5)), rolls = sphere(radius = 0.2 - 0.7))]
struct NegativeRadius;

fn main() {}
