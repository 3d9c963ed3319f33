//! Bad mechanisms and bad states get typed errors naming what is wrong.

use precess::mechanism::{
    JointKind, MechanismError, MechanismModel, MechanismScene, Parent, Route,
};
use precess::sym::Arena;

fn hinge(a: &Arena) -> JointKind {
    let (o, z) = (a.one(), a.zero());
    JointKind::Revolute { axis: [o, z, z] }
}

/// A two-link chain whose masses and lengths are parameters.
fn two_links(a: &mut Arena) -> MechanismScene {
    let mut scene = MechanismScene::new();
    let z = a.zero();
    for i in 0..2 {
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(0)
        };
        let mut b = MechanismScene::body(
            a,
            &format!("link{i}"),
            parent,
            hinge(a),
            &[&format!("q{i}")],
        );
        b.mass = a.parameter(&format!("m{i}"));
        b.center = [z, z, a.integer(-1)];
        if i == 1 {
            b.joint.at = [z, z, a.integer(-1)];
        }
        scene.bodies.push(b);
    }
    let g = a.parameter("g");
    scene.gravity = Some([z, z, a.neg(g)]);
    scene
}

#[test]
fn an_empty_mechanism_has_no_moving_joint() {
    let a = Arena::new();
    assert_eq!(
        MechanismScene::new().validate(&a),
        Err(MechanismError::NoMovingJoint)
    );
}

#[test]
fn parents_must_exist_and_form_a_tree() {
    let mut a = Arena::new();
    let mut scene = two_links(&mut a);
    scene.bodies[1].joint.parent = Parent::Body(7);
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::UnknownParent {
            body: "link1".into(),
            parent: 7,
            count: 2
        })
    );
    scene.bodies[1].joint.parent = Parent::Body(0);
    scene.bodies[0].joint.parent = Parent::Body(1);
    let err = scene.validate(&a).unwrap_err();
    assert_eq!(
        err,
        MechanismError::Cycle {
            bodies: vec!["link0".into(), "link1".into()]
        }
    );
    assert!(err.to_string().contains("link0 → link1"));
    // A body that is its own parent.
    scene.bodies[0].joint.parent = Parent::Body(0);
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::Cycle {
            bodies: vec!["link0".into()]
        })
    );
}

#[test]
fn names_must_be_unique() {
    let mut a = Arena::new();
    let mut scene = two_links(&mut a);
    scene.bodies[1].joint.coordinates[0] = "q0".into();
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::DuplicateName {
            kind: "coordinate",
            name: "q0".into()
        })
    );
    let mut scene = two_links(&mut a);
    scene.bodies[1].joint.name = "link0".into();
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::DuplicateName {
            kind: "joint",
            name: "link0".into()
        })
    );
    let mut scene = two_links(&mut a);
    scene.bodies[1].name = "link0".into();
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::DuplicateName {
            kind: "body",
            name: "link0".into()
        })
    );
}

#[test]
fn counts_must_match_the_joint() {
    let mut a = Arena::new();
    let mut scene = two_links(&mut a);
    scene.bodies[0].joint.coordinates.push("extra".into());
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::WrongCoordinateCount {
            joint: "link0".into(),
            kind: "revolute",
            expected: 1,
            got: 2
        })
    );
    let mut scene = two_links(&mut a);
    scene.bodies[1].joint.loads.clear();
    assert!(matches!(
        scene.validate(&a),
        Err(MechanismError::WrongLoadCount {
            expected: 1,
            got: 0,
            ..
        })
    ));
}

#[test]
fn axes_must_not_vanish() {
    let mut a = Arena::new();
    let mut scene = two_links(&mut a);
    let z = a.zero();
    scene.bodies[1].joint.kind = JointKind::Prismatic { axis: [z; 3] };
    assert_eq!(
        scene.validate(&a),
        Err(MechanismError::ZeroAxis {
            joint: "link1".into(),
            squared_length: None
        })
    );
    // An axis of parameters is checked for its values by the run-time model.
    let mut scene = two_links(&mut a);
    let k = a.parameter("k");
    scene.bodies[1].joint.kind = JointKind::Revolute { axis: [k, z, z] };
    let values = [("m0", 1.0), ("m1", 1.0), ("g", 9.81), ("k", 0.0)];
    let err = MechanismModel::new(&mut a, &scene, Route::Factored, &values).unwrap_err();
    assert_eq!(
        err,
        MechanismError::ZeroAxis {
            joint: "link1".into(),
            squared_length: Some(0.0)
        }
    );
    let values = [("m0", 1.0), ("m1", 1.0), ("g", 9.81), ("k", 2.0)];
    let mut model = MechanismModel::new(&mut a, &scene, Route::Factored, &values).expect("valid");
    assert!(matches!(
        model.set("k", 0.0),
        Err(MechanismError::ZeroAxis { .. })
    ));
}

#[test]
fn a_massless_chain_has_a_singular_mass_matrix() {
    for route in [Route::Symbolic, Route::Factored, Route::Auto] {
        let mut a = Arena::new();
        let scene = two_links(&mut a);
        let values = [("m0", 0.0), ("m1", 0.0), ("g", 9.81)];
        let model = MechanismModel::new(&mut a, &scene, route, &values).expect("derives");
        let err = model
            .accelerations(0.0, &[0.1, 0.2], &[0.0, 0.0])
            .unwrap_err();
        assert!(
            matches!(err, MechanismError::SingularMassMatrix { pivot: 0, value } if value == 0.0),
            "{route:?}: {err}"
        );
        // Literal zero masses are singular everywhere: refused when deriving.
        let mut scene = two_links(&mut a);
        let z = a.zero();
        scene.bodies[0].mass = z;
        scene.bodies[1].mass = z;
        assert!(matches!(
            scene.derive(&mut a, route),
            Err(MechanismError::SingularMassMatrix { .. })
        ));
    }
}

#[test]
fn bad_states_are_refused() {
    let mut a = Arena::new();
    let scene = two_links(&mut a);
    let values = [("m0", 1.0), ("m1", 2.0), ("g", 9.81)];
    let model = MechanismModel::new(&mut a, &scene, Route::Auto, &values).expect("derives");
    let err = model
        .accelerations(0.0, &[f64::NAN, 0.0], &[0.0, 0.0])
        .unwrap_err();
    assert!(
        matches!(err, MechanismError::NonFinite { quantity: "q", .. }),
        "{err}"
    );
    let err = model
        .energy(0.0, &[0.0, 0.0], &[0.0, f64::INFINITY])
        .unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::NonFinite {
                quantity: "q̇", ..
            }
        ),
        "{err}"
    );
    let err = model.accelerations(0.0, &[0.0], &[0.0, 0.0]).unwrap_err();
    assert_eq!(
        err,
        MechanismError::StateLength {
            quantity: "q",
            expected: 2,
            got: 1
        }
    );
    assert!(matches!(
        model.system::<3>(),
        Err(MechanismError::StateLength { got: 3, .. })
    ));
    // The recursive route refuses the same bad state with the same error.
    let recursive =
        MechanismModel::new(&mut a, &scene, Route::Recursive, &values).expect("derives");
    assert!(matches!(
        recursive.accelerations(0.0, &[f64::NAN, 0.0], &[0.0, 0.0]),
        Err(MechanismError::NonFinite { quantity: "q", .. })
    ));
    assert!(matches!(
        MechanismModel::new(&mut a, &scene, Route::Auto, &[("m0", 1.0)]),
        Err(MechanismError::Binding(_))
    ));
}
