//! An independent recursive Newton–Euler algorithm in f64: each joint becomes a chain of
//! one-coordinate revolute or prismatic links (a universal two, a spherical the three
//! elementary rotations of its sequence) with massless links between, kinematics forward
//! from the ground in ground axes, forces backward. M by unit accelerations, the bias at
//! q̈ = 0, and q̈ = M⁻¹ (Q − bias).

use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Unit, Vector3};
use precess::rigid::AngleSequence;

use super::{NumJoint, NumMechanism};

#[derive(Clone, Copy)]
enum Motion {
    Turn,
    Slide,
}

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

/// q̈ from M q̈ = Q − bias, Q the joint springs, dampers and efforts.
pub fn accelerations(m: &NumMechanism, q: &[f64], qd: &[f64]) -> Vec<f64> {
    let n = q.len();
    let zero = vec![0.0; n];
    let mut mass = DMatrix::zeros(n, n);
    for j in 0..n {
        let mut e = zero.clone();
        e[j] = 1.0;
        let col = inverse_dynamics(m, q, &zero, &e, false);
        for i in 0..n {
            mass[(i, j)] = col[i];
        }
    }
    let bias = inverse_dynamics(m, q, qd, &zero, true);
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
