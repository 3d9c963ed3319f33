//! A top of many field-valued point masses: the derivation stays small (the body's mass
//! properties are abbreviations), and its accelerations equal those of the same top whose
//! inertia, mass and centre are summed directly in f64 and given as constants.

use crate::common;

use approx::assert_relative_eq;
use common::rng::Rng;
use precess::prelude::*;
use precess_core::body::{Description, Part, SymbolicBody};
use precess_core::lagrange::LagrangeError;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::{TopModel, TopScene};

/// A point-mass top: masses and positions.
fn particles(n: usize, rng: &mut Rng) -> Vec<(f64, [f64; 3])> {
    (0..n)
        .map(|_| {
            let at = [
                rng.uniform(-0.2, 0.2),
                rng.uniform(-0.2, 0.2),
                rng.uniform(0.1, 0.5),
            ];
            (rng.uniform(0.1, 2.0), at)
        })
        .collect()
}

/// The parametric top: every mass and coordinate a parameter `m{i}`, `x{i}`, …, set to the
/// values of `cloud` only after the derivation.
fn parametric(cloud: &[(f64, [f64; 3])]) -> (Arena, TopModel, usize) {
    let n = cloud.len();
    let mut a = Arena::new();
    let z = a.zero();
    let parts: Vec<Part<ExprId>> = (0..n)
        .map(|i| {
            let m = a.parameter(&format!("m{i}"));
            let at = ["x", "y", "z"].map(|c| a.parameter(&format!("{c}{i}")));
            Part::new(Shape::Particle { mass: m }, at)
        })
        .collect();
    let d = Description {
        parts,
        pivot: Some([z, z, z]),
    };
    let body = SymbolicBody::new(&mut a, &d).expect("a generic cloud of masses is a body");
    let p = body.props;
    let mut scene = TopScene::free(&mut a, p.inertia);
    scene.mass = p.mass;
    scene.center = p.center;
    scene.gravity = Some(a.number("9.81").unwrap());
    let top = scene.derive(&mut a).expect("the top derives");
    let size = a.len();
    let mut values: Vec<(String, f64)> = Vec::new();
    for (i, &(m, r)) in cloud.iter().enumerate() {
        values.push((format!("m{i}"), m));
        for (c, x) in ["x", "y", "z"].iter().zip(r) {
            values.push((format!("{c}{i}"), x));
        }
    }
    let values: Vec<(&str, f64)> = values.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let model = TopModel::new(&mut a, &top, &values).expect("every parameter is set");
    (a, model, size)
}

/// The same top with its mass properties summed here in f64: I = Σ m (|r|² E − r rᵀ).
fn direct(parts: &[(f64, [f64; 3])]) -> TopModel {
    let mut inertia = [[0.0; 3]; 3];
    let (mut mass, mut moment) = (0.0, [0.0; 3]);
    for &(m, r) in parts {
        let r2 = r.iter().map(|x| x * x).sum::<f64>();
        for i in 0..3 {
            for j in 0..3 {
                let delta = if i == j { r2 } else { 0.0 };
                inertia[i][j] += m * (delta - r[i] * r[j]);
            }
            moment[i] += m * r[i];
        }
        mass += m;
    }
    let mut a = Arena::new();
    let c = |a: &mut Arena, x: f64| a.float(x).unwrap();
    let t = inertia.map(|row| row.map(|x| c(&mut a, x)));
    let mut scene = TopScene::free(&mut a, t);
    scene.mass = c(&mut a, mass);
    scene.center = moment.map(|x| c(&mut a, x / mass));
    scene.gravity = Some(a.number("9.81").unwrap());
    let top = scene.derive(&mut a).expect("the numeric top derives");
    TopModel::new(&mut a, &top, &[]).expect("a numeric top has no parameters")
}

#[test]
fn forty_point_masses_match_direct_summation() {
    let n = 40;
    let mut rng = Rng::new(40);
    let cloud = particles(n, &mut rng);
    let (_, model, size) = parametric(&cloud);
    // The derivation does not grow with the number of parts (about 15,000 nodes for any N
    // once the entries are named; the unnamed entries needed millions at N = 10).
    assert!(size < 60_000, "the arena grew to {size} nodes");
    let reference = direct(&cloud);
    for _ in 0..200 {
        let state = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.2, 2.9),
            rng.uniform(-3.0, 3.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-20.0, 20.0),
        ];
        let got = model.accelerations(&state).expect("regular chart");
        let want = reference.accelerations(&state).expect("regular chart");
        for k in 0..3 {
            assert_relative_eq!(got[k], want[k], max_relative = 1e-8, epsilon = 1e-8);
        }
        assert_relative_eq!(
            model.energy(&state),
            reference.energy(&state),
            max_relative = 1e-10
        );
    }
}

#[test]
fn a_single_point_mass_is_still_singular() {
    // Its inertia about the pivot has a zero eigenvalue along r: the determinant vanishes
    // identically, which the named entries must not hide.
    assert!(
        matches!(single(), Err(LagrangeError::SingularMassMatrix { .. })),
        "a lone point mass cannot be a top about a pivot"
    );
}

fn single() -> Result<(), LagrangeError> {
    let mut a = Arena::new();
    let z = a.zero();
    let m = a.parameter("m");
    let at = [a.parameter("x"), a.parameter("y"), a.parameter("z")];
    let d = Description {
        parts: vec![Part::new(Shape::Particle { mass: m }, at)],
        pivot: Some([z, z, z]),
    };
    let body = SymbolicBody::new(&mut a, &d).expect("the mass properties exist");
    let mut scene = TopScene::free(&mut a, body.props.inertia);
    scene.mass = body.props.mass;
    scene.center = body.props.center;
    scene.gravity = Some(a.number("9.81").unwrap());
    scene.derive(&mut a).map(|_| ())
}

/// Twenty field-valued point masses compile (this took minutes and gigabytes before the
/// entries were named) and agree with the direct summation at one state.
#[derive(RigidBody)]
#[rigid(
    particle(mass = m0, at = [x0, y0, z0]),
    particle(mass = m1, at = [x1, y1, z1]),
    particle(mass = m2, at = [x2, y2, z2]),
    particle(mass = m3, at = [x3, y3, z3]),
    particle(mass = m4, at = [x4, y4, z4]),
    particle(mass = m5, at = [x5, y5, z5]),
    particle(mass = m6, at = [x6, y6, z6]),
    particle(mass = m7, at = [x7, y7, z7]),
    particle(mass = m8, at = [x8, y8, z8]),
    particle(mass = m9, at = [x9, y9, z9]),
    particle(mass = m10, at = [x10, y10, z10]),
    particle(mass = m11, at = [x11, y11, z11]),
    particle(mass = m12, at = [x12, y12, z12]),
    particle(mass = m13, at = [x13, y13, z13]),
    particle(mass = m14, at = [x14, y14, z14]),
    particle(mass = m15, at = [x15, y15, z15]),
    particle(mass = m16, at = [x16, y16, z16]),
    particle(mass = m17, at = [x17, y17, z17]),
    particle(mass = m18, at = [x18, y18, z18]),
    particle(mass = m19, at = [x19, y19, z19]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
#[rustfmt::skip]
struct Cloud {
    m0: f64, x0: f64, y0: f64, z0: f64, m1: f64, x1: f64, y1: f64, z1: f64,
    m2: f64, x2: f64, y2: f64, z2: f64, m3: f64, x3: f64, y3: f64, z3: f64,
    m4: f64, x4: f64, y4: f64, z4: f64, m5: f64, x5: f64, y5: f64, z5: f64,
    m6: f64, x6: f64, y6: f64, z6: f64, m7: f64, x7: f64, y7: f64, z7: f64,
    m8: f64, x8: f64, y8: f64, z8: f64, m9: f64, x9: f64, y9: f64, z9: f64,
    m10: f64, x10: f64, y10: f64, z10: f64, m11: f64, x11: f64, y11: f64, z11: f64,
    m12: f64, x12: f64, y12: f64, z12: f64, m13: f64, x13: f64, y13: f64, z13: f64,
    m14: f64, x14: f64, y14: f64, z14: f64, m15: f64, x15: f64, y15: f64, z15: f64,
    m16: f64, x16: f64, y16: f64, z16: f64, m17: f64, x17: f64, y17: f64, z17: f64,
    m18: f64, x18: f64, y18: f64, z18: f64, m19: f64, x19: f64, y19: f64, z19: f64,
}

#[test]
fn twenty_point_masses_compile_and_agree() {
    let mut rng = Rng::new(20);
    let p = particles(20, &mut rng);
    let v = |i: usize| (p[i].0, p[i].1[0], p[i].1[1], p[i].1[2]);
    macro_rules! cloud {
        ($($m:ident $x:ident $y:ident $z:ident $i:literal),*) => {
            Cloud { $($m: v($i).0, $x: v($i).1, $y: v($i).2, $z: v($i).3),* }
        };
    }
    let top = cloud!(
        m0 x0 y0 z0 0, m1 x1 y1 z1 1, m2 x2 y2 z2 2, m3 x3 y3 z3 3, m4 x4 y4 z4 4,
        m5 x5 y5 z5 5, m6 x6 y6 z6 6, m7 x7 y7 z7 7, m8 x8 y8 z8 8, m9 x9 y9 z9 9,
        m10 x10 y10 z10 10, m11 x11 y11 z11 11, m12 x12 y12 z12 12, m13 x13 y13 z13 13,
        m14 x14 y14 z14 14, m15 x15 y15 z15 15, m16 x16 y16 z16 16, m17 x17 y17 z17 17,
        m18 x18 y18 z18 18, m19 x19 y19 z19 19
    );
    let reference = direct(&p);
    let state = [0.3, 1.1, -0.4, 1.5, -2.0, 25.0];
    let got = top.accelerations_unchecked_in(AngleSequence::Zxz, 0.0, &state);
    let want = reference.accelerations(&state).expect("regular chart");
    for k in 0..3 {
        assert_relative_eq!(got[k], want[k], max_relative = 1e-8, epsilon = 1e-8);
    }
}
