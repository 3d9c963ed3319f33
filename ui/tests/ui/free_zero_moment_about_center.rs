use precess::prelude::*;

// About the pivot the rod has three positive moments; about its own centre of mass, along
// its axis, none.
#[derive(RigidBody)]
#[rigid(rod(mass = 1.0, length = 1.0, axis = x, at = [0.0, 0.0, 1.0]), pivot = [0.0, 0.0, 0.0])]
#[free]
struct Stick;

fn main() {}
