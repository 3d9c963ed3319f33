//! The parallel-axis theorem and composites, against direct summation over particles.

use crate::common;

use common::body::*;
use common::rng::Rng;
use nalgebra::{Matrix3, Vector3};
use precess::body::{Axis, BodyBuilder, Numeric, RigidBody, Shape, point_tensor};

#[test]
fn theorem_against_direct_summation() {
    // I_O = I_G + M (|d|² E − d dᵀ), d = G − O, for an arbitrary lumpy particle set.
    let mut rng = Rng::new(7);
    let ps: Vec<Particle> = (0..500)
        .map(|_| (rng.uniform(0.1, 2.0), rng.vector(-1.0, 1.0)))
        .collect();
    let (m, g) = mass_center(&ps);
    let i_g = tensor_about(&ps, &g);
    for _ in 0..20 {
        let o = rng.vector(-3.0, 3.0);
        let d = g - o;
        let shift = point_tensor(&mut Numeric, m, [d.x, d.y, d.z]);
        let theorem = i_g + Matrix3::from_fn(|i, j| shift[i][j]);
        let direct = tensor_about(&ps, &o);
        let e = rel_err(&theorem, &direct);
        assert!(e < 1e-13, "theorem off by {e:e}");
    }
}

#[test]
fn shift_along_the_symmetry_axis_raises_i1_and_i2_not_i3() {
    let (m, r, l, h) = (1.5, 0.2, 0.6, 0.9);
    let body = BodyBuilder::new()
        .part(
            Shape::Cylinder {
                mass: m,
                radius: r,
                length: l,
                axis: Axis::Z,
            },
            [0.0, 0.0, h],
        )
        .pivot([0.0; 3])
        .build()
        .expect("a valid body");
    let t = m * (3.0 * r * r + l * l) / 12.0;
    let closed =
        Matrix3::from_diagonal(&Vector3::new(t + m * h * h, t + m * h * h, 0.5 * m * r * r));
    let lattice = shifted(
        &revolution(m, -l / 2.0, l / 2.0, &|_| 0.0, &|_| r, 120),
        Vector3::new(0.0, 0.0, h),
    );
    let direct = tensor_about(&lattice, &Vector3::zeros());
    let i = body.inertia();
    println!(
        "shift along 3: closed {:.1e}, lattice {:.1e}",
        rel_err(&i, &closed),
        rel_err(&i, &direct)
    );
    assert!(rel_err(&i, &closed) < 4e-16);
    assert!(rel_err(&i, &direct) < 1e-4);
    // I3 is the same about the pivot as about the centre of mass.
    assert_eq!(i[(2, 2)], body.inertia_cm()[(2, 2)]);
    assert!(i[(0, 0)] > body.inertia_cm()[(0, 0)] + 0.99 * m * h * h);
}

#[test]
fn general_shift_of_a_box_against_its_lattice() {
    let (m, a, b, c) = (3.0, 0.4, 0.3, 0.2);
    let at = Vector3::new(0.3, -0.2, 0.7);
    let body = BodyBuilder::new()
        .part(
            Shape::Cuboid {
                mass: m,
                size: [a, b, c],
            },
            [at.x, at.y, at.z],
        )
        .pivot([0.0; 3])
        .build()
        .expect("a valid body");
    let lattice = shifted(&cuboid(m, a, b, c, 100), at);
    let e = rel_err(&body.inertia(), &tensor_about(&lattice, &Vector3::zeros()));
    println!("box shifted by (0.3, −0.2, 0.7): lattice {e:.1e}");
    assert!(e < 1e-4);
    // The off-diagonal products of inertia −M x y etc. are exact.
    assert!((body.inertia()[(0, 1)] - m * 0.3 * 0.2).abs() < 1e-15);
}

#[test]
fn spinning_top_composite() {
    // The design's top: a cylinder stem and a disk, about the pivot at the origin.
    let (ms, rs, ls) = (0.2, 0.004, 0.06);
    let (md, rd, hd) = (0.5, 0.03, 0.05);
    let body = BodyBuilder::new()
        .part(
            Shape::Cylinder {
                mass: ms,
                radius: rs,
                length: ls,
                axis: Axis::Z,
            },
            [0.0, 0.0, ls / 2.0],
        )
        .part(
            Shape::Disk {
                mass: md,
                radius: rd,
                axis: Axis::Z,
            },
            [0.0, 0.0, hd],
        )
        .pivot([0.0; 3])
        .build()
        .expect("a valid body");
    let t = ms * (3.0 * rs * rs + ls * ls) / 12.0
        + ms * (ls / 2.0).powi(2)
        + md * rd * rd / 4.0
        + md * hd * hd;
    let a = ms * rs * rs / 2.0 + md * rd * rd / 2.0;
    let closed = Matrix3::from_diagonal(&Vector3::new(t, t, a));
    let mut lattice = shifted(
        &revolution(ms, 0.0, ls, &|_| 0.0, &|_| rs, 100),
        Vector3::zeros(),
    );
    lattice.extend(shifted(&disk(md, rd, 300), Vector3::new(0.0, 0.0, hd)));
    let direct = tensor_about(&lattice, &Vector3::zeros());
    println!(
        "top: closed {:.1e}, lattice {:.1e}",
        rel_err(&body.inertia(), &closed),
        rel_err(&body.inertia(), &direct)
    );
    assert!(rel_err(&body.inertia(), &closed) < 4e-16);
    assert!(rel_err(&body.inertia(), &direct) < 1e-4);
    let g = (ms * ls / 2.0 + md * hd) / (ms + md);
    assert!((body.center_of_mass() - Vector3::new(0.0, 0.0, g)).norm() < 1e-16);
}

#[test]
fn off_axis_composite_about_its_centre_of_mass() {
    let body = BodyBuilder::new()
        .part(
            Shape::Sphere {
                mass: 1.0,
                radius: 0.1,
            },
            [0.1, 0.2, 0.0],
        )
        .part(
            Shape::Cuboid {
                mass: 2.0,
                size: [0.2, 0.1, 0.3],
            },
            [-0.1, 0.0, 0.3],
        )
        .part(
            Shape::Ring {
                mass: 0.5,
                radius: 0.2,
                axis: Axis::X,
            },
            [0.0, -0.3, 0.1],
        )
        .build()
        .expect("a valid body");
    let mut lattice = shifted(
        &ellipsoid(1.0, 0.1, 0.1, 0.1, 80),
        Vector3::new(0.1, 0.2, 0.0),
    );
    lattice.extend(shifted(
        &cuboid(2.0, 0.2, 0.1, 0.3, 80),
        Vector3::new(-0.1, 0.0, 0.3),
    ));
    lattice.extend(shifted(
        &z_to_x(&ring(0.5, 0.2, 2000)),
        Vector3::new(0.0, -0.3, 0.1),
    ));
    let (m, g) = mass_center(&lattice);
    let direct = tensor_about(&lattice, &g);
    let e = rel_err(&body.inertia(), &direct);
    println!("off-axis composite: lattice {e:.1e}");
    assert!((body.mass() - m).abs() < 1e-9, "{} {m}", body.mass());
    assert!((body.center_of_mass() - g).norm() < 1e-9);
    assert!(e < 1e-4);
    assert_eq!(body.reference_point(), body.center_of_mass());
}
