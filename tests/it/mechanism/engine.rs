//! The mechanism engine against an independent recursive Newton–Euler algorithm (in
//! the testkit's `mechanism::rnea`): every route's q̈ at 10³ random states.

use crate::common::mechanism as mechanism_support;

use mechanism_support::rng::Rng;
use mechanism_support::{
    NumBody, NumJoint, NumLoad, NumMechanism, Values, random_inertia, relative_difference, rnea,
    scene,
};
use precess::mechanism::{MechanismModel, Route};
use precess::rigid::AngleSequence;
use precess::sym::Arena;

const STATES: usize = 1000;
const TOLERANCE: f64 = 1e-12;

fn model(m: &NumMechanism, values: Values, route: Route) -> MechanismModel {
    let mut a = Arena::new();
    let (s, bound) = scene(&mut a, m, values);
    let d = s.derive(&mut a, route).expect("derives");
    let read = d.parameters(&a);
    let pairs: Vec<(&str, f64)> = bound
        .iter()
        .filter(|(n, _)| read.contains(n))
        .map(|(n, v)| (n.as_str(), *v))
        .collect();
    MechanismModel::from_derivation(&a, &d, &pairs).expect("binds")
}

/// A random state: angles anywhere, slides within ±0.5, spherical θ (ZXZ) or pitch (ZYX)
/// kept away from the chart's singularity.
pub(super) fn random_state(m: &NumMechanism, rng: &mut Rng) -> (Vec<f64>, Vec<f64>) {
    let mut q = Vec::new();
    for b in &m.bodies {
        match &b.joint {
            NumJoint::Prismatic(_) => q.push(rng.uniform(-0.5, 0.5)),
            NumJoint::Spherical(AngleSequence::Zxz) => q.extend([
                rng.uniform(-3.0, 3.0),
                rng.uniform(0.3, 2.8),
                rng.uniform(-3.0, 3.0),
            ]),
            NumJoint::Spherical(AngleSequence::Zyx) => q.extend([
                rng.uniform(-3.0, 3.0),
                rng.uniform(-1.2, 1.2),
                rng.uniform(-3.0, 3.0),
            ]),
            j => q.extend((0..j.dof()).map(|_| rng.uniform(-3.1, 3.1))),
        }
    }
    let qd = (0..q.len()).map(|_| rng.uniform(-2.0, 2.0)).collect();
    (q, qd)
}

/// The worst relative difference between the model and the RNEA over `STATES` states.
fn worst(m: &NumMechanism, model: &MechanismModel, seed: u64) -> f64 {
    let mut rng = Rng::new(seed);
    let mut worst: f64 = 0.0;
    for _ in 0..STATES {
        let (q, qd) = random_state(m, &mut rng);
        let ours = model.accelerations(0.0, &q, &qd).expect("regular");
        let reference = rnea::accelerations(m, &q, &qd);
        worst = worst.max(relative_difference(&ours, &reference, 1.0));
    }
    worst
}

fn check_all_routes(m: &NumMechanism, seed: u64) {
    for values in [Values::Literals, Values::Parameters] {
        // Auto takes one of these two (tests/mechanism_pendulum.rs runs it).
        for route in [Route::Factored, Route::Symbolic, Route::Recursive] {
            if route == Route::Symbolic && m.dof() > 3 {
                continue;
            }
            let model = model(m, values, route);
            let w = worst(m, &model, seed);
            assert!(w <= TOLERANCE, "{values:?} {route:?}: worst {w:e}");
        }
    }
}

pub fn pendulum() -> NumMechanism {
    let mut b = NumBody::new(None, [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    b.mass = 1.3;
    b.center = [0.0, 0.1, -0.7];
    b.inertia = nalgebra::Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
    b.loads[0] = NumLoad {
        spring: Some((2.0, 0.3)),
        damper: Some(0.4),
        effort: Some(0.25),
    };
    NumMechanism {
        bodies: vec![b],
        gravity: [0.0, 0.0, -9.81],
    }
}

pub fn double_pendulum() -> NumMechanism {
    let mut upper = NumBody::new(None, [0.0; 3], NumJoint::Revolute([0.0, 1.0, 0.0]));
    upper.mass = 0.8;
    upper.center = [0.0, 0.0, -0.5];
    let mut lower = NumBody::new(
        Some(0),
        [0.0, 0.0, -1.0],
        NumJoint::Revolute([0.0, 1.0, 0.0]),
    );
    lower.mass = 1.1;
    lower.center = [0.05, 0.0, -0.4];
    lower.inertia = nalgebra::Matrix3::new(0.09, 0.0, 0.01, 0.0, 0.12, 0.0, 0.01, 0.0, 0.05);
    NumMechanism {
        bodies: vec![upper, lower],
        gravity: [0.0, 0.0, -9.81],
    }
}

/// A spatial chain: a universal joint, a tilted revolute, a prismatic slide.
pub fn spatial_chain(rng: &mut Rng) -> NumMechanism {
    let mut root = NumBody::new(
        None,
        [0.1, 0.0, 0.2],
        NumJoint::Universal([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
    );
    root.center = [0.1, 0.2, -0.4];
    let mut middle = NumBody::new(
        Some(0),
        [0.0, 0.3, -0.8],
        NumJoint::Revolute([0.6, 0.0, 0.8]),
    );
    middle.center = [0.0, -0.1, -0.3];
    middle.loads[0].damper = Some(0.3);
    let mut tip = NumBody::new(
        Some(1),
        [0.2, 0.0, -0.6],
        NumJoint::Prismatic([0.0, 1.0, 1.0]),
    );
    tip.center = [0.05, 0.0, 0.1];
    tip.loads[0].spring = Some((5.0, 0.1));
    tip.body_torque = Some([0.1, -0.2, 0.05]);
    tip.space_torque = Some([0.0, 0.3, -0.1]);
    for (i, b) in [&mut root, &mut middle, &mut tip].into_iter().enumerate() {
        b.mass = 0.5 + 0.3 * i as f64;
        b.inertia = random_inertia(rng);
    }
    NumMechanism {
        bodies: vec![root, middle, tip],
        gravity: [0.3, -0.2, -9.81],
    }
}

/// A body on a spherical joint below a revolute arm.
pub fn spherical_on_arm(sequence: AngleSequence, rng: &mut Rng) -> NumMechanism {
    let mut arm = NumBody::new(None, [0.0; 3], NumJoint::Revolute([0.0, 0.0, 1.0]));
    arm.center = [0.4, 0.0, 0.0];
    arm.inertia = random_inertia(rng);
    let mut ball = NumBody::new(Some(0), [0.8, 0.0, 0.0], NumJoint::Spherical(sequence));
    ball.mass = 0.7;
    ball.center = [0.05, -0.02, 0.3];
    ball.inertia = random_inertia(rng);
    ball.body_torque = Some([0.02, 0.0, 0.1]);
    NumMechanism {
        bodies: vec![arm, ball],
        gravity: [0.0, 0.0, -9.81],
    }
}

#[test]
fn pendulum_with_spring_damper_and_effort_agrees_with_newton_euler() {
    check_all_routes(&pendulum(), 1);
}

#[test]
fn double_pendulum_agrees_with_newton_euler() {
    check_all_routes(&double_pendulum(), 2);
}

#[test]
fn spatial_chain_with_mixed_joints_agrees_with_newton_euler() {
    let m = spatial_chain(&mut Rng::new(3));
    check_all_routes(&m, 4);
}

#[test]
fn spherical_joint_on_an_arm_agrees_with_newton_euler() {
    for (k, seq) in [AngleSequence::Zxz, AngleSequence::Zyx]
        .into_iter()
        .enumerate()
    {
        let m = spherical_on_arm(seq, &mut Rng::new(5 + k as u64));
        check_all_routes(&m, 6);
    }
}
