//! Derived bodies of literals: mass properties against closed forms, the principal frame,
//! and the generated Euler's equations against the generic I⁻¹ (G − ω × I ω).

use crate::common;

use common::body::check_euler;
use nalgebra::{Matrix3, Vector3};
use precess::prelude::*;

/// The design's top with literal values: stem, disk, pivot at the origin.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
    disk(mass = 0.5, radius = 0.03, at = [0.0, 0.0, 0.05]),
    pivot = [0.0, 0.0, 0.0],
)]
struct Top;

/// The classic top: a cone standing on its apex at the pivot, base up.
#[derive(RigidBody)]
#[rigid(cone(mass = 1.0, radius = 0.1, height = 0.4, axis = -z, at = [0.0, 0.0, 0.4]), pivot = [0.0, 0.0, 0.0])]
struct ConeTop;

/// A brick about its centre of mass.
#[derive(RigidBody)]
#[rigid(box(mass = 2.0, size = [0.1, 0.2, 0.3]))]
struct Brick {}

/// Off-axis parts: the tensor has products of inertia, decomposed at compile time.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = 1.0, radius = 0.1, at = [0.1, 0.2, 0.0]),
    cone(mass = 2.0, radius = 0.1, height = 0.3, axis = x, at = [-0.1, 0.0, 0.3]),
    ring(mass = 0.5, radius = 0.2, axis = y, at = [0.0, -0.3, 0.1]),
)]
struct Lumpy;

/// An explicit full tensor.
#[derive(RigidBody)]
#[rigid(body(mass = 3.0, center = [0.0, 0.0, 0.0], inertia = [[2.0, 0.3, -0.1], [0.3, 1.5, 0.2], [-0.1, 0.2, 1.0]]))]
struct Explicit;

/// Every other shape, and arithmetic on literals.
#[derive(RigidBody)]
#[rigid(
    particle(mass = 0.1, at = [0.5, 0.0, 0.0]),
    shell(mass = 0.3, radius = 0.2),
    tube(mass = 1.0, inner = 0.05, outer = 0.1, length = 0.4, axis = y),
    rod(mass = 0.2, length = 1.0, axis = x, at = [0.0, 0.0, -0.1]),
    ellipsoid(mass = 1.5, semi_axes = [0.1, 0.2, 0.3], at = [0.0, 0.1 * 2.0, 0.0]),
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.2, 0.2, 0.1), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
struct Everything;

#[test]
fn top_matches_its_closed_form() {
    let (ms, rs, ls, md, rd, hd) = (0.2, 0.004, 0.06, 0.5, 0.03, 0.05);
    let t = ms * (3.0 * rs * rs + ls * ls) / 12.0
        + ms * (ls / 2.0f64).powi(2)
        + md * rd * rd / 4.0
        + md * hd * hd;
    let a = ms * rs * rs / 2.0 + md * rd * rd / 2.0;
    let top = Top;
    assert_eq!(top.mass(), 0.7);
    assert!(
        (top.center_of_mass() - Vector3::new(0.0, 0.0, (ms * 0.03 + md * hd) / 0.7)).norm() < 1e-17
    );
    assert_eq!(top.reference_point(), Vector3::zeros());
    let closed = Matrix3::from_diagonal(&Vector3::new(t, t, a));
    assert!((top.inertia() - closed).abs().max() <= 4e-16 * t);
    assert_eq!(top.principal().rotation.matrix(), &Matrix3::identity());
    assert!(
        (top.principal().moments - Vector3::new(t, t, a))
            .abs()
            .max()
            <= 4e-16 * t
    );
    // Symmetric about 3: ω̇3 = G3/I3 whatever ω1 and ω2.
    let w = top.euler_rhs_principal(
        &Vector3::new(3.0, -2.0, 50.0),
        &Vector3::new(0.0, 0.0, 1e-3),
    );
    assert!((w.z - 1e-3 / a).abs() < 1e-12 * w.z.abs());
    println!(
        "top: worst euler_rhs_principal {:.1e}",
        check_euler(&top, 1)
    );
}

#[test]
fn brick_about_its_centre() {
    let (m, a, b, c) = (2.0, 0.1, 0.2, 0.3);
    let closed = Vector3::new(
        m * (b * b + c * c) / 12.0,
        m * (a * a + c * c) / 12.0,
        m * (a * a + b * b) / 12.0,
    );
    let brick = Brick {};
    assert!((brick.principal().moments - closed).abs().max() < 1e-17);
    assert_eq!(brick.reference_point(), brick.center_of_mass());
    println!(
        "brick: worst euler_rhs_principal {:.1e}",
        check_euler(&brick, 2)
    );
}

#[test]
fn lumpy_body_has_a_rotated_principal_frame() {
    let body = Lumpy;
    let r = *body.principal().rotation.matrix();
    let i = body.inertia();
    let d = r.transpose() * i * r;
    let off = d[(0, 1)].abs().max(d[(0, 2)].abs()).max(d[(1, 2)].abs());
    assert!(off < 1e-14 * d.diagonal().max());
    assert!((r.determinant() - 1.0).abs() < 1e-14);
    assert!(r != Matrix3::identity());
    println!(
        "lumpy: worst euler_rhs_principal {:.1e}",
        check_euler(&body, 3)
    );
}

#[test]
fn explicit_tensor_is_kept() {
    let body = Explicit;
    let t = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.0);
    assert_eq!(body.inertia(), t);
    println!(
        "explicit: worst euler_rhs_principal {:.1e}",
        check_euler(&body, 4)
    );
}

#[test]
fn every_shape_against_closed_forms() {
    let e = Everything;
    let mut t = Matrix3::zeros();
    let add = |t: &mut Matrix3<f64>, m: f64, c: Vector3<f64>, diag: Vector3<f64>| {
        *t += Matrix3::from_diagonal(&diag)
            + m * (Matrix3::identity() * c.norm_squared() - c * c.transpose());
    };
    add(&mut t, 0.1, Vector3::new(0.5, 0.0, 0.0), Vector3::zeros());
    let s = 2.0 / 3.0 * 0.3 * 0.04;
    add(&mut t, 0.3, Vector3::zeros(), Vector3::new(s, s, s));
    let (ra, rb, l) = (0.05f64, 0.1f64, 0.4f64);
    let tt = (3.0 * (ra * ra + rb * rb) + l * l) / 12.0;
    add(
        &mut t,
        1.0,
        Vector3::zeros(),
        Vector3::new(tt, 0.5 * (ra * ra + rb * rb), tt),
    );
    add(
        &mut t,
        0.2,
        Vector3::new(0.0, 0.0, -0.1),
        Vector3::new(0.0, 0.2 / 12.0, 0.2 / 12.0),
    );
    let (a, b, c) = (0.1f64, 0.2f64, 0.3f64);
    let k = 1.5 / 5.0;
    add(
        &mut t,
        1.5,
        Vector3::new(0.0, 0.2, 0.0),
        Vector3::new(
            k * (b * b + c * c),
            k * (a * a + c * c),
            k * (a * a + b * b),
        ),
    );
    // Given about the pivot: taken as is.
    t += Matrix3::from_diagonal(&Vector3::new(0.2, 0.2, 0.1));
    let err = (e.inertia() - t).abs().max() / t.abs().max();
    println!("everything: inertia {err:.1e}");
    assert!(err < 1e-15);
    assert!((e.mass() - 4.1).abs() < 1e-15);
    println!(
        "everything: worst euler_rhs_principal {:.1e}",
        check_euler(&e, 5)
    );
}

#[test]
fn free_body_split() {
    // T = T_cm + ½ M V² and L = J_cm + R × P for the brick.
    let b = Brick {};
    let (w, v, r) = (
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.5, 0.0, -1.0),
        Vector3::new(0.0, 1.0, 0.0),
    );
    let t = 0.5 * w.dot(&(b.inertia_cm() * w)) + 0.5 * 2.0 * v.norm_squared();
    assert!((b.kinetic_energy_free(&w, &v) - t).abs() < 1e-15);
    let l = b.inertia_cm() * w + r.cross(&(2.0 * v));
    assert!((b.angular_momentum_about(&w, &r, &v) - l).norm() < 1e-15);
    assert!(b.validate().is_ok());
}

#[test]
fn cone_on_its_apex() {
    // About the apex: I⊥ = 3/20 m r² + 3/5 m h², I3 = 3/10 m r²; G at 3h/4 above it.
    let (m, r, h) = (1.0, 0.1, 0.4);
    let top = ConeTop;
    let t = 3.0 / 20.0 * m * r * r + 3.0 / 5.0 * m * h * h;
    let closed = Vector3::new(t, t, 3.0 / 10.0 * m * r * r);
    assert!((top.principal().moments - closed).abs().max() < 4e-16 * t);
    assert!((top.center_of_mass() - Vector3::new(0.0, 0.0, 0.75 * h)).norm() < 1e-16);
    println!(
        "cone top: worst euler_rhs_principal {:.1e}",
        check_euler(&top, 6)
    );
}
