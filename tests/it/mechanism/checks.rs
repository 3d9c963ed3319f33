//! The mechanism engine's checks and costs: the kinetic energy of long chains (its size grows
//! with the chain, and its value equals the time derivative of the centres), duplicate
//! parameter bindings, and run-time values held to the rules literals meet at compile time
//! (parallel universal axes, zero masses, a failed `set` leaving the model as it was).

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

/// A rod of mass m and length l hanging from a universal joint whose outer axis is x and
/// inner axis [ax, ay, 0] (parameters), under gravity −10 ẑ.
fn universal_scene(arena: &mut Arena) -> MechanismScene {
    let (o, z) = (arena.one(), arena.zero());
    let (ax, ay) = (arena.parameter("ax"), arena.parameter("ay"));
    let kind = JointKind::Universal {
        axes: [[o, z, z], [ax, ay, z]],
    };
    let mut rod = MechanismScene::body(arena, "rod", Parent::Ground, kind, &["alpha", "beta"]);
    let (m, l) = (arena.parameter("m"), arena.parameter("l"));
    rod.mass = m;
    let half = arena.constant_ratio(-1, 2);
    rod.center = [z, z, arena.mul(half, l)];
    let ml2 = arena.product(&[m, l, l]);
    let twelfth = arena.constant_ratio(1, 12);
    let i = arena.mul(twelfth, ml2);
    rod.inertia = [[i, z, z], [z, i, z], [z, z, z]];
    let mut scene = MechanismScene::new();
    scene.bodies.push(rod);
    let g = arena.integer(-10);
    scene.gravity = Some([z, z, g]);
    scene
}

const ROD: [(&str, f64); 4] = [("ax", 0.0), ("ay", 1.0), ("m", 2.0), ("l", 1.5)];

fn rod_model(values: &[(&str, f64)]) -> Result<MechanismModel, MechanismError> {
    let mut a = Arena::new();
    let scene = universal_scene(&mut a);
    MechanismModel::new(&mut a, &scene, Route::Auto, values)
}

#[test]
fn a_parameter_given_twice_is_refused_naming_both_values() {
    let mut values = ROD.to_vec();
    values.push(("m", 5.0));
    let expected = MechanismError::DuplicateParameter {
        name: "m".into(),
        first: 2.0,
        second: 5.0,
    };
    assert_eq!(rod_model(&values).err(), Some(expected.clone()));
    let mut a = Arena::new();
    let scene = universal_scene(&mut a);
    let d = scene.derive(&mut a, Route::Auto).expect("derives");
    assert_eq!(
        MechanismModel::from_derivation(&a, &d, &values).err(),
        Some(expected.clone())
    );
    assert_eq!(
        expected.to_string(),
        "parameter `m` is given twice (2, then 5): give each parameter once"
    );
}

/// The rod swings about x under gravity: at α = 0.3, β = 0 (inner axis y) the outer
/// coordinate is a pendulum of inertia m l²/3 about its end, α̈ = −(3 g / 2 l) sin α.
#[test]
fn parallel_universal_axes_from_parameters_are_refused_by_new_and_set() {
    let mut model = rod_model(&ROD).expect("a universal joint");
    let (q, qdot) = ([0.3, 0.0], [0.0, 0.0]);
    let before = model.accelerations(0.0, &q, &qdot).expect("regular");
    let pendulum = -1.5 * 10.0 / 1.5 * 0.3f64.sin();
    assert!(
        (before[0] - pendulum).abs() < 1e-13,
        "{before:?} vs {pendulum}"
    );

    // The inner axis turned onto the outer one: parallel, whatever the sign or length.
    for (ax, ay) in [(1.0, 0.0), (-3.0, 0.0), (2.0, 1e-9)] {
        let values = [("ax", ax), ("ay", ay), ("m", 2.0), ("l", 1.5)];
        match rod_model(&values) {
            Err(MechanismError::ParallelAxes { joint, sine, .. }) => {
                assert_eq!(joint, "rod");
                let expected = ay.abs() / (ax * ax + ay * ay).sqrt();
                assert!((sine - expected).abs() <= 1e-24, "{sine:e} vs {expected:e}");
            }
            other => panic!("ax = {ax}, ay = {ay}: expected parallel axes, got {other:?}"),
        }
    }
    // [1e12, 1, 0] is 1e-12 rad from x.
    let e = model.set("ax", 1e12).err();
    assert!(
        matches!(&e, Some(MechanismError::ParallelAxes { joint, sine, .. }) if joint == "rod" && (sine - 1e-12).abs() < 1e-27),
        "{e:?}"
    );
    let text = e.map(|e| e.to_string()).unwrap_or_default();
    assert!(
        text.contains("axes are parallel") && text.contains("1e-12"),
        "{text}"
    );
    // A refused set leaves the model as it was: the same q̈, bit for bit.
    let after = model.accelerations(0.0, &q, &qdot).expect("still regular");
    assert_eq!(before, after);
}

#[test]
fn a_refused_set_leaves_the_model_as_it_was_so_the_next_error_names_its_own_cause() {
    let mut model = rod_model(&ROD).expect("a universal joint");
    let (q, qdot) = ([0.3, -0.2], [0.1, 0.4]);
    let before = model.accelerations(0.0, &q, &qdot).expect("regular");
    assert!(matches!(
        model.set("m", -1.0),
        Err(MechanismError::NegativeParameter { value, .. }) if value == -1.0
    ));
    assert_eq!(
        model.accelerations(0.0, &q, &qdot).ok(),
        Some(before.clone())
    );
    // The next change is judged on its own: a good length is taken…
    model.set("l", 3.0).expect("a good length");
    // …and a zero axis is named as such, not as the earlier negative mass.
    let e = model.set("ay", 0.0).err();
    assert!(
        matches!(&e, Some(MechanismError::ZeroAxis { joint, squared_length: Some(v) }) if joint == "rod" && *v == 0.0),
        "{e:?}"
    );
    let fresh = rod_model(&[("ax", 0.0), ("ay", 1.0), ("m", 2.0), ("l", 3.0)]).expect("model");
    assert_eq!(
        model.accelerations(0.0, &q, &qdot).ok(),
        fresh.accelerations(0.0, &q, &qdot).ok()
    );
}

#[test]
fn constant_parallel_axes_are_refused_by_validate_and_the_numeric_algorithm() {
    let mut a = Arena::new();
    let (o, z) = (a.one(), a.zero());
    let two = a.integer(-2);
    let kind = JointKind::Universal {
        axes: [[o, z, z], [two, z, z]],
    };
    let mut scene = MechanismScene::new();
    let mut rod = MechanismScene::body(&mut a, "rod", Parent::Ground, kind, &["alpha", "beta"]);
    rod.mass = o;
    rod.center = [z, z, a.integer(-1)];
    scene.bodies.push(rod);
    let expected = MechanismError::ParallelAxes {
        joint: "rod".into(),
        sine: 0.0,
        // √ε, the sine below which the pair's pivot is under the rounding of its neighbours.
        minimum: f64::EPSILON.sqrt(),
    };
    assert_eq!(scene.validate(&a).err(), Some(expected.clone()));
    assert_eq!(scene.derive(&mut a, Route::Auto).err(), Some(expected));

    let mut a = Arena::new();
    let scene = universal_scene(&mut a);
    let mut env = vec![f64::NAN; 64];
    for (name, v) in [("ax", 1.0), ("ay", 0.0), ("m", 2.0), ("l", 1.5)] {
        let s = a.parameter(name);
        if let Some(sym) = a.as_symbol(s) {
            env[sym.index()] = v;
        }
    }
    let e = precess::mechanism::MechanismAba::new(&mut a, &scene, &env).err();
    assert!(
        matches!(&e, Some(MechanismError::ParallelAxes { joint, sine, .. }) if joint == "rod" && *sine == 0.0),
        "{e:?}"
    );
}

/// A rod on a universal joint whose inner axis and mass are fields.
#[derive(Clone, Copy, Debug, precess::prelude::Mechanism)]
#[mechanism(gravity = [0.0, 0.0, -10.0])]
#[body(rod, parent = ground, joint = universal(axes = [x, [bx, by, 0.0]]), q = [alpha, beta],
       parts(rod(mass = m, length = l, at = [0.0, 0.0, -0.5 * l])))]
struct Gimbal {
    bx: f64,
    by: f64,
    m: f64,
    l: f64,
}

const GIMBAL: Gimbal = Gimbal {
    bx: 0.0,
    by: 1.0,
    m: 2.0,
    l: 1.5,
};

/// Both the check and the checked accelerations refuse `g`, with the same error.
fn gimbal_refused(g: Gimbal) -> MechanismError {
    use precess::prelude::MechanismDynamics;
    let e = g.check_parameters().expect_err("refused");
    let a = g
        .accelerations(0.0, &[0.3, 0.1], &[0.0, 0.0])
        .expect_err("refused by the checked accelerations too");
    assert_eq!(e.to_string(), a.to_string());
    e
}

#[test]
fn parallel_field_axes_of_a_derived_universal_joint_are_refused() {
    use precess::prelude::MechanismDynamics;
    let q = GIMBAL
        .accelerations(0.0, &[0.3, 0.0], &[0.0, 0.0])
        .expect("regular");
    let pendulum = -1.5 * 10.0 / 1.5 * 0.3f64.sin();
    assert!((q[0] - pendulum).abs() < 1e-13, "{q:?} vs {pendulum}");
    for (bx, by) in [(1.0, 0.0), (-2.0, 0.0), (1.0, 1e-10)] {
        let e = gimbal_refused(Gimbal { bx, by, ..GIMBAL });
        let expected = by.abs() / (bx * bx + by * by).sqrt();
        assert!(
            matches!(&e, MechanismError::ParallelAxes { joint, sine, .. } if joint == "rod" && (sine - expected).abs() <= 1e-25),
            "bx = {bx}, by = {by}: {e:?}"
        );
    }
    // At 1e-7 rad apart the axes are still a joint.
    assert_eq!(
        Gimbal {
            bx: 1.0,
            by: 1e-7,
            ..GIMBAL
        }
        .check_parameters(),
        Ok(())
    );
}

/// The gimbal with a literal massless outer ring and a rod below it.
#[derive(Clone, Copy, Debug, precess::prelude::Mechanism)]
#[mechanism(gravity = [0.0, 0.0, -10.0])]
#[body(ring, parent = ground, joint = revolute(axis = z), q = phi,
       parts(ring(mass = 0.0, radius = 0.08, axis = y)))]
#[body(rod, parent = ring, joint = revolute(axis = x), q = theta,
       parts(rod(mass = 2.0, length = 1.5, at = [0.0, 0.0, -0.75])))]
struct LiteralMassless;

/// The same with the ring's mass and radius fields.
#[derive(Clone, Copy, Debug, precess::prelude::Mechanism)]
#[mechanism(gravity = [0.0, 0.0, -10.0])]
#[body(ring, parent = ground, joint = revolute(axis = z), q = phi,
       parts(ring(mass = m, radius = r, axis = y)))]
#[body(rod, parent = ring, joint = revolute(axis = x), q = theta,
       parts(rod(mass = 2.0, length = 1.5, at = [0.0, 0.0, -0.75])))]
struct FieldMassless {
    m: f64,
    r: f64,
}

/// One rule for literal and field masses: a zero mass is a massless part (it compiled only
/// as a field before), a negative one is refused, and a massless part's geometry is still
/// checked. The rod hangs from the massless ring: θ̈ = −(3 g / 2 l) sin θ, and the ring turns
/// with the rod's inertia about z, m l² sin²θ / 3.
#[test]
fn a_zero_mass_is_a_massless_part_whether_literal_or_field() {
    use precess::prelude::MechanismDynamics;
    let (q, qdot) = ([0.2, 0.4], [0.3, -0.1]);
    let literal = LiteralMassless
        .accelerations(0.0, &q, &qdot)
        .expect("regular");
    let field = FieldMassless { m: 0.0, r: 0.08 }
        .accelerations(0.0, &q, &qdot)
        .expect("regular");
    // The same equations, the field's folded differently: equal to rounding.
    for (l, f) in literal.iter().zip(&field) {
        assert!(
            (l - f).abs() <= 4.0 * f64::EPSILON * l.abs(),
            "{literal:?} vs {field:?}"
        );
    }
    // θ̈ = −(3 g / 2 l) sin θ + φ̇² sin θ cos θ for the rod about its end.
    let (s, c) = 0.4f64.sin_cos();
    let expected = -1.5 * 10.0 / 1.5 * s + 0.3 * 0.3 * s * c;
    assert!(
        (literal[1] - expected).abs() < 1e-13,
        "{literal:?} vs {expected}"
    );
    let negative = FieldMassless { m: -1.0, r: 0.08 }.check_parameters();
    assert!(
        matches!(&negative, Err(MechanismError::Part { body, error: precess::body::BodyError::NonPositiveMass { value, .. } }) if body == "ring" && *value == -1.0),
        "{negative:?}"
    );
    let flat = FieldMassless { m: 0.0, r: 0.0 }.check_parameters();
    assert!(
        matches!(&flat, Err(MechanismError::Part { body, error: precess::body::BodyError::NonPositiveDimension { key: "radius", .. } }) if body == "ring"),
        "{flat:?}"
    );
}

mod properties {
    use proptest::prelude::*;

    use super::*;

    const NAMES: [&str; 4] = ["ax", "ay", "m", "l"];

    fn value() -> impl Strategy<Value = f64> {
        prop_oneof![
            -3.0..3.0f64,
            Just(0.0),
            Just(-1.0),
            Just(1e12),
            Just(f64::NAN),
            Just(f64::INFINITY),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Any name given twice, anywhere in the list, is refused naming it and its values.
        #[test]
        fn any_duplicate_is_named(order in Just(ROD.to_vec()).prop_shuffle(), which in 0..4usize, at in 0..5usize, v in -5.0..5.0f64) {
            let mut values = order;
            let (name, _) = ROD[which];
            values.insert(at, (name, v));
            let first = values.iter().position(|(n, _)| *n == name).unwrap_or(0);
            let second = values.iter().rposition(|(n, _)| *n == name).unwrap_or(0);
            let expected = MechanismError::DuplicateParameter {
                name: name.into(),
                first: values[first].1,
                second: values[second].1,
            };
            prop_assert_eq!(rod_model(&values).err(), Some(expected));
        }

        /// After any sequence of sets, good and bad, the model is the one built from the
        /// values its sets accepted: a refused set changes nothing.
        #[test]
        fn refused_sets_change_nothing(sets in proptest::collection::vec((0..4usize, value()), 1..8)) {
            let mut model = rod_model(&ROD).map_err(|e| TestCaseError::fail(e.to_string()))?;
            let mut accepted = ROD.to_vec();
            for (which, v) in sets {
                let name = NAMES[which];
                let mut trial = accepted.clone();
                if let Some(slot) = trial.iter_mut().find(|(n, _)| *n == name) {
                    slot.1 = v;
                }
                let fresh = rod_model(&trial);
                let set = model.set(name, v).map(|_| ());
                // The same value is accepted or refused by both paths, for the same cause.
                prop_assert_eq!(set.is_ok(), fresh.is_ok(), "{} = {}: {:?} vs {:?}", name, v, set, fresh.as_ref().err());
                if set.is_ok() {
                    accepted = trial;
                }
            }
            let expected = rod_model(&accepted).map_err(|e| TestCaseError::fail(e.to_string()))?;
            let (q, qdot) = ([0.3, -0.2], [0.1, 0.4]);
            let got = model.accelerations(0.0, &q, &qdot).map(|a| a.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
            let want = expected.accelerations(0.0, &q, &qdot).map(|a| a.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
            // By their text: a NaN pivot in an error is not equal to itself.
            prop_assert_eq!(format!("{got:?}"), format!("{want:?}"));
        }
    }
}

/// A 10-link spatial chain (the build script's), large enough that q̈ is emitted once and
/// shared by the checked and unchecked methods.
#[derive(precess::prelude::Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(rod1, parent = ground, joint = revolute(axis = x), q = q1, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod2, parent = rod1, joint = revolute(axis = y, at = [0.0, 0.0, -0.3]), q = q2, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod3, parent = rod2, joint = revolute(axis = x, at = [0.0, 0.0, -0.3]), q = q3, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod4, parent = rod3, joint = revolute(axis = y, at = [0.0, 0.0, -0.3]), q = q4, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod5, parent = rod4, joint = revolute(axis = x, at = [0.0, 0.0, -0.3]), q = q5, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod6, parent = rod5, joint = revolute(axis = y, at = [0.0, 0.0, -0.3]), q = q6, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod7, parent = rod6, joint = revolute(axis = x, at = [0.0, 0.0, -0.3]), q = q7, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod8, parent = rod7, joint = revolute(axis = y, at = [0.0, 0.0, -0.3]), q = q8, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod9, parent = rod8, joint = revolute(axis = x, at = [0.0, 0.0, -0.3]), q = q9, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
#[body(rod10, parent = rod9, joint = revolute(axis = y, at = [0.0, 0.0, -0.3]), q = q10, parts(rod(mass = 0.5, length = 0.3, at = [0.0, 0.0, -0.15])))]
struct Chain10;

/// The same chain as a scene, interpreted: rods along z of mass 0.5 and length 0.3 (inertia
/// m l²/12 across), each hinged 0.3 below the last, gravity −9.81 ẑ.
fn chain10_model() -> MechanismModel {
    let mut a = Arena::new();
    let (o, z) = (a.one(), a.zero());
    let mut scene = MechanismScene::new();
    let (m, c, at, i) = (
        a.constant_ratio(1, 2),
        a.constant_ratio(-15, 100),
        a.constant_ratio(-3, 10),
        a.constant_ratio(3, 800),
    );
    for k in 0..10 {
        let axis = if k % 2 == 0 { [o, z, z] } else { [z, o, z] };
        let parent = if k == 0 {
            Parent::Ground
        } else {
            Parent::Body(k - 1)
        };
        let name = format!("q{}", k + 1);
        let mut b = MechanismScene::body(
            &mut a,
            &format!("rod{}", k + 1),
            parent,
            JointKind::Revolute { axis },
            &[&name],
        );
        b.mass = m;
        b.center = [z, z, c];
        b.inertia = [[i, z, z], [z, i, z], [z, z, z]];
        if k > 0 {
            b.joint.at = [z, z, at];
        }
        scene.bodies.push(b);
    }
    let g = a.constant_ratio(-981, 100);
    scene.gravity = Some([z, z, g]);
    MechanismModel::new(&mut a, &scene, Route::Recursive, &[]).expect("the chain")
}

#[test]
fn a_long_chains_shared_accelerations_match_the_interpreted_model() {
    use precess::ode::System;
    use precess::prelude::MechanismDynamics;
    let model = chain10_model();
    let q: [f64; 10] = std::array::from_fn(|i| 0.3 + i as f64 / 7.0);
    let qdot: [f64; 10] = std::array::from_fn(|i| 0.5 - i as f64 / 11.0);
    let reference = model.accelerations(0.0, &q, &qdot).expect("regular");
    let checked = Chain10.accelerations(0.0, &q, &qdot).expect("regular");
    let unchecked = Chain10.accelerations_unchecked(0.0, &q, &qdot);
    assert_eq!(checked, unchecked);
    let mut y = [0.0; 20];
    y[..10].copy_from_slice(&q);
    y[10..].copy_from_slice(&qdot);
    let mut dydt = [0.0; 20];
    Chain10.rhs(0.0, &y, &mut dydt);
    assert_eq!(dydt[10..], checked[..]);
    let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (k, (x, r)) in checked.iter().zip(&reference).enumerate() {
        assert!(
            (x - r).abs() <= 1e-12 * scale,
            "q̈[{k}] = {x}, interpreted {r}"
        );
    }
}
