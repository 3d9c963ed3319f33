//! A state of the rolling disk in the variables of its closed form (`contact::theory`'s
//! frame: yaw ψ, the angle α of the disk's plane to the table, ψ̇, the lean rate θ̇ = −α̇ and
//! the spin ω₃), placed in both declarations, and the closed form's ω̇ at it.
//!
//! Written with α itself rather than the lean θ = π/2 − α, so that a disk within 1e-9 rad of
//! flat is placed and judged without the rounding of π/2 − α.

use precess::contact::theory::RollingDisk;
use precess::nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::scenes::{GRAVITY, MASS, Q, RADIUS, U, angle_rates, angles};

/// The closed form's disk.
pub fn disk() -> RollingDisk {
    RollingDisk::thin(RADIUS, MASS, GRAVITY)
}

/// A rolling state in the closed form's variables.
#[derive(Clone, Copy, Debug)]
pub struct Standing {
    /// The angle α of the disk's plane to the table (π/2 upright, 0 flat).
    pub alpha: f64,
    /// The yaw ψ: the contact point moves along t = (cos ψ, sin ψ, 0).
    pub yaw: f64,
    /// ψ̇.
    pub yaw_rate: f64,
    /// θ̇ = −α̇.
    pub lean_rate: f64,
    /// ω₃ = ω·n.
    pub spin: f64,
    /// The body's turn χ about its axis: body x is cos χ u − sin χ t.
    pub turn: f64,
}

/// The frame (t, u, n) of a state and its attitude: body z = −n (up when the disk lies
/// flat), body x = cos χ u − sin χ t.
pub struct Frame {
    /// t, along the contact's motion.
    pub t: Vector3<f64>,
    /// u, from the contact point to the centre.
    pub u: Vector3<f64>,
    /// n, the disk's axis in the closed form's sense.
    pub n: Vector3<f64>,
    /// Body → space.
    pub attitude: Matrix3<f64>,
    /// ω, space axes.
    pub omega: Vector3<f64>,
}

impl Standing {
    /// The frame at this state.
    pub fn frame(&self) -> Frame {
        let (sa, ca) = self.alpha.sin_cos();
        let t = Vector3::new(self.yaw.cos(), self.yaw.sin(), 0.0);
        let h = Vector3::z().cross(&t);
        let u = Vector3::z() * sa + h * ca;
        let n = -Vector3::z() * ca + h * sa;
        let (sx, cx) = self.turn.sin_cos();
        let x = u * cx - t * sx;
        let z = -n;
        let y = z.cross(&x);
        let omega = u * (self.yaw_rate * sa) - t * self.lean_rate + n * self.spin;
        Frame {
            t,
            u,
            n,
            attitude: Matrix3::from_columns(&[x, y, z]),
            omega,
        }
    }

    /// The closed form's ω̇ (space axes): in the frame turning at Ω = ψ̇ ẑ − θ̇ t, with
    /// ω = p u − θ̇ t + ω₃ n, p = ψ̇ sin α, s = −ψ̇ cos α,
    /// ω̇ = (ṗ + θ̇ (s − ω₃)) u + (−θ̈ + p (s − ω₃)) t + ω̇₃ n, where from
    /// [`RollingDisk::accelerations`] (cos θ = sin α, sin θ = cos α)
    /// ṗ = ψ̈ sin α − ψ̇ θ̇ cos α = ψ̇ θ̇ cos α + (C/A) θ̇ ω₃, and θ̈, ω̇₃ as there.
    pub fn omega_rate(&self) -> Vector3<f64> {
        let d = disk();
        let (a, c, m, r, g) = (d.transverse, d.axial, d.mass, d.radius, d.gravity);
        let (sa, ca) = self.alpha.sin_cos();
        let (yr, lr, w3) = (self.yaw_rate, self.lean_rate, self.spin);
        let mr2 = m * r * r;
        let lean = (m * g * r * ca - a * yr * yr * ca * sa - (c + mr2) * yr * w3 * sa) / (a + mr2);
        let pdot = yr * lr * ca + c / a * lr * w3;
        let spin = mr2 * yr * lr * sa / (c + mr2);
        let (p, s) = (yr * sa, -yr * ca);
        let f = self.frame();
        f.u * (pdot + lr * (s - w3)) + f.t * (-lean + p * (s - w3)) + f.n * spin
    }

    /// The mechanism's state: the contact point at the origin, the hub at r u.
    pub fn wheel(&self) -> (Q, U) {
        let f = self.frame();
        let a = angles(&f.attitude);
        let hub = f.u * RADIUS;
        (
            [hub.x, hub.y, hub.z, a[0], a[1], a[2]],
            angle_rates(&a, &f.omega),
        )
    }

    /// The table's attitude and ω in body axes.
    pub fn table(&self) -> (UnitQuaternion<f64>, Vector3<f64>) {
        let f = self.frame();
        let rot = Rotation3::from_matrix_unchecked(f.attitude);
        (
            UnitQuaternion::from_rotation_matrix(&rot),
            f.attitude.transpose() * f.omega,
        )
    }
}
