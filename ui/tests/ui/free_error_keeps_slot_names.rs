use precess::prelude::*;

// A description with an error still names the state's slots, so code reading `Brick::VZ`
// adds no error of its own to the one that matters.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
#[free(gravity = 9.81, drag = -0.5)]
struct Brick;

fn main() {
    let _vertical_speed = Brick::VZ;
}
