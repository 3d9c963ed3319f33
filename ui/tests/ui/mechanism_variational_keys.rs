// An unknown key in the group, an unknown group, a second group, a value where a name
// belongs: each refused on its own tokens.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, variational(tangent = 1), variations(tangents = 1))]
#[mechanism(variational(tangents = 1))]
#[body(arm, joint = revolute(axis = x), q = theta,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Keys;

fn main() {}
