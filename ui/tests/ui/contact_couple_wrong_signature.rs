use precess::prelude::*;

#[derive(RigidBody)]
#[rigid(disk(mass = 0.3, radius = 0.05))]
#[contact(surface = disk_rim(radius = 0.05), law = rolling, gravity = 9.81, torque = air)]
struct Disk;

/// A couple of time, as `#[top]`'s is: `#[contact]`'s is a function of the state alone.
fn air(_: &Disk, t: f64, _: &Matrix3<f64>, w: &Vector3<f64>) -> Vector3<f64> {
    -t * w
}

#[derive(RigidBody)]
#[rigid(disk(mass = 0.3, radius = 0.05))]
#[contact(surface = disk_rim(radius = 0.05), law = rolling, gravity = 9.81, torque = |w| w)]
struct Closure;

fn main() {}
