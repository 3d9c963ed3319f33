use precess::prelude::*;

// Order 1 compiles nowhere: the integrator sizes a step from two orders, so it could never run.
precess::taylor_system! {
    struct Decay;
    state [x];
    taylor = 1;
    d/dt x = -x;
}

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1), taylor = 1)]
struct Ball;

#[derive(RigidBody)]
#[rigid(disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, taylor = 1)]
struct Top;

#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(gravity = 9.81, taylor = 1)]
struct Thrown;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 1)]
#[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Pendulum;

fn main() {}
