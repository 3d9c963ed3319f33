//! An independent Newton–Euler formulation of a rigid body on a table, written out here in
//! space axes with its contact force solved for, to check the closed forms of
//! `contact::theory` against: a body rolling without slip on a sphere or a disk rim, and a
//! sphere sliding under viscous friction. Integrated with classical RK4 on the rotation
//! matrix (its drift off SO(3) is O(h⁴) per unit time, far below what the tests resolve).

use precess::nalgebra::{Matrix3, Vector3};

/// The surface a body touches the table with, fixed in the body (body axes, from the centre
/// of mass).
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// A sphere of radius `radius` about `centre`.
    Sphere { centre: Vector3<f64>, radius: f64 },
    /// The sharp rim of a disk of radius `radius` about the centre of mass, axis body z.
    Rim { radius: f64 },
    /// An ellipsoid of semi-axes `semi` along the body axes about `centre`.
    Ellipsoid {
        centre: Vector3<f64>,
        semi: Vector3<f64>,
    },
}

/// A rigid body: mass, inertia about its centre of mass (body axes), shape, gravity.
#[derive(Clone, Copy, Debug)]
pub struct Body {
    pub mass: f64,
    pub inertia: Matrix3<f64>,
    pub shape: Shape,
    pub gravity: f64,
}

/// The attitude (body to space) and the angular velocity in space axes.
#[derive(Clone, Copy, Debug)]
pub struct Rolling {
    pub rot: Matrix3<f64>,
    pub omega: Vector3<f64>,
}

fn skew(w: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -w.z, w.y, w.z, 0.0, -w.x, -w.y, w.x, 0.0)
}

impl Body {
    /// r = G − P and its rate of change, space axes, while the body turns at ω.
    pub fn arm(&self, rot: &Matrix3<f64>, omega: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        match self.shape {
            Shape::Sphere { centre, radius } => {
                let c = rot * centre;
                (Vector3::z() * radius - c, -omega.cross(&c))
            }
            Shape::Rim { radius } => {
                // u: the unit vector in the disk's plane from the contact up to the centre.
                let n = rot * Vector3::z();
                let nd = omega.cross(&n);
                let cz = n.z;
                let w = Vector3::z() - n * cz;
                let s = w.norm();
                let wd = -(n * nd.z + nd * cz);
                let sd = w.dot(&wd) / s;
                let u = w / s;
                let ud = wd / s - w * (sd / (s * s));
                (u * radius, ud * radius)
            }
            Shape::Ellipsoid { centre, semi } => {
                // P = s(n), n = −γ the outward normal at the contact in body axes:
                // s(n) = c + D² n / √(nᵀ D² n), its derivative Ds = D²/√q − D²n (D²n)ᵀ/q^{3/2},
                // and ṅ = −γ̇ = −γ × ω_b.
                let d2 = Matrix3::from_diagonal(&semi.component_mul(&semi));
                let gamma = rot.transpose() * Vector3::z();
                let wb = rot.transpose() * omega;
                let n = -gamma;
                let d2n = d2 * n;
                let q = n.dot(&d2n);
                let s = centre + d2n / q.sqrt();
                let ds = d2 / q.sqrt() - d2n * d2n.transpose() / (q * q.sqrt());
                let nd = -gamma.cross(&wb);
                let sp = rot * s;
                (-sp, -omega.cross(&sp) - rot * (ds * nd))
            }
        }
    }

    /// The angular acceleration (space axes) of the body rolling without slip, with an extra
    /// couple `torque` about the centre of mass: from m a_G = F − m g ẑ, a_G = ω̇ × r + ω × ṙ,
    /// and I ω̇ + ω × I ω = τ − r × F, (I + m(|r|² − r rᵀ)) ω̇ = τ − ω × I ω − m r × (ω × ṙ + g ẑ).
    pub fn rolling_acceleration(&self, s: &Rolling, torque: &Vector3<f64>) -> Vector3<f64> {
        let (r, rd) = self.arm(&s.rot, &s.omega);
        let i = s.rot * self.inertia * s.rot.transpose();
        let m = self.mass;
        let lhs = i + (Matrix3::identity() * r.norm_squared() - r * r.transpose()) * m;
        let rhs = torque
            - s.omega.cross(&(i * s.omega))
            - r.cross(&(s.omega.cross(&rd) + Vector3::z() * self.gravity)) * m;
        lhs.lu().solve(&rhs).unwrap_or_else(Vector3::zeros)
    }

    /// The centre of mass's velocity while rolling: v_G = ω × r.
    pub fn rolling_velocity(&self, s: &Rolling) -> Vector3<f64> {
        s.omega.cross(&self.arm(&s.rot, &s.omega).0)
    }

    /// One RK4 step of the rolling body, with a couple given as a function of the state.
    pub fn rolling_step(
        &self,
        s: &Rolling,
        h: f64,
        couple: &dyn Fn(&Rolling) -> Vector3<f64>,
    ) -> Rolling {
        let f = |x: &Rolling| {
            (
                skew(&x.omega) * x.rot,
                self.rolling_acceleration(x, &couple(x)),
            )
        };
        let add = |x: &Rolling, k: &(Matrix3<f64>, Vector3<f64>), c: f64| Rolling {
            rot: x.rot + k.0 * c,
            omega: x.omega + k.1 * c,
        };
        let k1 = f(s);
        let k2 = f(&add(s, &k1, h / 2.0));
        let k3 = f(&add(s, &k2, h / 2.0));
        let k4 = f(&add(s, &k3, h));
        Rolling {
            rot: s.rot + (k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) * (h / 6.0),
            omega: s.omega + (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) * (h / 6.0),
        }
    }
}

/// A sphere sliding on the table: attitude, angular velocity (space), the centre of mass's
/// horizontal velocity (its vertical velocity follows from the contact).
#[derive(Clone, Copy, Debug)]
pub struct Sliding {
    pub rot: Matrix3<f64>,
    pub omega: Vector3<f64>,
    pub v: [f64; 2],
}

/// A sphere body sliding under viscous friction F = −c u (u the contact point's slip).
pub struct SlidingSphere {
    pub body: Body,
    pub centre: Vector3<f64>,
    pub radius: f64,
    pub friction: f64,
}

type SlidingRate = (Matrix3<f64>, Vector3<f64>, [f64; 2]);

impl SlidingSphere {
    /// The centre of mass's full velocity: vz from the contact, z_G = R − (q c)_z.
    pub fn velocity(&self, s: &Sliding) -> Vector3<f64> {
        let c = s.rot * self.centre;
        Vector3::new(s.v[0], s.v[1], -s.omega.cross(&c).z)
    }

    /// The rates, and the normal force N solved from the contact's second derivative:
    /// ω̇ = N w₁ + w₀ is linear in N and m z̈_G = N − m g with z̈_G = −(ω̇ × c + ω × (ω × c))_z.
    pub fn rates(&self, s: &Sliding) -> (SlidingRate, f64) {
        let (m, g) = (self.body.mass, self.body.gravity);
        let c = s.rot * self.centre;
        let a = c - Vector3::z() * self.radius;
        let slip = self.velocity(s) + s.omega.cross(&a);
        let friction = Vector3::new(-self.friction * slip.x, -self.friction * slip.y, 0.0);
        let i = s.rot * self.body.inertia * s.rot.transpose();
        let inv = i.try_inverse().unwrap_or_else(Matrix3::zeros);
        let w1 = inv * a.cross(&Vector3::z());
        let w0 = inv * (a.cross(&friction) - s.omega.cross(&(i * s.omega)));
        let k1 = -w1.cross(&c).z;
        let k0 = -w0.cross(&c).z - s.omega.cross(&s.omega.cross(&c)).z;
        let normal = m * (g + k0) / (1.0 - m * k1);
        let wd = w1 * normal + w0;
        (
            (skew(&s.omega) * s.rot, wd, [friction.x / m, friction.y / m]),
            normal,
        )
    }

    /// One RK4 step.
    pub fn step(&self, s: &Sliding, h: f64) -> Sliding {
        let add = |x: &Sliding, k: &SlidingRate, c: f64| Sliding {
            rot: x.rot + k.0 * c,
            omega: x.omega + k.1 * c,
            v: [x.v[0] + k.2[0] * c, x.v[1] + k.2[1] * c],
        };
        let k1 = self.rates(s).0;
        let k2 = self.rates(&add(s, &k1, h / 2.0)).0;
        let k3 = self.rates(&add(s, &k2, h / 2.0)).0;
        let k4 = self.rates(&add(s, &k3, h)).0;
        Sliding {
            rot: s.rot + (k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) * (h / 6.0),
            omega: s.omega + (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) * (h / 6.0),
            v: [
                s.v[0] + (k1.2[0] + (k2.2[0] + k3.2[0]) * 2.0 + k4.2[0]) * (h / 6.0),
                s.v[1] + (k1.2[1] + (k2.2[1] + k3.2[1]) * 2.0 + k4.2[1]) * (h / 6.0),
            ],
        }
    }
}
