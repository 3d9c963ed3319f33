// Free speeds that are not coordinates, are repeated, or are too many for the wheels' rows.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [thta, theta, theta, 1.0])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct NotCoordinates;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [s, theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct TooMany;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = theta)]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct NotAList;

fn main() {}
