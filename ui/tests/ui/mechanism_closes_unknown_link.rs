use precess::prelude::*;

#[derive(Mechanism)]
#[body(crank, joint = revolute(axis = z), q = theta1,
       parts(rod(mass = 0.5, length = 1.0, axis = x, at = [0.5, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [1.0, 0.0, 0.0]), q = theta2,
       parts(rod(mass = 1.5, length = 3.0, axis = x, at = [1.5, 0.0, 0.0])),
       closes = roker(at = [3.0, 0.0, 0.0], to = [2.5, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [3.0, 0.0, 0.0]), q = theta3,
       parts(rod(mass = 1.2, length = 2.5, axis = x, at = [1.25, 0.0, 0.0])))]
struct FourBar;

fn main() {}
