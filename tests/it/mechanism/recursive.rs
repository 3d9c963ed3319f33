//! The recursive route (the symbolic articulated-body algorithm) against the numeric ABA and
//! against an independent formulation written here: M(q) q̈ = Q − Σ Jᵀ (m (a_c − g), I α + ω × I ω
//! − τ) with world-frame Jacobians, solved by LU. Random trees of revolute, prismatic,
//! universal and spherical joints with gravity, springs, dampers, efforts and torques.

use crate::common;

use common::rng::Rng;
use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Unit, Vector3};
use precess_core::codegen::Program;
use precess_core::lagrange::Coordinates;
use precess_core::mechanism::recursive::chains::{pendulum_on_cart, spatial_chain};
use precess_core::mechanism::{
    CoordinateLoad, JointKind, MechanismAba, MechanismError, MechanismScene, Parent, Spring,
    coordinate_forces, derive_recursive, recursive_accelerations,
};
use precess_core::rigid::AngleSequence;
use precess_core::sym::{Arena, ExprId};

/// A joint as this test describes it, in f64.
#[derive(Clone, Copy, Debug)]
enum Kind {
    Revolute(Vector3<f64>),
    Prismatic(Vector3<f64>),
    Universal(Vector3<f64>, Vector3<f64>),
    Spherical(AngleSequence),
}

#[derive(Clone, Debug)]
struct Load {
    stiffness: f64,
    rest: f64,
    damping: f64,
    effort: f64,
}

#[derive(Clone, Debug)]
struct Body {
    parent: Option<usize>,
    kind: Kind,
    at: Vector3<f64>,
    mass: f64,
    center: Vector3<f64>,
    inertia: Matrix3<f64>,
    body_torque: Option<Vector3<f64>>,
    space_torque: Option<Vector3<f64>>,
    loads: Vec<Load>,
}

fn dof(kind: &Kind) -> usize {
    match kind {
        Kind::Revolute(_) | Kind::Prismatic(_) => 1,
        Kind::Universal(..) => 2,
        Kind::Spherical(_) => 3,
    }
}

/// Rounds to three decimals so the value is an exact decimal literal.
fn round3(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

fn rvec(rng: &mut Rng, lo: f64, hi: f64) -> Vector3<f64> {
    rng.vector(lo, hi).map(round3)
}

fn random_axis(rng: &mut Rng) -> Vector3<f64> {
    if rng.uniform(0.0, 1.0) < 0.5 {
        let mut e = Vector3::zeros();
        e[(rng.uniform(0.0, 3.0) as usize).min(2)] = 1.0;
        e
    } else {
        loop {
            let v = rvec(rng, -1.0, 1.0);
            if v.norm() > 0.3 {
                return v;
            }
        }
    }
}

/// n bodies, each joint kind appearing in turn from `offset`; a chain, or a tree when `tree`.
fn random_mechanism(rng: &mut Rng, n: usize, offset: usize, tree: bool) -> Vec<Body> {
    (0..n)
        .map(|i| {
            let kind = match (i + offset) % 4 {
                0 => Kind::Revolute(random_axis(rng)),
                1 => Kind::Prismatic(random_axis(rng)),
                2 => {
                    // Two axes well apart: parallel axes are a genuinely singular joint.
                    let first = random_axis(rng);
                    let second = loop {
                        let k = random_axis(rng);
                        if first.cross(&k).norm() > 0.5 * first.norm() * k.norm() {
                            break k;
                        }
                    };
                    Kind::Universal(first, second)
                }
                _ => Kind::Spherical(if rng.uniform(0.0, 1.0) < 0.5 {
                    AngleSequence::Zxz
                } else {
                    AngleSequence::Zyx
                }),
            };
            let parent = match (i, tree) {
                (0, _) => None,
                (_, false) => Some(i - 1),
                (_, true) => Some((rng.uniform(0.0, i as f64) as usize).min(i - 1)),
            };
            let diag = rvec(rng, 0.02, 0.06);
            let (xy, xz, yz) = (
                round3(rng.uniform(-0.004, 0.004)),
                round3(rng.uniform(-0.004, 0.004)),
                round3(rng.uniform(-0.004, 0.004)),
            );
            let inertia = Matrix3::new(diag.x, xy, xz, xy, diag.y, yz, xz, yz, diag.z);
            let loads = (0..dof(&kind))
                .map(|_| Load {
                    stiffness: round3(rng.uniform(0.0, 2.0)),
                    rest: round3(rng.uniform(-0.5, 0.5)),
                    damping: round3(rng.uniform(0.0, 0.3)),
                    effort: round3(rng.uniform(-0.5, 0.5)),
                })
                .collect();
            Body {
                parent,
                kind,
                at: rvec(rng, -0.3, 0.3),
                mass: round3(rng.uniform(0.5, 2.0)),
                center: rvec(rng, -0.2, 0.2),
                inertia,
                body_torque: (i % 2 == 0).then(|| rvec(rng, -0.3, 0.3)),
                space_torque: (i % 3 == 1).then(|| rvec(rng, -0.3, 0.3)),
                loads,
            }
        })
        .collect()
}

fn lit(a: &mut Arena, x: f64) -> ExprId {
    a.number(&format!("{x:.3}")).expect("a decimal")
}

fn lit3(a: &mut Arena, v: &Vector3<f64>) -> [ExprId; 3] {
    [lit(a, v.x), lit(a, v.y), lit(a, v.z)]
}

/// The scene of `bodies`; gravity's magnitude and the springs' stiffnesses are parameters
/// `g` and `k{i}` (so both folded constants and bound parameters are exercised).
fn scene_of(a: &mut Arena, bodies: &[Body], gravity: &Vector3<f64>) -> MechanismScene {
    let mut scene = MechanismScene::new();
    let mut next = 0;
    for (i, b) in bodies.iter().enumerate() {
        let kind = match b.kind {
            Kind::Revolute(k) => JointKind::Revolute { axis: lit3(a, &k) },
            Kind::Prismatic(k) => JointKind::Prismatic { axis: lit3(a, &k) },
            Kind::Universal(k1, k2) => JointKind::Universal {
                axes: [lit3(a, &k1), lit3(a, &k2)],
            },
            Kind::Spherical(sequence) => JointKind::Spherical { sequence },
        };
        let names: Vec<String> = (0..dof(&b.kind))
            .map(|k| format!("q{}", next + k))
            .collect();
        let name_refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let parent = b.parent.map_or(Parent::Ground, Parent::Body);
        let mut body = MechanismScene::body(a, &format!("b{i}"), parent, kind, &name_refs);
        body.joint.at = lit3(a, &b.at);
        body.mass = lit(a, b.mass);
        body.center = lit3(a, &b.center);
        for r in 0..3 {
            for c in 0..3 {
                body.inertia[r][c] = lit(a, b.inertia[(r, c)]);
            }
        }
        body.body_torque = b.body_torque.map(|t| lit3(a, &t));
        body.space_torque = b.space_torque.map(|t| lit3(a, &t));
        body.joint.loads = b
            .loads
            .iter()
            .enumerate()
            .map(|(k, l)| CoordinateLoad {
                spring: Some(Spring {
                    stiffness: a.parameter(&format!("k{}", next + k)),
                    rest: lit(a, l.rest),
                }),
                damper: Some(lit(a, l.damping)),
                effort: Some(lit(a, l.effort)),
            })
            .collect();
        next += dof(&b.kind);
        scene.bodies.push(body);
    }
    let g = a.parameter("g");
    let dir = lit3(a, &(gravity / gravity.norm()).map(round3));
    scene.gravity = Some(dir.map(|c| a.mul(g, c)));
    scene
}

/// The elementary 1-dof steps of a joint: (turn?, axis in the frame before the step).
fn steps(kind: &Kind) -> Vec<(bool, Vector3<f64>)> {
    match *kind {
        Kind::Revolute(k) => vec![(true, k.normalize())],
        Kind::Prismatic(k) => vec![(false, k.normalize())],
        Kind::Universal(k1, k2) => vec![(true, k1.normalize()), (true, k2.normalize())],
        Kind::Spherical(seq) => seq
            .axes()
            .iter()
            .map(|&i| (true, Vector3::ith(i, 1.0)))
            .collect(),
    }
}

/// World-frame state of one body frame.
#[derive(Clone, Copy)]
struct Frame {
    r: Matrix3<f64>,
    p: Vector3<f64>,
    w: Vector3<f64>,
    v: Vector3<f64>,
    alpha: Vector3<f64>,
    acc: Vector3<f64>,
}

/// q̈ by the independent formulation (see the file's summary); `g` the gravity vector.
fn reference_qdd(bodies: &[Body], g: &Vector3<f64>, q: &[f64], qd: &[f64]) -> DVector<f64> {
    let n = q.len();
    let ground = Frame {
        r: Matrix3::identity(),
        p: Vector3::zeros(),
        w: Vector3::zeros(),
        v: Vector3::zeros(),
        alpha: Vector3::zeros(),
        acc: Vector3::zeros(),
    };
    // Per coordinate: (turn?, world axis, world joint point, owning body); per body its frame.
    let mut columns: Vec<(bool, Vector3<f64>, Vector3<f64>)> = vec![Default::default(); n];
    let mut ancestors: Vec<Vec<usize>> = Vec::new(); // coordinates moving each body
    let mut frames: Vec<Frame> = Vec::new();
    let mut first = 0;
    for b in bodies {
        let (mut f, mut chain) = match b.parent {
            Some(p) => (frames[p], ancestors[p].clone()),
            None => (ground, Vec::new()),
        };
        for (k, (turn, axis)) in steps(&b.kind).into_iter().enumerate() {
            let j = first + k;
            let r_off = if k == 0 { f.r * b.at } else { Vector3::zeros() };
            let o = f.p + r_off;
            let v_o = f.v + f.w.cross(&r_off);
            let a_o = f.acc + f.alpha.cross(&r_off) + f.w.cross(&f.w.cross(&r_off));
            let a = f.r * axis;
            columns[j] = (turn, a, o);
            if turn {
                let rot = Rotation3::from_axis_angle(&Unit::new_normalize(axis), q[j]);
                f = Frame {
                    r: f.r * rot.matrix(),
                    p: o,
                    w: f.w + a * qd[j],
                    v: v_o,
                    alpha: f.alpha + f.w.cross(&(a * qd[j])),
                    acc: a_o,
                };
            } else {
                let d = a * q[j];
                f = Frame {
                    r: f.r,
                    p: o + d,
                    w: f.w,
                    v: v_o + f.w.cross(&d) + a * qd[j],
                    alpha: f.alpha,
                    acc: a_o
                        + f.alpha.cross(&d)
                        + f.w.cross(&f.w.cross(&d))
                        + 2.0 * f.w.cross(&(a * qd[j])),
                };
            }
            chain.push(j);
        }
        first += dof(&b.kind);
        frames.push(f);
        ancestors.push(chain);
    }
    let mut m = DMatrix::zeros(n, n);
    let mut rhs = DVector::zeros(n);
    let mut j0 = 0;
    for b in bodies {
        for (k, l) in b.loads.iter().enumerate() {
            let j = j0 + k;
            rhs[j] = -l.stiffness * (q[j] - l.rest) - l.damping * qd[j] + l.effort;
        }
        j0 += dof(&b.kind);
    }
    for (bi, b) in bodies.iter().enumerate() {
        let f = frames[bi];
        let rc = f.r * b.center;
        let c = f.p + rc;
        let a_c = f.acc + f.alpha.cross(&rc) + f.w.cross(&f.w.cross(&rc));
        let iw = f.r * b.inertia * f.r.transpose();
        let force = b.mass * (a_c - g);
        let mut moment = iw * f.alpha + f.w.cross(&(iw * f.w));
        if let Some(t) = b.body_torque {
            moment -= f.r * t;
        }
        if let Some(t) = b.space_torque {
            moment -= t;
        }
        let jac = |j: usize| -> (Vector3<f64>, Vector3<f64>) {
            let (turn, a, o) = columns[j];
            if turn {
                (a.cross(&(c - o)), a)
            } else {
                (a, Vector3::zeros())
            }
        };
        for &j in &ancestors[bi] {
            let (jv, jw) = jac(j);
            rhs[j] -= jv.dot(&force) + jw.dot(&moment);
            for &k in &ancestors[bi] {
                let (kv, kw) = jac(k);
                m[(j, k)] += b.mass * jv.dot(&kv) + jw.dot(&(iw * kw));
            }
        }
    }
    m.lu().solve(&rhs).expect("a regular mass matrix")
}

/// The symbol environment for (q, q̇) with g and the stiffnesses bound.
fn environment(
    a: &Arena,
    coords: &Coordinates,
    bodies: &[Body],
    g: f64,
    q: &[f64],
    qd: &[f64],
) -> Vec<f64> {
    let mut env = vec![f64::NAN; a.symbol_count()];
    let mut set = |e: ExprId, x: f64| {
        if let Some(s) = a.as_symbol(e) {
            env[s.index()] = x;
        }
    };
    for i in 0..q.len() {
        set(coords.q[i], q[i]);
        set(coords.rates[i], qd[i]);
    }
    let stiffness = bodies
        .iter()
        .flat_map(|b| b.loads.iter().map(|l| l.stiffness));
    for (i, k) in stiffness.enumerate() {
        if let Some(s) = a.find_parameter(&format!("k{i}")) {
            env[s.index()] = k;
        }
    }
    if let Some(s) = a.find_parameter("g") {
        env[s.index()] = g;
    }
    env
}

/// A state away from the Euler angles' singular middle angle.
fn random_state(rng: &mut Rng, bodies: &[Body]) -> (Vec<f64>, Vec<f64>) {
    let (mut q, mut qd) = (Vec::new(), Vec::new());
    for b in bodies {
        for k in 0..dof(&b.kind) {
            let x = match (b.kind, k) {
                (Kind::Spherical(AngleSequence::Zxz), 1) => rng.uniform(0.4, 2.7),
                (Kind::Spherical(AngleSequence::Zyx), 1) => rng.uniform(-1.1, 1.1),
                (Kind::Prismatic(_), _) => rng.uniform(-0.3, 0.3),
                _ => rng.uniform(-3.1, 3.1),
            };
            q.push(x);
            qd.push(rng.uniform(-2.0, 2.0));
        }
    }
    (q, qd)
}

fn relative(a: &[f64], b: &DVector<f64>) -> f64 {
    let diff: f64 = a.iter().zip(b.iter()).map(|(x, y)| (x - y).powi(2)).sum();
    diff.sqrt() / b.norm().max(1.0)
}

#[test]
fn recursive_route_agrees_with_the_numeric_aba_and_an_independent_formulation() {
    let mut rng = Rng::new(0x5eed_ab4a);
    let mut states = 0;
    let (mut worst_sym, mut worst_aba) = (0.0f64, 0.0f64);
    for n in 1..=6 {
        for offset in 0..4 {
            let tree = offset == 3;
            let bodies = random_mechanism(&mut rng, n, offset, tree);
            let gvec = Vector3::new(0.1, -0.2, -1.0).map(round3);
            let gdir = (gvec / gvec.norm()).map(round3);
            let g_mag = 9.81;
            let gravity = gdir * g_mag;
            let mut a = Arena::new();
            let scene = scene_of(&mut a, &bodies, &gvec);
            let (coords, form) = derive_recursive(&mut a, &scene)
                .unwrap_or_else(|e| panic!("n = {n}, offset {offset}: {e} {bodies:?}"));
            let program = Program::lower(&a, &form.accelerations);
            let pivots = Program::lower(&a, &form.pivots);
            let mut bound = environment(&a, &coords, &bodies, g_mag, &[], &[]);
            bound.iter_mut().for_each(|x| {
                if x.is_nan() {
                    *x = 0.0;
                }
            });
            let mut aba = MechanismAba::new(&mut a, &scene, &bound).expect("binds");
            let dof = scene.dof();
            let mut qdd_aba = vec![0.0; dof];
            for _ in 0..45 {
                let (q, qd) = random_state(&mut rng, &bodies);
                let env = environment(&a, &coords, &bodies, g_mag, &q, &qd);
                let qdd_sym = program.eval(&env);
                assert!(pivots.eval(&env).iter().all(|&d| d > 0.0));
                aba.accelerations(&q, &qd, &mut qdd_aba).expect("regular");
                let reference = reference_qdd(&bodies, &gravity, &q, &qd);
                let (e_sym, e_aba) = (
                    relative(&qdd_sym, &reference),
                    relative(&qdd_aba, &reference),
                );
                worst_sym = worst_sym.max(e_sym);
                worst_aba = worst_aba.max(e_aba);
                assert!(
                    e_sym <= 1e-12 && e_aba <= 1e-12,
                    "n = {n}, offset {offset}: symbolic {e_sym:e}, numeric {e_aba:e} at q = {q:?}"
                );
                states += 1;
            }
        }
    }
    assert!(states >= 1000, "{states} states");
    eprintln!("{states} states: symbolic ≤ {worst_sym:e}, numeric ABA ≤ {worst_aba:e}");
}

fn ops(scene_of_n: impl Fn(&mut Arena, usize) -> MechanismScene, n: usize) -> usize {
    let mut a = Arena::new();
    let scene = scene_of_n(&mut a, n);
    let (_, form) = derive_recursive(&mut a, &scene).expect("derives");
    Program::lower(&a, &form.accelerations).op_count().total()
}

#[test]
fn operation_count_grows_linearly_with_the_chain() {
    // The first links cost less (the ground is at rest, so their velocity terms vanish), so
    // ops(n) ≈ a n − b with b > 0 and the ratio approaches 2 from above as n grows; n² growth
    // would give 4.
    for (name, f) in [
        (
            "planar",
            pendulum_on_cart as fn(&mut Arena, usize) -> MechanismScene,
        ),
        ("spatial", spatial_chain),
    ] {
        for n in [15, 25] {
            let (small, large) = (ops(f, n), ops(f, 2 * n));
            let ratio = large as f64 / small as f64;
            assert!(
                ratio <= 2.3,
                "{name} chain: ops({}) / ops({n}) = {large} / {small} = {ratio}",
                2 * n
            );
        }
    }
}

#[test]
fn a_pendulum_on_a_cart_matches_its_closed_form() {
    // One link: (m0 + m1) ẍ + m1 l (−sin θ θ̈ − cos θ θ̇²)·… written out with the angle from +y:
    // the particle sits at (x − l sin θ, l cos θ). Then
    //   (m0 + m1) ẍ − m1 l (cos θ θ̈ − sin θ θ̇²) = F,
    //   −m1 l cos θ ẍ + m1 l² θ̈ − m1 g l sin θ = 0.
    let mut a = Arena::new();
    let scene = pendulum_on_cart(&mut a, 1);
    let (coords, form) = derive_recursive(&mut a, &scene).expect("derives");
    let (m0, m1, l, g, f) = (1.3, 0.7, 0.45, 9.81, 0.4);
    let (th, thd): (f64, f64) = (0.8, -1.1);
    let mut env = vec![0.0; a.symbol_count()];
    for (name, x) in [("m0", m0), ("m1", m1), ("l0", l), ("g", g), ("F", f)] {
        env[a.find_parameter(name).expect("declared").index()] = x;
    }
    env[a.as_symbol(coords.q[1]).expect("symbol").index()] = th;
    env[a.as_symbol(coords.rates[1]).expect("symbol").index()] = thd;
    let (s, c) = th.sin_cos();
    let m = DMatrix::from_row_slice(2, 2, &[m0 + m1, -m1 * l * c, -m1 * l * c, m1 * l * l]);
    let rhs = DVector::from_row_slice(&[f - m1 * l * s * thd * thd, m1 * g * l * s]);
    let expected = m.lu().solve(&rhs).expect("regular");
    for i in 0..2 {
        let got = a.eval(form.accelerations[i], &env);
        approx::assert_relative_eq!(got, expected[i], max_relative = 1e-13);
    }
}

#[test]
fn a_massless_leaf_is_a_singular_mass_matrix() {
    let mut a = Arena::new();
    let (z, o) = (a.zero(), a.one());
    let mut scene = MechanismScene::new();
    scene.bodies.push(MechanismScene::body(
        &mut a,
        "ghost",
        Parent::Ground,
        JointKind::Revolute { axis: [z, z, o] },
        &["q"],
    ));
    let coords = Coordinates::new(&mut a, &["q"]);
    let forces = coordinate_forces(&mut a, &scene, &coords);
    assert_eq!(
        recursive_accelerations(&mut a, &scene, &coords, &forces),
        Err(MechanismError::SingularMassMatrix {
            pivot: 0,
            value: 0.0
        })
    );
    // A parameter mass set to zero at run time: the numeric algorithm refuses the state.
    scene.bodies[0].mass = a.parameter("m");
    scene.bodies[0].center = [o, z, z];
    let env = vec![0.0; a.symbol_count()];
    let mut aba = MechanismAba::new(&mut a, &scene, &env).expect("binds");
    let mut qdd = [0.0];
    assert!(matches!(
        aba.accelerations(&[0.1], &[0.0], &mut qdd),
        Err(MechanismError::SingularMassMatrix { pivot: 0, .. })
    ));
}

#[test]
fn malformed_trees_are_typed_errors() {
    let mut a = Arena::new();
    let (z, o) = (a.zero(), a.one());
    let one_body = |a: &mut Arena, parent, axis| {
        let mut s = MechanismScene::new();
        let mut b = MechanismScene::body(a, "b", parent, JointKind::Revolute { axis }, &["q"]);
        b.mass = o;
        b.center = [o, z, z];
        s.bodies.push(b);
        s
    };
    let zero_axis = one_body(&mut a, Parent::Ground, [z, z, z]);
    assert!(matches!(
        derive_recursive(&mut a, &zero_axis),
        Err(MechanismError::ZeroAxis {
            squared_length: None,
            ..
        })
    ));
    let cycle = one_body(&mut a, Parent::Body(0), [z, z, o]);
    assert!(matches!(
        derive_recursive(&mut a, &cycle),
        Err(MechanismError::Cycle { .. })
    ));
    let unknown = one_body(&mut a, Parent::Body(3), [z, z, o]);
    assert!(matches!(
        derive_recursive(&mut a, &unknown),
        Err(MechanismError::UnknownParent {
            parent: 3,
            count: 1,
            ..
        })
    ));
    assert_eq!(
        derive_recursive(&mut a, &MechanismScene::new()),
        Err(MechanismError::NoMovingJoint)
    );
}

/// The committed generated chains of the scale benchmark (`benches/generated/`).
#[allow(clippy::all, clippy::pedantic, unused_parens)]
mod generated {
    pub mod planar_5 {
        include!("../../../benches/generated/planar_5.rs");
    }
    pub mod spatial_5 {
        include!("../../../benches/generated/spatial_5.rs");
    }
    pub mod planar_25 {
        include!("../../../benches/generated/planar_25.rs");
    }
    pub mod spatial_25 {
        include!("../../../benches/generated/spatial_25.rs");
    }
}

#[test]
fn generated_chains_are_current() {
    use precess_core::mechanism::recursive::chains::{ChainKind, generated_source};
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/benches/generated");
    let bless = std::env::var_os("PRECESS_BLESS").is_some();
    for kind in [ChainKind::Planar, ChainKind::Spatial] {
        for n in [2, 5, 10, 25] {
            let path = format!("{dir}/{}_{n}.rs", kind.name());
            let fresh = generated_source(kind, n).expect("derives");
            if bless {
                std::fs::write(&path, &fresh).expect("writable");
            }
            let committed = std::fs::read_to_string(&path).unwrap_or_default();
            assert!(
                committed == fresh,
                "{path} differs from what the engine emits now: rerun with PRECESS_BLESS=1"
            );
        }
    }
}

/// The parameter values of the planar chains: masses 1 + i/10, lengths 1/2 + i/20, g, F.
fn planar_value(name: &str) -> f64 {
    let index = |s: &str| s.parse::<f64>().unwrap_or(0.0);
    match name {
        "g" => 9.81,
        "F" => 0.7,
        _ if name.starts_with('m') => 1.0 + index(&name[1..]) / 10.0,
        _ if name.starts_with('l') => 0.5 + index(&name[1..]) / 20.0,
        _ => f64::NAN,
    }
}

/// A generated `accelerations(q, q̇, p)`.
type Generated<const D: usize, const P: usize> = fn(&[f64; D], &[f64; D], &[f64; P]) -> [f64; D];

fn check_generated<const D: usize, const P: usize>(
    kind: precess_core::mechanism::recursive::chains::ChainKind,
    n: usize,
    parameters: [&str; P],
    generated: Generated<D, P>,
) {
    let mut a = Arena::new();
    let scene = kind.scene(&mut a, n);
    let mut env = vec![0.0; a.symbol_count()];
    let p = parameters.map(planar_value);
    for (name, &x) in parameters.iter().zip(&p) {
        env[a.find_parameter(name).expect("declared").index()] = x;
    }
    let mut aba = MechanismAba::new(&mut a, &scene, &env).expect("binds");
    let mut rng = Rng::new(n as u64);
    let mut expected = [0.0; D];
    for _ in 0..50 {
        let q: [f64; D] = std::array::from_fn(|_| rng.uniform(-3.0, 3.0));
        let qd: [f64; D] = std::array::from_fn(|_| rng.uniform(-2.0, 2.0));
        let got = generated(&q, &qd, &p);
        aba.accelerations(&q, &qd, &mut expected).expect("regular");
        let e = relative(&got, &DVector::from_row_slice(&expected));
        assert!(e <= 1e-12, "{kind:?} {n}: {e:e}");
    }
}

#[test]
fn generated_chains_agree_with_the_numeric_aba() {
    use precess_core::mechanism::recursive::chains::ChainKind;
    check_generated(
        ChainKind::Planar,
        5,
        generated::planar_5::PARAMETERS,
        generated::planar_5::accelerations,
    );
    check_generated(
        ChainKind::Spatial,
        5,
        generated::spatial_5::PARAMETERS,
        generated::spatial_5::accelerations,
    );
    check_generated(
        ChainKind::Planar,
        25,
        generated::planar_25::PARAMETERS,
        generated::planar_25::accelerations,
    );
    check_generated(
        ChainKind::Spatial,
        25,
        generated::spatial_25::PARAMETERS,
        generated::spatial_25::accelerations,
    );
}

/// A pendulum on the recursive route whose torque comes from a user function: the function's
/// value enters q̈ only through the route's bound intermediates, and the derive must still
/// see that q̈ reads it (it once looked at the outputs alone and left the call out).
#[derive(precess::prelude::Mechanism)]
#[mechanism(gravity = 9.81, route = recursive)]
#[body(bob, joint = revolute(axis = x), q = theta, effort = push,
       parts(particle(mass = m, at = [0.0, 0.0, -l])))]
struct Pushed {
    m: f64,
    l: f64,
}

fn push(_: &Pushed, t: f64, _q: &[f64; 1], _qdot: &[f64; 1]) -> f64 {
    0.4 + t
}

#[test]
fn a_user_effort_reaches_the_recursive_route() {
    use precess::mechanism::MechanismDynamics;
    let p = Pushed { m: 0.7, l: 1.3 };
    for (t, theta) in [(0.0, 0.3), (1.5, -1.1), (2.0, 2.5)] {
        let qdd = p.accelerations(t, &[theta], &[0.8]).expect("regular");
        // θ̈ = −(g/l) sin θ + τ(t)/(m l²).
        let expected = -9.81 / 1.3 * f64::sin(theta) + (0.4 + t) / (0.7 * 1.3 * 1.3);
        approx::assert_relative_eq!(qdd[0], expected, max_relative = 1e-13);
    }
}

/// A 25-link 3D chain derives in full (q̈ by the recursive route, and the energy, whose
/// kinematics past `MAX_LAGRANGIAN` coordinates stay unexpanded: expanded, they doubled per
/// link and this derivation never finished), and the energy it derives is conserved along
/// the q̈ of the other algorithm: an error in T or V would show as drift.
#[test]
fn a_25_link_spatial_chain_derives_in_full_and_conserves_its_energy() {
    use precess_core::mechanism::{MechanismModel, Route};
    use precess_core::ode::{AdaptiveConfig, Dop853};
    const N: usize = 25;
    let mut a = Arena::new();
    let scene = spatial_chain(&mut a, N);
    let model = MechanismModel::new(&mut a, &scene, Route::Auto, &[]).expect("derives");
    let mut rng = Rng::new(25);
    let mut y0 = [0.0; 2 * N];
    for y in y0.iter_mut() {
        *y = rng.uniform(-0.5, 0.5);
    }
    let (q0, v0) = y0.split_at(N);
    let e0 = model.energy(0.0, q0, v0).expect("energy");
    let system = model.system::<{ 2 * N }>().expect("2N");
    let mut ode =
        Dop853::new(system, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12)).expect("starts");
    ode.advance_to(0.5).expect("integrates");
    let (q, v) = ode.y().split_at(N);
    let e = model.energy(0.5, q, v).expect("energy");
    // The energy moves (q̇ ~ 0.5 rad/s over 25 links): a wrong T or V would not stay put.
    let kinetic_scale = 0.5 * 0.5 * 0.3 * 0.3 * (N * N) as f64;
    let drift = (e - e0).abs() / e0.abs().max(kinetic_scale);
    assert!(drift < 1e-9, "energy drift {drift:.2e} (E0 = {e0})");
}
