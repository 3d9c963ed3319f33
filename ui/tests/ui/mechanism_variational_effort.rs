// A user effort function's derivatives are unknown: no variational equations beside it.
use precess::prelude::*;

fn drive(_: &Driven, t: f64, _: &[f64; 1], _: &[f64; 1]) -> f64 {
    t.sin()
}

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, variational(tangents = 1))]
#[body(arm, joint = revolute(axis = x), q = theta, effort = drive,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Driven;

fn main() {}
