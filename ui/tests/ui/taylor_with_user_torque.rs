use precess::prelude::*;

fn spin(_: &Top, _: f64, _: &Matrix3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
    Vector3::zeros()
}

#[derive(RigidBody)]
#[rigid(disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, torque = spin, taylor = 20)]
struct Top;

fn main() {}
