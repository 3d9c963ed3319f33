//! Every example mechanism's derived link poses (`MechanismPoses`, the very structs the
//! examples derive) against the frames of the independent Newton–Euler reference of
//! the testkit's `mechanism::rnea`, at random coordinates: the rotation R_b and origin o_b of
//! each body, and its centre o_b + R_b c.

use crate::common::mechanism::examples;
use crate::common::mechanism::{NumMechanism, rnea};

use crate::common::mechanism::rng::Rng;
use examples::babyboot::Babyboot;
use examples::chain::Chain;
use examples::double_pendulum::DoublePendulum;
use examples::gimballed_gyroscope::Gyroscope;
use examples::{
    angles, babyboot_reference, chain_reference, double_pendulum_reference, gyroscope_reference,
};
use nalgebra::Vector3;
use precess::mechanism::MechanismPoses;

/// The largest difference of any rotation entry, origin or centre coordinate over `count`
/// random q.
fn worst<M: MechanismPoses<N>, const N: usize>(
    model: &M,
    reference: &NumMechanism,
    rng: &mut Rng,
    count: usize,
) -> f64 {
    let mut worst: f64 = 0.0;
    for _ in 0..count {
        let q: [f64; N] = angles(rng);
        let poses = model.link_poses(&q);
        let frames = rnea::body_frames(reference, &q);
        assert_eq!(poses.len(), frames.len());
        for ((pose, (r, o)), body) in poses.iter().zip(&frames).zip(&reference.bodies) {
            let center = o + r * Vector3::from(body.center);
            worst = worst
                .max((pose.rotation - r).amax())
                .max((pose.origin - o).amax())
                .max((pose.center - center).amax());
        }
    }
    worst
}

#[test]
fn every_example_mechanism_s_link_poses_are_the_reference_frames() {
    let mut rng = Rng::new(45);
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.3,
        m2: 0.5,
        l2: 0.7,
    };
    let g = Gyroscope {
        m_outer: 0.3,
        m_inner: 0.2,
    };
    let cases = [
        (
            "double pendulum",
            worst(&p, &double_pendulum_reference(&p), &mut rng, 200),
        ),
        (
            "gimballed gyroscope",
            worst(&g, &gyroscope_reference(&g), &mut rng, 200),
        ),
        (
            "babyboot",
            worst(&Babyboot, &babyboot_reference(), &mut rng, 200),
        ),
        ("chain", worst(&Chain, &chain_reference(), &mut rng, 200)),
    ];
    for (name, w) in cases {
        assert!(
            w < 1e-13,
            "{name}: poses differ from the reference by {w:e}"
        );
    }
}

#[test]
fn a_chain_s_joint_points_are_its_parents_rod_ends() {
    // Each link of the chain hangs from its parent's end, 0.5 down the parent's own z.
    let mut rng = Rng::new(46);
    for _ in 0..100 {
        let q: [f64; 8] = angles(&mut rng);
        let poses = Chain.link_poses(&q);
        for pair in poses.windows(2) {
            let end = pair[0].origin + pair[0].rotation * Vector3::new(0.0, 0.0, -0.5);
            assert!((pair[1].joint - end).amax() < 1e-14);
            assert!((pair[1].origin - end).amax() < 1e-14);
        }
        assert_eq!(poses[0].joint, Vector3::zeros());
    }
}
