//! Field types the derive accepts as parameters: `f64` however the primitive is written.

use approx::assert_relative_eq;
use precess::prelude::*;

/// A sphere whose fields name the primitive through each of its paths.
#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = r, at = [x, y, 0.0]))]
struct PrimitivePaths {
    m: core::primitive::f64,
    r: ::core::primitive::f64,
    x: std::primitive::f64,
    y: ::std::primitive::f64,
}

#[test]
fn the_primitive_f64_paths_are_f64_fields() {
    let body = PrimitivePaths {
        m: 3.0,
        r: 0.2,
        x: 1.0,
        y: -2.0,
    };
    assert_eq!(body.mass(), 3.0);
    assert_eq!(body.center_of_mass(), Vector3::new(1.0, -2.0, 0.0));
    // A solid sphere about its centre: I = 2/5 m r² on every axis.
    let i = 0.4 * 3.0 * 0.2 * 0.2;
    assert_relative_eq!(
        body.inertia(),
        Matrix3::from_diagonal_element(i),
        max_relative = 1e-15
    );
    assert!(body.validate().is_ok());
}
