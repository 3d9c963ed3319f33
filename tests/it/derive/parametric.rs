//! Derived bodies with field parameters: values computed from the fields at run time,
//! checked against closed forms at several parameter values, and validated at run time.

use crate::common;

use common::body::check_euler;
use nalgebra::{Matrix3, Vector3};
use precess::prelude::*;

/// The design's top: a literal stem and a disk whose mass, radius and height are fields.
#[derive(RigidBody, Clone, Copy)]
#[rigid(
    cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
    disk(mass = m, radius = r, at = [0.0, 0.0, h]),
    pivot = [0.0, 0.0, 0.0],
)]
struct Top {
    m: f64,
    r: f64,
    h: f64,
}

/// A dumbbell whose arm is tilted in x–z by field offsets: not symbolically diagonal, so the
/// frame is decomposed at run time.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = m, radius = 0.05, at = [d, 0.0, d / 2.0]),
    sphere(mass = 2.0 * m, radius = 0.05, at = [-d, 0.0, -(d / 2.0)]),
    cuboid(mass = 0.1, size = [0.3, a, 0.2]),
)]
struct Dumbbell {
    m: f64,
    d: f64,
    a: f64,
    #[allow(dead_code)]
    label: u32,
}

/// An explicit tensor with a parametric entry.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[i1, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.5]]))]
struct Tensor {
    i1: f64,
}

#[test]
fn top_follows_its_fields() {
    for (m, r, h) in [(0.5, 0.03, 0.05), (1.5, 0.1, 0.2), (0.01, 0.5, 0.01)] {
        let top = Top { m, r, h };
        let (ms, rs, ls) = (0.2, 0.004, 0.06);
        let t = ms * (3.0 * rs * rs + ls * ls) / 12.0
            + ms * (ls / 2.0f64).powi(2)
            + m * r * r / 4.0
            + m * h * h;
        let a = ms * rs * rs / 2.0 + m * r * r / 2.0;
        assert!((top.mass() - (ms + m)).abs() < 1e-15);
        let closed = Matrix3::from_diagonal(&Vector3::new(t, t, a));
        let err = (top.inertia() - closed).abs().max() / t;
        assert!(err < 1e-15, "inertia off by {err:e}");
        assert_eq!(top.principal().rotation.matrix(), &Matrix3::identity());
        assert!(top.validate().is_ok());
        println!(
            "top {m} {r} {h}: inertia {err:.1e}, euler_rhs_principal {:.1e}",
            check_euler(&top, 7)
        );
    }
}

#[test]
fn dumbbell_decomposes_at_run_time() {
    let body = Dumbbell {
        m: 1.0,
        d: 0.3,
        a: 0.15,
        label: 0,
    };
    let (m, d, a) = (1.0, 0.3, 0.15);
    // Direct: spheres' own moments, the cuboid's, and Σ m (r² E − x xᵀ) about the centre.
    let g = (m * Vector3::new(d, 0.0, d / 2.0) + 2.0 * m * Vector3::new(-d, 0.0, -d / 2.0))
        / (3.0 * m + 0.1);
    let mut t = Matrix3::zeros();
    for (mi, c) in [
        (m, Vector3::new(d, 0.0, d / 2.0)),
        (2.0 * m, Vector3::new(-d, 0.0, -d / 2.0)),
        (0.1, Vector3::zeros()),
    ] {
        let x: Vector3<f64> = c - g;
        t += mi * (Matrix3::identity() * x.norm_squared() - x * x.transpose());
    }
    t += Matrix3::identity() * (0.4 * 3.0 * m * 0.05 * 0.05);
    t += Matrix3::from_diagonal(&Vector3::new(a * a + 0.04, 0.09 + 0.04, 0.09 + a * a))
        * (0.1 / 12.0);
    let err = (body.inertia() - t).abs().max() / t.abs().max();
    assert!(err < 1e-14, "inertia off by {err:e}");
    let r = *body.principal().rotation.matrix();
    let dd = r.transpose() * t * r;
    assert!(dd[(0, 2)].abs() < 1e-14 * dd.diagonal().max());
    println!(
        "dumbbell: inertia {err:.1e}, euler_rhs_principal {:.1e}",
        check_euler(&body, 8)
    );
}

#[test]
fn run_time_validation() {
    assert_eq!(
        Top {
            m: -1.0,
            r: 0.03,
            h: 0.05
        }
        .validate(),
        Err(BodyError::NonPositiveMass {
            part: 1,
            kind: "disk",
            value: -1.0
        })
    );
    assert!(matches!(
        Top {
            m: 1.0,
            r: 0.0,
            h: 0.05
        }
        .validated(),
        Err(BodyError::NonPositiveDimension {
            part: 1,
            key: "radius",
            ..
        })
    ));
    assert!(matches!(
        Top {
            m: 1.0,
            r: f64::NAN,
            h: 0.05
        }
        .validate(),
        Err(BodyError::NonFinite { .. })
    ));
    assert!(
        Top {
            m: 1.0,
            r: 0.1,
            h: 0.05
        }
        .validated()
        .is_ok()
    );
    assert!(matches!(
        Tensor { i1: 5.0 }.validate(),
        Err(BodyError::TriangleInequality { .. })
    ));
    assert!(matches!(
        Tensor { i1: -1.0 }.validate(),
        Err(BodyError::NotPositiveDefinite { .. })
    ));
    assert!(Tensor { i1: 1.0 }.validate().is_ok());
    assert!(matches!(
        Dumbbell {
            m: 1.0,
            d: 0.3,
            a: -0.1,
            label: 0
        }
        .validate(),
        Err(BodyError::NonPositiveDimension { key: "size", .. })
    ));
}

#[test]
fn description_builds_the_same_body_at_run_time() {
    // A derived body's description, built with the run-time builder, gives the same body
    // with its frame precomputed once.
    let derived = Dumbbell {
        m: 1.0,
        d: 0.3,
        a: 0.15,
        label: 0,
    };
    let built = Body::new(derived.description()).expect("a valid body");
    let scale = derived.inertia().abs().max();
    assert!((built.inertia() - derived.inertia()).abs().max() < 1e-15 * scale);
    let (pb, pd) = (built.principal(), derived.principal());
    assert!((pb.moments - pd.moments).abs().max() < 1e-15 * scale);
    assert!((pb.rotation.matrix() - pd.rotation.matrix()).abs().max() < 1e-12);
    let (w, g) = (Vector3::new(1.0, -2.0, 3.0), Vector3::new(0.1, 0.2, -0.3));
    assert!(
        (built.euler_rhs_principal(&w, &g) - derived.euler_rhs_principal(&w, &g)).norm()
            < 1e-12 * derived.euler_rhs_principal(&w, &g).norm()
    );
    assert_eq!(built.description(), &derived.description());
}
