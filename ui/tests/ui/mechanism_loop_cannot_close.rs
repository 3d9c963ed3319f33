use precess::prelude::*;

// The rocker's pin is 8 from its pivot: the loop's longest side (8) is not shorter than the
// sum of the others (crank 1 + coupler 3 + ground 3 = 7).
#[derive(Mechanism)]
#[body(crank, joint = revolute(axis = z), q = theta1,
       parts(rod(mass = 0.5, length = 1.0, axis = x, at = [0.5, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [1.0, 0.0, 0.0]), q = theta2,
       parts(rod(mass = 1.5, length = 3.0, axis = x, at = [1.5, 0.0, 0.0])),
       closes = rocker(at = [3.0, 0.0, 0.0], to = [8.0, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [3.0, 0.0, 0.0]), q = theta3,
       parts(rod(mass = 1.2, length = 8.0, axis = x, at = [4.0, 0.0, 0.0])))]
struct FourBar;

fn main() {}
