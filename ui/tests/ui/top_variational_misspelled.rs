use precess::prelude::*;

// A misspelt group written as a setting: the message lists the variational equations and
// proposes them.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, variatonal = 6)]
struct Spinner;

fn main() {}
