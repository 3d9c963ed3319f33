// A coordinate named as a const the rolling derive emits beside the coordinates' own.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [speeds])]
#[body(cart, joint = prismatic(axis = x), q = state, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = speeds,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = 0.5, axle = y))]
struct Reserved;

fn main() {}
