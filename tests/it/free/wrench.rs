//! Issue 26, item 7: one wrench function for contact-like forces. A wrench in space axes, in
//! description axes and at a point agrees with the same force and torque given through
//! `force =` and `torque =` (converted by hand with the attitude), a constant space torque
//! gives L(t) = L₀ + τ t, and a ball sliding on a table under a penalty contact wrench ends
//! rolling at 5/7 of its speed, having lost exactly the energy its power says.

use approx::assert_relative_eq;
use precess::free::{AppliedWrench, FreeDynamics, FreeError, FreeFlight, FreeState, FreeSystem};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;

/// A force and a torque, both space axes, that depend on time and on the state.
fn gust_space(t: f64, s: &FreeState) -> (Vector3<f64>, Vector3<f64>) {
    let f = Vector3::new(
        0.3 * t.sin(),
        -0.2 * s.velocity.z,
        0.1 + 0.05 * s.position.x,
    );
    let tau = Vector3::new(0.02 * s.omega_principal.y, -0.01 * (2.0 * t).cos(), 0.015);
    (f, tau)
}

/// A force and a torque, both description axes.
fn gust_body(t: f64, s: &FreeState) -> (Vector3<f64>, Vector3<f64>) {
    let f = Vector3::new(0.2, -0.1 * t.cos(), 0.05 * s.velocity.x);
    let tau = Vector3::new(0.01 * s.omega_principal.z, 0.0, -0.02 * t.sin());
    (f, tau)
}

/// A force in space axes at a point fixed in the body, `LEVER` in description axes from the
/// centre of mass.
fn push(t: f64, s: &FreeState) -> (Vector3<f64>, Vector3<f64>) {
    let f = Vector3::new(0.4 * t.cos(), 0.1, -0.3 * s.velocity.y);
    let point = s.position + description(s) * Vector3::from(LEVER);
    (f, point)
}

const LEVER: [f64; 3] = [0.05, -0.1, 0.12];

/// The attitude of the description axes (description → space) of the body below, written
/// from the principal frame by hand.
fn description(s: &FreeState) -> UnitQuaternion<f64> {
    let pr = Wrenched.principal_cm();
    s.attitude * UnitQuaternion::from_rotation_matrix(&pr.rotation).inverse()
}

/// A box with an off-centre point mass, so its principal axes are tilted from the
/// description axes and its centre of mass is off the origin, under one wrench of each kind.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]),
    particle(mass = 0.2, at = [0.1, 0.0, 0.1]),
)]
#[free(gravity = 9.81, wrench = in_space, wrench = in_body, wrench = at_point)]
struct Wrenched;

fn in_space(_: &Wrenched, t: f64, s: &FreeState) -> AppliedWrench {
    let (f, tau) = gust_space(t, s);
    AppliedWrench::space(f, tau)
}

fn in_body(_: &Wrenched, t: f64, s: &FreeState) -> AppliedWrench {
    let (f, tau) = gust_body(t, s);
    AppliedWrench::body(f, tau)
}

fn at_point(_: &Wrenched, t: f64, s: &FreeState) -> AppliedWrench {
    let (f, p) = push(t, s);
    AppliedWrench::at_point_space(f, p)
}

/// The same body and the same forces through `force =` (space axes) and `torque =`
/// (description axes), every conversion written here by hand.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]),
    particle(mass = 0.2, at = [0.1, 0.0, 0.1]),
)]
#[free(gravity = 9.81, force = hand_force, torque = hand_torque)]
struct Separate;

fn hand_force(_: &Separate, t: f64, s: &FreeState) -> Vector3<f64> {
    let r = description(s);
    gust_space(t, s).0 + r * gust_body(t, s).0 + push(t, s).0
}

fn hand_torque(_: &Separate, t: f64, s: &FreeState) -> Vector3<f64> {
    let r = description(s);
    let (f, p) = push(t, s);
    let lever_torque = (p - s.position).cross(&f);
    r.inverse() * (gust_space(t, s).1 + lever_torque) + gust_body(t, s).1
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-12, 1e-12)
}

#[test]
fn a_wrench_in_each_frame_equals_force_and_torque_converted_by_hand() {
    let s0 = FreeState {
        position: Vector3::new(0.4, -1.0, 2.0),
        velocity: Vector3::new(1.0, 0.5, 3.0),
        attitude: UnitQuaternion::from_euler_angles(0.3, -0.7, 1.9),
        omega_principal: Vector3::new(4.0, -2.0, 7.0),
    };
    let mut flight = FreeFlight::new(FreeSystem(&Wrenched), 0.0, &s0, tight()).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..=40 {
        let t = 0.05 * f64::from(k);
        flight.advance_to(t).unwrap();
        let y = flight.y();
        let (a, b) = (Wrenched.wrench(t, y), Separate.wrench(t, y));
        let scale = a.force_space.norm() + a.torque_principal.norm();
        let diff = (a.force_space - b.force_space).norm()
            + (a.torque_principal - b.torque_principal).norm();
        worst = worst.max(diff / scale);
        let (mut da, mut db) = ([0.0; 13], [0.0; 13]);
        Wrenched.free_rhs(t, y, &mut da);
        Separate.free_rhs(t, y, &mut db);
        for i in 0..13 {
            assert_relative_eq!(da[i], db[i], epsilon = 1e-13, max_relative = 1e-13);
        }
        assert_relative_eq!(
            Wrenched.power(t, y),
            Separate.power(t, y),
            epsilon = 1e-13,
            max_relative = 1e-13
        );
    }
    eprintln!("wrench against force = and torque = by hand: {worst:.1e} relative at worst");
    assert!(worst < 1e-14, "wrench differs by {worst:e} relative");
}

/// The force at a point against r × F formed by hand in principal axes straight from the
/// state's attitude (principal → space), with no description frame in between.
#[derive(RigidBody)]
#[rigid(sphere(mass = 2.0, radius = 0.1))]
#[free(wrench = kick)]
struct Kicked;

const KICK: [f64; 3] = [1.5, -0.5, 2.0];
const KICK_AT: [f64; 3] = [0.3, 0.2, 0.9];

fn kick(_: &Kicked, _: f64, _: &FreeState) -> AppliedWrench {
    AppliedWrench::at_point_space(KICK, KICK_AT)
}

#[test]
fn a_force_at_a_point_turns_the_body_by_r_cross_f() {
    let s = FreeState {
        position: Vector3::new(0.1, -0.3, 0.4),
        velocity: Vector3::zeros(),
        attitude: UnitQuaternion::from_euler_angles(1.0, 0.2, -0.4),
        omega_principal: Vector3::zeros(),
    };
    let w = Kicked.wrench(0.0, &s.to_array());
    let f = Vector3::from(KICK);
    let r = Vector3::from(KICK_AT) - s.position;
    // (0.2, 0.5, 0.5) × (1.5, −0.5, 2.0) = (1.25, 0.35, −0.85), then into principal axes.
    assert_relative_eq!(
        r.cross(&f),
        Vector3::new(1.25, 0.35, -0.85),
        epsilon = 1e-15
    );
    let expected = s.attitude.inverse() * Vector3::new(1.25, 0.35, -0.85);
    assert_eq!(w.force_space, f);
    assert_relative_eq!(w.torque_principal, expected, epsilon = 1e-15);
}

/// A brick under a constant torque fixed in space, given through a wrench.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free(wrench = steady)]
struct Twisted;

const TAU: [f64; 3] = [0.03, -0.05, 0.02];

fn steady(_: &Twisted, _: f64, _: &FreeState) -> AppliedWrench {
    AppliedWrench::space(Vector3::zeros(), TAU)
}

#[test]
fn a_constant_space_torque_changes_angular_momentum_linearly() {
    let s0 = FreeState {
        position: Vector3::new(1.0, 0.0, -0.5),
        velocity: Vector3::new(0.2, -0.1, 0.3),
        attitude: UnitQuaternion::from_euler_angles(0.4, -0.3, 1.1),
        omega_principal: Vector3::new(3.0, 0.2, 6.0),
    };
    // L about the origin, from the state alone: x × M v + R I ω.
    let momentum = |s: &FreeState| {
        let m = 2.0;
        let i = Twisted.principal_cm().moments;
        s.position.cross(&(s.velocity * m)) + s.attitude * i.component_mul(&s.omega_principal)
    };
    let l0 = momentum(&s0);
    let mut flight = FreeFlight::new(FreeSystem(&Twisted), 0.0, &s0, tight()).unwrap();
    for t in [0.5, 2.0, 5.0, 10.0] {
        flight.advance_to(t).unwrap();
        let s = flight.state().unwrap();
        let expected = l0 + Vector3::from(TAU) * t;
        eprintln!(
            "L(t) − (L₀ + τ t) at t = {t}: {:.1e}",
            (momentum(&s) - expected).norm()
        );
        assert_relative_eq!(momentum(&s), expected, epsilon = 1e-10);
        assert_relative_eq!(
            Twisted.angular_momentum_origin(flight.y()),
            expected,
            epsilon = 1e-10
        );
    }
}

/// A solid ball on a table at z = 0: a penalty normal force δ (k − c ż) and viscous friction
/// −μ v_c on the slip velocity of the contact point, both at the contact point, computed once.
#[derive(RigidBody)]
#[rigid(sphere(mass = 0.17, radius = 0.0286))]
#[free(gravity = 9.81, wrench = table)]
struct Ball;

/// The ball's mass, radius and gravity as declared above.
const M: f64 = 0.17;
const R: f64 = 0.0286;
const G: f64 = 9.81;
const K: f64 = 5.0e4;
const C: f64 = 50.0;
/// Chosen so the slip decays at 3.5 μ / M = 20 per second.
const MU: f64 = 20.0 * M / 3.5;

fn table(_: &Ball, _: f64, s: &FreeState) -> AppliedWrench {
    let depth = R - s.position.z;
    if depth <= 0.0 {
        return AppliedWrench::zero();
    }
    let contact = s.position - Vector3::new(0.0, 0.0, R);
    let normal = (depth * (K - C * s.velocity.z)).max(0.0);
    let slip = s.velocity + s.omega_space().cross(&(contact - s.position));
    let friction = Vector3::new(slip.x, slip.y, 0.0) * -MU;
    AppliedWrench::at_point_space(Vector3::new(0.0, 0.0, normal) + friction, contact)
}

#[test]
fn a_ball_slid_on_a_table_rolls_at_five_sevenths_and_loses_a_seventh_of_m_v_squared() {
    // Resting at the depth where the normal force carries the weight, sliding without spin.
    let (v0, depth) = (2.0, M * G / K);
    let s0 = FreeState {
        position: Vector3::new(0.0, 0.0, R - depth),
        velocity: Vector3::new(v0, 0.0, 0.0),
        attitude: UnitQuaternion::identity(),
        omega_principal: Vector3::zeros(),
    };
    let mut flight = FreeFlight::new(FreeSystem(&Ball), 0.0, &s0, tight()).unwrap();
    let e0 = Ball.energy(flight.y());
    // ∫ P dt by Simpson's rule on a fine grid: the power the generated code reports.
    let (dt, steps) = (1e-4, 20_000);
    let mut work = Ball.power(0.0, flight.y()) * dt / 3.0;
    let mut e_prev = e0;
    for k in 1..=steps {
        let t = dt * f64::from(k);
        flight.advance_to(t).unwrap();
        let weight = if k == steps {
            1.0
        } else {
            f64::from(2 + 2 * (k % 2))
        };
        work += weight * Ball.power(t, flight.y()) * dt / 3.0;
        // The contact only takes energy out: no step of the run gains any.
        let e = Ball.energy(flight.y());
        assert!(
            e <= e_prev + 1e-12,
            "energy rose at t = {t}: {e} > {e_prev}"
        );
        e_prev = e;
    }
    let s = flight.state().unwrap();
    let lost = e0 - Ball.energy(flight.y());
    eprintln!(
        "ball: v/v0 − 5/7 = {:.1e}, lost/(M v0²/7) − 1 = {:.1e}, ∫P dt/ΔE − 1 = {:.1e}",
        s.velocity.x / v0 - 5.0 / 7.0,
        lost / (M * v0 * v0 / 7.0) - 1.0,
        work / -lost - 1.0
    );
    // Angular momentum about the contact line is kept: M v₀ R = M v R + (2/5) M R² v/R.
    assert_relative_eq!(s.velocity.x, 5.0 / 7.0 * v0, max_relative = 1e-10);
    assert_relative_eq!(s.omega_space().y * R, 5.0 / 7.0 * v0, max_relative = 1e-10);
    assert_relative_eq!(lost, M * v0 * v0 / 7.0, max_relative = 1e-10);
    // dE/dt = P integrated: the power quantity accounts for every joule lost.
    assert_relative_eq!(work, -lost, max_relative = 1e-9);
}

/// A wrench function that returns NaN: the checked wrench names the part.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1))]
#[free(wrench = broken)]
struct Broken;

fn broken(_: &Broken, _: f64, _: &FreeState) -> AppliedWrench {
    AppliedWrench::body(Vector3::zeros(), Vector3::new(0.0, f64::NAN, 0.0))
}

#[test]
fn a_non_finite_wrench_is_a_typed_error_naming_the_part() {
    let y = FreeState::at_rest().to_array();
    let err = Broken.try_wrench(0.0, &y).unwrap_err();
    assert!(
        matches!(&err, FreeError::NonFiniteWrench { part, values }
            if part.contains("torque") && values[1].is_nan()),
        "{err}"
    );
    let direct = broken(&Broken, 0.0, &FreeState::at_rest())
        .check()
        .unwrap_err();
    assert!(
        matches!(&direct, FreeError::NonFiniteWrench { part, .. }
            if *part == "torque about the centre of mass, description axes"),
        "{direct}"
    );
    assert!(
        Ball.try_wrench(0.0, &FreeState::at_rest().to_array())
            .is_ok()
    );
}

/// One property-test case: a force and torque in space axes, and a second force at a point
/// (space coordinates), read by the two probes' wrench functions.
#[derive(Clone, Copy, Default)]
struct Case {
    force: [f64; 3],
    torque: [f64; 3],
    point_force: [f64; 3],
    point: [f64; 3],
}

thread_local! {
    static CASE: std::cell::Cell<Case> = std::cell::Cell::new(Case::default());
}

/// The case given in space axes and at its point.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]),
    particle(mass = 0.2, at = [0.1, 0.0, 0.1]),
)]
#[free(wrench = case_in_space)]
struct SpaceProbe;

fn case_in_space(_: &SpaceProbe, _: f64, _: &FreeState) -> AppliedWrench {
    let c = CASE.with(std::cell::Cell::get);
    AppliedWrench::space(c.force, c.torque) + AppliedWrench::at_point_space(c.point_force, c.point)
}

/// The same case in description axes, the lever torque and both conversions by hand.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]),
    particle(mass = 0.2, at = [0.1, 0.0, 0.1]),
)]
#[free(wrench = case_in_body)]
struct BodyProbe;

fn case_in_body(b: &BodyProbe, _: f64, s: &FreeState) -> AppliedWrench {
    let c = CASE.with(std::cell::Cell::get);
    let g = Vector3::from(c.point_force);
    let lever = (Vector3::from(c.point) - s.position).cross(&g);
    let to_space =
        s.attitude * UnitQuaternion::from_rotation_matrix(&b.principal_cm().rotation).inverse();
    let f = to_space.inverse() * (Vector3::from(c.force) + g);
    let tau = to_space.inverse() * (Vector3::from(c.torque) + lever);
    AppliedWrench::body(f, tau)
}

fn vector() -> impl proptest::strategy::Strategy<Value = [f64; 3]> {
    proptest::array::uniform3(-10.0..10.0f64)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// A frame mixed up (a space torque taken as a body one, a lever about the wrong point,
    /// a conversion the wrong way round) makes the two probes disagree at some attitude.
    #[test]
    fn a_wrench_resolves_the_same_in_every_frame(
        angles in vector(),
        position in vector(),
        force in vector(),
        torque in vector(),
        point_force in vector(),
        point in vector(),
    ) {
        CASE.with(|cell| cell.set(Case { force, torque, point_force, point }));
        let s = FreeState {
            position: Vector3::from(position),
            velocity: Vector3::zeros(),
            attitude: UnitQuaternion::from_euler_angles(angles[0], angles[1], angles[2]),
            omega_principal: Vector3::zeros(),
        };
        let y = s.to_array();
        let (a, b) = (SpaceProbe.wrench(0.0, &y), BodyProbe.wrench(0.0, &y));
        let scale = 1.0 + a.force_space.norm() + a.torque_principal.norm();
        proptest::prop_assert!((a.force_space - b.force_space).norm() < 1e-13 * scale);
        proptest::prop_assert!(
            (a.torque_principal - b.torque_principal).norm() < 1e-13 * scale,
            "{} vs {}", a.torque_principal, b.torque_principal
        );
    }
}
