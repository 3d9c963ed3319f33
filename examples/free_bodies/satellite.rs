//! A satellite with a reaction wheel on its intermediate axis, the scene of the `gyrostat`
//! example, shared with its test so both run the very struct the example declares.
//!
//! Spun at n about the wheel's axis s (the intermediate one), the body is a gyrostat with
//! h = J Ω along s. Linearising the Volterra–Zhukovsky equations about ω = n ŝ, each
//! transverse component obeys ε̈ = −k ε with
//!
//! k = (h − (I_p − I_s) n)(h − (I_q − I_s) n)/(I_p I_q),
//!
//! p, q the other two axes: k > 0 (a wobble of period 2π/√k) once h passes (I_major − I_s) n,
//! k < 0 (growth as cosh(√−k t)) below it, as without a wheel.

#![allow(dead_code)] // the example and its test each use the part they need

use precess::free::{FreeDynamics, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Dop853, OdeError};
use precess::prelude::*;

/// A box-shaped bus with a wheel along its intermediate axis x; the wheel's inertia is part
/// of the body's (locked), its spin `wheel` [rad/s] relative to the bus is the rotor's.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 100 kg, size = [100 cm, 120 cm, 80 cm]),
    cylinder(mass = 2 kg, radius = 10 cm, length = 4 cm, axis = x),
)]
#[free(rotor(axis = [1, 0, 0], inertia = 0.5 * 2 * 0.1 * 0.1, rate = wheel))]
pub struct Satellite {
    /// The wheel's spin relative to the bus [rad/s].
    pub wheel: f64,
}

/// The wheel's axial moment J = ½ m r² [kg m²].
pub const WHEEL_INERTIA: f64 = 0.01;
/// The bus's spin about x [rad/s].
pub const SPIN: f64 = 0.5;

/// One rpm in rad/s.
pub const RPM: f64 = std::f64::consts::PI / 30.0;

impl Satellite {
    /// k of the linearised wobble about a spin n along x (see the module's docs).
    pub fn k(&self, n: f64) -> f64 {
        let [ix, iy, iz] = self.moments();
        let h = WHEEL_INERTIA * self.wheel;
        (h - (iy - ix) * n) * (h - (iz - ix) * n) / (iy * iz)
    }

    /// The wheel rate [rad/s] above which a spin n along x is stable, (I_z − I_x) n/J.
    pub fn threshold(&self, n: f64) -> f64 {
        let [ix, _, iz] = self.moments();
        (iz - ix) * n / WHEEL_INERTIA
    }

    /// The amplitude of ω_z in the linearised wobble about a spin n along x started at
    /// ω_y = a: ω_y = a cos(√k t) drives ω_z = a √k I_y/(h − (I_z − I_x) n) sin(√k t).
    pub fn z_amplitude(&self, n: f64, a: f64) -> f64 {
        let [ix, iy, iz] = self.moments();
        let h = WHEEL_INERTIA * self.wheel;
        a * self.k(n).sqrt() * iy / (h - (iz - ix) * n)
    }

    /// The principal moments about the centre of mass (along x, y, z).
    pub fn moments(&self) -> [f64; 3] {
        let m = self.principal_cm().moments;
        [m.x, m.y, m.z]
    }
}

/// What a run records.
pub struct Run {
    /// Sample times [s] and ω [rad/s].
    pub samples: Vec<(f64, Vector3<f64>)>,
    /// Mean period between downward zero crossings of ω_y [s] (NaN with fewer than two).
    pub period: f64,
    /// The largest |ω_y| [rad/s].
    pub largest: f64,
    /// The first time |ω_y| exceeded `grown` [s] (NaN if never).
    pub grown_at: f64,
    /// |I ω + h| and ½ ωᵀ I ω at the start and the end.
    pub momentum: (f64, f64),
    /// ½ ωᵀ I ω at the start and the end.
    pub energy: (f64, f64),
}

impl Run {
    /// The largest |ω_z| sampled [rad/s].
    pub fn largest_z(&self) -> f64 {
        self.samples
            .iter()
            .map(|(_, w)| w.z.abs())
            .fold(0.0, f64::max)
    }
}

/// Spins the satellite at n about x with ω_y(0) = a, samples every `dt` up to `t_end`.
///
/// # Errors
/// The stepper's.
pub fn run(sat: &Satellite, a: f64, grown: f64, dt: f64, t_end: f64) -> Result<Run, OdeError> {
    let s0 = FreeState {
        omega_principal: Vector3::new(SPIN, a, 0.0),
        ..FreeState::at_rest()
    };
    let i = Vector3::from(sat.moments());
    let h = Vector3::new(WHEEL_INERTIA * sat.wheel, 0.0, 0.0);
    let integrals = |w: &Vector3<f64>| {
        (
            (i.component_mul(w) + h).norm(),
            0.5 * w.dot(&i.component_mul(w)),
        )
    };
    let system = FreeSystem(sat);
    let mut ode = Dop853::new(
        &system,
        0.0,
        s0.to_array(),
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )?;
    let omega = |y: &[f64; 13]| Vector3::new(y[10], y[11], y[12]);
    let mut samples = vec![(0.0, s0.omega_principal)];
    let (mut crossings, mut first, mut last, mut largest) = (0u32, f64::NAN, f64::NAN, a.abs());
    let mut grown_at = f64::NAN;
    let steps = (t_end / dt).round() as u32;
    for k in 1..=steps {
        let t = dt * f64::from(k);
        ode.advance_to(t)?;
        let w = omega(ode.y());
        let previous = samples.last().map_or(a, |(_, p)| p.y);
        if previous > 0.0 && w.y <= 0.0 {
            crossings += 1;
            if first.is_nan() {
                first = t;
            }
            last = t;
        }
        largest = largest.max(w.y.abs());
        if grown_at.is_nan() && w.y.abs() > grown {
            grown_at = t;
        }
        samples.push((t, w));
    }
    let (l0, e0) = integrals(&s0.omega_principal);
    let (l1, e1) = integrals(&omega(ode.y()));
    let period = if crossings > 1 {
        (last - first) / f64::from(crossings - 1)
    } else {
        f64::NAN
    };
    Ok(Run {
        samples,
        period,
        largest,
        grown_at,
        momentum: (l0, l1),
        energy: (e0, e1),
    })
}
