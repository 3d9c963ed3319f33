use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 0)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct OrderZero;

#[derive(Mechanism)]
#[mechanism(taylor = 20.5)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct NotAnInteger;

#[derive(Mechanism)]
#[mechanism(taylor = 20)]
#[mechanism(taylor = 12)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Duplicate;

#[derive(Mechanism)]
#[mechanism(taylr = 20)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Misspelt;

fn main() {}
