// An unknown field, a field given twice, a field the equations never read, a value that
// is not a field.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = g, variational(sensitivities = [mass, m, g, m, label, 2.0]))]
#[body(arm, joint = revolute(axis = x), q = theta,
       parts(particle(mass = m, at = [0.0, 0.0, -1.0])))]
struct Sensitivities {
    m: f64,
    g: f64,
    label: f64,
}

fn main() {}
