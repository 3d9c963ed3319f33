// A body whose coordinates are not named, so their count is unknown: the struct used after
// the error still adds no error of its own.
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(arm, parent = ground, joint = revolute(axis = x),
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Unnamed;

fn main() {
    let e = Unnamed.energy(&[0.1], &[0.0]);
    let a = Unnamed.accelerations(0.0, &[0.1], &[0.0]);
    let _ = (e, a.is_ok());
}
