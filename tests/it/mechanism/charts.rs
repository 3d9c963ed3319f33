//! Spherical joints through gimbal lock: `ChartedMechanism` against the sleeping top's closed
//! form R(t) = Rz(ω₃ t), against `ChartedTop` on the same body, against a planar pendulum
//! on a revolute joint (a spherical pendulum swinging in a plane through the ZXZ lock), and
//! against itself started in the other chart; energy along the way; the exact map between
//! charts.

use crate::common;

use approx::assert_relative_eq;
use common::rng::Rng;
use precess::mechanism::charts::{ChartSet, ChartedDynamics, ChartedMechanism, MechanismCharts};
use precess::mechanism::{JointKind, MechanismScene, Parent, Route};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::prelude::*;
use precess::rigid::{joint_rate_matrix, joint_rotation, map_to_partner};
use precess::sym::Arena;

fn tight() -> ChartConfig {
    ChartConfig {
        switch_below: 0.3,
        stepper: AdaptiveConfig::with_tol(1e-12, 1e-12),
    }
}

fn rz(angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Vector3::z_axis(), angle).matrix()
}

fn rx(angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Vector3::x_axis(), angle).matrix()
}

/// A symmetric top on a spherical joint: unit mass a unit length up, I = diag(¼, ¼, ½)
/// about its centre, so I₁ = 5/4 and I₃ = ½ about the joint; gravity 1 along −z.
#[derive(Mechanism)]
#[mechanism(gravity = 1.0)]
#[body(top, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.25, 0.25, 0.5))))]
struct UprightTop;

/// The same body as a `#[top]`.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.25, 0.25, 0.5)),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct HeavyTop;

/// ω₃ = 6: above the sleeping-top threshold ω₃² = 4 M g l I₁ / I₃² = 20, so it stays up.
const SPIN: f64 = 6.0;

#[test]
fn a_sleeping_top_upright_follows_the_closed_form_where_zxz_cannot_start() {
    let w0 = Vector3::new(0.0, 0.0, SPIN);
    // Exactly upright the declared ZXZ chart is singular (sin θ = 0).
    let declared = ChartedMechanism::new(
        &UprightTop,
        0.0,
        [0.0, 0.0, 0.0, 0.0, 0.0, SPIN],
        ChartSet::DECLARED,
        tight(),
    );
    assert!(matches!(
        declared,
        Err(MechanismError::Joint {
            source: ChartError::SingularChart { det: 0.0, .. },
            ..
        })
    ));
    let attitudes = [(Matrix3::identity(), w0)];
    let mut top =
        ChartedMechanism::from_attitudes(&UprightTop, 0.0, [0.0; 6], &attitudes, tight()).unwrap();
    assert_eq!(top.charts(), ChartSet(1));
    assert_eq!(top.sequence(0), Some(AngleSequence::Zyx));
    let e0 = top.energy();
    // V = m g l = 1 and T = ½ I₃ ω₃² = 9.
    assert_relative_eq!(e0, 10.0, max_relative = 1e-14);
    for t in [1.0, 2.5, 5.0] {
        top.advance_to(t).unwrap();
        let r = top.joint_rotation(0).unwrap();
        assert_relative_eq!(r, rz(SPIN * t), epsilon = 1e-9);
        assert_relative_eq!(top.joint_omega(0).unwrap(), w0, epsilon = 1e-9);
    }
    assert_relative_eq!(top.energy(), e0, max_relative = 1e-12);
}

#[test]
fn a_top_nodding_through_the_vertical_agrees_with_charted_top() {
    // Started in ZXZ at θ = 0.6 nodding down, with the azimuthal rate that makes the momentum
    // about the vertical equal that about the figure axis, I₁ sin²θ φ̇ = I₃ ω₃ (1 − cos θ):
    // then θ passes through 0, ZXZ's lock (its energy, 1.80 against the 1 of the upright
    // top, lets it).
    let (i1, i3) = (1.25, 0.5);
    let theta = 0.6f64;
    let phi_dot = i3 * SPIN * (1.0 - theta.cos()) / (i1 * theta.sin().powi(2));
    let psi_dot = SPIN - phi_dot * theta.cos();
    let y0 = [0.0, theta, 0.0, phi_dot, -1.0, psi_dot];
    let mut mech =
        ChartedMechanism::new(&UprightTop, 0.0, y0, ChartSet::DECLARED, tight()).unwrap();
    let r0 = mech.joint_rotation(0).unwrap();
    let w0 = mech.joint_omega(0).unwrap();
    let [zxz, zyx] = TopChart::both(&HeavyTop);
    let mut top = ChartedTop::new([zxz, zyx], 0.0, &r0, &w0, tight()).unwrap();
    let e0 = mech.energy();
    assert_relative_eq!(e0, top.energy(), max_relative = 1e-13);
    let mut closest = f64::INFINITY;
    let mut t = 0.0;
    while t < 3.0 {
        t += 0.01;
        mech.advance_to(t).unwrap();
        top.advance_to(t).unwrap();
        let r = mech.joint_rotation(0).unwrap();
        closest = closest.min(r[(0, 2)].hypot(r[(1, 2)]));
        assert_relative_eq!(r, top.rotation(), epsilon = 1e-8);
        assert_relative_eq!(mech.joint_omega(0).unwrap(), top.omega(), epsilon = 1e-7);
        assert_relative_eq!(mech.energy(), e0, max_relative = 1e-10);
    }
    assert!(
        closest < 1e-2,
        "never came near the vertical: sin θ ≥ {closest}"
    );
    // Into ZYX near the vertical, where it stays: ZYX is regular all along.
    assert_eq!((mech.switches(), mech.charts()), (1, ChartSet(1)));
}

/// A spherical pendulum (a rod hanging from a ball joint) with a second rod on a hinge at
/// its end: at zero angles both hang straight down, where ZXZ is singular.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(rod(mass = 1.0, length = 1.0, at = [0.0, 0.0, -0.5]),
             disk(mass = 0.3, radius = 0.2, at = [0.0, 0.0, -1.0])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -1.0]), q = alpha,
       parts(rod(mass = 0.5, length = 0.8, at = [0.0, 0.0, -0.4])))]
struct BallAndHinge;

#[test]
fn a_pendulum_on_a_ball_joint_swings_through_lock_in_either_starting_chart() {
    // θ = 0.4 with a little azimuthal rate: θ swings down close to 0 and back.
    let q = [0.3, 0.4, -0.2];
    let qd = [0.05, -1.5, 0.3];
    let y0 = [q[0], q[1], q[2], 0.2, qd[0], qd[1], qd[2], -0.4];
    let mut zxz =
        ChartedMechanism::new(&BallAndHinge, 0.0, y0, ChartSet::DECLARED, tight()).unwrap();
    let (p, pd, _) = map_to_partner(AngleSequence::Zxz, &q, &qd).unwrap();
    let y1 = [p[0], p[1], p[2], 0.2, pd[0], pd[1], pd[2], -0.4];
    let mut zyx = ChartedMechanism::new(&BallAndHinge, 0.0, y1, ChartSet(1), tight()).unwrap();
    let e0 = zxz.energy();
    assert_relative_eq!(zyx.energy(), e0, max_relative = 1e-14);
    let mut closest = f64::INFINITY;
    let mut drift = 0.0f64;
    let mut t = 0.0;
    while t < 3.0 {
        t += 0.01;
        zxz.advance_to(t).unwrap();
        zyx.advance_to(t).unwrap();
        let r = zxz.joint_rotation(0).unwrap();
        // The ZXZ lock is the body z axis vertical, |det B| = sin θ = |R e_z × e_z|.
        closest = closest.min(r[(0, 2)].hypot(r[(1, 2)]));
        drift = drift.max(((zxz.energy() - e0) / e0).abs());
        drift = drift.max(((zyx.energy() - e0) / e0).abs());
    }
    println!(
        "ball and hinge: max |ΔE/E| {drift:e}, closest sin θ {closest:e}, switches {}",
        zxz.switches()
    );
    assert!(drift <= 1e-9, "energy drift {drift:e}");
    assert!(closest < 0.1, "never came near the lock: sin θ ≥ {closest}");
    assert!(zxz.switches() >= 1);
    assert_relative_eq!(
        zxz.joint_rotation(0).unwrap(),
        zyx.joint_rotation(0).unwrap(),
        epsilon = 1e-7
    );
    assert_relative_eq!(
        zxz.joint_omega(0).unwrap(),
        zyx.joint_omega(0).unwrap(),
        epsilon = 1e-6
    );
    let (a, b) = (zxz.state(), zyx.state());
    assert_relative_eq!(a[3], b[3], epsilon = 1e-7);
    assert_relative_eq!(a[7], b[7], epsilon = 1e-6);
}

/// A unit mass a unit length below a ball joint, I = 1/10 about its centre, built at run
/// time.
fn spherical_pendulum(arena: &mut Arena) -> MechanismScene {
    let (o, z) = (arena.one(), arena.zero());
    let down = arena.integer(-1);
    let ball = JointKind::Spherical {
        sequence: AngleSequence::Zxz,
    };
    let mut bob =
        MechanismScene::body(arena, "bob", Parent::Ground, ball, &["phi", "theta", "psi"]);
    bob.mass = o;
    bob.center = [z, z, down];
    let ten = arena.integer(10);
    let tenth = arena.recip(ten).unwrap();
    bob.inertia = [[tenth, z, z], [z, tenth, z], [z, z, tenth]];
    let mut scene = MechanismScene::new();
    scene.bodies.push(bob);
    scene.gravity = Some([z, z, arena.parameter("g")]);
    scene
}

/// The same swing on a hinge about x: a sphere of radius ½ has I = ⅖ m r² = 1/10.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(bob, joint = revolute(axis = x), q = alpha,
       parts(sphere(mass = 1.0, radius = 0.5, at = [0.0, 0.0, -1.0])))]
struct PlanarPendulum;

#[test]
fn a_run_time_spherical_pendulum_swings_exactly_through_the_zxz_lock_as_a_hinge_does() {
    let mut arena = Arena::new();
    let scene = spherical_pendulum(&mut arena);
    let charts = MechanismCharts::new(&mut arena, &scene, Route::Auto, &[("g", -9.81)]).unwrap();
    // Swinging in the y–z plane: the bob passes straight below the joint, where φ and ψ
    // of ZXZ are undefined.
    let alpha0 = 0.8;
    // Rz(0) Rx(α₀) Rz(0) = Rx(α₀), started in the declared ZXZ.
    let y0 = [0.0, alpha0, 0.0, 0.0, 0.0, 0.0];
    let mut ball = ChartedMechanism::new(&charts, 0.0, y0, ChartSet::DECLARED, tight()).unwrap();
    let config = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut hinge = Dop853::new(&PlanarPendulum, 0.0, [alpha0, 0.0], config).unwrap();
    let e0 = ball.energy();
    // V = −m g·r = −9.81 cos α₀.
    assert_relative_eq!(e0, -9.81 * alpha0.cos(), max_relative = 1e-14);
    for t in [0.25, 0.5, 1.0, 2.0, 3.0] {
        ball.advance_to(t).unwrap();
        hinge.advance_to(t).unwrap();
        let alpha = hinge.y()[0];
        assert_relative_eq!(ball.joint_rotation(0).unwrap(), rx(alpha), epsilon = 1e-8);
        let w = Vector3::new(hinge.y()[1], 0.0, 0.0);
        assert_relative_eq!(ball.joint_omega(0).unwrap(), w, epsilon = 1e-7);
        assert_relative_eq!(ball.energy(), e0, max_relative = 1e-10);
    }
    assert_eq!((ball.switches(), ball.charts()), (1, ChartSet(1)));
}

#[test]
fn the_map_between_charts_round_trips() {
    let mut rng = Rng::new(14);
    let mut worst = [0.0f64; 4];
    for _ in 0..1000 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.3, 2.8),
            rng.uniform(-3.0, 3.0),
        ];
        let qd = [
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
        ];
        let Ok((p, pd, _)) = map_to_partner(AngleSequence::Zxz, &q, &qd) else {
            continue; // ZYX's own lock; rare among random attitudes.
        };
        // The partner describes the same attitude and angular velocity.
        let r = joint_rotation(AngleSequence::Zxz, &q);
        let w = joint_rate_matrix(AngleSequence::Zxz, &q) * Vector3::from(qd);
        let r_p = joint_rotation(AngleSequence::Zyx, &p);
        let w_p = joint_rate_matrix(AngleSequence::Zyx, &p) * Vector3::from(pd);
        worst[0] = worst[0].max((r - r_p).abs().max());
        worst[1] = worst[1].max((w - w_p).abs().max() / w.norm());
        let (back, back_d, _) = map_to_partner(AngleSequence::Zyx, &p, &pd).unwrap();
        let dq = (0..3).map(|k| (back[k] - q[k]).abs()).fold(0.0, f64::max);
        let dqd = (0..3)
            .map(|k| (back_d[k] - qd[k]).abs())
            .fold(0.0, f64::max);
        worst[2] = worst[2].max(dq);
        worst[3] = worst[3].max(dqd / Vector3::from(qd).norm());
    }
    println!(
        "worst: R {:e}, ω {:e}, q back {:e}, q̇ back {:e}",
        worst[0], worst[1], worst[2], worst[3]
    );
    assert!(worst.iter().all(|&e| e <= 1e-14), "worst errors {worst:?}");
}

#[test]
fn the_rate_matrix_is_the_derivative_of_the_joint_rotation() {
    // ω̂ = Jᵀ J̇ by central differences along q̇, for both sequences.
    let mut rng = Rng::new(3);
    for sequence in [AngleSequence::Zxz, AngleSequence::Zyx] {
        for _ in 0..50 {
            let q = [0, 1, 2].map(|_| rng.uniform(-3.0, 3.0));
            let qd = [0, 1, 2].map(|_| rng.uniform(-2.0, 2.0));
            let h = 1e-6;
            let step = |s: f64| [0, 1, 2].map(|k| q[k] + s * qd[k]);
            let jdot = (joint_rotation(sequence, &step(h)) - joint_rotation(sequence, &step(-h)))
                / (2.0 * h);
            let w_hat = joint_rotation(sequence, &q).transpose() * jdot;
            let w = Vector3::new(w_hat[(2, 1)], w_hat[(0, 2)], w_hat[(1, 0)]);
            let b = joint_rate_matrix(sequence, &q);
            assert_relative_eq!(b * Vector3::from(qd), w, epsilon = 1e-8);
        }
    }
}

#[test]
fn bad_settings_and_states_are_typed_errors() {
    let bad = ChartConfig {
        switch_below: f64::NAN,
        ..ChartConfig::default()
    };
    let y = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0];
    assert!(matches!(
        ChartedMechanism::new(&UprightTop, 0.0, y, ChartSet::DECLARED, bad),
        Err(MechanismError::Chart(ChartError::InvalidSwitch { .. }))
    ));
    assert!(matches!(
        ChartedMechanism::new(&UprightTop, 0.0, y, ChartSet(2), tight()),
        Err(MechanismError::UnavailableCharts { charts: 2 })
    ));
    let nan = [0.0, f64::NAN, 0.0, 0.0, 0.0, 0.0];
    assert!(matches!(
        ChartedMechanism::new(&UprightTop, 0.0, nan, ChartSet::DECLARED, tight()),
        Err(MechanismError::NonFinite { .. })
    ));
    assert!(matches!(
        ChartedMechanism::from_attitudes(&UprightTop, 0.0, y, &[], tight()),
        Err(MechanismError::AttitudeCount {
            expected: 1,
            got: 0
        })
    ));
    let sheared = (
        Matrix3::new(1.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        Vector3::zeros(),
    );
    assert!(matches!(
        ChartedMechanism::from_attitudes(&UprightTop, 0.0, y, &[sheared], tight()),
        Err(MechanismError::Attitude { .. })
    ));
    let mut top = ChartedMechanism::new(&UprightTop, 0.0, y, ChartSet::DECLARED, tight()).unwrap();
    assert!(matches!(top.advance_to(-1.0), Err(MechanismError::Ode(_))));
    assert_eq!(top.joint_rotation(1), None);
    // The derived mechanism lists its joint and both its charts.
    let joints = ChartedDynamics::<6>::spherical_joints(&UprightTop);
    assert_eq!(joints.len(), 1);
    assert_eq!((joints[0].name.as_str(), joints[0].first), ("top", 0));
    assert!(ChartedDynamics::<6>::has_charts(&UprightTop, ChartSet(1)));
}

/// Two rods on ball joints, one hanging from the other: two spherical joints, so the derive
/// emits all four chart sets.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, joint = spherical(sequence = zxz), q = [phi1, theta1, psi1],
       parts(rod(mass = 1.0, length = 1.0, at = [0.0, 0.0, -0.5]),
             sphere(mass = 0.2, radius = 0.1, at = [0.0, 0.0, -1.0])))]
#[body(lower, parent = upper, joint = spherical(sequence = zxz, at = [0.0, 0.0, -1.0]),
       q = [phi2, theta2, psi2],
       parts(rod(mass = 0.5, length = 0.8, at = [0.0, 0.0, -0.4]),
             sphere(mass = 0.2, radius = 0.1, at = [0.0, 0.0, -0.8])))]
struct TwoBalls;

#[test]
fn two_ball_joints_switch_each_on_its_own_and_agree_with_the_all_zyx_start() {
    for charts in 0..4 {
        assert!(ChartedDynamics::<12>::has_charts(
            &TwoBalls,
            ChartSet(charts)
        ));
    }
    let (q1, qd1) = ([0.2, 0.35, -0.1], [0.1, -1.2, 0.4]);
    let (q2, qd2) = ([-0.4, 0.3, 0.5], [-0.2, 1.0, -0.3]);
    let state = |a: [f64; 3], ad: [f64; 3], b: [f64; 3], bd: [f64; 3]| {
        let mut y = [0.0; 12];
        y[..3].copy_from_slice(&a);
        y[3..6].copy_from_slice(&b);
        y[6..9].copy_from_slice(&ad);
        y[9..].copy_from_slice(&bd);
        y
    };
    let y0 = state(q1, qd1, q2, qd2);
    let mut declared =
        ChartedMechanism::new(&TwoBalls, 0.0, y0, ChartSet::DECLARED, tight()).unwrap();
    let (p1, pd1, _) = map_to_partner(AngleSequence::Zxz, &q1, &qd1).unwrap();
    let (p2, pd2, _) = map_to_partner(AngleSequence::Zxz, &q2, &qd2).unwrap();
    let y1 = state(p1, pd1, p2, pd2);
    let mut partner = ChartedMechanism::new(&TwoBalls, 0.0, y1, ChartSet(3), tight()).unwrap();
    let e0 = declared.energy();
    assert_relative_eq!(partner.energy(), e0, max_relative = 1e-14);
    let mut drift = 0.0f64;
    let mut t = 0.0;
    while t < 2.0 {
        t += 0.05;
        declared.advance_to(t).unwrap();
        partner.advance_to(t).unwrap();
        drift = drift.max(((declared.energy() - e0) / e0).abs());
        drift = drift.max(((partner.energy() - e0) / e0).abs());
    }
    println!(
        "two balls: max |ΔE/E| {drift:e}, switches {}",
        declared.switches()
    );
    assert!(drift <= 1e-9, "energy drift {drift:e}");
    assert!(
        declared.switches() >= 2,
        "switched {} times",
        declared.switches()
    );
    for j in 0..2 {
        assert_relative_eq!(
            declared.joint_rotation(j).unwrap(),
            partner.joint_rotation(j).unwrap(),
            epsilon = 1e-7
        );
        assert_relative_eq!(
            declared.joint_omega(j).unwrap(),
            partner.joint_omega(j).unwrap(),
            epsilon = 1e-6
        );
    }
}

#[test]
fn past_two_ball_joints_each_switches_alone_and_loaded_joints_never() {
    let mut arena = Arena::new();
    let (o, z) = (arena.one(), arena.zero());
    let down = arena.integer(-1);
    let tenth = {
        let ten = arena.integer(10);
        arena.recip(ten).unwrap()
    };
    // Four bodies each on its own ball joint to the ground: the rule is the same as for a
    // chain, and the derivations stay cheap.
    let mut scene = MechanismScene::new();
    for i in 0..4 {
        let ball = JointKind::Spherical {
            sequence: AngleSequence::Zyx,
        };
        let names = [0, 1, 2].map(|k| format!("q{i}{k}"));
        let names = names.each_ref().map(String::as_str);
        let mut b =
            MechanismScene::body(&mut arena, &format!("b{i}"), Parent::Ground, ball, &names);
        b.mass = o;
        b.center = [z, z, down];
        b.inertia = [[tenth, z, z], [z, tenth, z], [z, z, tenth]];
        scene.bodies.push(b);
    }
    // A damper on the last joint's first angle ties it to its declared chart.
    scene.bodies[3].joint.loads[0].damper = Some(tenth);
    scene.gravity = Some([z, z, arena.integer(-1)]);
    let charts = MechanismCharts::new(&mut arena, &scene, Route::Auto, &[]).unwrap();
    let joints = charts.spherical_joints();
    let switchable: Vec<bool> = joints.iter().map(|j| j.switchable).collect();
    assert_eq!(switchable, [true, true, true, false]);
    let available: Vec<u32> = (0..16)
        .filter(|&c| charts.has_charts(ChartSet(c)))
        .collect();
    assert_eq!(available, [0, 1, 2, 4]);
}

/// A top with a damper on its spin angle, and one whose hinge is driven by a user function
/// (four coordinates: the recursive route, whose bound intermediates hide the function's
/// value from a plain `free_symbols`; the expansion must still call it).
#[derive(Mechanism)]
#[mechanism(gravity = 1.0)]
#[body(top, joint = spherical(sequence = zxz), q = [phi, theta, psi], damper = [0.0, 0.0, 0.1],
       parts(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.25, 0.25, 0.5))))]
struct DampedSpin;

#[derive(Mechanism)]
#[mechanism(gravity = 1.0)]
#[body(top, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.25, 0.25, 0.5))))]
#[body(flap, parent = top, joint = revolute(axis = x, at = [0.0, 0.0, 1.0]), q = alpha,
       effort = drive, parts(particle(mass = 0.1, at = [0.0, 0.0, 0.2])))]
struct DrivenFlap;

fn drive(_: &DrivenFlap, t: f64, _q: &[f64; 4], _qdot: &[f64; 4]) -> f64 {
    0.01 * t.sin()
}

#[test]
fn loads_on_angles_and_user_functions_keep_the_declared_charts() {
    let damped = ChartedDynamics::<6>::spherical_joints(&DampedSpin);
    assert!(!damped[0].switchable);
    assert!(!ChartedDynamics::<6>::has_charts(&DampedSpin, ChartSet(1)));
    let driven = ChartedDynamics::<8>::spherical_joints(&DrivenFlap);
    assert!(!driven[0].switchable);
    assert!(!ChartedDynamics::<8>::has_charts(&DrivenFlap, ChartSet(1)));
    // It still runs in its declared chart, away from the lock.
    let y0 = [0.0, 1.0, 0.0, 0.2, 0.0, 0.0, 0.0, 0.0];
    let mut flap =
        ChartedMechanism::new(&DrivenFlap, 0.0, y0, ChartSet::DECLARED, tight()).unwrap();
    flap.advance_to(0.5).unwrap();
    assert_eq!((flap.switches(), flap.charts()), (0, ChartSet::DECLARED));
}

/// The relative angular acceleration ω̇ = B q̈ + Ḃ q̇ of a joint, Ḃ q̇ by central differences
/// along q̇.
fn joint_omega_dot(
    sequence: AngleSequence,
    q: [f64; 3],
    qd: [f64; 3],
    qdd: [f64; 3],
) -> Vector3<f64> {
    let h = 1e-6;
    let at = |s: f64| [0, 1, 2].map(|k| q[k] + s * qd[k]);
    let b_dot =
        (joint_rate_matrix(sequence, &at(h)) - joint_rate_matrix(sequence, &at(-h))) / (2.0 * h);
    joint_rate_matrix(sequence, &q) * Vector3::from(qdd) + b_dot * Vector3::from(qd)
}

#[test]
fn every_chart_arm_of_the_derive_is_the_same_motion() {
    // At random states, the state mapped into each chart set gives the same angular
    // accelerations of both joints and the same energy as the declared charts.
    let mut rng = Rng::new(7);
    let part = |y: &[f64; 12], at: usize| [y[at], y[at + 1], y[at + 2]];
    for _ in 0..100 {
        let mut y = [0.0; 12];
        for (k, v) in y.iter_mut().enumerate() {
            *v = match k {
                1 | 4 => rng.uniform(0.4, 2.7),
                0..6 => rng.uniform(-3.0, 3.0),
                _ => rng.uniform(-2.0, 2.0),
            };
        }
        let mut dydt = [0.0; 12];
        TwoBalls.rhs_in(ChartSet::DECLARED, 0.0, &y, &mut dydt);
        let e = TwoBalls.energy_in(ChartSet::DECLARED, 0.0, &y);
        let omega_dot = [0, 3].map(|at| {
            joint_omega_dot(
                AngleSequence::Zxz,
                part(&y, at),
                part(&y, at + 6),
                part(&dydt, at + 6),
            )
        });
        for charts in 1..4 {
            let charts = ChartSet(charts);
            let mut z = y;
            for (j, at) in [0, 3].into_iter().enumerate() {
                if charts.is_switched(j) {
                    let (p, pd, _) =
                        map_to_partner(AngleSequence::Zxz, &part(&y, at), &part(&y, at + 6))
                            .unwrap();
                    z[at..at + 3].copy_from_slice(&p);
                    z[at + 6..at + 9].copy_from_slice(&pd);
                }
            }
            let mut dzdt = [0.0; 12];
            TwoBalls.rhs_in(charts, 0.0, &z, &mut dzdt);
            assert_relative_eq!(TwoBalls.energy_in(charts, 0.0, &z), e, max_relative = 1e-12);
            for (j, at) in [0, 3].into_iter().enumerate() {
                let sequence = charts.sequence(j, AngleSequence::Zxz);
                let w = joint_omega_dot(
                    sequence,
                    part(&z, at),
                    part(&z, at + 6),
                    part(&dzdt, at + 6),
                );
                assert_relative_eq!(w, omega_dot[j], epsilon = 1e-6, max_relative = 1e-6);
            }
        }
    }
}
