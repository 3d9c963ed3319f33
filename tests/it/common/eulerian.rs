//! The Eulerian form of a top, written independently of precess with nalgebra: a unit
//! quaternion (body to space) and the body angular velocity, under gravity about the pivot.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use precess_core::ode::System;

pub struct Eulerian {
    pub inertia: Matrix3<f64>,
    /// M g c: the weight's lever, so the gravity torque is `lever × Rᵀ(−ẑ)`.
    pub weight_lever: Vector3<f64>,
}

impl Eulerian {
    pub fn state(r: &Matrix3<f64>, w: &Vector3<f64>) -> [f64; 7] {
        let q = precess_testkit::rotations::quaternion_of(r);
        [q.w, q.i, q.j, q.k, w.x, w.y, w.z]
    }

    pub fn rotation(y: &[f64; 7]) -> Matrix3<f64> {
        let q = UnitQuaternion::new_normalize(Quaternion::new(y[0], y[1], y[2], y[3]));
        *q.to_rotation_matrix().matrix()
    }
}

impl System<7> for Eulerian {
    fn rhs(&self, _t: f64, y: &[f64; 7], d: &mut [f64; 7]) {
        let q = Quaternion::new(y[0], y[1], y[2], y[3]);
        let w = Vector3::new(y[4], y[5], y[6]);
        let qd = q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        let r = UnitQuaternion::new_normalize(q);
        let down = r.inverse() * Vector3::new(0.0, 0.0, -1.0);
        let tau = self.weight_lever.cross(&down);
        let inv = self
            .inertia
            .try_inverse()
            .expect("positive definite inertia");
        let wd = inv * (tau - w.cross(&(self.inertia * w)));
        d[..4].copy_from_slice(&[qd.w, qd.i, qd.j, qd.k]);
        d[4..].copy_from_slice(wd.as_slice());
    }
}
