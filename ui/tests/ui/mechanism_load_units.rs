use precess::prelude::*;

// Each load takes the dimension its coordinate gives it: a hinge's spring is a torque per
// radian and its effort a torque; a slider's spring is a force per metre, its rest a length.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81 m)]
#[body(arm, joint = revolute(axis = x, at = [0.0, 0.0, 2 kg]), q = theta,
       spring(k = 20 N, rest = 10 deg), effort = 3 N, parts(particle(mass = 1.0)))]
#[body(slider, parent = arm, joint = prismatic(axis = z), q = s,
       spring(k = 200 N/m, rest = 30 deg), damper = 2 N * 1 s, parts(particle(mass = 1.0)))]
struct Loads;

fn main() {}
