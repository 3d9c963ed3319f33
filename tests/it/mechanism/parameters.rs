//! Field values of `#[derive(Mechanism)]` meet the rules literals meet at compile time: each
//! quantity a key may take from a field (gravity, a joint's location and axes, springs,
//! dampers, efforts, torques, each part's mass, dimensions and inertia), given a bad value,
//! makes the checked accelerations a typed `MechanismError` naming the body or joint, the
//! quantity and the value, before anything is evaluated.

use precess::body::BodyError;
use precess::mechanism::MechanismError;
use precess::prelude::*;

/// An arm on a tilted hinge and a hand on a universal joint, every load and every part
/// dimension a field.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = [0.0, gy, gz])]
#[body(arm, parent = ground, joint = revolute(name = shoulder, axis = [ax, 0.0, 1.0], at = [0.0, 0.0, h]),
       q = theta, damper = c, effort = tau, spring(k = k, rest = rest),
       body_torque = [tb, 0.0, 0.0], space_torque = [0.0, ts, 0.0],
       parts(cylinder(mass = m, radius = r, length = len, at = [0.0, 0.0, -d]),
             body(mass = mb, inertia = diag(i1, i2, i3), at = [0.0, 0.0, -len])))]
#[body(hand, parent = arm, joint = universal(axes = [[ux, uy, 0.0], y], at = [0.0, 0.0, -len]),
       q = [alpha, beta], parts(sphere(mass = mh, radius = rh)))]
struct Arm {
    gy: f64,
    gz: f64,
    ax: f64,
    h: f64,
    c: f64,
    tau: f64,
    k: f64,
    rest: f64,
    tb: f64,
    ts: f64,
    m: f64,
    r: f64,
    len: f64,
    d: f64,
    mb: f64,
    i1: f64,
    i2: f64,
    i3: f64,
    ux: f64,
    uy: f64,
    mh: f64,
    rh: f64,
}

const GOOD: Arm = Arm {
    gy: 0.5,
    gz: -9.81,
    ax: 0.2,
    h: 0.1,
    c: 0.05,
    tau: 0.3,
    k: 2.0,
    rest: 0.1,
    tb: 0.01,
    ts: -0.02,
    m: 1.0,
    r: 0.05,
    len: 0.6,
    d: 0.3,
    mb: 0.2,
    i1: 0.01,
    i2: 0.012,
    i3: 0.015,
    ux: 1.0,
    uy: 0.1,
    mh: 0.3,
    rh: 0.04,
};

/// The checked accelerations' error at a regular state for `arm`.
fn refused(arm: Arm) -> MechanismError {
    let q = [0.3, 0.2, -0.1];
    let qdot = [0.1, -0.2, 0.3];
    let e = arm.check_parameters().expect_err("a bad value is refused");
    let from_accelerations = arm
        .accelerations(0.0, &q, &qdot)
        .expect_err("the checked accelerations refuse it too");
    // By their text: a NaN value is not equal to itself.
    assert_eq!(format!("{e:?}"), format!("{from_accelerations:?}"));
    e
}

fn non_finite(owner: &str, quantity: &str, value: f64) -> MechanismError {
    MechanismError::NonFiniteParameter {
        owner: owner.to_owned(),
        quantity: quantity.to_owned(),
        value,
    }
}

#[test]
fn good_values_pass_and_give_finite_accelerations() {
    assert_eq!(GOOD.check_parameters(), Ok(()));
    let a = GOOD.accelerations(0.0, &[0.3, 0.2, -0.1], &[0.1, -0.2, 0.3]);
    assert!(a.is_ok_and(|a| a.iter().all(|v| v.is_finite())));
}

#[test]
fn non_finite_settings_and_geometry_are_named() {
    let shoulder = "joint `shoulder`";
    let arm = "body `arm`";
    let cases: [(Arm, MechanismError); 9] = [
        (
            Arm {
                gy: f64::NAN,
                ..GOOD
            },
            non_finite("the mechanism", "gravity[1]", f64::NAN),
        ),
        (
            Arm {
                gz: f64::INFINITY,
                ..GOOD
            },
            non_finite("the mechanism", "gravity[2]", f64::INFINITY),
        ),
        (
            Arm {
                h: f64::NEG_INFINITY,
                ..GOOD
            },
            non_finite(shoulder, "at[2]", f64::NEG_INFINITY),
        ),
        (
            Arm {
                ax: f64::NAN,
                ..GOOD
            },
            non_finite(shoulder, "axis[0]", f64::NAN),
        ),
        (
            Arm {
                rest: f64::INFINITY,
                ..GOOD
            },
            non_finite(shoulder, "spring rest of `theta`", f64::INFINITY),
        ),
        (
            Arm {
                tau: f64::NAN,
                ..GOOD
            },
            non_finite(shoulder, "effort on `theta`", f64::NAN),
        ),
        (
            Arm {
                c: f64::INFINITY,
                ..GOOD
            },
            non_finite(shoulder, "damper of `theta`", f64::INFINITY),
        ),
        (
            Arm {
                tb: f64::NAN,
                ..GOOD
            },
            non_finite(arm, "body_torque[0]", f64::NAN),
        ),
        (
            Arm {
                ts: f64::INFINITY,
                ..GOOD
            },
            non_finite(arm, "space_torque[1]", f64::INFINITY),
        ),
    ];
    for (bad, expected) in cases {
        let got = refused(bad);
        // NaN ≠ NaN: compare the names and the value's class.
        match (&got, &expected) {
            (
                MechanismError::NonFiniteParameter {
                    owner,
                    quantity,
                    value,
                },
                MechanismError::NonFiniteParameter {
                    owner: o,
                    quantity: q,
                    value: v,
                },
            ) => {
                assert_eq!((owner, quantity), (o, q));
                assert!(value.is_nan() && v.is_nan() || value == v, "{got}");
            }
            _ => panic!("expected {expected}, got {got}"),
        }
        println!("{got}");
    }
}

#[test]
fn negative_springs_and_dampers_are_refused_by_name() {
    let e = refused(Arm { c: -0.1, ..GOOD });
    assert_eq!(
        e,
        MechanismError::NegativeParameter {
            owner: "joint `shoulder`".into(),
            quantity: "damper of `theta`".into(),
            value: -0.1,
        }
    );
    let e = refused(Arm { k: -2.0, ..GOOD });
    assert_eq!(
        e,
        MechanismError::NegativeParameter {
            owner: "joint `shoulder`".into(),
            quantity: "spring stiffness of `theta`".into(),
            value: -2.0,
        }
    );
}

#[test]
fn an_axis_of_zero_length_from_fields_is_refused() {
    let e = refused(Arm {
        ux: 0.0,
        uy: 0.0,
        ..GOOD
    });
    assert_eq!(
        e,
        MechanismError::ZeroAxis {
            joint: "hand".into(),
            squared_length: Some(0.0),
        }
    );
    // Below the smallest normal |axis|² the direction is lost to underflow.
    let e = refused(Arm {
        ux: 1e-160,
        uy: 0.0,
        ..GOOD
    });
    assert!(
        matches!(e, MechanismError::ZeroAxis { ref joint, .. } if joint == "hand"),
        "{e}"
    );
}

#[test]
fn parts_from_fields_meet_the_body_rules() {
    let part = |body: &str, error: BodyError| MechanismError::Part {
        body: body.into(),
        error,
    };
    assert_eq!(
        refused(Arm { m: -1.0, ..GOOD }),
        part(
            "arm",
            BodyError::NonPositiveMass {
                part: 0,
                kind: "cylinder",
                value: -1.0
            }
        )
    );
    assert_eq!(
        refused(Arm { r: 0.0, ..GOOD }),
        part(
            "arm",
            BodyError::NonPositiveDimension {
                part: 0,
                kind: "cylinder",
                key: "radius",
                value: 0.0
            }
        )
    );
    assert_eq!(
        refused(Arm { rh: -0.04, ..GOOD }),
        part(
            "hand",
            BodyError::NonPositiveDimension {
                part: 0,
                kind: "sphere",
                key: "radius",
                value: -0.04
            }
        )
    );
    // 0.01 + 0.012 < 0.03: no rigid body has these principal moments.
    let e = refused(Arm { i3: 0.03, ..GOOD });
    assert!(
        matches!(&e, MechanismError::Part { body, error: BodyError::TriangleInequality { part: 1, .. } } if body == "arm"),
        "{e}"
    );
    let e = refused(Arm { i1: -0.01, ..GOOD });
    assert!(
        matches!(&e, MechanismError::Part { body, error: BodyError::NotPositiveDefinite { part: 1, .. } } if body == "arm"),
        "{e}"
    );
    let e = refused(Arm {
        d: f64::NAN,
        ..GOOD
    });
    assert!(
        matches!(&e, MechanismError::Part { body, error: BodyError::NonFinite { part: 0, .. } } if body == "arm"),
        "{e}"
    );
    println!("{e}");
}

#[test]
fn a_massless_part_is_allowed_its_geometry_still_checked() {
    // A zero mass is a massless link (the singular mass matrix's concern), not a bad value.
    assert_eq!(Arm { mb: 0.0, ..GOOD }.check_parameters(), Ok(()));
    assert_eq!(
        Arm {
            mh: 0.0,
            rh: 0.0,
            ..GOOD
        }
        .check_parameters(),
        Err(MechanismError::Part {
            body: "hand".into(),
            error: BodyError::NonPositiveDimension {
                part: 0,
                kind: "sphere",
                key: "radius",
                value: 0.0
            },
        })
    );
}

/// The run-time model gives parameters the same mass-property checks: a pendulum whose mass
/// and inertia are parameters (`m`, and `a`, `b`, `c` on the diagonal), on a hinge about x
/// (which reads only `m` and `a`) or on a ball joint (which reads them all).
mod run_time {
    use precess::mechanism::{JointKind, MechanismModel, MechanismScene, Parent, Route};
    use precess::rigid::AngleSequence;
    use precess::sym::Arena;

    use super::*;

    fn model(ball: bool, values: &[(&str, f64)]) -> Result<MechanismModel, MechanismError> {
        let mut a = Arena::new();
        let (o, z) = (a.one(), a.zero());
        let (kind, names) = if ball {
            let sequence = AngleSequence::Zyx;
            (
                JointKind::Spherical { sequence },
                vec!["yaw", "pitch", "roll"],
            )
        } else {
            (JointKind::Revolute { axis: [o, z, z] }, vec!["theta"])
        };
        let mut body = MechanismScene::body(&mut a, "bob", Parent::Ground, kind, &names);
        body.mass = a.parameter("m");
        let down = a.integer(-1);
        body.center = [z, z, down];
        let (ia, ib, ic) = (a.parameter("a"), a.parameter("b"), a.parameter("c"));
        body.inertia = [[ia, z, z], [z, ib, z], [z, z, ic]];
        let mut scene = MechanismScene::new();
        scene.bodies.push(body);
        let g = a.integer(-10);
        scene.gravity = Some([z, z, g]);
        MechanismModel::new(&mut a, &scene, Route::Auto, values)
    }

    const GOOD: [(&str, f64); 4] = [("m", 2.0), ("a", 0.5), ("b", 0.4), ("c", 0.3)];

    fn ball_with(changes: &[(&str, f64)]) -> Result<MechanismModel, MechanismError> {
        let mut values = GOOD.to_vec();
        for &(name, v) in changes {
            if let Some(slot) = values.iter_mut().find(|(n, _)| *n == name) {
                slot.1 = v;
            }
        }
        model(true, &values)
    }

    #[test]
    fn good_values_give_the_pendulum() {
        let hinge = model(false, &GOOD[..2]).expect("a body");
        // (m l² + a) θ̈ = −m g l sin θ with l = 1, g = 10.
        let qdd = hinge.accelerations(0.0, &[0.3], &[0.0]).expect("finite");
        let expected = -2.0 * 10.0 * 0.3f64.sin() / (2.0 + 0.5);
        assert!(
            (qdd[0] - expected).abs() < 1e-14,
            "{} vs {expected}",
            qdd[0]
        );
        // The ball joint rolled by 0.3 about x swings back the same way.
        let ball = ball_with(&[]).expect("a body");
        let qdd = ball
            .accelerations(0.0, &[0.0, 0.0, 0.3], &[0.0; 3])
            .expect("finite");
        assert!((qdd[2] - expected).abs() < 1e-14, "{qdd:?} vs {expected}");
        // A point mass (no inertia about its centre) is a body too.
        ball_with(&[("a", 0.0), ("b", 0.0), ("c", 0.0)]).expect("a point mass");
    }

    #[test]
    fn a_negative_mass_is_refused_at_construction_and_by_set() {
        match ball_with(&[("m", -1.0)]) {
            Err(MechanismError::NegativeParameter {
                owner,
                quantity,
                value,
            }) => {
                assert_eq!((owner.as_str(), quantity.as_str()), ("body `bob`", "mass"));
                assert_eq!(value, -1.0);
            }
            other => panic!("expected a negative mass, got {other:?}"),
        }
        let mut hinge = model(false, &GOOD[..2]).expect("a body");
        assert!(matches!(
            hinge.set("m", -3.0),
            Err(MechanismError::NegativeParameter { value, .. }) if value == -3.0
        ));
    }

    #[test]
    fn impossible_inertias_are_refused() {
        // 0.1 + 0.2 < 0.9: no mass distribution has these principal moments.
        match ball_with(&[("a", 0.1), ("b", 0.2), ("c", 0.9)]) {
            Err(MechanismError::Part {
                body,
                error: BodyError::TriangleInequality { moments, .. },
            }) => {
                assert_eq!(body, "bob");
                assert_eq!(moments, [0.1, 0.2, 0.9]);
            }
            other => panic!("expected the triangle inequality, got {other:?}"),
        }
        assert!(matches!(
            ball_with(&[("b", -0.4)]),
            Err(MechanismError::Part {
                error: BodyError::NotPositiveDefinite { .. },
                ..
            })
        ));
        let mut ball = ball_with(&[]).expect("a body");
        assert!(matches!(
            ball.set("c", 5.0),
            Err(MechanismError::Part {
                error: BodyError::TriangleInequality { .. },
                ..
            })
        ));
        // The hinge reads only `a`: the moments across it are not its concern.
        model(false, &[("m", 2.0), ("a", 0.5)]).expect("b and c unread");
    }
}
