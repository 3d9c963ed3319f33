//! Every shape's inertia tensor against its textbook closed form and against direct
//! summation over a particle lattice of the same solid.

use crate::common;

use common::body::*;
use nalgebra::{Matrix3, Vector3};
use precess::body::{Axis, BodyBuilder, RigidBody, Shape};

const N: usize = 120;

/// Builds a one-part body at the origin and returns its tensor about its centre of mass and
/// the centre.
fn built(shape: Shape<f64>) -> (Matrix3<f64>, Vector3<f64>) {
    let b = BodyBuilder::new()
        .part(shape, [0.0; 3])
        .build()
        .expect("a valid body");
    (b.inertia_cm(), b.center_of_mass())
}

/// Checks the built tensor against the closed form (to rounding) and the lattice.
fn check(
    name: &str,
    shape: Shape<f64>,
    closed: [f64; 3],
    lattice: Vec<Particle>,
    lattice_tol: f64,
) {
    let (t, g) = built(shape);
    let closed = Matrix3::from_diagonal(&Vector3::from(closed));
    let e_closed = rel_err(&t, &closed);
    let (_, lg) = mass_center(&lattice);
    let e_lattice = rel_err(&t, &tensor_about(&lattice, &lg));
    let e_center = (g - lg).norm();
    println!(
        "{name:10} closed form {e_closed:.1e}  lattice {e_lattice:.1e}  centre {e_center:.1e}"
    );
    assert!(e_closed <= 4e-16, "{name}: closed form off by {e_closed:e}");
    assert!(
        e_lattice <= lattice_tol,
        "{name}: lattice off by {e_lattice:e}"
    );
    assert!(
        e_center <= 1e-12 + lattice_tol,
        "{name}: centre off by {e_center:e}"
    );
}

const M: f64 = 2.5;

#[test]
fn sphere() {
    let r = 0.3;
    let i = 0.4 * M * r * r;
    check(
        "sphere",
        Shape::Sphere { mass: M, radius: r },
        [i; 3],
        ellipsoid(M, r, r, r, N),
        1e-4,
    );
}

#[test]
fn shell() {
    let r = 0.3;
    let i = 2.0 / 3.0 * M * r * r;
    check(
        "shell",
        Shape::Shell { mass: M, radius: r },
        [i; 3],
        common::body::shell(M, r, 400),
        1e-4,
    );
}

#[test]
fn cuboid() {
    let (a, b, c) = (0.2, 0.5, 0.9);
    let k = M / 12.0;
    let closed = [
        k * (b * b + c * c),
        k * (a * a + c * c),
        k * (a * a + b * b),
    ];
    let shape = Shape::Cuboid {
        mass: M,
        size: [a, b, c],
    };
    check(
        "cuboid",
        shape,
        closed,
        common::body::cuboid(M, a, b, c, N),
        1e-4,
    );
}

#[test]
fn cylinder() {
    let (r, l) = (0.3, 1.2);
    let t = M * (3.0 * r * r + l * l) / 12.0;
    let shape = Shape::Cylinder {
        mass: M,
        radius: r,
        length: l,
        axis: Axis::Z,
    };
    let lattice = revolution(M, -l / 2.0, l / 2.0, &|_| 0.0, &|_| r, N);
    check("cylinder", shape, [t, t, 0.5 * M * r * r], lattice, 1e-4);
}

#[test]
fn cylinder_along_x() {
    let (r, l) = (0.3, 1.2);
    let t = M * (3.0 * r * r + l * l) / 12.0;
    let shape = Shape::Cylinder {
        mass: M,
        radius: r,
        length: l,
        axis: Axis::X,
    };
    let lattice = z_to_x(&revolution(M, -l / 2.0, l / 2.0, &|_| 0.0, &|_| r, N));
    check("cylinder x", shape, [0.5 * M * r * r, t, t], lattice, 1e-4);
}

#[test]
fn tube() {
    let (a, b, l) = (0.2, 0.3, 0.8);
    let t = M * (3.0 * (a * a + b * b) + l * l) / 12.0;
    let shape = Shape::Tube {
        mass: M,
        inner: a,
        outer: b,
        length: l,
        axis: Axis::Z,
    };
    let lattice = revolution(M, -l / 2.0, l / 2.0, &|_| a, &|_| b, N);
    check(
        "tube",
        shape,
        [t, t, 0.5 * M * (a * a + b * b)],
        lattice,
        1e-4,
    );
}

#[test]
fn disk() {
    let r = 0.4;
    let shape = Shape::Disk {
        mass: M,
        radius: r,
        axis: Axis::Z,
    };
    let closed = [0.25 * M * r * r, 0.25 * M * r * r, 0.5 * M * r * r];
    check("disk", shape, closed, common::body::disk(M, r, 400), 1e-5);
}

#[test]
fn disk_along_y() {
    let r = 0.4;
    let shape = Shape::Disk {
        mass: M,
        radius: r,
        axis: Axis::Y,
    };
    let closed = [0.25 * M * r * r, 0.5 * M * r * r, 0.25 * M * r * r];
    // z → y: (x, y, z) ↦ (y, z, x) is a proper rotation taking the z axis to y.
    let lattice: Vec<Particle> = common::body::disk(M, r, 400)
        .into_iter()
        .map(|(m, x)| (m, Vector3::new(x.y, x.z, x.x)))
        .collect();
    check("disk y", shape, closed, lattice, 1e-5);
}

#[test]
fn ring() {
    let r = 0.4;
    let shape = Shape::Ring {
        mass: M,
        radius: r,
        axis: Axis::Z,
    };
    check(
        "ring",
        shape,
        [0.5 * M * r * r, 0.5 * M * r * r, M * r * r],
        common::body::ring(M, r, 1000),
        1e-12,
    );
}

#[test]
fn rod_as_part_of_a_body() {
    // A rod alone has a zero moment; pair it with a sphere at its centre.
    let (l, r) = (1.5, 0.1);
    let b = BodyBuilder::new()
        .part(
            Shape::Rod {
                mass: M,
                length: l,
                axis: Axis::Z,
            },
            [0.0; 3],
        )
        .part(
            Shape::Sphere {
                mass: 1.0,
                radius: r,
            },
            [0.0; 3],
        )
        .build()
        .expect("a valid body");
    let s = 0.4 * r * r;
    let closed =
        Matrix3::from_diagonal(&Vector3::new(M * l * l / 12.0 + s, M * l * l / 12.0 + s, s));
    let mut lattice = common::body::rod(M, l, 2000);
    lattice.extend(ellipsoid(1.0, r, r, r, 60));
    let e_closed = rel_err(&b.inertia(), &closed);
    let e_lattice = rel_err(&b.inertia(), &tensor_about(&lattice, &Vector3::zeros()));
    println!("rod+sphere closed form {e_closed:.1e}  lattice {e_lattice:.1e}");
    assert!(e_closed <= 4e-16);
    assert!(e_lattice <= 1e-5);
}

#[test]
fn cone() {
    let (r, h) = (0.3, 0.9);
    let t = 3.0 / 20.0 * M * r * r + 3.0 / 80.0 * M * h * h;
    let shape = Shape::Cone {
        mass: M,
        radius: r,
        height: h,
        axis: Axis::Z,
        reversed: false,
    };
    // Base at z = 0 (the part's `at`), apex at z = h.
    let lattice = revolution(M, 0.0, h, &|_| 0.0, &|z| r * (1.0 - z / h), N);
    check("cone", shape, [t, t, 0.3 * M * r * r], lattice, 3e-4);
    let (_, g) = built(Shape::Cone {
        mass: M,
        radius: r,
        height: h,
        axis: Axis::Z,
        reversed: false,
    });
    assert!((g - Vector3::new(0.0, 0.0, h / 4.0)).norm() < 1e-16);
}

#[test]
fn ellipsoid_solid() {
    let (a, b, c) = (0.2, 0.35, 0.6);
    let k = M / 5.0;
    let closed = [
        k * (b * b + c * c),
        k * (a * a + c * c),
        k * (a * a + b * b),
    ];
    let shape = Shape::Ellipsoid {
        mass: M,
        semi_axes: [a, b, c],
    };
    check("ellipsoid", shape, closed, ellipsoid(M, a, b, c, N), 1e-4);
}

#[test]
fn particle_pair() {
    // Two particles on x and one on y: I = Σ m (r² E − x xᵀ) directly.
    let b = BodyBuilder::new()
        .part(Shape::Particle { mass: 1.0 }, [1.0, 0.0, 0.0])
        .part(Shape::Particle { mass: 1.0 }, [-1.0, 0.0, 0.0])
        .part(Shape::Particle { mass: 2.0 }, [0.0, 0.5, 0.0])
        .pivot([0.0; 3])
        .build()
        .expect("a valid body");
    let closed = Matrix3::from_diagonal(&Vector3::new(0.5, 2.0, 2.5));
    assert_eq!(b.inertia(), closed);
}

#[test]
fn uniform_cubic_lattices() {
    let n = 160;
    let r = 0.3;
    // |p| written out: nalgebra's norm, unoptimised here, was most of the test's time.
    let sphere = cubic_lattice(M, [r; 3], n, &|p| {
        (p.x * p.x + p.y * p.y + p.z * p.z).sqrt() <= r
    });
    let (l, h) = (1.2, 0.9);
    let cylinder = cubic_lattice(M, [r, r, l / 2.0], n, &|p| p.x * p.x + p.y * p.y <= r * r);
    // Cone, base at z = 0 and apex at z = h: shifted so the grid spans [0, h].
    let cone = shifted(
        &cubic_lattice(M, [r, r, h / 2.0], n, &|p| {
            let z = p.z + h / 2.0;
            (p.x * p.x + p.y * p.y).sqrt() <= r * (1.0 - z / h)
        }),
        Vector3::new(0.0, 0.0, h / 2.0),
    );
    let cases = [
        ("sphere", Shape::Sphere { mass: M, radius: r }, sphere),
        (
            "cylinder",
            Shape::Cylinder {
                mass: M,
                radius: r,
                length: l,
                axis: Axis::Z,
            },
            cylinder,
        ),
        (
            "cone",
            Shape::Cone {
                mass: M,
                radius: r,
                height: h,
                axis: Axis::Z,
                reversed: false,
            },
            cone,
        ),
    ];
    for (name, shape, lattice) in cases {
        let (t, g) = built(shape);
        let (_, lg) = mass_center(&lattice);
        let e = rel_err(&t, &tensor_about(&lattice, &lg));
        println!(
            "{name:10} uniform cubic lattice ({} particles) {e:.1e}, centre {:.1e}",
            lattice.len(),
            (g - lg).norm()
        );
        assert!(e < 1e-3, "{name}: {e:e}");
        assert!((g - lg).norm() < 5e-3 * h);
    }
}

#[test]
fn reversed_cone_points_down() {
    let (r, h) = (0.3, 0.9);
    let t = 3.0 / 20.0 * M * r * r + 3.0 / 80.0 * M * h * h;
    let shape = Shape::Cone {
        mass: M,
        radius: r,
        height: h,
        axis: Axis::Z,
        reversed: true,
    };
    // Base at z = 0, apex at z = −h.
    let lattice = revolution(M, -h, 0.0, &|_| 0.0, &|z| r * (1.0 + z / h), N);
    check(
        "cone −z",
        shape.clone(),
        [t, t, 0.3 * M * r * r],
        lattice,
        3e-4,
    );
    let (_, g) = built(shape);
    assert!((g - Vector3::new(0.0, 0.0, -h / 4.0)).norm() < 1e-16);
}
