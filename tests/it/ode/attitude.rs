//! Attitude on the unit quaternions: RKMK4's order, its norm preservation over 10⁶ steps, and
//! the whole free-body state under a force and a torque, against DOP853 on the plain ODE
//! (q̇ = ½ q ⊗ (0, ω) beside Euler's equations and M ẍ = F) as the second method.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess_core::ode::{AdaptiveConfig, Dop853Pair, FixedStepConfig, OdeError, System, solve};
use precess_core::rigid::{Attitude, AttitudeModel, RigidBodyModel, RigidState, Rkmk4};

const I: [f64; 3] = [1.0, 2.0, 3.0];

struct Spun;
impl AttitudeModel for Spun {
    fn inertia(&self) -> [f64; 3] {
        I
    }
    fn torque(&self, t: f64, _s: &Attitude) -> Vector3<f64> {
        Vector3::new(0.1 * t.sin(), 0.0, 0.05)
    }
}

struct Rocket;
impl RigidBodyModel for Rocket {
    fn mass(&self) -> f64 {
        2.0
    }
    fn inertia(&self) -> [f64; 3] {
        I
    }
    fn force(&self, _t: f64, s: &RigidState) -> Vector3<f64> {
        // Weight plus a thrust along the body z axis: couples translation to attitude.
        Vector3::new(0.0, 0.0, -2.0 * 9.81) + s.q * Vector3::new(0.0, 0.0, 5.0)
    }
    fn torque(&self, t: f64, _s: &RigidState) -> Vector3<f64> {
        Vector3::new(0.1, -0.2, 0.05 * t.cos())
    }
}

fn euler(w: &[f64], g: [f64; 3], d: &mut [f64]) {
    d[0] = ((I[1] - I[2]) * w[1] * w[2] + g[0]) / I[0];
    d[1] = ((I[2] - I[0]) * w[2] * w[0] + g[1]) / I[1];
    d[2] = ((I[0] - I[1]) * w[0] * w[1] + g[2]) / I[2];
}

fn quat_rate(q: &[f64], w: &[f64], d: &mut [f64]) {
    d[0] = -0.5 * (q[1] * w[0] + q[2] * w[1] + q[3] * w[2]);
    d[1] = 0.5 * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]);
    d[2] = 0.5 * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]);
    d[3] = 0.5 * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
}

/// The attitude problem as a plain ODE in (q, ω) ∈ ℝ⁷.
struct SpunOde;
impl System<7> for SpunOde {
    fn rhs(&self, t: f64, y: &[f64; 7], d: &mut [f64; 7]) {
        quat_rate(&y[0..4], &y[4..7], &mut d[0..4]);
        euler(&y[4..7], [0.1 * t.sin(), 0.0, 0.05], &mut d[4..7]);
    }
}

/// The rocket as a plain ODE in (x, v, q, ω) ∈ ℝ¹³.
struct RocketOde;
impl System<13> for RocketOde {
    fn rhs(&self, t: f64, y: &[f64; 13], d: &mut [f64; 13]) {
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[6], y[7], y[8], y[9]));
        let f = Vector3::new(0.0, 0.0, -2.0 * 9.81) + q * Vector3::new(0.0, 0.0, 5.0);
        d[0..3].copy_from_slice(&y[3..6]);
        for k in 0..3 {
            d[3 + k] = f[k] / 2.0;
        }
        quat_rate(&y[6..10], &y[10..13], &mut d[6..10]);
        euler(&y[10..13], [0.1, -0.2, 0.05 * t.cos()], &mut d[10..13]);
    }
}

fn q0() -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1)
}

fn attitude_error(h: f64, t_end: f64, reference: &[f64; 7]) -> f64 {
    let s0 = Attitude {
        q: q0(),
        omega: Vector3::new(0.3, 1.0, -0.4),
    };
    let mut m = Rkmk4::new(Spun, 0.0, s0, FixedStepConfig::with_step(h)).unwrap();
    m.advance_to(t_end).unwrap();
    let s = m.state();
    let qr = UnitQuaternion::from_quaternion(Quaternion::new(
        reference[0],
        reference[1],
        reference[2],
        reference[3],
    ));
    let dw = (s.omega - Vector3::new(reference[4], reference[5], reference[6])).amax();
    s.q.angle_to(&qr).max(dw)
}

#[test]
fn rkmk4_is_order_four_against_dop853() {
    let q = q0();
    let y0 = [q.w, q.i, q.j, q.k, 0.3, 1.0, -0.4];
    let reference = solve::<Dop853Pair, _, 7>(
        SpunOde,
        0.0,
        y0,
        5.0,
        &[],
        AdaptiveConfig::with_tol(1e-14, 1e-14),
    )
    .unwrap()
    .y;
    let (e1, e2) = (
        attitude_error(0.1, 5.0, &reference),
        attitude_error(0.05, 5.0, &reference),
    );
    let p = (e1 / e2).log2();
    eprintln!("RKMK4 errors {e1:e} {e2:e}, order {p:.2}");
    assert!((3.8..4.4).contains(&p), "order {p}");
    assert!(e2 < 1e-6);
}

#[test]
fn quaternion_norm_after_a_million_steps() {
    let s0 = Attitude {
        q: q0(),
        omega: Vector3::new(0.3, 1.0, -0.4),
    };
    let mut m = Rkmk4::new(Spun, 0.0, s0, FixedStepConfig::with_step(1e-3)).unwrap();
    m.advance_to(1000.0).unwrap();
    assert_eq!(m.stats().steps, 1_000_000);
    let e = (m.state().q.quaternion().norm() - 1.0).abs();
    eprintln!("|q| − 1 after 1e6 RKMK4 steps: {e:e}");
    assert!(e <= 1e-15, "{e:e}");
}

#[test]
fn rigid_body_under_force_and_torque_matches_dop853() {
    let q = q0();
    let s0 = RigidState {
        x: Vector3::new(1.0, 0.0, 2.0),
        v: Vector3::new(0.5, -1.0, 3.0),
        q,
        omega: Vector3::new(0.3, 1.0, -0.4),
    };
    let y0 = [
        1.0, 0.0, 2.0, 0.5, -1.0, 3.0, q.w, q.i, q.j, q.k, 0.3, 1.0, -0.4,
    ];
    let r = solve::<Dop853Pair, _, 13>(
        RocketOde,
        0.0,
        y0,
        3.0,
        &[],
        AdaptiveConfig::with_tol(1e-14, 1e-14),
    )
    .unwrap()
    .y;
    let mut m = Rkmk4::new(Rocket, 0.0, s0, FixedStepConfig::with_step(1e-3)).unwrap();
    m.advance_to(3.0).unwrap();
    let s = m.state();
    let ex = (s.x - Vector3::new(r[0], r[1], r[2])).amax();
    let ev = (s.v - Vector3::new(r[3], r[4], r[5])).amax();
    let eq =
        s.q.angle_to(&UnitQuaternion::from_quaternion(Quaternion::new(
            r[6], r[7], r[8], r[9],
        )));
    let ew = (s.omega - Vector3::new(r[10], r[11], r[12])).amax();
    eprintln!("rocket errors x {ex:e} v {ev:e} q {eq:e} ω {ew:e}");
    assert!(ex.max(ev).max(eq).max(ew) <= 1e-10);
}

#[test]
fn free_fall_is_exact() {
    struct Drop;
    impl RigidBodyModel for Drop {
        fn mass(&self) -> f64 {
            3.0
        }
        fn inertia(&self) -> [f64; 3] {
            [1.0, 1.0, 1.0]
        }
        fn force(&self, _t: f64, _s: &RigidState) -> Vector3<f64> {
            Vector3::new(0.0, 0.0, -3.0 * 9.81)
        }
    }
    let s0 = RigidState {
        x: Vector3::zeros(),
        v: Vector3::new(1.0, 2.0, 10.0),
        q: UnitQuaternion::identity(),
        omega: Vector3::zeros(),
    };
    let mut m = Rkmk4::new(Drop, 0.0, s0, FixedStepConfig::with_step(0.1)).unwrap();
    m.advance_to(2.0).unwrap();
    let x = m.state().x;
    assert!(
        (x - Vector3::new(2.0, 4.0, 20.0 - 0.5 * 9.81 * 4.0)).amax() <= 1e-13,
        "{x}"
    );
}

#[test]
fn bad_bodies_and_steps_are_typed_errors() {
    struct Flat([f64; 3], f64);
    impl RigidBodyModel for Flat {
        fn mass(&self) -> f64 {
            self.1
        }
        fn inertia(&self) -> [f64; 3] {
            self.0
        }
    }
    let s0 = RigidState {
        x: Vector3::zeros(),
        v: Vector3::zeros(),
        q: UnitQuaternion::identity(),
        omega: Vector3::zeros(),
    };
    let cfg = FixedStepConfig::default();
    assert!(matches!(
        Rkmk4::new(Flat([1.0, 0.0, 1.0], 1.0), 0.0, s0, cfg),
        Err(OdeError::InvalidInertia { .. })
    ));
    assert!(matches!(
        Rkmk4::new(Flat([1.0, 1.0, 1.0], -1.0), 0.0, s0, cfg),
        Err(OdeError::InvalidInertia { .. })
    ));
    assert!(matches!(
        Rkmk4::new(
            Flat([1.0, 1.0, 1.0], 1.0),
            0.0,
            s0,
            FixedStepConfig::with_step(0.0)
        ),
        Err(OdeError::InvalidStep { .. })
    ));
    let bad = RigidState {
        omega: Vector3::new(f64::NAN, 0.0, 0.0),
        ..s0
    };
    assert!(matches!(
        Rkmk4::new(Flat([1.0, 1.0, 1.0], 1.0), 0.0, bad, cfg),
        Err(OdeError::NonFiniteInitialState { .. })
    ));
}

#[test]
fn rkmk4_stops_at_the_first_non_finite_step() {
    // A sphere with the torque I ω ⊙ ω: ω̇ᵢ = ωᵢ², which blows up at t = 1 from ω = (1, 1, 1).
    struct Runaway;
    impl AttitudeModel for Runaway {
        fn inertia(&self) -> [f64; 3] {
            [1.0, 1.0, 1.0]
        }
        fn torque(&self, _t: f64, s: &Attitude) -> Vector3<f64> {
            s.omega.component_mul(&s.omega)
        }
    }
    let s0 = Attitude {
        q: UnitQuaternion::identity(),
        omega: Vector3::new(1.0, 1.0, 1.0),
    };
    let mut m = Rkmk4::new(Runaway, 0.0, s0, FixedStepConfig::with_step(1e-3)).unwrap();
    match m.advance_to(1e3) {
        Err(OdeError::NonFiniteState { t }) => assert!((0.99..1.1).contains(&t), "t = {t}"),
        other => panic!("expected NonFiniteState near t = 1, got {other:?}"),
    }
    assert!(m.stats().steps < 1_100, "{} steps", m.stats().steps);
    assert!(m.state().omega.iter().all(|w| w.is_finite()));
    assert!(matches!(
        m.advance_to(f64::NAN),
        Err(OdeError::NonFiniteTime { .. })
    ));
}

#[test]
fn a_quaternion_that_is_no_rotation_is_refused() {
    // UnitQuaternion::new_unchecked lets any quaternion through; (0, 0, 0, 0) and (1, 1, 0, 0)
    // are no rotations.
    for (q, norm) in [
        (Quaternion::new(0.0, 0.0, 0.0, 0.0), 0.0),
        (Quaternion::new(1.0, 1.0, 0.0, 0.0), 2f64.sqrt()),
    ] {
        let s0 = Attitude {
            q: UnitQuaternion::new_unchecked(q),
            omega: Vector3::new(0.0, 0.0, 1.0),
        };
        match Rkmk4::new(Spun, 0.0, s0, FixedStepConfig::default()).map(|m| *m.state()) {
            Err(OdeError::NotUnitQuaternion { norm: n }) => assert_eq!(n, norm),
            other => panic!("expected NotUnitQuaternion, got {other:?}"),
        }
    }
}
