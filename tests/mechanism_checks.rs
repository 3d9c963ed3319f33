//! The mechanism engine's checks and costs: the kinetic energy of long chains (its size grows
//! with the chain, and its value equals the time derivative of the centres), duplicate
//! parameter bindings, and run-time values held to the rules literals meet at compile time
//! (parallel universal axes, zero field masses, a failed `set` leaving the model as it was).

use precess::codegen::{Bindings, Program};
use precess::mechanism::{
    JointKind, MechanismError, MechanismModel, MechanismScene, Parent, Route,
};
use precess::sym::mat3::{dot, mat_vec};
use precess::sym::{Arena, ExprId, SymbolId};

/// Body `i`'s joint: revolutes about x and y, then a prismatic along an oblique axis, a
/// universal and a spherical joint in turn, so every kind's velocity enters T.
fn joint(arena: &mut Arena, i: usize) -> (JointKind, usize) {
    let (o, z) = (arena.one(), arena.zero());
    let two = arena.integer(2);
    match i % 5 {
        0 => (JointKind::Revolute { axis: [o, z, z] }, 1),
        1 => (JointKind::Revolute { axis: [z, o, z] }, 1),
        2 => (JointKind::Prismatic { axis: [o, two, o] }, 1),
        3 => (
            JointKind::Universal {
                axes: [[z, z, o], [o, o, z]],
            },
            2,
        ),
        _ => (
            JointKind::Spherical {
                sequence: precess::rigid::AngleSequence::Zxz,
            },
            3,
        ),
    }
}

/// An n-body chain of mixed joints with parameter masses m_i and lengths l_i, centres off
/// every axis and full (diagonal) inertias, under gravity g.
fn chain(arena: &mut Arena, n: usize) -> MechanismScene {
    let z = arena.zero();
    let mut scene = MechanismScene::new();
    for i in 0..n {
        let (kind, dof) = joint(arena, i);
        let names: Vec<String> = (0..dof).map(|k| format!("q{i}_{k}")).collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(i - 1)
        };
        let mut b = MechanismScene::body(arena, &format!("link{i}"), parent, kind, &names);
        let m = arena.parameter(&format!("m{i}"));
        let l = arena.parameter(&format!("l{i}"));
        let (tenth, half) = (arena.constant_ratio(1, 10), arena.constant_ratio(-1, 2));
        b.mass = m;
        b.center = [arena.mul(tenth, l), z, arena.mul(half, l)];
        let ml2 = arena.product(&[m, l, l]);
        let moments = [3, 4, 5].map(|k| {
            let c = arena.constant_ratio(k, 60);
            arena.mul(c, ml2)
        });
        b.inertia = [[moments[0], z, z], [z, moments[1], z], [z, z, moments[2]]];
        if i > 0 {
            let prev = arena.parameter(&format!("l{}", i - 1));
            b.joint.at = [z, z, arena.neg(prev)];
        }
        scene.bodies.push(b);
    }
    let g = arena.parameter("g");
    scene.gravity = Some([z, z, arena.neg(g)]);
    scene
}

fn values(n: usize) -> Vec<(String, f64)> {
    let mut v = vec![("g".to_owned(), 9.81)];
    for i in 0..n {
        v.push((format!("m{i}"), 1.0 + i as f64 / 10.0));
        v.push((format!("l{i}"), 0.5 + i as f64 / 20.0));
    }
    v
}

/// A state away from rest, qᵢ = 0.3 + i/7, q̇ᵢ = 0.5 − i/11.
fn state(dof: usize) -> (Vec<f64>, Vec<f64>) {
    (
        (0..dof).map(|i| 0.3 + i as f64 / 7.0).collect(),
        (0..dof).map(|i| 0.5 - i as f64 / 11.0).collect(),
    )
}

/// T of a chain of n bodies: its operation count, its value at `state`, and the value of
/// the second formulation, Σ ½ m |d c/dt|² + ½ ωᵀ I ω with d c/dt the symbolic time
/// derivative of each centre.
fn kinetic(n: usize) -> (usize, f64, f64) {
    let mut a = Arena::new();
    let scene = chain(&mut a, n);
    let d = scene.derive(&mut a, Route::Recursive).expect("derives");
    let ops = Program::lower(&a, &[d.kinetic]).op_count().total();
    let owned = values(n);
    let bound: Vec<(&str, f64)> = owned.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let model = MechanismModel::new(&mut a, &scene, Route::Recursive, &bound).expect("model");
    let (q, qdot) = state(model.dof());
    let t = model.kinetic(0.0, &q, &qdot).expect("T");

    let order = scene.validate(&a).expect("valid");
    let kin = scene
        .kinematics(&mut a, &order, &d.coordinates)
        .expect("kinematics");
    let half = a.constant_ratio(1, 2);
    let mut terms = Vec::new();
    for (body, k) in scene.bodies.iter().zip(&kin) {
        let v = k.center.map(|e| a.dt(e));
        let v2 = dot(&mut a, &v, &v);
        let iw = mat_vec(&mut a, &body.inertia, &k.omega);
        let w2 = dot(&mut a, &k.omega, &iw);
        let tr = a.product(&[half, body.mass, v2]);
        let rot = a.mul(half, w2);
        terms.push(a.add(tr, rot));
    }
    let reference = a.sum(&terms);
    let program = Program::lower(&a, &[reference]);
    let c = &d.coordinates;
    let supplied: Vec<SymbolId> =
        c.q.iter()
            .chain(&c.rates)
            .filter_map(|&e| a.as_symbol(e))
            .collect();
    let without_g: Vec<(&str, f64)> = bound.iter().copied().filter(|&(k, _)| k != "g").collect();
    let bindings =
        Bindings::new(&a, std::slice::from_ref(&program), &supplied, &without_g).expect("bindings");
    let inputs = supplied.iter().copied().zip(q.iter().chain(&qdot).copied());
    let mut out = [0.0];
    bindings.eval(&program, inputs, &mut out);
    (ops, t, out[0])
}

#[test]
fn long_chains_kinetic_energy_equals_the_derivative_of_the_centres() {
    for n in [4, 7, 12] {
        let (_, t, reference) = kinetic(n);
        assert!(t > 0.0, "n = {n}: T = {t}");
        assert!(
            (t - reference).abs() <= 1e-12 * reference,
            "n = {n}: T = {t}, from d c/dt {reference}, off by {:e}",
            (t - reference) / reference
        );
    }
}

/// The derivative of a centre holds one product-rule term per rotation above its body, so
/// T built from it grew as n³ (a 100-link chain's was 900 000 operations; this chain's T had
/// 3 761 operations at 10 bodies and 94 865 at 40, 25×); the recursive velocities give
/// 1 011 and 5 706 (5.6×: flattened sums of the origins still grow a little faster than the
/// chain). The bound is below the 16× of quadratic growth.
#[test]
fn kinetic_energy_grows_with_the_chain_not_its_cube() {
    let (small, _, _) = kinetic(10);
    let (large, _, _) = kinetic(40);
    let ratio = large as f64 / small as f64;
    assert!(
        ratio < 8.0,
        "T of 40 bodies has {large} operations, of 10 bodies {small}: {ratio:.1}× for 4× the bodies"
    );
}

// `Arena::constant_ratio` stand-in for the tests above.
trait Ratio {
    fn constant_ratio(&mut self, p: i64, q: i64) -> ExprId;
}

impl Ratio for Arena {
    fn constant_ratio(&mut self, p: i64, q: i64) -> ExprId {
        let p = self.integer(p);
        let q = self.integer(q);
        self.div(p, q).expect("non-zero denominator")
    }
}
