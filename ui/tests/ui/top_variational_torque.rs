use precess::prelude::*;

fn drive(_: &Heavy, _: f64, _: &Matrix3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
    Vector3::zeros()
}

#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.0, 0.0, 0.1], inertia = diag(0.01, 0.01, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(torque = drive, variational())]
struct Heavy {
    m: f64,
}

fn main() {}
