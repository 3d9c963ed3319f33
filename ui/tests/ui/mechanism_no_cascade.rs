// One error in the description, and the struct used after it as a mechanism, as a system
// and through its coordinate consts: only the one error is reported.
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(arm, parent = ground, joint = revolute(axis = [0.0, 0.0, 0.0]), q = theta,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Broken;

fn main() {
    let theta_ddot = Broken.accelerations(0.0, &[0.1], &[0.0]).map(|a| a[Broken::THETA]);
    let names: [&str; 1] = Broken::COORDINATES;
    let ode = Dop853::new(Broken, 0.0, [0.1, 0.0], AdaptiveConfig::with_tol(1e-9, 1e-9));
    let _ = (theta_ddot, names, ode.is_ok());
}
