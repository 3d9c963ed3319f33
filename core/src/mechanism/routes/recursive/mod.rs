//! The recursive route: Featherstone's articulated-body algorithm written over the symbolic
//! engine, so a mechanism's q̈ comes out as O(n) straight-line code with its constants folded.
//!
//! Every link works in its own frame with spatial vectors as pairs of 3-vectors
//! (`spatial`). The three passes are the textbook ones:
//!
//! 1. outward: velocities vᵢ = Xᵢ v_λ + Sᵢ q̇ᵢ, the velocity-product accelerations
//!    cᵢ = vᵢ ×ₘ Sᵢ q̇ᵢ and the bias forces pᵢ = vᵢ ×* Iᵢ vᵢ − fᵢᵉˣᵗ;
//! 2. inward: Uᵢ = Iᵢᴬ Sᵢ, the pivots Dᵢ = Sᵢᵀ Uᵢ, uᵢ = τᵢ − Sᵢᵀ pᵢᴬ, and the parent's
//!    articulated inertia and bias force gain Xᵢ* (Iᴬ − Uᵢ Uᵢᵀ/Dᵢ) Xᵢ and
//!    Xᵢ* (pᴬ + Iᵃ cᵢ + Uᵢ uᵢ/Dᵢ);
//! 3. outward: a′ᵢ = Xᵢ a_λ + cᵢ, q̈ᵢ = (uᵢ − Uᵢᵀ a′ᵢ)/Dᵢ, aᵢ = a′ᵢ + Sᵢ q̈ᵢ.
//!
//! Gravity enters as the ground's acceleration a₀ = (0, −g); body torques and space torques as
//! external forces; the joint forces (springs, dampers, efforts) as τ. Every intermediate is an
//! unexpanded expression, so hash-consing shares it and [`crate::codegen::Program::lower`]
//! emits each once: the cost is a fixed number of operations per link, fewer where the
//! constants have zeros (a planar chain keeps only its in-plane terms).
//!
//! Multi-dof joints are chains of revolutes through massless frames (see `links.rs` for why).

mod bind;
pub mod chains;
mod links;
mod spatial;

use crate::lagrange::Coordinates;
use crate::mechanism::{MechanismError, MechanismScene};
use crate::sym::mat3::{self, Mat3};
use crate::sym::{Arena, ExprId};

use bind::Binder;
pub(crate) use links::{Link, Motion, flatten};
use spatial::{Inertia, Pair, Turn, V3};

/// The accelerations of the recursive route and the pivots that must be positive.
#[derive(Clone, Debug, PartialEq)]
pub struct RecursiveForm {
    /// q̈ in state order, in q, q̇, the joint forces and the parameters.
    pub accelerations: Vec<ExprId>,
    /// The articulated-body pivots Dᵢ = Sᵢᵀ Iᵢᴬ Sᵢ in state order: the mass matrix is regular
    /// exactly where every one is non-zero, and positive definite where all are positive.
    pub pivots: Vec<ExprId>,
}

/// The joint's kinematics for one link at coordinate q: its rotation (child → parent, `None`
/// for a slide) and its origin in the parent frame.
struct Placement {
    rotation: Option<Turn>,
    origin: V3,
}

fn placement(arena: &mut Arena, binder: &mut Binder, link: &Link, q: ExprId) -> Placement {
    match link.motion {
        Motion::Turn => {
            let (s, c) = (arena.sin(q), arena.cos(q));
            Placement {
                rotation: Some(Turn::new(arena, binder, &link.axis, s, c)),
                origin: link.at,
            }
        }
        Motion::Slide => {
            let shift = spatial::scale3(arena, q, &link.axis);
            Placement {
                rotation: None,
                origin: spatial::add3(arena, &link.at, &shift),
            }
        }
    }
}

/// The motion subspace S of a link times a scalar: (k x, 0) for a turn, (0, k x) for a slide.
fn subspace(arena: &mut Arena, link: &Link, x: ExprId) -> Pair {
    let kx = spatial::scale3(arena, x, &link.axis);
    let z = [arena.zero(); 3];
    match link.motion {
        Motion::Turn => Pair { ang: kx, lin: z },
        Motion::Slide => Pair { ang: z, lin: kx },
    }
}

/// Sᵀ x for a force pair x.
fn project(arena: &mut Arena, link: &Link, x: &Pair) -> ExprId {
    match link.motion {
        Motion::Turn => mat3::dot(arena, &link.axis, &x.ang),
        Motion::Slide => mat3::dot(arena, &link.axis, &x.lin),
    }
}

/// The rigid inertia of body `b` about its frame's origin, and its first moment m c.
fn body_inertia(arena: &mut Arena, scene: &MechanismScene, b: usize) -> Inertia {
    let body = &scene.bodies[b];
    let m = body.mass;
    let c = body.center;
    let h = spatial::scale3(arena, m, &c);
    // Parallel axes: I_O = I_G + m (|c|² 1 − c cᵀ).
    let c2 = mat3::dot(arena, &c, &c);
    let mut io = body.inertia;
    for (i, row) in io.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            let cc = arena.mul(c[i], c[j]);
            let shift = if i == j {
                arena.sub(c2, cc)
            } else {
                arena.neg(cc)
            };
            let ms = arena.mul(m, shift);
            *e = arena.add(*e, ms);
        }
    }
    Inertia::rigid(arena, m, &h, &io)
}

/// The velocity-product force v ×* (I v) of body `b` moving at v (in its frame), written
/// about its centre of mass c: with the centre's velocity v_c = v + ω × c,
/// f = m ω × v_c and n = ω × I_G ω + c × f. This equals the spatial cross product with the
/// inertia about the origin (v × m v_c = −(ω × c) × m v_c and the Jacobi identity), at
/// about half its operations: the momenta about the origin are never formed.
fn velocity_product_force(
    arena: &mut Arena,
    binder: &mut Binder,
    scene: &MechanismScene,
    b: usize,
    v: &Pair,
) -> Pair {
    let body = &scene.bodies[b];
    let w = v.ang;
    let wc = mat3::cross(arena, &w, &body.center);
    let vc = spatial::add3(arena, &v.lin, &wc);
    let vc = binder.bind3(arena, &vc);
    let wvc = mat3::cross(arena, &w, &vc);
    let wvc = binder.bind3(arena, &wvc);
    let f = spatial::scale3(arena, body.mass, &wvc);
    let iw = mat3::mat_vec(arena, &body.inertia, &w);
    let gyro = mat3::cross(arena, &w, &iw);
    let cf = mat3::cross(arena, &body.center, &f);
    Pair {
        ang: spatial::add3(arena, &gyro, &cf),
        lin: f,
    }
}

/// q̈ of `scene` by the articulated-body algorithm, with `joint_forces[i]` the generalised
/// force on coordinate i (springs, dampers, efforts; gravity and the body and space torques
/// are applied here).
///
/// # Errors
/// A malformed tree, as [`MechanismScene::validate`] ([`MechanismError::NoMovingJoint`],
/// [`MechanismError::UnknownParent`], [`MechanismError::Cycle`],
/// [`MechanismError::WrongCoordinateCount`], [`MechanismError::ZeroAxis`], …);
/// [`MechanismError::StateLength`] if `coords` or `joint_forces` do not have one entry per
/// coordinate, and
/// [`MechanismError::SingularMassMatrix`] if a pivot is identically zero (a massless leaf).
///
/// # Examples
/// ```
/// use precess_core::lagrange::Coordinates;
/// use precess_core::mechanism::{JointKind, MechanismScene, Parent, recursive_accelerations};
/// use precess_core::sym::Arena;
/// // A point mass m on a massless rod of length l: θ̈ = −(g/l) sin θ.
/// let mut a = Arena::new();
/// let (z, o) = (a.zero(), a.one());
/// let (m, l, g) = (a.parameter("m"), a.parameter("l"), a.parameter("g"));
/// let mut scene = MechanismScene::new();
/// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground,
///     JointKind::Revolute { axis: [z, z, o] }, &["theta"]);
/// bob.mass = m;
/// bob.center = [l, z, z];
/// scene.bodies.push(bob);
/// let minus_g = a.neg(g);
/// scene.gravity = Some([z, minus_g, z]);
/// let coords = Coordinates::new(&mut a, &["theta"]);
/// let form = recursive_accelerations(&mut a, &scene, &coords, &[z]).unwrap();
/// let mut env = vec![0.0; a.symbol_count()];
/// let set = |a: &Arena, e: precess_core::sym::ExprId, env: &mut Vec<f64>, x: f64| {
///     env[a.as_symbol(e).unwrap().index()] = x;
/// };
/// set(&a, m, &mut env, 2.0);
/// set(&a, l, &mut env, 0.5);
/// set(&a, g, &mut env, 9.81);
/// set(&a, coords.q[0], &mut env, 0.3);
/// // θ measured from the x axis with gravity along −y: θ̈ = −(g/l) cos θ.
/// approx::assert_relative_eq!(a.eval(form.accelerations[0], &env),
///     -9.81 / 0.5 * 0.3f64.cos(), max_relative = 1e-14);
/// ```
pub fn recursive_accelerations(
    arena: &mut Arena,
    scene: &MechanismScene,
    coords: &Coordinates,
    joint_forces: &[ExprId],
) -> Result<RecursiveForm, MechanismError> {
    let dof = scene.dof();
    for (quantity, got) in [
        ("coordinates", coords.q.len()),
        ("rates", coords.rates.len()),
        ("joint forces", joint_forces.len()),
    ] {
        if got != dof {
            return Err(MechanismError::StateLength {
                quantity,
                expected: dof,
                got,
            });
        }
    }
    let (links, _) = flatten(arena, scene)?;
    let n = links.len();
    let mut binder = Binder::default();

    // Pass 1: kinematics, velocities and bias forces.
    let mut places = Vec::with_capacity(n);
    let mut velocity: Vec<Pair> = Vec::with_capacity(n);
    let mut bias_accel: Vec<Pair> = Vec::with_capacity(n);
    let mut art: Vec<Inertia> = Vec::with_capacity(n);
    let mut bias_force: Vec<Pair> = Vec::with_capacity(n);
    // Ground → link rotations, built only where a space torque needs them.
    let needs_space = scene.bodies.iter().any(|b| b.space_torque.is_some());
    let mut to_ground: Vec<Option<Mat3>> = Vec::with_capacity(n);
    for link in &links {
        let q = coords.q[link.coordinate];
        let qd = coords.rates[link.coordinate];
        let place = placement(arena, &mut binder, link, q);
        let parent_v = match link.parent {
            Some(p) => velocity[p],
            None => Pair::zero(arena),
        };
        let vj = subspace(arena, link, qd);
        let carried =
            spatial::motion_to_child(arena, place.rotation.as_ref(), &place.origin, &parent_v);
        let v = carried.add(arena, &vj);
        let v = v.bound(arena, &mut binder);
        let c = spatial::cross_motion(arena, &v, &vj);
        let c = c.bound(arena, &mut binder);
        if needs_space {
            let parent_r = link.parent.and_then(|p| to_ground[p]);
            let r = match (parent_r, place.rotation.map(|t| t.matrix)) {
                (Some(pr), Some(r)) => Some(mat3::mat_mul(arena, &pr, &r)),
                (pr, r) => pr.or(r),
            };
            to_ground.push(r);
        }
        let (inertia, p) = match link.body {
            Some(b) => {
                let inertia = body_inertia(arena, scene, b);
                let mut p = velocity_product_force(arena, &mut binder, scene, b, &v);
                let body = &scene.bodies[b];
                if let Some(t) = body.body_torque {
                    p.ang = spatial::sub3(arena, &p.ang, &t);
                }
                if let Some(t) = body.space_torque {
                    let local = match to_ground.last().copied().flatten() {
                        Some(r) => spatial::mat_t_vec(arena, &r, &t),
                        None => t,
                    };
                    p.ang = spatial::sub3(arena, &p.ang, &local);
                }
                (inertia, p)
            }
            None => (Inertia::zero(arena), Pair::zero(arena)),
        };
        places.push(place);
        velocity.push(v);
        bias_accel.push(c);
        art.push(inertia);
        bias_force.push(p);
    }

    // Pass 2: articulated inertias and bias forces, leaves first.
    let mut u_force: Vec<Pair> = vec![Pair::zero(arena); n];
    let mut inv_pivot: Vec<ExprId> = vec![arena.zero(); n];
    let mut u_scalar: Vec<ExprId> = vec![arena.zero(); n];
    let mut pivots = vec![arena.zero(); dof];
    for i in (0..n).rev() {
        let link = &links[i];
        let ia = art[i].bound(arena, &mut binder);
        let pa = bias_force[i].bound(arena, &mut binder);
        let s1 = subspace(arena, link, arena.one());
        let u = ia.apply(arena, &s1);
        let u = u.bound(arena, &mut binder);
        let d = project(arena, link, &u);
        let d = binder.bind(arena, d);
        pivots[link.coordinate] = d;
        if d == arena.zero() {
            return Err(MechanismError::SingularMassMatrix {
                pivot: link.coordinate,
                value: 0.0,
            });
        }
        let d_inv = arena.pow_nonzero_base(d, -1);
        let sp = project(arena, link, &pa);
        let uu = arena.sub(joint_forces[link.coordinate], sp);
        let uu = binder.bind(arena, uu);
        if let Some(parent) = link.parent {
            let w = Pair {
                ang: spatial::scale3(arena, d_inv, &u.ang),
                lin: spatial::scale3(arena, d_inv, &u.lin),
            };
            let w = w.bound(arena, &mut binder);
            let reduced = ia.minus_outer(arena, &w, &u);
            let reduced = reduced.bound(arena, &mut binder);
            let ic = reduced.apply(arena, &bias_accel[i]);
            let wu = Pair {
                ang: spatial::scale3(arena, uu, &w.ang),
                lin: spatial::scale3(arena, uu, &w.lin),
            };
            let pa_child = pa.add(arena, &ic).add(arena, &wu);
            let pa_child = pa_child.bound(arena, &mut binder);
            let place = &places[i];
            let i_up = reduced.seen_from_parent(
                arena,
                &mut binder,
                place.rotation.as_ref(),
                &place.origin,
            );
            let p_up = spatial::force_to_parent(
                arena,
                &mut binder,
                place.rotation.as_ref(),
                &place.origin,
                &pa_child,
            );
            art[parent] = art[parent].add(arena, &i_up);
            bias_force[parent] = bias_force[parent].add(arena, &p_up);
        }
        u_force[i] = u;
        inv_pivot[i] = d_inv;
        u_scalar[i] = uu;
    }

    // Pass 3: accelerations, root first; the ground accelerates at −g.
    let ground = Pair {
        ang: [arena.zero(); 3],
        lin: match scene.gravity {
            Some(g) => spatial::neg3(arena, &g),
            None => [arena.zero(); 3],
        },
    };
    let mut accel: Vec<Pair> = Vec::with_capacity(n);
    let mut qdd = vec![arena.zero(); dof];
    for (i, link) in links.iter().enumerate() {
        let parent_a = match link.parent {
            Some(p) => accel[p],
            None => ground,
        };
        let place = &places[i];
        let carried =
            spatial::motion_to_child(arena, place.rotation.as_ref(), &place.origin, &parent_a);
        let a_prime = carried.add(arena, &bias_accel[i]);
        let a_prime = a_prime.bound(arena, &mut binder);
        let x = match spatial::unit_axis(arena, &link.axis) {
            // S = e_k (of the angular or the linear part): U's entry there is D itself, so
            // (u − Uᵀa′)/D = (u − Σ_{other} U a′)/D − a′_k, and the bracket is the new
            // acceleration's k-th entry as it stands (a_k = a′_k + q̈).
            Some(k) => {
                let mut u_rest = u_force[i];
                let mut a_k = a_prime.ang[k];
                match link.motion {
                    Motion::Turn => u_rest.ang[k] = arena.zero(),
                    Motion::Slide => {
                        u_rest.lin[k] = arena.zero();
                        a_k = a_prime.lin[k];
                    }
                }
                let ua = spatial::dot_pair(arena, &u_rest, &a_prime);
                let num = arena.sub(u_scalar[i], ua);
                let y = arena.mul(num, inv_pivot[i]);
                let y = binder.bind(arena, y);
                arena.sub(y, a_k)
            }
            None => {
                let ua = spatial::dot_pair(arena, &u_force[i], &a_prime);
                let num = arena.sub(u_scalar[i], ua);
                arena.mul(num, inv_pivot[i])
            }
        };
        let x = binder.bind(arena, x);
        qdd[link.coordinate] = x;
        let sx = subspace(arena, link, x);
        let a = a_prime.add(arena, &sx);
        accel.push(a.bound(arena, &mut binder));
    }
    Ok(RecursiveForm {
        accelerations: qdd,
        pivots,
    })
}

/// The per-coordinate generalised forces of the declared joint loads:
/// τᵢ = −kᵢ (qᵢ − restᵢ) − cᵢ q̇ᵢ + effortᵢ (terms not declared contribute nothing).
pub fn coordinate_forces(
    arena: &mut Arena,
    scene: &MechanismScene,
    coords: &Coordinates,
) -> Vec<ExprId> {
    let mut out = Vec::with_capacity(scene.dof());
    let loads = scene.bodies.iter().flat_map(|b| b.joint.loads.iter());
    for (i, load) in loads.enumerate() {
        let (Some(&q), Some(&qd)) = (coords.q.get(i), coords.rates.get(i)) else {
            break;
        };
        let mut terms = Vec::new();
        if let Some(s) = load.spring {
            let stretch = arena.sub(q, s.rest);
            let f = arena.mul(s.stiffness, stretch);
            terms.push(arena.neg(f));
        }
        if let Some(c) = load.damper {
            let f = arena.mul(c, qd);
            terms.push(arena.neg(f));
        }
        if let Some(e) = load.effort {
            terms.push(e);
        }
        out.push(arena.sum(&terms));
    }
    out
}

/// The coordinates of `scene` (in state order) and its q̈ by the recursive route, with the
/// joint loads of [`coordinate_forces`].
///
/// # Errors
/// As [`recursive_accelerations`].
pub fn derive_recursive(
    arena: &mut Arena,
    scene: &MechanismScene,
) -> Result<(Coordinates, RecursiveForm), MechanismError> {
    let names = scene.coordinate_names();
    let coords = Coordinates::new(arena, &names);
    let forces = coordinate_forces(arena, scene, &coords);
    let form = recursive_accelerations(arena, scene, &coords, &forces)?;
    Ok((coords, form))
}
