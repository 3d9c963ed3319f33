//! An independent recursive Newton–Euler algorithm in f64: each joint becomes a chain of
//! one-coordinate revolute or prismatic links (a universal two, a spherical the three
//! elementary rotations of its sequence) with massless links between, kinematics forward
//! from the ground in ground axes, forces backward. M by unit accelerations, the bias at
//! q̈ = 0, and q̈ = M⁻¹ (Q − bias). Also what the tests judge the derived q̈ with: its
//! Jacobian by differences, the mass matrix's condition and the backward error.

use precess::nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Unit, Vector3};
use precess::rigid::AngleSequence;

use super::{NumJoint, NumMechanism};

#[derive(Clone, Copy)]
enum Motion {
    Turn,
    Slide,
}

/// One coordinate's link: a turn about or a slide along `axis` (the parent's axes) at `at`.
struct Link {
    parent: Option<usize>,
    at: Vector3<f64>,
    axis: Unit<Vector3<f64>>,
    motion: Motion,
    coordinate: usize,
    /// The body whose mass this link carries (the last link of its joint).
    body: Option<usize>,
}

fn links(m: &NumMechanism) -> Vec<Link> {
    let mut out: Vec<Link> = Vec::new();
    let mut last_link_of_body = vec![0usize; m.bodies.len()];
    let mut coordinate = 0;
    // Bodies may be listed children first: place parents first.
    let mut order: Vec<usize> = Vec::new();
    while order.len() < m.bodies.len() {
        for (i, b) in m.bodies.iter().enumerate() {
            let ready = b.parent.is_none_or(|p| order.contains(&p));
            if ready && !order.contains(&i) {
                order.push(i);
            }
        }
    }
    let mut offsets = vec![0; m.bodies.len()];
    for (i, b) in m.bodies.iter().enumerate() {
        offsets[i] = coordinate;
        coordinate += b.joint.dof();
    }
    for &i in &order {
        let b = &m.bodies[i];
        let mut parent = b.parent.map(|p| last_link_of_body[p]);
        let unit = |v: [f64; 3]| Unit::new_normalize(Vector3::from(v));
        let steps: Vec<(Unit<Vector3<f64>>, Motion)> = match &b.joint {
            NumJoint::Revolute(a) => vec![(unit(*a), Motion::Turn)],
            NumJoint::Prismatic(a) => vec![(unit(*a), Motion::Slide)],
            NumJoint::Universal(a, c) => vec![(unit(*a), Motion::Turn), (unit(*c), Motion::Turn)],
            NumJoint::Spherical(s) => {
                let e = |k: usize| {
                    let mut v = [0.0; 3];
                    v[k] = 1.0;
                    unit(v)
                };
                let axes = match s {
                    AngleSequence::Zxz => [2, 0, 2],
                    AngleSequence::Zyx => [2, 1, 0],
                };
                axes.iter().map(|&k| (e(k), Motion::Turn)).collect()
            }
        };
        let count = steps.len();
        for (k, (axis, motion)) in steps.into_iter().enumerate() {
            let at = if k == 0 {
                Vector3::from(b.at)
            } else {
                Vector3::zeros()
            };
            out.push(Link {
                parent,
                at,
                axis,
                motion,
                coordinate: offsets[i] + k,
                body: (k + 1 == count).then_some(i),
            });
            parent = Some(out.len() - 1);
        }
        last_link_of_body[i] = out.len() - 1;
    }
    out
}

/// A link's frame in ground axes: its attitude, origin and their rates.
struct Frame {
    rotation: Matrix3<f64>,
    origin: Vector3<f64>,
    omega: Vector3<f64>,
    alpha: Vector3<f64>,
    velocity: Vector3<f64>,
    acceleration: Vector3<f64>,
}

/// The generalised forces that produce q̈ at (q, q̇), with gravity and external torques when
/// `loads` (inverse dynamics).
pub fn inverse_dynamics(
    m: &NumMechanism,
    q: &[f64],
    qd: &[f64],
    qdd: &[f64],
    loads: bool,
) -> Vec<f64> {
    let links = links(m);
    let ground = Frame {
        rotation: Matrix3::identity(),
        origin: Vector3::zeros(),
        omega: Vector3::zeros(),
        alpha: Vector3::zeros(),
        velocity: Vector3::zeros(),
        acceleration: Vector3::zeros(),
    };
    let mut frames: Vec<Frame> = Vec::with_capacity(links.len());
    for l in &links {
        let p = l.parent.map_or(&ground, |p| &frames[p]);
        let (qi, vi, ai) = (q[l.coordinate], qd[l.coordinate], qdd[l.coordinate]);
        let axis = p.rotation * l.axis.into_inner();
        let (rotation, offset) = match l.motion {
            Motion::Turn => (
                p.rotation * Rotation3::from_axis_angle(&l.axis, qi).into_inner(),
                l.at,
            ),
            Motion::Slide => (p.rotation, l.at + l.axis.into_inner() * qi),
        };
        let r = p.rotation * offset;
        let origin = p.origin + r;
        let mut velocity = p.velocity + p.omega.cross(&r);
        let mut acceleration =
            p.acceleration + p.alpha.cross(&r) + p.omega.cross(&p.omega.cross(&r));
        let (mut omega, mut alpha) = (p.omega, p.alpha);
        match l.motion {
            Motion::Turn => {
                omega += axis * vi;
                alpha += axis * ai + p.omega.cross(&(axis * vi));
            }
            Motion::Slide => {
                velocity += axis * vi;
                acceleration += axis * ai + 2.0 * p.omega.cross(&(axis * vi));
            }
        }
        frames.push(Frame {
            rotation,
            origin,
            omega,
            alpha,
            velocity,
            acceleration,
        });
    }
    let g = Vector3::from(m.gravity);
    let mut force = vec![Vector3::zeros(); links.len()];
    let mut moment = vec![Vector3::zeros(); links.len()]; // about the link's origin
    for (i, l) in links.iter().enumerate() {
        let Some(b) = l.body else { continue };
        let body = &m.bodies[b];
        let f = &frames[i];
        let arm = f.rotation * Vector3::from(body.center);
        let a_c = f.acceleration + f.alpha.cross(&arm) + f.omega.cross(&f.omega.cross(&arm));
        let inertia = f.rotation * body.inertia * f.rotation.transpose();
        let mut fi = body.mass * a_c;
        let mut ni = inertia * f.alpha + f.omega.cross(&(inertia * f.omega));
        if loads {
            fi -= body.mass * g;
            if let Some(t) = body.body_torque {
                ni -= f.rotation * Vector3::from(t);
            }
            if let Some(t) = body.space_torque {
                ni -= Vector3::from(t);
            }
        }
        force[i] = fi;
        moment[i] = ni + arm.cross(&fi);
    }
    let mut tau = vec![0.0; q.len()];
    for i in (0..links.len()).rev() {
        let l = &links[i];
        let p = l.parent.map_or(&ground, |p| &frames[p]);
        let axis = p.rotation * l.axis.into_inner();
        tau[l.coordinate] = match l.motion {
            Motion::Turn => axis.dot(&moment[i]),
            Motion::Slide => axis.dot(&force[i]),
        };
        if let Some(pi) = l.parent {
            let r = frames[i].origin - frames[pi].origin;
            let (fi, ni) = (force[i], moment[i]);
            force[pi] += fi;
            moment[pi] += ni + r.cross(&fi);
        }
    }
    tau
}

/// The mass matrix at q: column j is the inverse dynamics of q̈ = e_j without bias.
pub fn mass_matrix(m: &NumMechanism, q: &[f64]) -> DMatrix<f64> {
    let n = q.len();
    let zero = vec![0.0; n];
    let mut mass = DMatrix::zeros(n, n);
    for j in 0..n {
        let mut e = zero.clone();
        e[j] = 1.0;
        let column = inverse_dynamics(m, q, &zero, &e, false);
        for (i, v) in column.iter().enumerate() {
            mass[(i, j)] = *v;
        }
    }
    mass
}

/// q̈ from M q̈ = Q − bias, Q the joint springs, dampers and efforts.
///
/// # Panics
/// If the mass matrix is singular at q (a test's state drawn where it must not be).
pub fn accelerations(m: &NumMechanism, q: &[f64], qd: &[f64]) -> Vec<f64> {
    let n = q.len();
    let mass = mass_matrix(m, q);
    let bias = inverse_dynamics(m, q, qd, &vec![0.0; n], true);
    let mut rhs = DVector::zeros(n);
    let mut k = 0;
    for b in &m.bodies {
        for load in &b.loads {
            let mut f = -bias[k];
            if let Some((s, rest)) = load.spring {
                f -= s * (q[k] - rest);
            }
            if let Some(c) = load.damper {
                f -= c * qd[k];
            }
            if let Some(e) = load.effort {
                f += e;
            }
            rhs[k] = f;
            k += 1;
        }
    }
    let x = mass.lu().solve(&rhs).expect("regular mass matrix");
    x.iter().copied().collect()
}

/// ∂q̈/∂(q, q̇) (n × 2n) of [`accelerations`] by the five-point stencil (f(−2h) − 8 f(−h) +
/// 8 f(h) − f(2h)) / 12h: truncation h⁴ f⁽⁵⁾/30, rounding ≈ ε |q̈| / h; at h = 1e-3 both
/// ≈ 1e-13 relative for a smooth q̈.
pub fn acceleration_jacobian(m: &NumMechanism, q: &[f64], qd: &[f64], h: f64) -> DMatrix<f64> {
    let n = q.len();
    let state: Vec<f64> = q.iter().chain(qd).copied().collect();
    let mut jacobian = DMatrix::zeros(n, 2 * n);
    for j in 0..2 * n {
        let shifted = |k: f64| {
            let mut y = state.clone();
            y[j] += k * h;
            accelerations(m, &y[..n], &y[n..])
        };
        let (m2, m1, p1, p2) = (shifted(-2.0), shifted(-1.0), shifted(1.0), shifted(2.0));
        for i in 0..n {
            jacobian[(i, j)] = (m2[i] - 8.0 * m1[i] + 8.0 * p1[i] - p2[i]) / (12.0 * h);
        }
    }
    jacobian
}

/// The 2-norm condition number σ_max / σ_min of a symmetric mass matrix, its singular
/// values being its eigenvalues' moduli (infinite when singular). The eigenvalues by cyclic
/// Jacobi rotations, to sweeps that leave the off-diagonal below 1e-14 of the matrix's size
/// (above its rounding floor): each eigenvalue then moves by less than that (Weyl), 1e-10 of
/// the smallest a condition of 1e4 allows. nalgebra's SVD, compiled optimised here, was
/// 10 s of the testkit's build.
pub fn condition(mass: &DMatrix<f64>) -> f64 {
    let n = mass.nrows();
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| mass[(i, j)]).collect())
        .collect();
    let size: f64 = a.iter().flatten().map(|x| x * x).sum::<f64>().sqrt();
    for _sweep in 0..64 {
        let off: f64 = (0..n)
            .flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum::<f64>()
            .sqrt();
        if off <= 1e-14 * size {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                // The rotation in the (p, q) plane that zeroes a_pq (Golub & Van Loan 8.5.2).
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + theta.hypot(1.0));
                let c = 1.0 / t.hypot(1.0);
                let s = t * c;
                for row in a.iter_mut() {
                    let (x, y) = (row[p], row[q]);
                    row[p] = c * x - s * y;
                    row[q] = s * x + c * y;
                }
                let (head, tail) = a.split_at_mut(q);
                for (x, y) in head[p].iter_mut().zip(tail[0].iter_mut()) {
                    (*x, *y) = (c * *x - s * *y, s * *x + c * *y);
                }
            }
        }
    }
    let moduli = (0..n).map(|i| a[i][i].abs());
    let (lo, hi) = moduli.fold((f64::INFINITY, 0.0_f64), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    hi / lo
}

/// The backward error of a q̈ against the reference's: |M (q̈ − q̈_ref)|∞ / max(| |M|
/// |q̈_ref| |∞, 1), the residual against the size of the terms whose rounding any
/// algorithm's M q̈ carries.
pub fn backward_error(mass: &DMatrix<f64>, qdd: &[f64], reference: &[f64]) -> f64 {
    let n = qdd.len();
    let error = DVector::from_iterator(n, qdd.iter().zip(reference).map(|(a, b)| a - b));
    let scale = mass.abs() * DVector::from_iterator(n, reference.iter().map(|a| a.abs()));
    (mass * error).amax() / scale.amax().max(1.0)
}

/// Each body's frame at q, in body order: (R_b, o_b), its axes to ground axes and its
/// origin, by the same one-coordinate links as [`inverse_dynamics`] (a joint's intermediate
/// links carry no body), each link's rotation the product of its parent's and the
/// elementary or axis-angle turn of its own coordinate.
pub fn body_frames(m: &NumMechanism, q: &[f64]) -> Vec<(Matrix3<f64>, Vector3<f64>)> {
    let links = links(m);
    let mut frames: Vec<(Matrix3<f64>, Vector3<f64>)> = Vec::with_capacity(links.len());
    let mut bodies = vec![(Matrix3::identity(), Vector3::zeros()); m.bodies.len()];
    for l in &links {
        let (r_p, o_p) = l
            .parent
            .map_or((Matrix3::identity(), Vector3::zeros()), |p| frames[p]);
        let qi = q[l.coordinate];
        let frame = match l.motion {
            Motion::Turn => (
                r_p * Rotation3::from_axis_angle(&l.axis, qi).into_inner(),
                o_p + r_p * l.at,
            ),
            Motion::Slide => (r_p, o_p + r_p * (l.at + l.axis.into_inner() * qi)),
        };
        if let Some(b) = l.body {
            bodies[b] = frame;
        }
        frames.push(frame);
    }
    bodies
}
