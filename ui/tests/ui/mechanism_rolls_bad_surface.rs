// A rolling surface that is not one, and surfaces with keys missing, unknown or repeated.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = cylinder(radius = 0.5))]
struct UnknownSurface;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5))]
struct NoAxle;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)),
       rolls = sphere(radius = 0.5, axle = y, radius = 0.4))]
struct BadKeys;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = 0.5)]
struct NotACall;

fn main() {}
