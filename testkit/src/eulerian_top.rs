//! A top about its pivot in the Eulerian form, written with nalgebra independently of the
//! engine: ω̇ = I⁻¹ (τ − ω × I ω), τ = c × (Rᵀ(−M g ẑ)) + G_body + Rᵀ G_space − k ω + u, and
//! R and the body ω from the textbook angle formulas. The top tests check the derived
//! Euler-angle equations against it at 10⁴ states per scene; here, optimised, because
//! unoptimised nalgebra made it most of their run time.
#![warn(missing_docs)]

use precess::nalgebra::{Matrix3, Rotation3, Vector3};
use precess::rigid::AngleSequence;

/// A numeric top: everything the Eulerian form needs, and a name for messages.
#[derive(Clone, Debug)]
pub struct NumTop {
    /// What the scene is called in messages.
    pub name: &'static str,
    /// The Euler angles' sequence.
    pub sequence: AngleSequence,
    /// The inertia about the pivot, body axes.
    pub inertia: Matrix3<f64>,
    /// The mass.
    pub mass: f64,
    /// The centre of mass from the pivot, body axes.
    pub center: Vector3<f64>,
    /// The acceleration of gravity along −ẑ, if any.
    pub gravity: Option<f64>,
    /// A couple fixed in body axes.
    pub body_torque: Option<Vector3<f64>>,
    /// A couple fixed in space axes.
    pub space_torque: Option<Vector3<f64>>,
    /// A damping couple −k ω.
    pub damping: Option<f64>,
    /// A user couple u, body axes.
    pub user_torque: Option<Vector3<f64>>,
}

impl NumTop {
    /// ω̇ (body axes) at the attitude `r` (body to space) and body angular velocity `w`.
    ///
    /// # Panics
    /// If the inertia is singular.
    pub fn omega_dot(&self, r: &Rotation3<f64>, w: &Vector3<f64>) -> Vector3<f64> {
        let rt = r.inverse();
        let mut tau = Vector3::zeros();
        if let Some(g) = self.gravity {
            tau += self
                .center
                .cross(&(rt * Vector3::new(0.0, 0.0, -self.mass * g)));
        }
        if let Some(b) = self.body_torque {
            tau += b;
        }
        if let Some(sp) = self.space_torque {
            tau += rt * sp;
        }
        if let Some(k) = self.damping {
            tau -= k * w;
        }
        if let Some(u) = self.user_torque {
            tau += u;
        }
        let inv = self.inertia.try_inverse().expect("positive definite");
        inv * (tau - w.cross(&(self.inertia * w)))
    }
}

/// R (body to space) and the body ω at angles `q` and rates `qd` of `seq`, from the
/// textbook formulas (not from the engine).
pub fn attitude(seq: AngleSequence, q: [f64; 3], qd: [f64; 3]) -> (Rotation3<f64>, Vector3<f64>) {
    let (x, y, z) = (Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis());
    match seq {
        AngleSequence::Zxz => {
            let [phi, th, psi] = q;
            let [dphi, dth, dpsi] = qd;
            let r = Rotation3::from_axis_angle(&z, phi)
                * Rotation3::from_axis_angle(&x, th)
                * Rotation3::from_axis_angle(&z, psi);
            let w = Vector3::new(
                dphi * th.sin() * psi.sin() + dth * psi.cos(),
                dphi * th.sin() * psi.cos() - dth * psi.sin(),
                dphi * th.cos() + dpsi,
            );
            (r, w)
        }
        AngleSequence::Zyx => {
            let [yaw, pitch, roll] = q;
            let [dyaw, dpitch, droll] = qd;
            let r = Rotation3::from_axis_angle(&z, yaw)
                * Rotation3::from_axis_angle(&y, pitch)
                * Rotation3::from_axis_angle(&x, roll);
            let w = Vector3::new(
                droll - dyaw * pitch.sin(),
                dpitch * roll.cos() + dyaw * pitch.cos() * roll.sin(),
                -dpitch * roll.sin() + dyaw * pitch.cos() * roll.cos(),
            );
            (r, w)
        }
    }
}
