//! Shared by the mechanism tests: a numeric description of a mechanism and an independent
//! recursive Newton–Euler algorithm over it (both in the testkit, optimised), and the
//! symbolic scene built from the description.

pub mod examples;
pub use super::rng;
pub use precess_testkit::mechanism::{NumBody, NumJoint, NumLoad, NumMechanism, rnea};

use nalgebra::{Matrix3, Vector3};
use precess::mechanism::{CoordinateLoad, JointKind, MechanismScene, Parent, Spring};
use precess::sym::{Arena, ExprId};

/// How the numbers enter the scene: as exact literals (folded into the derivation) or as
/// parameters bound at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Values {
    Literals,
    Parameters,
}

/// The decimal `x` prints as, exactly (0.6 is 3/5, so 0.6² + 0.8² is 1 and the axis's
/// length folds); within half an ulp of `x`, far below the tests' tolerances.
pub fn exact(arena: &mut Arena, x: f64) -> ExprId {
    arena.number(&format!("{x:?}")).expect("a finite decimal")
}

/// The symbolic scene of `m`, with the `(name, value)` pairs to bind (empty for literals).
/// Axes and joint positions are always literals; masses, centres, inertias, loads and
/// gravity follow `values`.
pub fn scene(
    arena: &mut Arena,
    m: &NumMechanism,
    values: Values,
) -> (MechanismScene, Vec<(String, f64)>) {
    let mut bound: Vec<(String, f64)> = Vec::new();
    let mut value = |arena: &mut Arena, name: String, x: f64| -> ExprId {
        match values {
            Values::Literals => exact(arena, x),
            Values::Parameters => {
                bound.push((name.clone(), x));
                arena.parameter(&name)
            }
        }
    };
    let lit = |arena: &mut Arena, v: [f64; 3]| v.map(|x| exact(arena, x));
    let mut scene = MechanismScene::new();
    let mut coordinate = 0;
    for (i, b) in m.bodies.iter().enumerate() {
        let kind = match &b.joint {
            NumJoint::Revolute(a) => JointKind::Revolute {
                axis: lit(arena, *a),
            },
            NumJoint::Prismatic(a) => JointKind::Prismatic {
                axis: lit(arena, *a),
            },
            NumJoint::Universal(a, c) => JointKind::Universal {
                axes: [lit(arena, *a), lit(arena, *c)],
            },
            NumJoint::Spherical(s) => JointKind::Spherical { sequence: *s },
        };
        let names: Vec<String> = (0..b.joint.dof())
            .map(|k| format!("q{}", coordinate + k))
            .collect();
        let refs: Vec<&str> = names.iter().map(String::as_str).collect();
        let parent = b.parent.map_or(Parent::Ground, Parent::Body);
        let mut body = MechanismScene::body(arena, &format!("b{i}"), parent, kind, &refs);
        body.joint.at = lit(arena, b.at);
        body.mass = value(arena, format!("m{i}"), b.mass);
        body.center = [0, 1, 2].map(|k| value(arena, format!("c{i}_{k}"), b.center[k]));
        for r in 0..3 {
            for c in 0..3 {
                body.inertia[r][c] = if c < r {
                    body.inertia[c][r]
                } else {
                    value(arena, format!("I{i}_{r}{c}"), b.inertia[(r, c)])
                };
            }
        }
        body.joint.loads = b
            .loads
            .iter()
            .enumerate()
            .map(|(k, l)| {
                let j = coordinate + k;
                CoordinateLoad {
                    spring: l.spring.map(|(s, r)| Spring {
                        stiffness: value(arena, format!("k{j}"), s),
                        rest: value(arena, format!("rest{j}"), r),
                    }),
                    damper: l.damper.map(|c| value(arena, format!("c{j}"), c)),
                    effort: l.effort.map(|e| value(arena, format!("e{j}"), e)),
                }
            })
            .collect();
        body.body_torque = b
            .body_torque
            .map(|t| [0, 1, 2].map(|k| value(arena, format!("tb{i}_{k}"), t[k])));
        body.space_torque = b
            .space_torque
            .map(|t| [0, 1, 2].map(|k| value(arena, format!("ts{i}_{k}"), t[k])));
        coordinate += b.joint.dof();
        scene.bodies.push(body);
    }
    if m.gravity != [0.0; 3] {
        scene.gravity = Some([0, 1, 2].map(|k| value(arena, format!("g_{k}"), m.gravity[k])));
    }
    (scene, bound)
}

/// A symmetric positive definite inertia with principal moments obeying the triangle
/// inequality, turned by a random rotation.
pub fn random_inertia(rng: &mut rng::Rng) -> Matrix3<f64> {
    let a = rng.uniform(0.05, 0.2);
    let b = rng.uniform(0.05, 0.2);
    let c = rng.uniform((a - b).abs() + 0.01, a + b);
    let axis = rng.vector(-1.0, 1.0);
    let r = nalgebra::Rotation3::new(axis).into_inner();
    r * Matrix3::from_diagonal(&Vector3::new(a, b, c)) * r.transpose()
}

/// The relative difference max|a − b| / max(max|b|, floor), the one measure of agreement.
pub fn relative_difference(a: &[f64], b: &[f64], floor: f64) -> f64 {
    let scale = b.iter().fold(floor, |s, x| s.max(x.abs()));
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / scale
}

/// The double pendulum built by hand at run time, shared with the benches.
pub use precess_testkit::scenes::double_pendulum;
