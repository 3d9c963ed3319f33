// Rolling bodies without the floor or the free speeds, and the rolling settings without a
// rolling body.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct NoFloor;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)))]
struct NothingRolls;

fn main() {}
