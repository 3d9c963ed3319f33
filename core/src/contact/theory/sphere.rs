//! Bodies whose contact surface is a sphere: the integrals of a rolling sphere (energy,
//! Jellett's, Routh's) and the tippe top's inverted state from Jellett's integral.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// A rigid body whose contact surface is a sphere: radius R about a centre fixed in the body
/// at `centre` from the centre of mass (body axes). The tippe top, Routh's sphere and
/// Chaplygin's ball are all of this kind.
///
/// On a table the contact point is P = O − R ẑ whatever the attitude, so the arm from the
/// centre of mass to the contact, a = P − G = q·centre − R ẑ, is a closed form of q.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereBody {
    /// The sphere's radius R.
    pub radius: f64,
    /// The sphere's centre O from the centre of mass G, body axes.
    pub centre: Vector3<f64>,
    /// The mass M.
    pub mass: f64,
    /// The inertia tensor about G, body axes.
    pub inertia: Matrix3<f64>,
    /// Gravity g.
    pub gravity: f64,
}

impl SphereBody {
    /// The arm a = P − G from the centre of mass to the contact point, space axes.
    pub fn contact_arm(&self, q: &UnitQuaternion<f64>) -> Vector3<f64> {
        q * self.centre - Vector3::z() * self.radius
    }

    /// The height of the centre of mass above the table: R − (q·centre)_z.
    pub fn height(&self, q: &UnitQuaternion<f64>) -> f64 {
        self.radius - (q * self.centre).z
    }

    /// The velocity of the centre of mass when the body rolls without slip: the contact point
    /// is at rest, so v_G = ω × (G − P) = a × ω (space axes; `omega` in body axes).
    pub fn rolling_velocity(&self, q: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> Vector3<f64> {
        self.contact_arm(q).cross(&(q * omega))
    }

    /// The energy E = ½ M |v|² + ½ ωᵀ I ω + M g z_G (v the centre of mass's velocity, space
    /// axes; `omega` in body axes).
    pub fn energy(&self, q: &UnitQuaternion<f64>, omega: &Vector3<f64>, v: &Vector3<f64>) -> f64 {
        0.5 * self.mass * v.norm_squared()
            + 0.5 * omega.dot(&(self.inertia * omega))
            + self.mass * self.gravity * self.height(q)
    }

    /// Jellett's integral λ = −L·a, L = I ω the angular momentum about the centre of mass
    /// (space axes) and a the arm to the contact point.
    ///
    /// It is conserved under any contact force whatever the friction, provided the contact
    /// surface is a sphere and the body is axisymmetric about the line GO (Jellett 1872; the
    /// tippe top's analysis of Cohen 1977 and Or 1994 rests on it): dL/dt = a × F for the
    /// contact force F at P, which is ⊥ a, and da/dt = ω × (q·centre) ∥ ω × k, which is ⊥ L
    /// when L = I₁ ω + (I₃ − I₁)(ω·k) k.
    pub fn jellett(&self, q: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> f64 {
        let l = q * (self.inertia * omega);
        -l.dot(&self.contact_arm(q))
    }

    /// The angular momentum about the contact point, K = I ω + M a × (ω × a) in space axes
    /// (the moment of M v_G = M a × ω about P, added to I ω about G). For Chaplygin's ball
    /// (G = O, any moments) K·ẑ and |K|² are conserved while it rolls without slip.
    pub fn contact_momentum(&self, q: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> Vector3<f64> {
        let a = self.contact_arm(q);
        let w = q * omega;
        q * (self.inertia * omega) + self.mass * (w * a.norm_squared() - a * a.dot(&w))
    }

    /// Routh's integral of an axisymmetric sphere rolling without slip, its symmetry axis e₃
    /// through G and O (I₁ = I₂ = `inertia[(0,0)]`, I₃ = `inertia[(2,2)]`):
    ///
    /// Q_R = ω₃ √(I₁ I₃ + M I₁ |a × k|² + M I₃ (a·k)²),
    ///
    /// ω₃ = ω·e₃ the spin about the symmetry axis, k = q e₃ that axis in space (Routh 1884):
    /// the moments about k and across it, each with M times the squared arm along the other.
    /// (Checked against a Newton–Euler simulation in the tests; the variant with I₁ and I₃
    /// swapped in the arm terms is not conserved.)
    pub fn routh(&self, q: &UnitQuaternion<f64>, omega: &Vector3<f64>) -> f64 {
        let (i1, i3, m) = (self.inertia[(0, 0)], self.inertia[(2, 2)], self.mass);
        let a = self.contact_arm(q);
        let k = q * Vector3::z();
        let ak = a.dot(&k);
        let across = a.cross(&k).norm_squared();
        omega.z * (i1 * i3 + m * i1 * across + m * i3 * ak * ak).sqrt()
    }
}

/// The tippe top as an eccentric sphere: radius R, its centre of mass on the symmetry axis at
/// αR below the sphere's centre when the stem is up, axisymmetric moments I₁ = I₂ and I₃ about
/// the centre of mass.
///
/// Started spinning fast about the vertical with its stem up (centre of mass low, θ = 0), a
/// top with sliding friction turns over onto its stem (θ = π) when 1 − α < I₁/I₃ < 1 + α
/// (Cohen 1977; Bou-Rabee, Marsden & Romero 2004; Rauch-Wojciechowski & Rutstam 2014). The
/// friction changes the energy but not Jellett's λ = −L·a, and both asymptotic states spin
/// about the vertical, so λ fixes the inverted state: with L = I₃ n ẑ and a = −R(1 ∓ α) ẑ,
/// λ = R I₃ n (1 − α) upright and λ = R I₃ n′ (1 + α) inverted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TippeTop {
    /// The sphere's radius R.
    pub radius: f64,
    /// The eccentricity α: the centre of mass is αR from the sphere's centre, 0 < α < 1.
    pub alpha: f64,
    /// The mass M.
    pub mass: f64,
    /// The transverse moment I₁ = I₂ about the centre of mass.
    pub i1: f64,
    /// The axial moment I₃ about the centre of mass.
    pub i3: f64,
    /// Gravity g.
    pub gravity: f64,
}

impl TippeTop {
    /// The same top as a [`SphereBody`]: body z is the symmetry axis pointing from the centre
    /// of mass to the sphere's centre (up when the stem is up).
    pub fn body(&self) -> SphereBody {
        SphereBody {
            radius: self.radius,
            centre: Vector3::new(0.0, 0.0, self.alpha * self.radius),
            mass: self.mass,
            inertia: Matrix3::from_diagonal(&Vector3::new(self.i1, self.i1, self.i3)),
            gravity: self.gravity,
        }
    }

    /// Whether the top inverts: 1 − α < I₁/I₃ < 1 + α, the range where spinning upright is
    /// unstable and spinning inverted is stable under sliding friction.
    pub fn inverts(&self) -> bool {
        let gamma = self.i1 / self.i3;
        1.0 - self.alpha < gamma && gamma < 1.0 + self.alpha
    }

    /// Jellett's λ of the top spinning at n about the vertical with its stem up:
    /// λ = R I₃ n (1 − α).
    pub fn upright_jellett(&self, spin: f64) -> f64 {
        self.radius * self.i3 * spin * (1.0 - self.alpha)
    }

    /// The energy spinning upright at n: E = ½ I₃ n² + M g R (1 − α).
    pub fn upright_energy(&self, spin: f64) -> f64 {
        0.5 * self.i3 * spin * spin + self.mass * self.gravity * self.radius * (1.0 - self.alpha)
    }

    /// The spin n′ about the vertical (space axes, the same sense as the upright spin) of the
    /// inverted top with Jellett's λ: n′ = λ / (R I₃ (1 + α)). Measured about the body's own
    /// axis, which now points down, the spin has changed sign. From a top started upright at
    /// n, n′ = n (1 − α)/(1 + α).
    pub fn inverted_spin(&self, lambda: f64) -> f64 {
        lambda / (self.radius * self.i3 * (1.0 + self.alpha))
    }

    /// The energy of the inverted top with Jellett's λ:
    /// E′ = λ² / (2 I₃ R² (1 + α)²) + M g R (1 + α).
    pub fn inverted_energy(&self, lambda: f64) -> f64 {
        let n = self.inverted_spin(lambda);
        0.5 * self.i3 * n * n + self.mass * self.gravity * self.radius * (1.0 + self.alpha)
    }

    /// The least upright spin for which the inverted state has less energy than the upright
    /// one, so that friction can take the top over at all: from E′ < E,
    /// I₃ n² > M g R (1 + α)², n_min = (1 + α) √(M g R / I₃). A necessary condition.
    pub fn min_inversion_spin(&self) -> f64 {
        (1.0 + self.alpha) * (self.mass * self.gravity * self.radius / self.i3).sqrt()
    }

    /// The threshold on Jellett's λ above which the effective potential of the inclination
    /// has a single minimum that moves from θ ≈ 0 to θ ≈ π during the inversion,
    /// λ_thres = √(M g R³ I₃ α) (1 + α)² / √(1 + α − γ), γ = I₁/I₃ (Rauch-Wojciechowski &
    /// Rutstam, SIGMA 10 (2014) 017, stated there for 1 − α² < γ < 1). `None` outside
    /// γ < 1 + α, where the root is not real.
    pub fn jellett_threshold(&self) -> Option<f64> {
        let gamma = self.i1 / self.i3;
        let d = 1.0 + self.alpha - gamma;
        (d > 0.0).then(|| {
            let r = self.radius;
            (self.mass * self.gravity * r * r * r * self.i3 * self.alpha).sqrt()
                * (1.0 + self.alpha).powi(2)
                / d.sqrt()
        })
    }
}
