// The floor's normal must be a signed ground axis.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = [0.0, 0.0, 1.0], speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct Vector;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = w, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct NotAnAxis;

fn main() {}
