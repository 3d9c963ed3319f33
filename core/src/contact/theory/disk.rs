//! The rolling disk on its sharp rim: its equations in lean, yaw and spin, its steady circles,
//! the upright disk's stability, and Euler's disk collapsing under an air-layer dissipation.
//!
//! The frame: the disk's contact point P moves along t = (cos ψ, sin ψ, 0) (ψ the yaw);
//! h = ẑ × t is horizontal to its left; the disk's plane holds t and u = cos θ ẑ + sin θ h,
//! the unit vector from P to the centre C; its axis is n = −sin θ ẑ + cos θ h. θ is the lean
//! from the vertical (the disk leans towards +h when θ > 0) and Euler's disk's angle to the
//! table is α = π/2 − θ. The frame (u, t, n) is right-handed and turns at ψ̇ ẑ − θ̇ t; the
//! disk turns at ω = ψ̇ cos θ u − θ̇ t + ω₃ n, ω₃ = φ̇ − ψ̇ sin θ the spin about its own axis.

use nalgebra::Vector3;

/// A disk of radius r rolling without slip on its sharp rim: mass m, moments A about a
/// diameter and C about its axis, both through its centre (its centre of mass).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollingDisk {
    /// The radius r.
    pub radius: f64,
    /// The mass m.
    pub mass: f64,
    /// The transverse moment A (about a diameter).
    pub transverse: f64,
    /// The axial moment C.
    pub axial: f64,
    /// Gravity g.
    pub gravity: f64,
}

/// The state of a rolling disk in the frame of the module: lean, its rate, the yaw rate and
/// the spin ω₃ about the disk's axis (the yaw itself and the position drop out).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiskState {
    /// The lean θ from the vertical.
    pub lean: f64,
    /// θ̇.
    pub lean_rate: f64,
    /// The yaw rate ψ̇.
    pub yaw_rate: f64,
    /// The spin ω₃ = ω·n.
    pub spin: f64,
}

/// The accelerations of a rolling disk at a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiskAccelerations {
    /// θ̈.
    pub lean: f64,
    /// ψ̈.
    pub yaw: f64,
    /// ω̇₃.
    pub spin: f64,
}

/// A steady circular motion: the lean is constant, the disk turns about a vertical axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyCircle {
    /// The precession (yaw) rate Ω = ψ̇ > 0.
    pub precession: f64,
    /// The spin ω₃ about the disk's axis.
    pub spin: f64,
    /// The radius ρ of the centre's circle (signed: its centre is at C + ρ h); the contact
    /// point runs on the circle of radius ρ + r sin θ.
    pub centre_radius: f64,
}

impl DiskState {
    /// The frame (t, u, n) at yaw ψ, space axes.
    pub fn axes(&self, yaw: f64) -> [Vector3<f64>; 3] {
        let t = Vector3::new(yaw.cos(), yaw.sin(), 0.0);
        let h = Vector3::z().cross(&t);
        let (s, c) = self.lean.sin_cos();
        [t, Vector3::z() * c + h * s, -Vector3::z() * s + h * c]
    }

    /// The disk's angular velocity at yaw ψ, space axes: ψ̇ cos θ u − θ̇ t + ω₃ n.
    pub fn angular_velocity(&self, yaw: f64) -> Vector3<f64> {
        let [t, u, n] = self.axes(yaw);
        u * (self.yaw_rate * self.lean.cos()) - t * self.lean_rate + n * self.spin
    }
}

impl RollingDisk {
    /// A thin uniform disk: A = m r²/4, C = m r²/2.
    pub fn thin(radius: f64, mass: f64, gravity: f64) -> Self {
        let mr2 = mass * radius * radius;
        RollingDisk {
            radius,
            mass,
            transverse: mr2 / 4.0,
            axial: mr2 / 2.0,
            gravity,
        }
    }

    /// The accelerations from the Newton–Euler equations in the turning frame (u, t, n), the
    /// contact force eliminated:
    ///
    /// - (A + m r²) θ̈ = m g r sin θ − A ψ̇² sin θ cos θ − (C + m r²) ψ̇ ω₃ cos θ,
    /// - A ψ̈ cos θ = 2 A ψ̇ θ̇ sin θ + C θ̇ ω₃,
    /// - (C + m r²) ω̇₃ = m r² ψ̇ θ̇ cos θ.
    ///
    /// ψ̈ is undefined when the disk lies flat (cos θ = 0): the yaw of a flat disk is not a
    /// coordinate; it comes out infinite or NaN there.
    pub fn accelerations(&self, s: &DiskState) -> DiskAccelerations {
        let (a, c, m, r, g) = (
            self.transverse,
            self.axial,
            self.mass,
            self.radius,
            self.gravity,
        );
        let (sn, cs) = s.lean.sin_cos();
        let mr2 = m * r * r;
        let (yr, lr, w3) = (s.yaw_rate, s.lean_rate, s.spin);
        DiskAccelerations {
            lean: (m * g * r * sn - a * yr * yr * sn * cs - (c + mr2) * yr * w3 * cs) / (a + mr2),
            yaw: (2.0 * a * yr * lr * sn + c * lr * w3) / (a * cs),
            spin: mr2 * yr * lr * cs / (c + mr2),
        }
    }

    /// The steady circle at lean θ with the contact point on a circle of radius R (on the
    /// side the disk leans to): from θ̈ = 0 with ω₃ = Ω ρ / r and ρ = R − r sin θ,
    ///
    /// Ω² = m g r sin θ / (cos θ [A sin θ + (C + m r²) ρ / r]).
    ///
    /// For the thin uniform disk this is Ω² = g tan θ / (3R/2 − 5 r sin θ / 4). `None` when
    /// no steady circle has these θ and R (Ω² not positive and finite).
    pub fn steady_circle(&self, lean: f64, path_radius: f64) -> Option<SteadyCircle> {
        let (a, c, m, r) = (self.transverse, self.axial, self.mass, self.radius);
        let (sn, cs) = lean.sin_cos();
        let rho = path_radius - r * sn;
        let w2 = m * self.gravity * r * sn / (cs * (a * sn + (c + m * r * r) * rho / r));
        (w2 > 0.0 && w2.is_finite()).then(|| {
            let precession = w2.sqrt();
            SteadyCircle {
                precession,
                spin: precession * rho / r,
                centre_radius: rho,
            }
        })
    }

    /// The least spin at which the upright disk rolling straight is stable (linearly: a
    /// small lean oscillates rather than grows): ω₃² > m g r A / (C (C + m r²)).
    ///
    /// Linearising the equations of [`Self::accelerations`] about θ = 0, ψ̇ = 0, ω₃ = ω₀:
    /// A ψ̈ = C ω₀ θ̇ integrates to ψ̇ = (C ω₀ / A) θ, and then
    /// (A + m r²) θ̈ = (m g r − (C + m r²) C ω₀² / A) θ. For the thin uniform disk
    /// ω₀² > g / (3 r), i.e. a rolling speed v² > g r / 3.
    pub fn critical_spin(&self) -> f64 {
        let (a, c, m, r) = (self.transverse, self.axial, self.mass, self.radius);
        (m * self.gravity * r * a / (c * (c + m * r * r))).sqrt()
    }

    /// The rate of the lean's linear motion about the upright disk spinning at ω₀: the
    /// squared frequency ν² = ((C + m r²) C ω₀² / A − m g r) / (A + m r²) of θ̈ = −ν² θ
    /// (a growth rate √(−ν²) when negative).
    pub fn upright_frequency_squared(&self, spin: f64) -> f64 {
        let (a, c, m, r) = (self.transverse, self.axial, self.mass, self.radius);
        ((c + m * r * r) * c * spin * spin / a - m * self.gravity * r) / (a + m * r * r)
    }
}

/// Euler's disk: a disk rolling on its rim with its centre at rest, its plane at α to the
/// table, settling under a dissipation.
///
/// Its steady motion (the steady circle with ρ = 0, so ω₃ = 0) has Ω² = m g r / (A sin α)
/// and energy E = (3/2) m g r sin α, exactly, for any A (for the thin disk Ω² sin α = 4 g / r,
/// Moffatt, Nature 404 (2000) 833). As E falls Ω grows without bound: a finite-time
/// singularity whose exponents depend on how the power P dissipated scales with α.
///
/// The model here is a viscous couple whose coefficient grows as the air gap under the disk
/// closes, τ = −κ ω / sin³ α. In the steady motion |ω| = Ω sin α, so it dissipates
/// P = κ Ω² / sin α, Moffatt's scaling for the air layer (P ∝ Ω²/α). The balance
/// dE/dt = −P then gives d(sin³ α)/dt = −2κ / A exactly, so sin α = (2κ (t₀ − t) / A)^{1/3}
/// and Ω ∝ (t₀ − t)^{−1/6}: Moffatt's exponents 1/3 and −1/6.
///
/// The literature disputes the mechanism rather than this arithmetic: Caps et al. (Phys. Rev.
/// E 69 (2004) 056610) measured power laws and found slip at the contact dominant; Le Saux,
/// Leine & Glocker (J. Nonlinear Sci. 15 (2005) 27) and Leine (Arch. Appl. Mech. 79 (2009)
/// 1063) derive the energy decay for sliding, pivoting and rolling friction; each model's
/// exponents follow from [`power_law_exponents`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerDisk {
    /// The disk.
    pub disk: RollingDisk,
    /// The couple's coefficient κ (torque per rad/s at α = π/2).
    pub kappa: f64,
}

impl EulerDisk {
    /// The steady precession rate at angle α to the table: Ω = √(m g r / (A sin α)).
    pub fn precession(&self, alpha: f64) -> f64 {
        let d = self.disk;
        (d.mass * d.gravity * d.radius / (d.transverse * alpha.sin())).sqrt()
    }

    /// The steady energy at angle α: E = (3/2) m g r sin α (the table at zero height).
    pub fn energy(&self, alpha: f64) -> f64 {
        1.5 * self.disk.mass * self.disk.gravity * self.disk.radius * alpha.sin()
    }

    /// The dissipating couple τ = −κ ω / sin³ α (any axes: it is along −ω).
    pub fn couple(&self, omega: &Vector3<f64>, alpha: f64) -> Vector3<f64> {
        -omega * (self.kappa / alpha.sin().powi(3))
    }

    /// sin α at a time t₀ − t before the collapse, in the steady (adiabatic) motion:
    /// sin α = (2κ (t₀ − t) / A)^{1/3}.
    pub fn sin_lean(&self, time_to_go: f64) -> f64 {
        (2.0 * self.kappa * time_to_go / self.disk.transverse).cbrt()
    }

    /// The time from angle α to the collapse: t₀ − t = A sin³ α / (2κ).
    pub fn collapse_time(&self, alpha: f64) -> f64 {
        self.disk.transverse * alpha.sin().powi(3) / (2.0 * self.kappa)
    }
}

/// The exponents (n_α, n_Ω) of α ∝ (t₀ − t)^{n_α} and Ω ∝ (t₀ − t)^{n_Ω} for a disk settling
/// through its steady motions (E ∝ α, Ω ∝ α^{−1/2} at small α) under a dissipated power
/// P ∝ Ω^m α^k: the balance α̇ ∝ −α^p, p = k − m/2, reaches α = 0 in finite time when p < 1,
/// with n_α = 1/(1 − p) and n_Ω = −n_α/2. `None` when p ≥ 1 (the decay never ends).
///
/// ```
/// use precess_core::contact::theory::power_law_exponents;
/// // Moffatt's air layer, P ∝ Ω²/α.
/// assert_eq!(power_law_exponents(2.0, -1.0), Some((1.0 / 3.0, -1.0 / 6.0)));
/// ```
pub fn power_law_exponents(omega_power: f64, lean_power: f64) -> Option<(f64, f64)> {
    let p = lean_power - omega_power / 2.0;
    (p < 1.0).then(|| {
        let n = 1.0 / (1.0 - p);
        (n, -n / 2.0)
    })
}
