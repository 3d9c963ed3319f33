// A pendulum's state (θ, θ̇) has n = 2 entries: at most two tangent vectors.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, variational(tangents = 3))]
#[body(arm, joint = revolute(axis = x), q = theta,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Tangents;

fn main() {}
