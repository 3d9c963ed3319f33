//! Euler's equations of run-time bodies against the generic I⁻¹ (G − ω × I ω) taken in the
//! description frame with nalgebra's inverse, at 10⁴ random states; the split of L and T
//! for a freely moving body against direct summation over its particles.

use crate::common;

use common::body::*;
use common::rng::Rng;
use nalgebra::Vector3;
use precess::body::{About, Axis, Body, BodyBuilder, RigidBody, Shape};

fn bodies() -> Vec<Body> {
    let tilted = [[2.0, 0.3, -0.1], [0.3, 1.5, 0.2], [-0.1, 0.2, 1.0]];
    vec![
        BodyBuilder::new()
            .part(
                Shape::Cylinder {
                    mass: 0.2,
                    radius: 0.004,
                    length: 0.06,
                    axis: Axis::Z,
                },
                [0.0, 0.0, 0.03],
            )
            .part(
                Shape::Disk {
                    mass: 0.5,
                    radius: 0.03,
                    axis: Axis::Z,
                },
                [0.0, 0.0, 0.05],
            )
            .pivot([0.0; 3])
            .build(),
        BodyBuilder::new()
            .part(
                Shape::Cuboid {
                    mass: 2.0,
                    size: [0.1, 0.2, 0.3],
                },
                [0.0; 3],
            )
            .build(),
        BodyBuilder::new()
            .part(
                Shape::Sphere {
                    mass: 1.0,
                    radius: 0.1,
                },
                [0.1, 0.2, 0.0],
            )
            .part(
                Shape::Cone {
                    mass: 2.0,
                    radius: 0.1,
                    height: 0.3,
                    axis: Axis::X,
                    reversed: false,
                },
                [-0.1, 0.0, 0.3],
            )
            .build(),
        BodyBuilder::new()
            .part(
                Shape::Explicit {
                    mass: 3.0,
                    inertia: tilted,
                    about: About::Center,
                },
                [0.0; 3],
            )
            .build(),
    ]
    .into_iter()
    .map(|b| b.expect("a valid body"))
    .collect()
}

#[test]
fn euler_rhs_matches_the_generic_form_at_random_states() {
    let worst = bodies()
        .iter()
        .zip(3..)
        .map(|(body, seed)| check_euler(body, seed))
        .fold(0.0f64, f64::max);
    println!("worst relative error of euler_rhs_principal: {worst:.1e}");
}

#[test]
fn energy_and_momentum_about_the_reference_point() {
    let mut rng = Rng::new(5);
    for body in bodies() {
        let w = rng.vector(-3.0, 3.0);
        let i = body.inertia();
        assert!((body.kinetic_energy(&w) - 0.5 * w.dot(&(i * w))).abs() < 1e-14);
        assert_eq!(body.angular_momentum(&w), i * w);
    }
}

#[test]
fn free_body_split_against_particles() {
    // A lumpy rigid set of particles, moving with velocity V of its centre and spin ω:
    // L_O = Σ m x × ẋ and T = ½ Σ m |ẋ|² summed directly, against J_cm + R × P and
    // T_cm + ½ M V².
    let mut rng = Rng::new(9);
    let mut builder = BodyBuilder::new();
    let mut ps: Vec<Particle> = Vec::new();
    for _ in 0..12 {
        let (m, x) = (rng.uniform(0.1, 1.0), rng.vector(-1.0, 1.0));
        builder = builder.part(Shape::Particle { mass: m }, [x.x, x.y, x.z]);
        ps.push((m, x));
    }
    let body = builder.build().expect("a valid body");
    let (_, g) = mass_center(&ps);
    for _ in 0..100 {
        let (w, v, o) = (
            rng.vector(-2.0, 2.0),
            rng.vector(-2.0, 2.0),
            rng.vector(-5.0, 5.0),
        );
        let mut l = Vector3::zeros();
        let mut t = 0.0;
        for (m, x) in &ps {
            let xdot = v + w.cross(&(x - g));
            l += (x - o).cross(&(xdot * *m));
            t += 0.5 * m * xdot.norm_squared();
        }
        let r = body.center_of_mass() - o;
        let l_split = body.angular_momentum_about(&w, &r, &v);
        let t_split = body.kinetic_energy_free(&w, &v);
        assert!(
            (l_split - l).norm() < 1e-12 * l.norm().max(1.0),
            "{l_split} vs {l}"
        );
        assert!((t_split - t).abs() < 1e-12 * t);
    }
}
