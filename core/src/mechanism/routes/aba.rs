//! A generic numeric articulated-body algorithm (Featherstone's ABA, O(n)) over a mechanism
//! scene with its parameters bound: the reference the generated code is benchmarked and
//! tested against.

use nalgebra::{Matrix3, Vector3};

use super::recursive::{Motion, flatten};
use crate::mechanism::{
    JointKind, MechanismError, MechanismScene, check_axis, check_universal_axes,
};
use crate::sym::{Arena, ExprId};

/// One link with its constants evaluated.
#[derive(Clone, Debug)]
struct NumericLink {
    parent: Option<usize>,
    turn: bool,
    axis: Vector3<f64>,
    at: Vector3<f64>,
    coordinate: usize,
    mass: f64,
    first_moment: Vector3<f64>,
    inertia_origin: Matrix3<f64>,
    body_torque: Vector3<f64>,
    space_torque: Option<Vector3<f64>>,
}

/// The per-link scratch of one evaluation (allocated once, in [`MechanismAba::new`]).
#[derive(Clone, Debug, Default)]
struct Scratch {
    rotation: Matrix3<f64>,
    origin: Vector3<f64>,
    to_ground: Matrix3<f64>,
    w: Vector3<f64>,
    v: Vector3<f64>,
    cw: Vector3<f64>,
    cv: Vector3<f64>,
    a: Matrix3<f64>,
    b: Matrix3<f64>,
    c: Matrix3<f64>,
    pn: Vector3<f64>,
    pf: Vector3<f64>,
    un: Vector3<f64>,
    uf: Vector3<f64>,
    d: f64,
    u: f64,
    aw: Vector3<f64>,
    av: Vector3<f64>,
}

/// Per-coordinate joint loads, evaluated: −k (q − rest) − c q̇ + effort.
#[derive(Clone, Copy, Debug, Default)]
struct NumericLoad {
    stiffness: f64,
    rest: f64,
    damping: f64,
    effort: f64,
}

/// The articulated-body algorithm in f64 for one mechanism with its parameters bound.
///
/// Multi-dof joints are chains of revolutes through massless frames, as on the symbolic
/// recursive route; each evaluation costs O(n) and allocates nothing.
///
/// # Examples
/// ```
/// use precess_core::mechanism::{JointKind, MechanismAba, MechanismScene, Parent};
/// use precess_core::sym::Arena;
/// // A point mass 2 kg at 0.5 m on a massless rod, gravity −9.81 ŷ: θ̈ = −(g/l) cos θ.
/// let mut a = Arena::new();
/// let (z, o) = (a.zero(), a.one());
/// let mut scene = MechanismScene::new();
/// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground,
///     JointKind::Revolute { axis: [z, z, o] }, &["theta"]);
/// bob.mass = a.integer(2);
/// bob.center = [a.number("0.5").unwrap(), z, z];
/// scene.bodies.push(bob);
/// scene.gravity = Some([z, a.number("-9.81").unwrap(), z]);
/// let mut aba = MechanismAba::new(&mut a, &scene, &[]).unwrap();
/// let mut qdd = [0.0];
/// aba.accelerations(&[0.3], &[1.0], &mut qdd).unwrap();
/// approx::assert_relative_eq!(qdd[0], -9.81 / 0.5 * 0.3f64.cos(), max_relative = 1e-14);
/// ```
#[derive(Clone, Debug)]
pub struct MechanismAba {
    links: Vec<NumericLink>,
    loads: Vec<NumericLoad>,
    gravity: Vector3<f64>,
    scratch: Vec<Scratch>,
    pivots: Vec<f64>,
}

fn value(
    arena: &Arena,
    e: ExprId,
    env: &[f64],
    quantity: &'static str,
) -> Result<f64, MechanismError> {
    let x = arena.eval(e, env);
    if x.is_finite() {
        Ok(x)
    } else {
        Err(MechanismError::NonFinite {
            quantity,
            values: vec![x],
        })
    }
}

fn vector(
    arena: &Arena,
    v: &[ExprId; 3],
    env: &[f64],
    quantity: &'static str,
) -> Result<Vector3<f64>, MechanismError> {
    Ok(Vector3::new(
        value(arena, v[0], env, quantity)?,
        value(arena, v[1], env, quantity)?,
        value(arena, v[2], env, quantity)?,
    ))
}

fn cross_matrix(x: &Vector3<f64>) -> Matrix3<f64> {
    x.cross_matrix()
}

impl MechanismAba {
    /// The algorithm for `scene` with each symbol `s` bound to `env[s.index()]` (parameters,
    /// and the inputs that stand for efforts; missing entries are NaN and refused).
    ///
    /// # Errors
    /// A malformed tree as for [`crate::mechanism::recursive_accelerations`];
    /// [`MechanismError::NonFinite`] for a constant that evaluates to NaN or ±∞;
    /// [`MechanismError::ZeroAxis`] for an axis with no direction at these values and
    /// [`MechanismError::ParallelAxes`] for a universal joint's parallel axes (the rules of
    /// [`crate::mechanism::check_universal_axes`]).
    pub fn new(
        arena: &mut Arena,
        scene: &MechanismScene,
        env: &[f64],
    ) -> Result<MechanismAba, MechanismError> {
        // The rules of `check_axis` and `check_universal_axes`, as for every other path.
        for b in &scene.bodies {
            let joint = b.joint.name.as_str();
            let numeric = |axis: &[ExprId; 3]| -> Result<[f64; 3], MechanismError> {
                let v = vector(arena, axis, env, "joint axis")?;
                Ok([v.x, v.y, v.z])
            };
            match &b.joint.kind {
                JointKind::Revolute { axis } | JointKind::Prismatic { axis } => {
                    check_axis(joint, "axis", numeric(axis)?)?;
                }
                JointKind::Universal { axes } => {
                    let (outer, inner) = (numeric(&axes[0])?, numeric(&axes[1])?);
                    check_universal_axes(joint, outer, inner)?;
                }
                JointKind::Spherical { .. } | JointKind::Free { .. } => {}
            }
        }
        let (symbolic, _) = flatten(arena, scene)?;
        let mut links = Vec::with_capacity(symbolic.len());
        for l in &symbolic {
            let mut link = NumericLink {
                parent: l.parent,
                turn: l.motion == Motion::Turn,
                axis: vector(arena, &l.axis, env, "joint axis")?,
                at: vector(arena, &l.at, env, "joint location")?,
                coordinate: l.coordinate,
                mass: 0.0,
                first_moment: Vector3::zeros(),
                inertia_origin: Matrix3::zeros(),
                body_torque: Vector3::zeros(),
                space_torque: None,
            };
            if let Some(b) = l.body.and_then(|b| scene.bodies.get(b)) {
                let m = value(arena, b.mass, env, "mass")?;
                let c = vector(arena, &b.center, env, "centre of mass")?;
                let mut ig = Matrix3::zeros();
                for i in 0..3 {
                    for j in 0..3 {
                        ig[(i, j)] = value(arena, b.inertia[i][j], env, "inertia")?;
                    }
                }
                link.mass = m;
                link.first_moment = c * m;
                link.inertia_origin =
                    ig + (Matrix3::identity() * c.norm_squared() - c * c.transpose()) * m;
                if let Some(t) = &b.body_torque {
                    link.body_torque = vector(arena, t, env, "body torque")?;
                }
                if let Some(t) = &b.space_torque {
                    link.space_torque = Some(vector(arena, t, env, "space torque")?);
                }
            }
            links.push(link);
        }
        let mut loads = Vec::with_capacity(scene.dof());
        for load in scene.bodies.iter().flat_map(|b| b.joint.loads.iter()) {
            let mut nl = NumericLoad::default();
            if let Some(s) = load.spring {
                nl.stiffness = value(arena, s.stiffness, env, "spring stiffness")?;
                nl.rest = value(arena, s.rest, env, "spring rest value")?;
            }
            if let Some(c) = load.damper {
                nl.damping = value(arena, c, env, "damping")?;
            }
            if let Some(e) = load.effort {
                nl.effort = value(arena, e, env, "effort")?;
            }
            loads.push(nl);
        }
        if loads.len() != scene.dof() {
            return Err(MechanismError::StateLength {
                quantity: "coordinate loads",
                expected: scene.dof(),
                got: loads.len(),
            });
        }
        let gravity = match &scene.gravity {
            Some(g) => vector(arena, g, env, "gravity")?,
            None => Vector3::zeros(),
        };
        let n = links.len();
        Ok(MechanismAba {
            links,
            loads,
            gravity,
            scratch: vec![Scratch::default(); n],
            pivots: vec![0.0; scene.dof()],
        })
    }

    /// The number of coordinates.
    pub fn dof(&self) -> usize {
        self.pivots.len()
    }

    /// The pivots Dᵢ = Sᵢᵀ Iᵢᴬ Sᵢ of the last evaluation, in state order.
    pub fn pivots(&self) -> &[f64] {
        &self.pivots
    }

    /// Sets the effort (generalised force) on coordinate `i`, replacing the bound value.
    ///
    /// # Errors
    /// [`MechanismError::StateLength`] if `i` is not a coordinate index.
    pub fn set_effort(&mut self, i: usize, effort: f64) -> Result<(), MechanismError> {
        let dof = self.dof();
        match self.loads.get_mut(i) {
            Some(l) => {
                l.effort = effort;
                Ok(())
            }
            None => Err(MechanismError::StateLength {
                quantity: "effort index",
                expected: dof,
                got: i,
            }),
        }
    }

    /// q̈ at (q, q̇), written into `qdd`.
    ///
    /// # Errors
    /// [`MechanismError::StateLength`] for slices of the wrong length,
    /// [`MechanismError::NonFinite`] for a non-finite state, and
    /// [`MechanismError::SingularMassMatrix`] where a pivot is not positive.
    pub fn accelerations(
        &mut self,
        q: &[f64],
        qd: &[f64],
        qdd: &mut [f64],
    ) -> Result<(), MechanismError> {
        let dof = self.dof();
        for (quantity, got) in [("q", q.len()), ("q̇", qd.len()), ("q̈", qdd.len())] {
            if got != dof {
                return Err(MechanismError::StateLength {
                    quantity,
                    expected: dof,
                    got,
                });
            }
        }
        if q.iter().chain(qd).any(|x| !x.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "state",
                values: q.iter().chain(qd).copied().collect(),
            });
        }
        let n = self.links.len();
        // Pass 1: kinematics, velocities, bias terms.
        for i in 0..n {
            let l = &self.links[i];
            let x = q[l.coordinate];
            let xd = qd[l.coordinate];
            let (rotation, origin) = if l.turn {
                let (s, c) = x.sin_cos();
                let k = l.axis;
                let r =
                    Matrix3::identity() * c + cross_matrix(&k) * s + k * k.transpose() * (1.0 - c);
                (r, l.at)
            } else {
                (Matrix3::identity(), l.at + l.axis * x)
            };
            let (pw, pv, pr) = match l.parent {
                Some(p) => (
                    self.scratch[p].w,
                    self.scratch[p].v,
                    self.scratch[p].to_ground,
                ),
                None => (Vector3::zeros(), Vector3::zeros(), Matrix3::identity()),
            };
            let rt = rotation.transpose();
            let mut w = rt * pw;
            let mut v = rt * (pv + pw.cross(&origin));
            let (sw, sv) = if l.turn {
                (l.axis * xd, Vector3::zeros())
            } else {
                (Vector3::zeros(), l.axis * xd)
            };
            w += sw;
            v += sv;
            let cw = w.cross(&sw);
            let cv = w.cross(&sv) + v.cross(&sw);
            let hx = cross_matrix(&l.first_moment);
            let n_mom = l.inertia_origin * w + l.first_moment.cross(&v);
            let f_mom = v * l.mass + w.cross(&l.first_moment);
            let to_ground = pr * rotation;
            let mut pn = w.cross(&n_mom) + v.cross(&f_mom) - l.body_torque;
            if let Some(t) = l.space_torque {
                pn -= to_ground.transpose() * t;
            }
            let pf = w.cross(&f_mom);
            let s = &mut self.scratch[i];
            s.rotation = rotation;
            s.origin = origin;
            s.to_ground = to_ground;
            s.w = w;
            s.v = v;
            s.cw = cw;
            s.cv = cv;
            s.a = l.inertia_origin;
            s.b = hx;
            s.c = Matrix3::identity() * l.mass;
            s.pn = pn;
            s.pf = pf;
        }
        // Pass 2: articulated inertias, leaves first.
        for i in (0..n).rev() {
            let l = &self.links[i];
            let load = self.loads[l.coordinate];
            let s = &self.scratch[i];
            let (un, uf) = if l.turn {
                (s.a * l.axis, s.b.transpose() * l.axis)
            } else {
                (s.b * l.axis, s.c * l.axis)
            };
            let d = if l.turn {
                l.axis.dot(&un)
            } else {
                l.axis.dot(&uf)
            };
            let sp = if l.turn {
                l.axis.dot(&s.pn)
            } else {
                l.axis.dot(&s.pf)
            };
            let tau = -load.stiffness * (q[l.coordinate] - load.rest)
                - load.damping * qd[l.coordinate]
                + load.effort;
            let u = tau - sp;
            self.pivots[l.coordinate] = d;
            if d.is_nan() || d <= 0.0 {
                return Err(MechanismError::SingularMassMatrix {
                    pivot: l.coordinate,
                    value: d,
                });
            }
            if let Some(p) = l.parent {
                let (wn, wf) = (un / d, uf / d);
                let a = s.a - wn * un.transpose();
                let b = s.b - wn * uf.transpose();
                let c = s.c - wf * uf.transpose();
                let icn = a * s.cw + b * s.cv;
                let icf = b.transpose() * s.cw + c * s.cv;
                let pn = s.pn + icn + wn * u;
                let pf = s.pf + icf + wf * u;
                let r = s.rotation;
                let px = cross_matrix(&s.origin);
                let (ra, rb, rc) = (
                    r * a * r.transpose(),
                    r * b * r.transpose(),
                    r * c * r.transpose(),
                );
                let pc = px * rc;
                let a_up = ra - rb * px + px * rb.transpose() - pc * px;
                let b_up = rb + pc;
                let f_up = r * pf;
                let n_up = r * pn + s.origin.cross(&f_up);
                let parent = &mut self.scratch[p];
                parent.a += a_up;
                parent.b += b_up;
                parent.c += rc;
                parent.pn += n_up;
                parent.pf += f_up;
            }
            let s = &mut self.scratch[i];
            s.un = un;
            s.uf = uf;
            s.d = d;
            s.u = u;
        }
        // Pass 3: accelerations, the ground at −g.
        for i in 0..n {
            let l = &self.links[i];
            let (pa_w, pa_v) = match l.parent {
                Some(p) => (self.scratch[p].aw, self.scratch[p].av),
                None => (Vector3::zeros(), -self.gravity),
            };
            let s = &self.scratch[i];
            let rt = s.rotation.transpose();
            let aw = rt * pa_w + s.cw;
            let av = rt * (pa_v + pa_w.cross(&s.origin)) + s.cv;
            let x = (s.u - s.un.dot(&aw) - s.uf.dot(&av)) / s.d;
            qdd[l.coordinate] = x;
            let s = &mut self.scratch[i];
            if l.turn {
                s.aw = aw + l.axis * x;
                s.av = av;
            } else {
                s.aw = aw;
                s.av = av + l.axis * x;
            }
        }
        Ok(())
    }
}
