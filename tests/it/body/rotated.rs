//! Parts at any orientation, built at run time: every rotated solid's tensor and centre
//! against direct summation over the same solid's particle lattice turned by nalgebra's own
//! rotation, and against R D Rᵀ formed with it; closed-form cases (a rod turned a quarter
//! turn is the rod along the other axis, a cube looks the same at any turn); the ways of
//! writing a rotation agree; bad rotations are typed errors.

use crate::common;

use std::f64::consts::{FRAC_PI_2, PI};

use common::body::*;
use common::rng::Rng;
use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};
use precess::body::{
    About, Axis, BodyBuilder, Description, Numeric, Orientation, Part, RigidBody, Shape,
    mass_properties, matrix,
};

const M: f64 = 2.5;
const N: usize = 80;

/// nalgebra's turn by `angle` about `axis`: an implementation independent of precess's.
fn reference(axis: [f64; 3], angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), angle).matrix()
}

/// The tensor about its centre, and the centre, of one part, without the rules of a whole
/// body (a rod alone has a zero moment but a well-defined tensor).
fn part_properties(part: Part<f64>) -> (Matrix3<f64>, Vector3<f64>) {
    let d = Description {
        parts: vec![part],
        pivot: None,
    };
    let p = mass_properties(&mut Numeric, &d).expect("a part has mass properties");
    (matrix(&p.inertia_cm), Vector3::from(p.center))
}

/// One solid: its shape (axis z unless it says otherwise), its lattice in its own axes with
/// `at` at the origin, the diagonal of its closed form and its centre's offset from `at`, in
/// its own axes, and how closely the lattice represents it.
struct Solid {
    name: &'static str,
    shape: Shape<f64>,
    lattice: Vec<Particle>,
    closed: [f64; 3],
    offset: Vector3<f64>,
    tol: f64,
}

fn solids() -> Vec<Solid> {
    let (r, l, h) = (0.3, 1.2, 0.9);
    let (a, b, c) = (0.2, 0.5, 0.9);
    let cyl_t = M * (3.0 * r * r + l * l) / 12.0;
    let (ti, to) = (0.2, 0.3);
    let tube_t = M * (3.0 * (ti * ti + to * to) + l * l) / 12.0;
    let cone_t = 3.0 / 20.0 * M * r * r + 3.0 / 80.0 * M * h * h;
    let z = |v: f64| Vector3::new(0.0, 0.0, v);
    vec![
        Solid {
            name: "cuboid",
            shape: Shape::Cuboid {
                mass: M,
                size: [a, b, c],
            },
            lattice: cuboid(M, a, b, c, N),
            closed: [
                M * (b * b + c * c) / 12.0,
                M * (a * a + c * c) / 12.0,
                M * (a * a + b * b) / 12.0,
            ],
            offset: Vector3::zeros(),
            tol: 3e-4,
        },
        Solid {
            name: "ellipsoid",
            shape: Shape::Ellipsoid {
                mass: M,
                semi_axes: [a, b, c],
            },
            lattice: ellipsoid(M, a, b, c, N),
            closed: [
                M * (b * b + c * c) / 5.0,
                M * (a * a + c * c) / 5.0,
                M * (a * a + b * b) / 5.0,
            ],
            offset: Vector3::zeros(),
            tol: 3e-4,
        },
        Solid {
            name: "cylinder",
            shape: Shape::Cylinder {
                mass: M,
                radius: r,
                length: l,
                axis: Axis::Z,
            },
            lattice: revolution(M, -l / 2.0, l / 2.0, &|_| 0.0, &|_| r, N),
            closed: [cyl_t, cyl_t, 0.5 * M * r * r],
            offset: Vector3::zeros(),
            tol: 3e-4,
        },
        Solid {
            name: "cylinder x",
            shape: Shape::Cylinder {
                mass: M,
                radius: r,
                length: l,
                axis: Axis::X,
            },
            lattice: z_to_x(&revolution(M, -l / 2.0, l / 2.0, &|_| 0.0, &|_| r, N)),
            closed: [0.5 * M * r * r, cyl_t, cyl_t],
            offset: Vector3::zeros(),
            tol: 3e-4,
        },
        Solid {
            name: "tube",
            shape: Shape::Tube {
                mass: M,
                inner: ti,
                outer: to,
                length: l,
                axis: Axis::Z,
            },
            lattice: revolution(M, -l / 2.0, l / 2.0, &|_| ti, &|_| to, N),
            closed: [tube_t, tube_t, 0.5 * M * (ti * ti + to * to)],
            offset: Vector3::zeros(),
            tol: 3e-4,
        },
        Solid {
            name: "disk",
            shape: Shape::Disk {
                mass: M,
                radius: r,
                axis: Axis::Z,
            },
            lattice: disk(M, r, 300),
            closed: [0.25 * M * r * r, 0.25 * M * r * r, 0.5 * M * r * r],
            offset: Vector3::zeros(),
            tol: 3e-5,
        },
        Solid {
            name: "ring",
            shape: Shape::Ring {
                mass: M,
                radius: r,
                axis: Axis::Z,
            },
            lattice: ring(M, r, 1000),
            closed: [0.5 * M * r * r, 0.5 * M * r * r, M * r * r],
            offset: Vector3::zeros(),
            tol: 1e-12,
        },
        Solid {
            name: "rod",
            shape: Shape::Rod {
                mass: M,
                length: l,
                axis: Axis::Z,
            },
            lattice: rod(M, l, 2000),
            closed: [M * l * l / 12.0, M * l * l / 12.0, 0.0],
            offset: Vector3::zeros(),
            tol: 1e-6,
        },
        Solid {
            name: "cone",
            shape: Shape::Cone {
                mass: M,
                radius: r,
                height: h,
                axis: Axis::Z,
                reversed: false,
            },
            lattice: revolution(M, 0.0, h, &|_| 0.0, &|s| r * (1.0 - s / h), N),
            closed: [cone_t, cone_t, 0.3 * M * r * r],
            offset: z(h / 4.0),
            tol: 1e-3,
        },
        Solid {
            name: "cone −z",
            shape: Shape::Cone {
                mass: M,
                radius: r,
                height: h,
                axis: Axis::Z,
                reversed: true,
            },
            lattice: revolution(M, -h, 0.0, &|_| 0.0, &|s| r * (1.0 + s / h), N),
            closed: [cone_t, cone_t, 0.3 * M * r * r],
            offset: z(-h / 4.0),
            tol: 1e-3,
        },
    ]
}

#[test]
fn every_rotated_solid_matches_direct_summation() {
    let (axis, angle) = ([0.3, -1.0, 0.7], 1.1);
    let at = Vector3::new(0.2, -0.4, 0.9);
    let r = reference(axis, angle);
    for s in solids() {
        let part =
            Part::new(s.shape.clone(), at.into()).rotated(Orientation::axis_angle(axis, angle));
        let (t, g) = part_properties(part);
        // R D Rᵀ with nalgebra's R, and the centre at + R d.
        let closed = r * Matrix3::from_diagonal(&Vector3::from(s.closed)) * r.transpose();
        let e_closed = rel_err(&t, &closed);
        let e_center = (g - (at + r * s.offset)).norm();
        let lattice = placed(&s.lattice, &r, &at);
        let (_, lg) = mass_center(&lattice);
        let e_lattice = rel_err(&t, &tensor_about(&lattice, &lg));
        let e_lattice_center = (g - lg).norm();
        println!(
            "{:10} R D Rᵀ {e_closed:.1e}  lattice {e_lattice:.1e}  centre {e_center:.1e} / lattice {e_lattice_center:.1e}",
            s.name
        );
        // The rotation changes the tensor: the test would pass vacuously otherwise.
        assert!(rel_err(&t, &Matrix3::from_diagonal(&Vector3::from(s.closed))) > 0.01);
        assert!(e_closed < 2e-15, "{}: R D Rᵀ off by {e_closed:e}", s.name);
        assert!(e_center < 1e-15, "{}: centre off by {e_center:e}", s.name);
        assert!(
            e_lattice < s.tol,
            "{}: lattice off by {e_lattice:e}",
            s.name
        );
        assert!(
            e_lattice_center < s.tol,
            "{}: lattice centre off by {e_lattice_center:e}",
            s.name
        );
    }
}

#[test]
fn a_rotated_composite_matches_direct_summation_about_its_pivot() {
    // A tilted top: a rod stem along a slanted axis and a cone tilted with it, about a
    // pivot; the sum is checked as a whole, parallel-axis shifts included.
    let (l, r, h) = (0.8, 0.25, 0.4);
    let tilt = Orientation::sequence([(Axis::Z, 0.4), (Axis::X, 0.7)]);
    let rot = *(Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), 0.7))
    .matrix();
    let stem_at = rot * Vector3::new(0.0, 0.0, l / 2.0);
    let cone_at = rot * Vector3::new(0.0, 0.0, l);
    let body = BodyBuilder::new()
        .rotated_part(
            Shape::Rod {
                mass: 0.3,
                length: l,
                axis: Axis::Z,
            },
            stem_at,
            tilt.clone(),
        )
        .rotated_part(
            Shape::Cone {
                mass: 1.2,
                radius: r,
                height: h,
                axis: Axis::Z,
                reversed: false,
            },
            cone_at,
            tilt,
        )
        .pivot([0.0, 0.0, 0.0])
        .build()
        .expect("a valid top");
    let mut lattice = placed(&rod(0.3, l, 4000), &rot, &stem_at);
    lattice.extend(placed(
        &revolution(1.2, 0.0, h, &|_| 0.0, &|s| r * (1.0 - s / h), N),
        &rot,
        &cone_at,
    ));
    let (m, g) = mass_center(&lattice);
    let e = rel_err(&body.inertia(), &tensor_about(&lattice, &Vector3::zeros()));
    let e_center = (body.center_of_mass() - g).norm();
    println!("tilted top: lattice {e:.1e}, centre {e_center:.1e}");
    assert!((body.mass() - m).abs() < 1e-12);
    assert!(e < 3e-4, "{e:e}");
    assert!(e_center < 1e-4, "{e_center:e}");
    // The symmetry axis stays principal: R e_z is an eigenvector of I.
    let axis = rot * Vector3::z();
    let image = body.inertia() * axis;
    assert!((image - axis * image.dot(&axis)).norm() < 1e-14 * image.norm());
}

#[test]
fn a_rod_turned_a_quarter_turn_is_the_rod_along_the_other_axis() {
    let rod = |axis| Shape::Rod {
        mass: M,
        length: 1.5,
        axis,
    };
    let ball = Shape::Sphere {
        mass: 1.0,
        radius: 0.1,
    };
    let along_x = BodyBuilder::new()
        .part(rod(Axis::X), [0.1, 0.2, 0.3])
        .part(ball.clone(), [0.0; 3])
        .build()
        .expect("valid");
    // z → x: the part's z axis is the third column, (1, 0, 0); det = +1.
    let quarter = [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]];
    let by_matrix = BodyBuilder::new()
        .rotated_part(rod(Axis::Z), [0.1, 0.2, 0.3], quarter)
        .part(ball.clone(), [0.0; 3])
        .build()
        .expect("valid");
    // Exact: every entry of R is 0 or ±1.
    assert_eq!(by_matrix.inertia(), along_x.inertia());
    let by_angle = BodyBuilder::new()
        .rotated_part(
            rod(Axis::Z),
            [0.1, 0.2, 0.3],
            Orientation::axis_angle([0.0, 1.0, 0.0], FRAC_PI_2),
        )
        .part(ball, [0.0; 3])
        .build()
        .expect("valid");
    // cos(π/2) rounds to 6e-17: that much of the rod's L²/12 is left off-axis.
    let e = rel_err(&by_angle.inertia(), &along_x.inertia());
    println!("rod quarter turn by axis–angle: {e:.1e}");
    assert!(e < 1e-15, "{e:e}");
}

#[test]
fn a_cube_and_a_ball_look_the_same_at_any_turn() {
    let mut rng = Rng::new(11);
    let s = 0.4;
    let k = M * s * s / 6.0;
    let mut worst = 0.0f64;
    for _ in 0..200 {
        let axis = rng.vector(-1.0, 1.0);
        let angle = rng.uniform(-PI, PI);
        let q = UnitQuaternion::from_axis_angle(
            &Unit::new_normalize(rng.vector(-1.0, 1.0)),
            rng.uniform(-PI, PI),
        );
        let turns: [Orientation<f64>; 3] = [
            Orientation::axis_angle(axis, angle),
            q.into(),
            Orientation::sequence([(Axis::Z, angle), (Axis::Y, -angle / 3.0), (Axis::X, 2.0)]),
        ];
        for turn in turns {
            let cube = Part::new(
                Shape::Cuboid {
                    mass: M,
                    size: [s; 3],
                },
                [0.5, 0.0, -1.0],
            )
            .rotated(turn.clone());
            let (t, _) = part_properties(cube);
            worst = worst.max(rel_err(&t, &(Matrix3::identity() * k)));
            let ball = Part::new(
                Shape::Ellipsoid {
                    mass: M,
                    semi_axes: [s; 3],
                },
                [0.0; 3],
            )
            .rotated(turn);
            let (t, _) = part_properties(ball);
            worst = worst.max(rel_err(&t, &(Matrix3::identity() * 0.4 * M * s * s)));
        }
    }
    println!("cube and ball at 600 turns: worst {worst:.1e}");
    assert!(worst < 2e-15, "{worst:e}");
}

#[test]
fn a_turn_about_the_symmetry_axis_changes_nothing() {
    let cylinder = Shape::Cylinder {
        mass: M,
        radius: 0.3,
        length: 1.2,
        axis: Axis::Y,
    };
    let (plain, _) = part_properties(Part::new(cylinder.clone(), [0.0; 3]));
    for angle in [0.3, 1.0, 2.5, -4.0] {
        let turned = Part::new(cylinder.clone(), [0.0; 3])
            .rotated(Orientation::sequence([(Axis::Y, angle)]));
        let (t, _) = part_properties(turned);
        let e = rel_err(&t, &plain);
        assert!(e < 1e-15, "{angle}: {e:e}");
    }
}

#[test]
fn a_rotated_explicit_tensor_is_turned_before_it_is_shifted() {
    // The box of `solids()`, turned and placed, as an explicit body: its tensor given in the
    // part's axes about its centre, and about a pivot.
    let (a, b, c) = (0.2, 0.5, 0.9);
    let diag = [
        M * (b * b + c * c) / 12.0,
        M * (a * a + c * c) / 12.0,
        M * (a * a + b * b) / 12.0,
    ];
    let (axis, angle) = ([1.0, 2.0, -0.5], 0.8);
    let r = reference(axis, angle);
    let (at, pivot) = (Vector3::new(0.3, 0.1, 0.6), Vector3::new(-0.1, 0.2, 0.0));
    let turn = || Orientation::axis_angle(axis, angle);
    let cuboid = BodyBuilder::new()
        .rotated_part(
            Shape::Cuboid {
                mass: M,
                size: [a, b, c],
            },
            at,
            turn(),
        )
        .pivot(pivot)
        .build()
        .expect("valid");
    let about_center = Shape::Explicit {
        mass: M,
        inertia: [
            [diag[0], 0.0, 0.0],
            [0.0, diag[1], 0.0],
            [0.0, 0.0, diag[2]],
        ],
        about: About::Center,
    };
    // About the pivot in the part's axes: Rᵀ I_P R, with I_P = I_G + M (|g|² E − g gᵀ).
    let g = at - pivot;
    let i_p = r * Matrix3::from_diagonal(&Vector3::from(diag)) * r.transpose()
        + M * (Matrix3::identity() * g.norm_squared() - g * g.transpose());
    let local = r.transpose() * i_p * r;
    let local = (local + local.transpose()) / 2.0;
    let about_pivot = Shape::Explicit {
        mass: M,
        inertia: std::array::from_fn(|i| std::array::from_fn(|j| local[(i, j)])),
        about: About::Pivot,
    };
    for shape in [about_center, about_pivot] {
        let explicit = BodyBuilder::new()
            .rotated_part(shape, at, turn())
            .pivot(pivot)
            .build()
            .expect("valid");
        let e = rel_err(&explicit.inertia(), &cuboid.inertia());
        assert!(e < 1e-14, "{e:e}");
    }
    let lattice = placed(&common::body::cuboid(M, a, b, c, N), &r, &at);
    let e = rel_err(&cuboid.inertia(), &tensor_about(&lattice, &pivot));
    assert!(e < 3e-4, "{e:e}");
}
