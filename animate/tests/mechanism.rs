//! A mechanism's link poses against closed forms and an independent rotation product, and
//! its animation's keyframes against the poses.

use approx::assert_relative_eq;
use precess::animate::{self, Options};
use precess::mechanism::MechanismPoses;
use precess::nalgebra::{Matrix3, Rotation3, Unit, Vector3};
use precess::ode::Trajectory;
use precess::prelude::*;

/// Two point masses on massless rods swinging about x, the lower angle relative.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(name = shoulder, axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(name = elbow, axis = x, at = [0.0, 0.0, -l1]),
       q = theta2, parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct DoublePendulum {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
}

/// A 3D chain: a post turning about z, an arm on a skew hinge (1, 1, 0) at the post's top,
/// a rod on a hinge about the arm's own y at the arm's end.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(post, parent = ground, joint = revolute(axis = z, at = [0.1, 0.0, 0.0]), q = a,
       parts(cylinder(mass = 1.0, radius = 0.02, length = 0.4, axis = z, at = [0.0, 0.0, 0.2])))]
#[body(arm, parent = post, joint = revolute(axis = [1.0, 1.0, 0.0], at = [0.0, 0.0, 0.4]), q = b,
       parts(rod(mass = 0.5, length = 0.3, axis = x, at = [0.15, 0.0, 0.0])))]
#[body(tip, parent = arm, joint = revolute(axis = y, at = [0.3, 0.0, 0.0]), q = c,
       parts(sphere(mass = 0.2, radius = 0.03, at = [0.0, 0.0, -0.1])))]
struct Chain;

/// Reproducible numbers in [lo, hi): a linear congruential generator.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn a_double_pendulum_s_bobs_are_where_the_closed_form_puts_them() {
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.3,
        m2: 0.5,
        l2: 0.7,
    };
    let mut rng = Lcg(7);
    for _ in 0..50 {
        let (t1, t2) = (rng.next(-7.0, 7.0), rng.next(-7.0, 7.0));
        let poses = p.link_poses(&[t1, t2]);
        assert_eq!((poses[0].name, poses[1].name), ("upper", "lower"));
        // About x, the rods hang along −z: bob 1 at (0, l₁ sin θ₁, −l₁ cos θ₁), bob 2 a rod
        // further at the absolute angle θ₁ + θ₂.
        let bob1 = Vector3::new(0.0, p.l1 * t1.sin(), -p.l1 * t1.cos());
        let bob2 = bob1 + Vector3::new(0.0, p.l2 * (t1 + t2).sin(), -p.l2 * (t1 + t2).cos());
        assert_relative_eq!(poses[0].center, bob1, epsilon = 1e-14);
        assert_relative_eq!(poses[1].center, bob2, epsilon = 1e-14);
        assert_relative_eq!(poses[0].origin, Vector3::zeros(), epsilon = 1e-15);
        assert_relative_eq!(poses[1].origin, bob1, epsilon = 1e-14);
        assert_relative_eq!(poses[1].joint, bob1, epsilon = 1e-14);
        let r2 = Rotation3::from_axis_angle(&Vector3::x_axis(), t1 + t2);
        assert_relative_eq!(poses[1].rotation, *r2.matrix(), epsilon = 1e-14);
    }
}

#[test]
fn a_3d_chain_s_poses_equal_the_product_of_its_joint_rotations() {
    let mut rng = Lcg(11);
    let skew = Unit::new_normalize(Vector3::new(1.0, 1.0, 0.0));
    for _ in 0..50 {
        let q = [
            rng.next(-4.0, 4.0),
            rng.next(-4.0, 4.0),
            rng.next(-4.0, 4.0),
        ];
        let r0 = Rotation3::from_axis_angle(&Vector3::z_axis(), q[0]);
        let r1 = r0 * Rotation3::from_axis_angle(&skew, q[1]);
        let r2 = r1 * Rotation3::from_axis_angle(&Vector3::y_axis(), q[2]);
        let o0 = Vector3::new(0.1, 0.0, 0.0);
        let o1 = o0 + r0 * Vector3::new(0.0, 0.0, 0.4);
        let o2 = o1 + r1 * Vector3::new(0.3, 0.0, 0.0);
        let poses = Chain.link_poses(&q);
        let expected: [(Rotation3<f64>, Vector3<f64>); 3] = [(r0, o0), (r1, o1), (r2, o2)];
        for (pose, (r, o)) in poses.iter().zip(expected) {
            assert_relative_eq!(pose.rotation, *r.matrix(), epsilon = 1e-14);
            assert_relative_eq!(pose.origin, o, epsilon = 1e-14);
            assert_relative_eq!(pose.joint, o, epsilon = 1e-14);
        }
        assert_relative_eq!(
            poses[2].center,
            o2 + r2 * Vector3::new(0.0, 0.0, -0.1),
            epsilon = 1e-14
        );
        let orthogonal: Matrix3<f64> = poses[2].rotation.transpose() * poses[2].rotation;
        assert_relative_eq!(orthogonal, Matrix3::identity(), epsilon = 1e-14);
    }
    let parts = Chain.link_parts();
    assert_eq!(
        parts.iter().map(|d| d.parts.len()).collect::<Vec<_>>(),
        [1, 1, 1]
    );
    assert_eq!(parts[2].parts[0].at, [0.0, 0.0, -0.1]);
}

#[test]
fn the_animation_s_keyframes_are_the_link_poses() {
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.0,
        m2: 0.5,
        l2: 0.7,
    };
    let mut run = Trajectory::new(vec![]);
    for k in 0..=40 {
        let t = 0.05 * k as f64;
        run.push(t, [2.0 * t.sin(), -t, 0.0, 0.0], &[]).unwrap();
    }
    let animation = animate::mechanism(&p, &run, Options::default()).unwrap();
    for (link, keys) in [0, 1].map(|k| (k, animation.keyframes(k).unwrap())) {
        assert_eq!(keys.times.len(), 41);
        for (s, y) in run.states().iter().enumerate() {
            let pose = &p.link_poses(&[y[0], y[1]])[link];
            let translation = keys.translations[s].map(f64::from);
            assert_relative_eq!(Vector3::from(translation), pose.origin, epsilon = 1e-6);
            let [x, yq, z, w] = keys.rotations[s].map(f64::from);
            let q = precess::nalgebra::Quaternion::new(w, x, yq, z);
            let r = UnitQuaternion::from_quaternion(q).to_rotation_matrix();
            assert_relative_eq!(*r.matrix(), pose.rotation, epsilon = 1e-6);
        }
    }
    // The joints follow as bodies 2 and 3: the elbow on the upper bob.
    let elbow = animation.keyframes(3).unwrap();
    let y = run.states()[40];
    let bob1 = p.link_poses(&[y[0], y[1]])[0].center;
    let at = Vector3::from(elbow.translations[40].map(f64::from));
    assert_relative_eq!(at, bob1, epsilon = 1e-6);
    assert!(animation.keyframes(4).is_none());
    assert!(animation.to_glb().unwrap().len() > 1000);
}

#[test]
fn a_non_finite_coordinate_is_a_typed_error() {
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.0,
        m2: 0.5,
        l2: 0.7,
    };
    // A state array too short to hold q: NaN coordinates, reported for sample 0.
    let short: Trajectory<[f64; 1]> = {
        let mut r = Trajectory::new(vec![]);
        r.push(0.0, [0.1], &[]).unwrap();
        r
    };
    let err = animate::mechanism::<_, 2, _>(&p, &short, Options::default()).unwrap_err();
    assert!(
        matches!(err, animate::AnimateError::NonFinite { index: 0, .. }),
        "{err}"
    );
}
