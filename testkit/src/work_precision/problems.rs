//! The problems of the report and their independent references: closed forms (the exact
//! torque-free motion, Jacobi's sn, cn, dn, the heavy top's elliptic nutation) and a
//! 30-digit value, never another integrator.

use precess::exact::FreeBodyExact;
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::prelude::*;
use precess::rigid::{Attitude, AttitudeModel};
use precess::top::{HeavyTopMotion, HeavyTopTheory};

/// The problems, in the order of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Problem {
    /// (a) The torque-free body I = (3, 5, 9), m(0) = (0, 2, 0.01) to T = 200.
    Separatrix,
    /// (b) DETEST B5 to t = 20.
    B5,
    /// (c) The heavy top of `examples/heavy_top.rs` over 10¼ nutation periods.
    HeavyTop,
    /// (d) The same top spinning at ω₃ = 10³ rad/s.
    FastTop,
    /// (e) The torque-free body of (a) over 10⁶ steps: drift of |L| and of the energy.
    LongRun,
    /// (f) The top of (c) in the Lagrangian (Euler angles) and the Eulerian form.
    Forms,
}

impl Problem {
    /// All problems.
    pub const ALL: [Problem; 6] = [
        Problem::Separatrix,
        Problem::B5,
        Problem::HeavyTop,
        Problem::FastTop,
        Problem::LongRun,
        Problem::Forms,
    ];

    /// A short key (file names, CSV).
    pub fn key(self) -> &'static str {
        match self {
            Problem::Separatrix => "separatrix",
            Problem::B5 => "b5",
            Problem::HeavyTop => "heavy_top",
            Problem::FastTop => "fast_top",
            Problem::LongRun => "long_run",
            Problem::Forms => "forms",
        }
    }

    /// The heading in the report.
    pub fn title(self) -> &'static str {
        match self {
            Problem::Separatrix => {
                "(a) Torque-free body I = (3, 5, 9), m(0) = (0, 2, 0.01), T = 200"
            }
            Problem::B5 => "(b) DETEST B5 to t = 20",
            Problem::HeavyTop => "(c) Heavy top (examples/heavy_top.rs), 10¼ nutation periods",
            Problem::FastTop => "(d) Fast top, ω3 = 1000 rad/s, 10¼ nutation periods",
            Problem::LongRun => "(e) Long run: the body of (a) over 10⁶ steps",
            Problem::Forms => "(f) The top of (c): Lagrangian (Euler angles) against Eulerian form",
        }
    }

    /// What the error column measures.
    pub fn error_meaning(self) -> &'static str {
        match self {
            Problem::Separatrix => "max-norm error of m(200) against the exact torque-free motion",
            Problem::B5 => "max-norm error of y(20) against the 30-digit reference",
            Problem::HeavyTop | Problem::FastTop | Problem::Forms => {
                "error of cos θ at the end (mid-nutation, where it moves fastest) against the elliptic closed form"
            }
            Problem::LongRun => {
                "the larger of the relative changes of |L| and of the energy after 10⁶ steps of h = 0.01 (T = 10⁴); for split2 it is the method's bounded O(h²) energy error, not a drift"
            }
        }
    }
}

/// Problem (b), DETEST B5, the torque-free body and the heavy top are the shared reference
/// systems.
pub use crate::systems::{B5, B5_T, B5_Y0, B5_Y20, FreeBody, SpinningTop, max_diff};

/// I = (3, 5, 9) of problem (a).
pub const SEP_I: [f64; 3] = [3.0, 5.0, 9.0];
/// m(0) of problem (a).
pub const SEP_M0: [f64; 3] = [0.0, 2.0, 0.01];
/// The end of problem (a).
pub const SEP_T: f64 = 200.0;

/// The free body as an attitude model (for RKMK4).
pub struct FreeAttitude(pub [f64; 3]);
impl AttitudeModel for FreeAttitude {
    fn inertia(&self) -> [f64; 3] {
        self.0
    }
}

/// The exact m(T) of problem (a): the closed form with its phase and its moduli in
/// double-double (see `docs/exact.md`).
pub fn separatrix_reference() -> [f64; 3] {
    let m = FreeBodyExact::new(SEP_I, SEP_M0)
        .and_then(|e| e.m_at(SEP_T))
        .unwrap_or_else(|_| Vector3::repeat(f64::NAN));
    [m.x, m.y, m.z]
}

/// Gravity on the top as a torque model in principal axes (for RKMK4):
/// G = c × (Rᵀ(−M g ẑ)).
pub struct TopTorque {
    /// Principal moments about the pivot.
    pub inertia: [f64; 3],
    /// M g.
    pub weight: f64,
    /// Centre of mass, body axes.
    pub c: Vector3<f64>,
}
impl AttitudeModel for TopTorque {
    fn inertia(&self) -> [f64; 3] {
        self.inertia
    }
    fn torque(&self, _t: f64, s: &Attitude) -> Vector3<f64> {
        let down = s.q.inverse() * Vector3::new(0.0, 0.0, -self.weight);
        self.c.cross(&down)
    }
}

/// One heavy-top run: the top released at rest from θ₀ = 20° spinning at ω₃, to
/// `t_end` = 10¼ nutation periods, with the exact cos θ there.
#[derive(Debug, Clone, Copy)]
pub struct TopCase {
    /// Spin ω₃.
    pub omega3: f64,
    /// Initial tilt θ₀.
    pub theta0: f64,
    /// The end of the run.
    pub t_end: f64,
    /// The exact cos θ(t_end).
    pub u_end: f64,
    /// Transverse and axial moments about the pivot.
    pub i1: f64,
    /// Axial moment.
    pub i3: f64,
    /// M g l.
    pub mgl: f64,
    /// Mass.
    pub mass: f64,
    /// Distance from the pivot to the centre of mass.
    pub lever: f64,
    /// Nutation period.
    pub period: f64,
}

impl TopCase {
    /// The case at spin `omega3`.
    pub fn new(omega3: f64) -> Result<Self, Box<dyn std::error::Error>> {
        let top = SpinningTop;
        let moments = top.principal().moments;
        let (i1, i3) = (moments[0], moments[2]);
        let lever = top.center_of_mass().z;
        let mgl = top.mass() * 9.81 * lever;
        let theta0 = 20f64.to_radians();
        let theory = HeavyTopTheory::new(i1, i3, mgl)?;
        let motion: HeavyTopMotion =
            theory.motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, omega3])?;
        let period = motion.nutation_period();
        let t_end = 10.25 * period;
        Ok(TopCase {
            omega3,
            theta0,
            t_end,
            u_end: motion.cos_theta_at(t_end)?,
            i1,
            i3,
            mgl,
            mass: top.mass(),
            lever,
            period,
        })
    }

    /// The initial ZXZ state (φ, θ, ψ, φ̇, θ̇, ψ̇).
    pub fn angles0(&self) -> [f64; 6] {
        [0.0, self.theta0, 0.0, 0.0, 0.0, self.omega3]
    }

    /// The initial attitude (ZXZ with φ = ψ = 0: a turn by θ₀ about x).
    pub fn q0(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), self.theta0)
    }

    /// The body ω at the start.
    pub fn omega0(&self) -> Vector3<f64> {
        Vector3::new(0.0, 0.0, self.omega3)
    }

    /// |cos θ − exact| for an attitude at the end.
    pub fn error_q(&self, q: &UnitQuaternion<f64>) -> f64 {
        ((q * Vector3::z()).z - self.u_end).abs()
    }
}
