//! Rotated parts in the derive: literal rotations fold to constants, a field angle, axis or
//! matrix is read at run time. The derived body, the symbolic body and the run-time builder
//! agree with each other, with closed forms and with direct summation; a rotation made of
//! fields is checked by `validate()`.

use crate::common;

use std::f64::consts::PI;

use common::body::*;
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};
use precess::body::{
    Description, Frame, Orientation, Part, SymbolicBody, Tensor as Rows, rotation_matrix,
};
use precess::prelude::*;
use precess::sym::{Arena, ExprId};

/// Three turned parts of literals about a pivot: an axis–angle cylinder, a box turned by
/// Euler angles, and a hanging cone laid along x by a matrix.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 2.5, radius = 0.3, length = 1.2, at = [0.2, -0.4, 0.9],
             rotate = axis_angle([0.3, -1.0, 0.7], 1.1)),
    cuboid(mass = 1.0, size = [0.2, 0.5, 0.9], rotate = zxz(0.4, 0.7, -0.2)),
    cone(mass = 0.5, radius = 0.3, height = 0.9, axis = -z, at = [0.0, 0.0, 0.9],
         rotate = matrix([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])),
    pivot = [0.0, 0.0, 0.0],
)]
struct Literal;

fn literal_by_builder() -> Body {
    BodyBuilder::new()
        .rotated_part(
            Shape::Cylinder {
                mass: 2.5,
                radius: 0.3,
                length: 1.2,
                axis: Axis::Z,
            },
            [0.2, -0.4, 0.9],
            Orientation::axis_angle([0.3, -1.0, 0.7], 1.1),
        )
        .rotated_part(
            Shape::Cuboid {
                mass: 1.0,
                size: [0.2, 0.5, 0.9],
            },
            [0.0; 3],
            Orientation::sequence([(Axis::Z, 0.4), (Axis::X, 0.7), (Axis::Z, -0.2)]),
        )
        .rotated_part(
            Shape::Cone {
                mass: 0.5,
                radius: 0.3,
                height: 0.9,
                axis: Axis::Z,
                reversed: true,
            },
            [0.0, 0.0, 0.9],
            [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]],
        )
        .pivot([0.0; 3])
        .build()
        .expect("a valid body")
}

#[test]
fn literal_rotations_agree_with_the_builder_and_direct_summation() {
    let (derived, built) = (Literal, literal_by_builder());
    let e = rel_err(&derived.inertia(), &built.inertia());
    let e_cm = rel_err(&derived.inertia_cm(), &built.inertia_cm());
    let e_center = (derived.center_of_mass() - built.center_of_mass()).norm();
    println!("literal: derived vs builder {e:.1e} (about G {e_cm:.1e}), centre {e_center:.1e}");
    assert!(e < 4e-16 && e_cm < 4e-16, "{e:e} {e_cm:e}");
    assert!(e_center < 1e-16, "{e_center:e}");
    assert_eq!(derived.description(), *built.description());
    // The same three solids as particle lattices, turned by nalgebra's rotations.
    let n = 80;
    let cylinder =
        Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::new(0.3, -1.0, 0.7)), 1.1);
    let cuboid = Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), 0.7)
        * Rotation3::from_axis_angle(&Vector3::z_axis(), -0.2);
    let cone = Rotation3::from_axis_angle(&Vector3::y_axis(), PI / 2.0);
    let turn = |ps: Vec<Particle>, r: &Rotation3<f64>, at: Vector3<f64>| -> Vec<Particle> {
        placed(&ps, r.matrix(), &at)
    };
    let mut lattice = turn(
        revolution(2.5, -0.6, 0.6, &|_| 0.0, &|_| 0.3, n),
        &cylinder,
        Vector3::new(0.2, -0.4, 0.9),
    );
    lattice.extend(turn(
        common::body::cuboid(1.0, 0.2, 0.5, 0.9, n),
        &cuboid,
        Vector3::zeros(),
    ));
    lattice.extend(turn(
        revolution(0.5, -0.9, 0.0, &|_| 0.0, &|s| 0.3 * (1.0 + s / 0.9), n),
        &cone,
        Vector3::new(0.0, 0.0, 0.9),
    ));
    let e = rel_err(
        &derived.inertia(),
        &tensor_about(&lattice, &Vector3::zeros()),
    );
    let (_, g) = mass_center(&lattice);
    let e_center = (derived.center_of_mass() - g).norm();
    println!("literal: derived vs lattice {e:.1e}, centre {e_center:.1e}");
    assert!(e < 3e-4 && e_center < 1e-4, "{e:e} {e_center:e}");
    check_euler(&derived, 3);
}

/// A rod swinging in the x–z plane by a field angle, with a ball at its centre so the body
/// has three moments.
#[derive(RigidBody)]
#[rigid(
    rod(mass = 3.0, length = 2.0, rotate = y(angle)),
    sphere(mass = 1.0, radius = 0.1),
)]
struct Swing {
    angle: f64,
}

#[test]
fn a_field_angle_follows_the_closed_form() {
    let ball = 0.4 * 0.01;
    for angle in [0.0, 0.3, PI / 2.0, 2.0, -1.0] {
        // The rod along u = (sin α, 0, cos α): I = m L²/12 (E − u uᵀ).
        let u = Vector3::new(angle.sin(), 0.0, angle.cos());
        let closed = (Matrix3::identity() - u * u.transpose()) * 1.0 + Matrix3::identity() * ball;
        let swing = Swing { angle };
        let e = rel_err(&swing.inertia(), &closed);
        assert!(e < 1e-15, "{angle}: {e:e}");
        swing.validate().expect("any finite angle");
        let built = Body::new(swing.description()).expect("valid");
        assert!(rel_err(&built.inertia(), &closed) < 1e-15);
        check_euler(&swing, 7);
    }
    let nan = Swing { angle: f64::NAN }.validate().unwrap_err();
    assert!(
        matches!(
            nan,
            BodyError::NonFinite {
                part: 0,
                key: "rotate",
                ..
            }
        ),
        "{nan}"
    );
}

/// A box turned about an axis and by an angle that are fields.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = m, size = [0.2, 0.5, 0.9], at = [0.1, 0.0, 0.3], rotate = axis_angle([kx, ky, kz], angle)),
    pivot = [0.0, 0.0, 0.0],
)]
struct Tilted {
    m: f64,
    kx: f64,
    ky: f64,
    kz: f64,
    angle: f64,
}

#[test]
fn a_field_axis_and_angle_agree_with_the_builder_and_are_validated() {
    let mut rng = common::rng::Rng::new(17);
    for _ in 0..20 {
        let k = rng.vector(-1.0, 1.0);
        let (m, angle) = (rng.uniform(0.5, 2.0), rng.uniform(-PI, PI));
        let tilted = Tilted {
            m,
            kx: k.x,
            ky: k.y,
            kz: k.z,
            angle,
        };
        let built = BodyBuilder::new()
            .rotated_part(
                Shape::Cuboid {
                    mass: m,
                    size: [0.2, 0.5, 0.9],
                },
                [0.1, 0.0, 0.3],
                Orientation::axis_angle(k, angle),
            )
            .pivot([0.0; 3])
            .build()
            .expect("valid");
        let e = rel_err(&tilted.inertia(), &built.inertia());
        assert!(e < 1e-15, "{e:e}");
        // Not symbolically diagonal: the frame is decomposed at run time, and agrees.
        let (p, q) = (tilted.principal(), built.principal());
        assert!((p.moments - q.moments).norm() < 1e-14 * q.moments.norm());
        check_euler(&tilted, 11);
    }
    let zero = Tilted {
        m: 1.0,
        kx: 0.0,
        ky: 0.0,
        kz: 0.0,
        angle: 0.5,
    };
    let e = zero.validate().unwrap_err();
    assert_eq!(
        e,
        BodyError::ZeroRotationAxis {
            part: 0,
            kind: "cuboid",
            axis: [0.0; 3]
        }
    );
}

/// A disk on a hinge about y, its rotation given as a matrix of fields.
#[derive(RigidBody)]
#[rigid(
    disk(mass = 1.0, radius = 0.2, at = [0.0, 0.0, 0.5],
         rotate = matrix([[c, 0.0, s], [0.0, k, 0.0], [-s, 0.0, c]])),
    pivot = [0.0, 0.0, 0.0],
)]
struct Hinged {
    c: f64,
    s: f64,
    k: f64,
}

#[test]
fn a_field_matrix_is_checked_at_run_time() {
    let angle: f64 = 0.6;
    let hinged = Hinged {
        c: angle.cos(),
        s: angle.sin(),
        k: 1.0,
    };
    hinged.validate().expect("a rotation");
    let built = BodyBuilder::new()
        .rotated_part(
            Shape::Disk {
                mass: 1.0,
                radius: 0.2,
                axis: Axis::Z,
            },
            [0.0, 0.0, 0.5],
            Orientation::sequence([(Axis::Y, angle)]),
        )
        .pivot([0.0; 3])
        .build()
        .expect("valid");
    assert!(rel_err(&hinged.inertia(), &built.inertia()) < 1e-15);
    let stretched = Hinged {
        c: 1.0,
        s: 1.0,
        k: 1.0,
    }
    .validate()
    .unwrap_err();
    assert!(
        matches!(stretched, BodyError::NotOrthonormal { part: 0, kind: "disk", deviation } if deviation == 1.0),
        "{stretched}"
    );
    let mirror = Hinged {
        c: 1.0,
        s: 0.0,
        k: -1.0,
    }
    .validate()
    .unwrap_err();
    assert_eq!(
        mirror,
        BodyError::ImproperRotation {
            part: 0,
            kind: "disk",
            determinant: -1.0
        }
    );
    assert!(
        Hinged {
            c: 1.0,
            s: 0.0,
            k: 1.0
        }
        .validated()
        .is_ok()
    );
}

/// The symbolic body the macro builds, evaluated at the fields' values, against the builder:
/// the third path to the same tensor.
#[test]
fn the_symbolic_body_agrees_with_the_builder() {
    let mut a = Arena::new();
    let num = |a: &mut Arena, s: &str| a.number(s).expect("a literal");
    let (m, r, l) = (num(&mut a, "2.5"), num(&mut a, "0.3"), num(&mut a, "1.2"));
    let angle = a.parameter("angle");
    let axis = [num(&mut a, "0.3"), num(&mut a, "-1"), num(&mut a, "0.7")];
    let z = a.zero();
    let cylinder = Shape::Cylinder {
        mass: m,
        radius: r,
        length: l,
        axis: Axis::X,
    };
    let d = Description {
        parts: vec![Part::new(cylinder, [z, z, z]).rotated(Orientation::AxisAngle { axis, angle })],
        pivot: None,
    };
    let body = SymbolicBody::new(&mut a, &d).expect("a body");
    assert_eq!(body.frame, Frame::DecomposedAtRunTime);
    let index = a.as_symbol(angle).expect("a symbol").index();
    for value in [0.0, 0.4, 1.1, 3.0] {
        let mut env = vec![f64::NAN; a.symbol_count()];
        env[index] = value;
        let t = Matrix3::from_fn(|i, j| a.eval(body.props.inertia[i][j], &env));
        let built = BodyBuilder::new()
            .rotated_part(
                Shape::Cylinder {
                    mass: 2.5,
                    radius: 0.3,
                    length: 1.2,
                    axis: Axis::X,
                },
                [0.0; 3],
                Orientation::axis_angle([0.3, -1.0, 0.7], value),
            )
            .build()
            .expect("valid");
        let e = rel_err(&t, &built.inertia());
        assert!(e < 1e-15, "{value}: {e:e}");
    }
    // A turn about the symmetry axis cancels exactly (sin² + cos² = 1 in the engine's
    // canonical form): the tensor stays diagonal, with its moments as expressions.
    let about_own_axis = Orientation::Sequence(vec![(Axis::X, angle)]);
    let d = Description {
        parts: vec![Part::new(cylinder_x(&mut a), [z, z, z]).rotated(about_own_axis)],
        pivot: None,
    };
    let body = SymbolicBody::new(&mut a, &d).expect("a body");
    assert!(matches!(body.frame, Frame::Diagonal(_)), "{:?}", body.frame);
    // The matrices the engine builds are rotations, Rᵀ R = E, exactly for a literal axis or
    // elementary turns (sin² + cos² = 1, √c² = c), and to rounding for an axis of fields,
    // whose 1/|k|² the engine's zero test does not cancel.
    let (b, c) = (a.parameter("b"), a.parameter("c"));
    let exact = [
        Orientation::AxisAngle { axis, angle },
        Orientation::Sequence(vec![(Axis::Z, angle), (Axis::Y, b), (Axis::X, c)]),
    ];
    for o in exact {
        let r = rotation_matrix(&mut a, &o).expect("a matrix");
        for i in 0..3 {
            for j in 0..3 {
                let diff = gram_minus_identity(&mut a, &r, i, j);
                assert_eq!(a.is_zero(diff), Ok(true), "(RᵀR − E)[{i}][{j}] of {o:?}");
            }
        }
    }
    let k = [a.parameter("k1"), a.parameter("k2"), a.parameter("k3")];
    let r = rotation_matrix(&mut a, &Orientation::AxisAngle { axis: k, angle }).expect("a matrix");
    let mut rng = common::rng::Rng::new(29);
    for _ in 0..100 {
        let env: Vec<f64> = (0..a.symbol_count())
            .map(|_| rng.uniform(-3.0, 3.0))
            .collect();
        for i in 0..3 {
            for j in 0..3 {
                let diff = gram_minus_identity(&mut a, &r, i, j);
                assert!(a.eval(diff, &env).abs() < 1e-14);
            }
        }
    }
}

/// (RᵀR − E)[i][j].
fn gram_minus_identity(a: &mut Arena, r: &Rows<ExprId>, i: usize, j: usize) -> ExprId {
    let terms: Vec<ExprId> = (0..3).map(|l| a.mul(r[l][i], r[l][j])).collect();
    let dot = a.sum(&terms);
    let want = if i == j { a.one() } else { a.zero() };
    a.sub(dot, want)
}

fn cylinder_x(a: &mut Arena) -> Shape<ExprId> {
    let (m, r, l) = (a.parameter("m"), a.parameter("r"), a.parameter("l"));
    Shape::Cylinder {
        mass: m,
        radius: r,
        length: l,
        axis: Axis::X,
    }
}

/// A top whose disk is tilted on its stem: the derivation runs on the turned tensor.
#[derive(RigidBody)]
#[rigid(
    rod(mass = 0.1, length = 0.5, at = [0.0, 0.0, 0.25]),
    disk(mass = 1.0, radius = 0.2, at = [0.0, 0.0, 0.5], rotate = x(0.3)),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Wobbly;

#[test]
fn a_top_with_a_tilted_disk_follows_the_turned_tensor() {
    let disk = 1.0 * 0.04;
    let tilt = Rotation3::from_axis_angle(&Vector3::x_axis(), 0.3);
    // Disk about its centre, turned; rod; both shifted to the pivot.
    let shift =
        |m: f64, d: Vector3<f64>| m * (Matrix3::identity() * d.norm_squared() - d * d.transpose());
    let i = tilt.matrix()
        * Matrix3::from_diagonal(&Vector3::new(disk / 4.0, disk / 4.0, disk / 2.0))
        * tilt.matrix().transpose()
        + shift(1.0, Vector3::new(0.0, 0.0, 0.5))
        + Matrix3::from_diagonal(&Vector3::new(0.1 * 0.25 / 12.0, 0.1 * 0.25 / 12.0, 0.0))
        + shift(0.1, Vector3::new(0.0, 0.0, 0.25));
    assert!(rel_err(&Wobbly.inertia(), &i) < 1e-15);
    // The Eulerian form against ω̇ = I⁻¹ (τ − ω × I ω), τ = c × Rᵀ(−M g ẑ).
    let c = Vector3::new(0.0, 0.0, (0.1 * 0.25 + 0.5) / 1.1);
    let mut rng = common::rng::Rng::new(23);
    for _ in 0..100 {
        let q = UnitQuaternion::from_scaled_axis(rng.vector(-2.0, 2.0));
        let w = rng.vector(-5.0, 5.0);
        let tau = c.cross(&(q.inverse() * Vector3::new(0.0, 0.0, -1.1 * 9.81)));
        let want = generic_rhs(&i, &w, &tau);
        let got = Wobbly.eulerian_rhs(0.0, &q, &w);
        assert!(
            (got - want).norm() < 1e-12 * want.norm().max(1.0),
            "{got} vs {want}"
        );
    }
}

/// A cylinder spun about its own axis by a literal angle.
#[derive(RigidBody)]
#[rigid(cylinder(mass = 2.0, radius = 0.1, length = 0.4, rotate = z(0.7)))]
struct Spun;

#[test]
fn a_literal_turn_about_the_symmetry_axis_cancels_exactly() {
    // sin² + cos² = 1 cancels while expanding: the moments are the closed forms, exactly,
    // and the description axes stay principal.
    let p = Spun.principal();
    assert_eq!(p.rotation.matrix(), &Matrix3::identity());
    let t = 2.0 * (3.0 * 0.01 + 0.16) / 12.0;
    assert_eq!(p.moments, Vector3::new(t, t, 0.01));
    assert_eq!(Spun.inertia(), Matrix3::from_diagonal(&p.moments));
}

/// A top whose disk leans about an axis and by an angle that are fields.
#[derive(RigidBody)]
#[rigid(
    rod(mass = 0.1, length = 0.5, at = [0.0, 0.0, 0.25]),
    disk(mass = 1.0, radius = 0.2, at = [0.0, 0.0, 0.5], rotate = axis_angle([kx, ky, 1.0], lean)),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81)]
struct Leaning {
    kx: f64,
    ky: f64,
    lean: f64,
}

#[test]
fn the_angle_form_of_a_top_with_a_field_turn_agrees_with_the_eulerian_form() {
    // ω = B(q) q̇, so ω̇ = B q̈ + (dB/dt) q̇: the angle form's q̈ mapped to ω̇ must be
    // I⁻¹(τ − ω × I ω) with the tensor the builder turns. dB/dt by central differences.
    let top = Leaning {
        kx: 0.4,
        ky: -0.7,
        lean: 0.9,
    };
    let built = Body::new(top.description()).expect("valid");
    let (i, lever) = (
        built.inertia(),
        built.center_of_mass() * built.mass() * 9.81,
    );
    let mut rng = common::rng::Rng::new(31);
    let seq = <Leaning as TopDynamics>::SEQUENCE;
    let mut worst = 0.0f64;
    for _ in 0..50 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.3, 2.8),
            rng.uniform(-3.0, 3.0),
        ];
        let q_dot = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-20.0, 20.0),
        ];
        let q_ddot = top.accelerations_unchecked(0.0, &q, &q_dot);
        let b = |q: &[f64; 3]| top.rate_matrix_in(seq, q);
        let h = 1e-5;
        let step = |s: f64| std::array::from_fn(|k| q[k] + s * h * q_dot[k]);
        let b_dot = (b(&step(1.0)) - b(&step(-1.0))) / (2.0 * h);
        let (qd, qdd) = (Vector3::from(q_dot), Vector3::from(q_ddot));
        let w = b(&q) * qd;
        let w_dot = b(&q) * qdd + b_dot * qd;
        let down = top.rotation_in(seq, &q).transpose() * Vector3::new(0.0, 0.0, -1.0);
        let want = generic_rhs(&i, &w, &lever.cross(&down));
        worst = worst.max((w_dot - want).norm() / want.norm().max(1.0));
    }
    println!("leaning top: angle form against the Eulerian form {worst:.1e}");
    assert!(worst < 1e-7, "{worst:e}");
}
