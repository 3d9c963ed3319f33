// One error in a rolling description, and the struct used after it as a rolling mechanism,
// as a system and through its consts: only the one error is reported.
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, joint = prismatic(axis = x), q = s, parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, 0.5]), q = theta,
       parts(disk(mass = 1.0, radius = 0.5, axis = y)), rolls = disk(radius = -0.5, axle = y))]
struct Broken;

fn main() {
    let rates = Broken.rates(&[0.0, 0.0], &[1.0]).map(|r| r[Broken::S]);
    let system = Broken.rolling_system::<{ Broken::STATE }>();
    let ode = Dop853::new(system, 0.0, [0.0, 0.0, 1.0], AdaptiveConfig::with_tol(1e-9, 1e-9));
    let _ = (rates, ode.is_ok());
}
