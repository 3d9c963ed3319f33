//! The benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463,
//! 2007), the Carvallo–Whipple model derived nonlinear by `#[derive(Mechanism)]`, and its
//! linearisation about the upright straight run in the paper's canonical form
//! ([`Canonical`]: M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0, q = (φ, δ)).
//!
//! The paper's axes and names: x forward, z down, the rear wheel's contact at (x, y), yaw ψ,
//! roll φ, pitch θ, steer δ. Three massless carriers hold the rear contact (prismatic x, then
//! y) and the rear frame's lean (a universal joint: yaw about z, then roll about x); the rear
//! frame B with its rider pitches about y through the rear hub, r_R above the contact; the
//! rear wheel R turns on it; the front frame H (fork and handlebar) steers about the axis
//! tilted back by λ from the vertical, which meets the ground a trail c ahead of the front
//! contact; the front wheel F turns on it. Both wheels are knife-edge disks rolling without
//! slip: four rolling rows and the front contact's height, five constraints on eight
//! coordinates, leaving the roll, steer and rear-wheel rates free (the state is the eight
//! coordinates, then u = (φ̇, δ̇, θ̇_r)).
//!
//! The rear wheel's angle θ_r is measured from the rear frame (the paper's θ_R = θ_r + θ).
//!
//! `docs/bicycle.md` walks through it; `docs/linearisation.md` says how the canonical
//! matrices are formed.

mod canonical;
mod linearise;

pub use canonical::{Canonical, SpeedModes};
pub use linearise::BicycleLinearisationError;

use crate::prelude::*;

/// The Carvallo–Whipple bicycle with the parameters of the paper's Table 1 as fields, SI
/// units, z down. [`Bicycle::benchmark`] gives the paper's values.
#[derive(Clone, Copy, Debug, PartialEq, Mechanism)]
#[mechanism(gravity = [0.0, 0.0, g], up = -z, speeds = [phi, delta, theta_r])]
#[body(rear_x, parent = ground, joint = prismatic(axis = x), q = x,
       parts(particle(mass = 0.0)))]
#[body(rear_y, parent = rear_x, joint = prismatic(axis = y), q = y,
       parts(particle(mass = 0.0)))]
#[body(lean, parent = rear_y, joint = universal(axes = [z, x]), q = [psi, phi],
       parts(particle(mass = 0.0)))]
#[body(rear_frame, parent = lean, joint = revolute(axis = y, at = [0.0, 0.0, -r_r]), q = theta,
       parts(body(mass = m_b, at = [x_b, 0.0, z_b + r_r],
                  inertia = [[i_bxx, 0.0, i_bxz], [0.0, i_byy, 0.0], [i_bxz, 0.0, i_bzz]])))]
#[body(rear_wheel, parent = rear_frame, joint = revolute(axis = y), q = theta_r,
       parts(body(mass = m_r, inertia = diag(i_rxx, i_ryy, i_rxx))),
       rolls = disk(radius = r_r, axle = y))]
#[body(front_frame, parent = rear_frame, q = delta,
       joint = revolute(axis = [sin(lambda), 0.0, cos(lambda)], at = [w + c, 0.0, r_r]),
       parts(body(mass = m_h, at = [x_h - w - c, 0.0, z_h],
                  inertia = [[i_hxx, 0.0, i_hxz], [0.0, i_hyy, 0.0], [i_hxz, 0.0, i_hzz]])))]
#[body(front_wheel, parent = front_frame, joint = revolute(axis = y, at = [-c, 0.0, -r_f]),
       q = theta_f, parts(body(mass = m_f, inertia = diag(i_fxx, i_fyy, i_fxx))),
       rolls = disk(radius = r_f, axle = y))]
pub struct Bicycle {
    /// Wheel base w \[m\].
    pub w: f64,
    /// Trail c \[m\].
    pub c: f64,
    /// Steer axis tilt λ from the vertical \[rad\].
    pub lambda: f64,
    /// Gravity g \[m/s²\].
    pub g: f64,
    /// Rear wheel radius r_R \[m\].
    pub r_r: f64,
    /// Rear wheel mass m_R \[kg\].
    pub m_r: f64,
    /// Rear wheel's moment about a diameter, I_Rxx = I_Rzz \[kg·m²\].
    pub i_rxx: f64,
    /// Rear wheel's moment about its axle, I_Ryy \[kg·m²\].
    pub i_ryy: f64,
    /// Rear frame's centre of mass x_B \[m\].
    pub x_b: f64,
    /// Rear frame's centre of mass z_B \[m\] (negative: above the ground).
    pub z_b: f64,
    /// Rear frame's mass m_B \[kg\].
    pub m_b: f64,
    /// Rear frame's I_Bxx about its centre \[kg·m²\].
    pub i_bxx: f64,
    /// Rear frame's I_Byy \[kg·m²\].
    pub i_byy: f64,
    /// Rear frame's I_Bzz \[kg·m²\].
    pub i_bzz: f64,
    /// Rear frame's product I_Bxz \[kg·m²\].
    pub i_bxz: f64,
    /// Front frame's centre of mass x_H \[m\].
    pub x_h: f64,
    /// Front frame's centre of mass z_H \[m\].
    pub z_h: f64,
    /// Front frame's mass m_H \[kg\].
    pub m_h: f64,
    /// Front frame's I_Hxx about its centre \[kg·m²\].
    pub i_hxx: f64,
    /// Front frame's I_Hyy \[kg·m²\].
    pub i_hyy: f64,
    /// Front frame's I_Hzz \[kg·m²\].
    pub i_hzz: f64,
    /// Front frame's product I_Hxz \[kg·m²\].
    pub i_hxz: f64,
    /// Front wheel radius r_F \[m\].
    pub r_f: f64,
    /// Front wheel mass m_F \[kg\].
    pub m_f: f64,
    /// Front wheel's moment about a diameter, I_Fxx = I_Fzz \[kg·m²\].
    pub i_fxx: f64,
    /// Front wheel's moment about its axle, I_Fyy \[kg·m²\].
    pub i_fyy: f64,
}

impl Bicycle {
    /// The benchmark bicycle: Table 1 of Meijaard et al. (2007).
    pub fn benchmark() -> Bicycle {
        Bicycle {
            w: 1.02,
            c: 0.08,
            lambda: std::f64::consts::PI / 10.0,
            g: 9.81,
            r_r: 0.3,
            m_r: 2.0,
            i_rxx: 0.0603,
            i_ryy: 0.12,
            x_b: 0.3,
            z_b: -0.9,
            m_b: 85.0,
            i_bxx: 9.2,
            i_byy: 11.0,
            i_bzz: 2.8,
            i_bxz: 2.4,
            x_h: 0.9,
            z_h: -0.7,
            m_h: 4.0,
            i_hxx: 0.05892,
            i_hyy: 0.06,
            i_hzz: 0.00708,
            i_hxz: -0.00756,
            r_f: 0.35,
            m_f: 3.0,
            i_fxx: 0.1405,
            i_fyy: 0.28,
        }
    }

    /// The upright straight run at forward speed `v` along x: every coordinate zero but the
    /// pitch, which puts the front wheel on the ground, the rear wheel turning at −v / r_R
    /// (backwards about y, z being down), and `roll_rate` as a push.
    ///
    /// # Errors
    /// As [`RollingDynamics::close_contacts`].
    pub fn upright(&self, v: f64, roll_rate: f64) -> Result<[f64; Bicycle::STATE], MechanismError> {
        let mut q = [0.0; 8];
        self.close_contacts(&mut q)?;
        let mut y = [0.0; Bicycle::STATE];
        y[..8].copy_from_slice(&q);
        y[8] = roll_rate;
        y[10] = -v / self.r_r;
        Ok(y)
    }
}
