//! The reference the contact tests measure against: bodies described by numbers, built into
//! interpreted models, and an independent Newton–Euler formulation written out here in space
//! axes (a 6×6 or 4×4 linear solve with the contact force as unknowns), with the surfaces'
//! support maps and their derivatives written by hand.

use nalgebra::{DMatrix, DVector, Matrix3, UnitQuaternion, Vector3};
use precess::contact::{
    ContactLaw, ContactModel, ContactScene, ContactTorques, Friction, STATE_LEN, Surface,
    attitude_of, layout,
};
use precess::sym::{Arena, ExprId};

/// A contact surface by numbers, description axes.
#[derive(Clone, Copy, Debug)]
pub enum NumSurface {
    Sphere { c: [f64; 3], rho: f64 },
    Ellipsoid { c: [f64; 3], axes: [f64; 3] },
    DiskRim { c: [f64; 3], rho: f64 },
    Torus { c: [f64; 3], big: f64, tube: f64 },
    Paraboloid { v: [f64; 3], big: f64 },
}

/// A contact law by numbers.
#[derive(Clone, Copy, Debug)]
pub enum NumLaw {
    Rolling {
        cr: Option<f64>,
        cs: Option<f64>,
    },
    Frictionless,
    Viscous(f64),
    Coulomb(f64),
    StickSlip(f64),
    /// F = −μ N u.
    NormalViscous(f64),
}

/// The torques beyond a law's friction by numbers (`ContactTorques`): resistances and
/// pivoting friction ℓ_p.
#[derive(Clone, Copy, Debug, Default)]
pub struct NumTorques {
    pub cr: Option<f64>,
    pub cs: Option<f64>,
    pub pivoting: Option<f64>,
}

/// A body on a table by numbers.
#[derive(Clone, Copy, Debug)]
pub struct NumBody {
    pub mass: f64,
    pub center: [f64; 3],
    pub inertia: [[f64; 3]; 3],
    pub surface: NumSurface,
    pub gravity: f64,
}

pub const ROLLING: NumLaw = NumLaw::Rolling { cr: None, cs: None };

/// The rattleback of Kane & Levinson (1982): ellipsoid semi-axes (0.2, 0.03, 0.02) m, its
/// centre 0.01 m above the centre of mass along the short axis z, M = 1 kg, A = 2e-4,
/// B = 1.6e-3, C = 1.7e-3 and the tensor's xy entry D = −2e-5 kg·m².
pub fn rattleback() -> NumBody {
    let d = -2e-5;
    NumBody {
        mass: 1.0,
        center: [0.0; 3],
        inertia: [[2e-4, d, 0.0], [d, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]],
        surface: NumSurface::Ellipsoid {
            c: [0.0, 0.0, 0.01],
            axes: [0.2, 0.03, 0.02],
        },
        gravity: 9.81,
    }
}

/// A ball of radius 0.1 m with its centre of mass at its centre and unequal moments.
pub fn chaplygin_ball() -> NumBody {
    NumBody {
        mass: 2.0,
        center: [0.0; 3],
        inertia: [[0.006, 0.0, 0.0], [0.0, 0.008, 0.0], [0.0, 0.0, 0.011]],
        surface: NumSurface::Sphere {
            c: [0.0; 3],
            rho: 0.1,
        },
        gravity: 9.81,
    }
}

/// A tippe-top-like sphere of radius 0.02 m, axisymmetric about z, its centre of mass
/// 0.3 ρ below the sphere's centre along −z (inverting it raises the centre of mass).
pub fn offset_sphere() -> NumBody {
    NumBody {
        mass: 0.02,
        center: [0.0, 0.0, -0.006],
        inertia: [[3.2e-6, 0.0, 0.0], [0.0, 3.2e-6, 0.0], [0.0, 0.0, 2.9e-6]],
        surface: NumSurface::Sphere {
            c: [0.0; 3],
            rho: 0.02,
        },
        gravity: 9.81,
    }
}

/// A thin uniform disk of radius ρ = 0.1 m, M = 1 kg.
pub fn thin_disk() -> NumBody {
    disk(1.0, 0.1)
}

/// A thin uniform disk of mass `m` and radius `rho` on its rim: I = M ρ²/4 (1, 1, 2).
pub fn disk(m: f64, rho: f64) -> NumBody {
    let i = m * rho * rho / 4.0;
    NumBody {
        mass: m,
        center: [0.0; 3],
        inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, 2.0 * i]],
        surface: NumSurface::DiskRim { c: [0.0; 3], rho },
        gravity: 9.81,
    }
}

/// Builds the scene of `body` under `law` (every non-zero number a parameter) and its
/// interpreted model.
pub fn model(body: &NumBody, law: NumLaw) -> ContactModel {
    try_model(body, law).unwrap()
}

/// As [`model`], the error returned.
pub fn try_model(
    body: &NumBody,
    law: NumLaw,
) -> Result<ContactModel, precess::contact::ContactError> {
    try_model_with(body, law, NumTorques::default())
}

/// As [`try_model`], under the further `torques`.
pub fn try_model_with(
    body: &NumBody,
    law: NumLaw,
    torques: NumTorques,
) -> Result<ContactModel, precess::contact::ContactError> {
    let mut a = Arena::new();
    let mut values: Vec<(String, f64)> = Vec::new();
    let mut num = |a: &mut Arena, v: f64| -> ExprId { number(a, &mut values, v) };
    let mass = num(&mut a, body.mass);
    let center = body.center.map(|c| num(&mut a, c));
    let mut inertia = [[a.zero(); 3]; 3];
    // The upper triangle, each entry one parameter, mirrored.
    for (i, j) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
        inertia[i][j] = num(&mut a, body.inertia[i][j]);
        inertia[j][i] = inertia[i][j];
    }
    let surface = match body.surface {
        NumSurface::Sphere { c, rho } => Surface::Sphere {
            center: c.map(|x| num(&mut a, x)),
            radius: num(&mut a, rho),
        },
        NumSurface::Ellipsoid { c, axes } => Surface::Ellipsoid {
            center: c.map(|x| num(&mut a, x)),
            semi_axes: axes.map(|x| num(&mut a, x)),
        },
        NumSurface::DiskRim { c, rho } => Surface::DiskRim {
            center: c.map(|x| num(&mut a, x)),
            radius: num(&mut a, rho),
        },
        NumSurface::Torus { c, big, tube } => Surface::Torus {
            center: c.map(|x| num(&mut a, x)),
            radius: num(&mut a, big),
            tube: num(&mut a, tube),
        },
        NumSurface::Paraboloid { v, big } => Surface::Paraboloid {
            vertex: v.map(|x| num(&mut a, x)),
            curvature_radius: num(&mut a, big),
        },
    };
    let gravity = num(&mut a, body.gravity);
    let law = match law {
        NumLaw::Rolling { cr, cs } => ContactLaw::Rolling {
            rolling_resistance: cr.map(|c| a.parameter_valued(&mut values, "cr", c)),
            spin_resistance: cs.map(|c| a.parameter_valued(&mut values, "cs", c)),
        },
        NumLaw::Frictionless => ContactLaw::Sliding(Friction::Frictionless),
        NumLaw::Viscous(c) => {
            ContactLaw::Sliding(Friction::Viscous(a.parameter_valued(&mut values, "c", c)))
        }
        NumLaw::Coulomb(mu) => {
            ContactLaw::Sliding(Friction::Coulomb(a.parameter_valued(&mut values, "mu", mu)))
        }
        NumLaw::StickSlip(mu) => ContactLaw::StickSlip {
            mu: a.parameter_valued(&mut values, "mu", mu),
        },
        NumLaw::NormalViscous(mu) => ContactLaw::Sliding(Friction::NormalViscous(
            a.parameter_valued(&mut values, "mu", mu),
        )),
    };
    let torques = ContactTorques {
        rolling_resistance: torques
            .cr
            .map(|c| a.parameter_valued(&mut values, "cr_extra", c)),
        spin_resistance: torques
            .cs
            .map(|c| a.parameter_valued(&mut values, "cs_extra", c)),
        pivoting: torques
            .pivoting
            .map(|c| a.parameter_valued(&mut values, "pivoting", c)),
        user: None,
    };
    let scene = ContactScene {
        mass,
        center,
        inertia,
        surface,
        law,
        gravity,
    };
    let d = scene.derive_with(&mut a, &torques)?;
    let pairs: Vec<(&str, f64)> = values.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    ContactModel::new(&mut a, &d, &pairs)
}

/// A non-zero number as a fresh parameter, zero as the exact zero.
fn number(a: &mut Arena, values: &mut Vec<(String, f64)>, v: f64) -> ExprId {
    if v == 0.0 {
        return a.zero();
    }
    let name = format!("p{}", values.len());
    values.push((name.clone(), v));
    a.parameter(&name)
}

/// A parameter that is always a symbol (a coefficient tested at zero too).
trait Valued {
    fn parameter_valued(&mut self, values: &mut Vec<(String, f64)>, name: &str, v: f64) -> ExprId;
}

impl Valued for Arena {
    fn parameter_valued(&mut self, values: &mut Vec<(String, f64)>, name: &str, v: f64) -> ExprId {
        values.push((name.to_owned(), v));
        self.parameter(name)
    }
}

/// The support point s(n) and its derivative ∂s/∂n, by hand.
pub fn support(surface: &NumSurface, n: &Vector3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
    match *surface {
        NumSurface::Sphere { c, rho } => (Vector3::from(c) + rho * n, Matrix3::identity() * rho),
        NumSurface::Ellipsoid { c, axes } => {
            let d2 =
                Matrix3::from_diagonal(&Vector3::from(axes).component_mul(&Vector3::from(axes)));
            let d2n = d2 * n;
            let q = n.dot(&d2n);
            let s = Vector3::from(c) + d2n / q.sqrt();
            let ds = d2 / q.sqrt() - d2n * d2n.transpose() / q.powf(1.5);
            (s, ds)
        }
        NumSurface::DiskRim { c, rho } => {
            let (p, dp) = rim(n);
            (Vector3::from(c) + rho * p, rho * dp)
        }
        NumSurface::Torus { c, big, tube } => {
            let (p, dp) = rim(n);
            (
                Vector3::from(c) + big * p + tube * n,
                big * dp + tube * Matrix3::identity(),
            )
        }
        NumSurface::Paraboloid { v, big } => {
            let (n1, n2, n3) = (n.x, n.y, n.z);
            let s = Vector3::from(v)
                + Vector3::new(
                    -big * n1 / n3,
                    -big * n2 / n3,
                    big * (n1 * n1 + n2 * n2) / (2.0 * n3 * n3),
                );
            let ds = Matrix3::new(
                -big / n3,
                0.0,
                big * n1 / (n3 * n3),
                0.0,
                -big / n3,
                big * n2 / (n3 * n3),
                big * n1 / (n3 * n3),
                big * n2 / (n3 * n3),
                -big * (n1 * n1 + n2 * n2) / (n3 * n3 * n3),
            );
            (s, ds)
        }
    }
}

/// The unit vector P n/|P n| of the disk's plane and its derivative.
fn rim(n: &Vector3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
    let p = Vector3::new(n.x, n.y, 0.0);
    let len = p.norm();
    let proj = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0));
    (p / len, proj / len - p * p.transpose() / len.powi(3))
}

/// What the Newton–Euler reference gives at a state: ω̇ (body axes), the horizontal
/// acceleration of the centre of mass and the contact force (space axes).
#[derive(Clone, Copy, Debug)]
pub struct Reference {
    pub omega_dot: Vector3<f64>,
    pub accel: Vector3<f64>,
    pub force: Vector3<f64>,
}

fn skew(v: &Vector3<f64>) -> Matrix3<f64> {
    v.cross_matrix()
}

/// What both Newton–Euler solves read of the state (space axes): the attitude R, Ω, the
/// contact point ρ from the centre of mass and its rate, I_s and Ω × I_s Ω.
struct Kinematics {
    r_mat: Matrix3<f64>,
    omega: Vector3<f64>,
    rho: Vector3<f64>,
    rho_dot: Vector3<f64>,
    i_s: Matrix3<f64>,
    gyro: Vector3<f64>,
}

fn kinematics(body: &NumBody, y: &[f64; STATE_LEN]) -> Kinematics {
    let r_mat = attitude_of(y).to_rotation_matrix().into_inner();
    let omega_b = Vector3::new(y[layout::OMEGA], y[layout::OMEGA + 1], y[layout::OMEGA + 2]);
    let omega = r_mat * omega_b;
    let gamma = r_mat.transpose() * Vector3::z();
    let (s, ds) = support(&body.surface, &(-gamma));
    let r_b = s - Vector3::from(body.center);
    // ṙ (body) = (∂r/∂γ) γ̇ = −(∂s/∂n) γ̇, γ̇ = γ × ω.
    let r_dot_b = -ds * gamma.cross(&omega_b);
    let rho = r_mat * r_b;
    let rho_dot = omega.cross(&rho) + r_mat * r_dot_b;
    let inertia_b = Matrix3::from_fn(|i, j| body.inertia[i][j]);
    let i_s = r_mat * inertia_b * r_mat.transpose();
    let gyro = omega.cross(&(i_s * omega));
    Kinematics {
        r_mat,
        omega,
        rho,
        rho_dot,
        i_s,
        gyro,
    }
}

/// Newton–Euler in space axes: M a = F − M g ẑ, I_s Ω̇ + Ω × I_s Ω = ρ × F, with the
/// contact point's material velocity u = v + Ω × ρ held at zero (rolling: all three
/// components, differentiated along the moving contact: a = −Ω̇ × ρ − Ω × ρ̇) or at zero
/// vertically (sliding: the vertical component only, and F = F₀ + N e from the friction law).
pub fn newton_euler(body: &NumBody, law: NumLaw, y: &[f64; STATE_LEN]) -> Reference {
    newton_euler_pivoting(body, law, None, y)
}

/// As [`newton_euler`], with pivoting friction −ℓ_p N sign(Ω_z) ẑ when `pivoting` is given
/// (N the unknown normal force, so its coefficient joins the solve's matrix).
pub fn newton_euler_pivoting(
    body: &NumBody,
    law: NumLaw,
    pivoting: Option<f64>,
    y: &[f64; STATE_LEN],
) -> Reference {
    let Kinematics {
        r_mat,
        omega,
        rho,
        rho_dot,
        i_s,
        gyro,
    } = kinematics(body, y);
    let (m, g, z) = (body.mass, body.gravity, Vector3::z());
    // The pivoting torque per newton of N, about ẑ: −ℓ_p sign(Ω_z).
    let pivot = -pivoting.unwrap_or(0.0) * omega.z.signum();
    match law {
        NumLaw::Rolling { cr, cs } => {
            // Resistance torques: −c_r Ω_∥ − c_s Ω_⊥ about the vertical.
            let perp = z * omega.z;
            let tau = -cr.unwrap_or(0.0) * (omega - perp) - cs.unwrap_or(0.0) * perp;
            let mut a = DMatrix::<f64>::zeros(6, 6);
            let mut b = DVector::<f64>::zeros(6);
            // M (ρ × Ω̇) − F = M Ω × ρ̇ − M g ẑ.
            a.view_mut((0, 0), (3, 3)).copy_from(&(m * skew(&rho)));
            a.view_mut((0, 3), (3, 3))
                .copy_from(&(-Matrix3::identity()));
            b.rows_mut(0, 3)
                .copy_from(&(m * omega.cross(&rho_dot) - m * g * z));
            // I_s Ω̇ − ρ × F = −Ω × I_s Ω + τ.
            a.view_mut((3, 0), (3, 3)).copy_from(&i_s);
            a.view_mut((3, 3), (3, 3)).copy_from(&(-skew(&rho)));
            b.rows_mut(3, 3).copy_from(&(-gyro + tau));
            a[(5, 5)] -= pivot;
            let x = a.lu().solve(&b).unwrap();
            let omega_dot = Vector3::new(x[0], x[1], x[2]);
            let force = Vector3::new(x[3], x[4], x[5]);
            Reference {
                omega_dot: r_mat.transpose() * omega_dot,
                accel: (force - m * g * z) / m,
                force,
            }
        }
        _ => {
            let vz = -omega.cross(&rho).z;
            let v = Vector3::new(y[layout::VELOCITY], y[layout::VELOCITY + 1], vz);
            let u = v + omega.cross(&rho);
            let (f0, e) = match law {
                NumLaw::Viscous(c) => (-c * u, z),
                NumLaw::Coulomb(mu) => (Vector3::zeros(), z - mu * u / u.norm()),
                NumLaw::NormalViscous(mu) => (Vector3::zeros(), z - mu * u),
                _ => (Vector3::zeros(), z),
            };
            let mut a = DMatrix::<f64>::zeros(4, 4);
            let mut b = DVector::<f64>::zeros(4);
            // Vertical: M (ρ × Ω̇)_z − e_z N = M (Ω × ρ̇)_z + F₀_z − M g.
            let row = m * skew(&rho).row(2);
            for j in 0..3 {
                a[(0, j)] = row[j];
            }
            a[(0, 3)] = -e.z;
            b[0] = m * omega.cross(&rho_dot).z + f0.z - m * g;
            // I_s Ω̇ − (ρ × e) N = −Ω × I_s Ω + ρ × F₀.
            a.view_mut((1, 0), (3, 3)).copy_from(&i_s);
            let re = rho.cross(&e);
            for i in 0..3 {
                a[(1 + i, 3)] = -re[i];
            }
            a[(3, 3)] -= pivot;
            b.rows_mut(1, 3).copy_from(&(-gyro + rho.cross(&f0)));
            let x = a.lu().solve(&b).unwrap();
            let omega_dot = Vector3::new(x[0], x[1], x[2]);
            let force = f0 + x[3] * e;
            Reference {
                omega_dot: r_mat.transpose() * omega_dot,
                accel: (force - m * g * z) / m,
                force,
            }
        }
    }
}

/// A state array from its parts, (vx, vy) as given.
pub fn state(
    position: [f64; 2],
    velocity: [f64; 2],
    attitude: &UnitQuaternion<f64>,
    omega: &Vector3<f64>,
) -> [f64; STATE_LEN] {
    let q = attitude.quaternion();
    [
        position[0],
        position[1],
        velocity[0],
        velocity[1],
        q.w,
        q.i,
        q.j,
        q.k,
        omega.x,
        omega.y,
        omega.z,
    ]
}

/// Newton–Euler with the spin about the vertical held: as [`newton_euler`] under `law`
/// (rolling, or sliding under F = −μ N u), with a couple λ ẑ among the unknowns and the row
/// Ω̇_z = 0 (Ω·ẑ = ω·γ, and ẑ is fixed in space) added to the solve. Returns the reference
/// and λ.
pub fn newton_euler_held(body: &NumBody, law: NumLaw, y: &[f64; STATE_LEN]) -> (Reference, f64) {
    let Kinematics {
        r_mat,
        omega,
        rho,
        rho_dot,
        i_s,
        gyro,
    } = kinematics(body, y);
    let (m, g, z) = (body.mass, body.gravity, Vector3::z());
    match law {
        NumLaw::Rolling { .. } | NumLaw::StickSlip(_) => {
            // Unknowns Ω̇ (3), F (3), λ.
            let mut a = DMatrix::<f64>::zeros(7, 7);
            let mut b = DVector::<f64>::zeros(7);
            a.view_mut((0, 0), (3, 3)).copy_from(&(m * skew(&rho)));
            a.view_mut((0, 3), (3, 3))
                .copy_from(&(-Matrix3::identity()));
            b.rows_mut(0, 3)
                .copy_from(&(m * omega.cross(&rho_dot) - m * g * z));
            // I_s Ω̇ − ρ × F − λ ẑ = −Ω × I_s Ω.
            a.view_mut((3, 0), (3, 3)).copy_from(&i_s);
            a.view_mut((3, 3), (3, 3)).copy_from(&(-skew(&rho)));
            a[(5, 6)] = -1.0;
            b.rows_mut(3, 3).copy_from(&(-gyro));
            a[(6, 2)] = 1.0;
            let x = a.lu().solve(&b).unwrap();
            let force = Vector3::new(x[3], x[4], x[5]);
            let reference = Reference {
                omega_dot: r_mat.transpose() * Vector3::new(x[0], x[1], x[2]),
                accel: (force - m * g * z) / m,
                force,
            };
            (reference, x[6])
        }
        _ => {
            let vz = -omega.cross(&rho).z;
            let v = Vector3::new(y[layout::VELOCITY], y[layout::VELOCITY + 1], vz);
            let u = v + omega.cross(&rho);
            let e = match law {
                NumLaw::NormalViscous(mu) => z - mu * u,
                NumLaw::Coulomb(mu) => z - mu * u / u.norm(),
                _ => z,
            };
            // Unknowns Ω̇ (3), N, λ.
            let mut a = DMatrix::<f64>::zeros(5, 5);
            let mut b = DVector::<f64>::zeros(5);
            let row = m * skew(&rho).row(2);
            for j in 0..3 {
                a[(0, j)] = row[j];
            }
            a[(0, 3)] = -e.z;
            b[0] = m * omega.cross(&rho_dot).z - m * g;
            a.view_mut((1, 0), (3, 3)).copy_from(&i_s);
            let re = rho.cross(&e);
            for i in 0..3 {
                a[(1 + i, 3)] = -re[i];
            }
            a[(3, 4)] = -1.0;
            b.rows_mut(1, 3).copy_from(&(-gyro));
            a[(4, 2)] = 1.0;
            let x = a.lu().solve(&b).unwrap();
            let force = x[3] * e;
            let reference = Reference {
                omega_dot: r_mat.transpose() * Vector3::new(x[0], x[1], x[2]),
                accel: (force - m * g * z) / m,
                force,
            };
            (reference, x[4])
        }
    }
}
