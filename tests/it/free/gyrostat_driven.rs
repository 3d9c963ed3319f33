//! Issue 26 item 4: free bodies with rotors driven by a motor torque. A driven wheel's rate
//! Ω is a state slot; with I the inertia with the wheel locked,
//! (I − J â âᵀ) ω̇ = τ − ω × (I ω + J Ω â) − u â and Ω̇ = u/J − â·ω̇. Checked against values
//! found without the code: the closed form of a spin-up from rest, the conservation of the
//! total angular momentum whatever the motor does, the work–energy balance with the motor's
//! work, the wheel's own axial momentum J (â·ω + Ω) when u = 0, the constant-rate rotor where
//! the two must agree, and the same scene built at run time.

use approx::assert_relative_eq;
use precess::free::{
    DrivenRotor, FreeDynamics, FreeError, FreeModel, FreeQuantities, FreeScene, FreeState,
    FreeSystem,
};
use precess::ode::{AdaptiveConfig, Dop853, OdeError, System};
use precess::prelude::*;
use precess::sym::Arena;

/// The motor torque of [`SpinUp`], N m.
const U: f64 = 0.2;

/// Principal moments (1, 2, 3) along the description axes and a wheel of J = 0.5 on the
/// z axis, its motor giving the constant torque U.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.5, torque = constant_motor))]
struct SpinUp;

fn constant_motor(_: &SpinUp, _t: f64, _y: &[f64]) -> f64 {
    U
}

/// An asymmetric body with a wheel on a tilted axis, its motor torque varying in time and
/// with the wheel's own rate (a speed loop pulling towards 30 rad/s, plus a wobble).
#[derive(RigidBody)]
#[rigid(body(mass = 2.0, inertia = [[2.0, 0.1, 0.0], [0.1, 3.0, 0.2], [0.0, 0.2, 4.0]], about = center))]
#[free(rotor(axis = [1, 2, 2], inertia = 0.05, torque = Tilted::motor))]
struct Tilted;

impl Tilted {
    fn motor(&self, t: f64, y: &[f64]) -> f64 {
        0.02 * (30.0 - y[Tilted::ROTOR_0]) + 0.05 * (3.0 * t).sin()
    }
}

/// A symmetric body (I₁ = I₂) with a wheel on its symmetry axis: its motor off (u = 0) …
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.5, torque = motor_off))]
struct CoastingSymmetric;

fn motor_off<T>(_: &T, _t: f64, _y: &[f64]) -> f64 {
    0.0
}

/// … and the same wheel held at its rate: with the wheel on the symmetry axis the two agree.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 0, 1], inertia = 0.5, rate = 40))]
struct HeldSymmetric;

/// An asymmetric body with its motor off on a tilted wheel: the wheel is not held.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 1, 1], inertia = 0.5, torque = motor_off))]
struct CoastingTilted;

/// A wheel's inertia read from a field, on the z axis of a body with I₃ = 3.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 0, 1], inertia = j, torque = motor_off))]
struct FieldWheel {
    j: f64,
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

fn state14(omega: Vector3<f64>, attitude: UnitQuaternion<f64>, rate: f64) -> [f64; 14] {
    let head = FreeState {
        omega_principal: omega,
        attitude,
        ..FreeState::at_rest()
    }
    .to_array();
    let mut y = [0.0; 14];
    y[..13].copy_from_slice(&head);
    y[13] = rate;
    y
}

fn omega_of(y: &[f64; 14]) -> Vector3<f64> {
    Vector3::new(y[10], y[11], y[12])
}

/// From rest with a constant motor torque u on a wheel along principal axis 3: the body
/// turns back with ω₃ = −u t/(I₃ − J) and the wheel spins up with Ω = u t/J + u t/(I₃ − J)
/// (the total axial momentum (I₃ − J) ω₃ + J (ω₃ + Ω) staying 0).
#[test]
fn a_spin_up_from_rest_follows_the_closed_form() {
    assert_eq!(SpinUp::ROTOR_0, 13);
    assert_eq!(SpinUp::coordinate("rotor_0"), Some(13));
    let (i3, j) = (3.0, 0.5);
    let y0 = state14(Vector3::zeros(), UnitQuaternion::identity(), 0.0);
    let mut ode = Dop853::new(FreeSystem(&SpinUp), 0.0, y0, tight()).unwrap();
    for t in [0.5, 2.0, 7.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        assert_relative_eq!(y[12], -U * t / (i3 - j), max_relative = 1e-12);
        assert_relative_eq!(y[13], U * t / j + U * t / (i3 - j), max_relative = 1e-12);
        assert_relative_eq!(y[10], 0.0, epsilon = 1e-14);
        assert_relative_eq!(y[11], 0.0, epsilon = 1e-14);
        // Rotated about z by ∫ω₃ dt = −u t²/(2 (I₃ − J)).
        let angle = -U * t * t / (2.0 * (i3 - j));
        assert_relative_eq!(y[9], (angle / 2.0).sin(), epsilon = 1e-12);
    }
}

/// No external torque: the total angular momentum R (I ω + J Ω â) is fixed in space whatever
/// the motor does (its torque is internal), here a speed loop with a wobble on a tilted wheel
/// of a body with products of inertia.
#[test]
fn the_total_angular_momentum_is_conserved_under_any_motor_torque() {
    let q0 = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.7);
    let y0 = state14(Vector3::new(0.4, -0.3, 0.8), q0, 5.0);
    let l0 = Tilted.angular_momentum_origin(&y0);
    let mut ode = Dop853::new(FreeSystem(&Tilted), 0.0, y0, tight()).unwrap();
    let mut spun_up = false;
    for t in [1.0, 5.0, 20.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        let l = Tilted.angular_momentum_origin(y);
        assert_relative_eq!(l, l0, epsilon = 1e-11);
        spun_up |= y[13] > 15.0;
    }
    // The motor did something: the wheel's rate left its start.
    assert!(spun_up, "the wheel stayed near its start rate");
}

/// The generated angular momentum and energy are the totals written by hand: R (I ω + J Ω â)
/// and ½ ωᵀ I ω + J Ω â·ω + ½ J Ω² (I with the wheel locked, principal frame of the tilted
/// body turned into description axes by hand).
#[test]
fn energy_and_momentum_are_the_true_totals() {
    let q = UnitQuaternion::from_euler_angles(0.1, 0.5, -0.4);
    let (w, rate) = (Vector3::new(0.7, -0.2, 0.5), 12.0);
    let y = state14(w, q, rate);
    let i_desc = Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0);
    let pr = Tilted.principal_cm();
    let w_desc = pr.rotation * w;
    let a = Vector3::new(1.0, 2.0, 2.0) / 3.0;
    let j = 0.05;
    let e =
        0.5 * w_desc.dot(&(i_desc * w_desc)) + j * rate * a.dot(&w_desc) + 0.5 * j * rate * rate;
    assert_relative_eq!(Tilted.energy(&y), e, max_relative = 1e-13);
    let l_desc = i_desc * w_desc + j * rate * a;
    let attitude_desc = q * UnitQuaternion::from_rotation_matrix(&pr.rotation).inverse();
    assert_relative_eq!(
        Tilted.angular_momentum_origin(&y),
        attitude_desc * l_desc,
        epsilon = 1e-13
    );
}

/// The body, its wheel and the work done on them, integrated together: E(t) − E(0) equals
/// ∫ (ω·τ + u Ω) dt, τ = 0 here, so the motor's work u Ω alone (evaluated by the test from the
/// motor and the rate, not from the generated power).
#[test]
fn the_energy_changes_by_the_motor_work() {
    struct WithWork;
    impl System<15> for WithWork {
        fn rhs(&self, t: f64, y: &[f64; 15], dydt: &mut [f64; 15]) {
            let mut body = [0.0; 14];
            body.copy_from_slice(&y[..14]);
            let mut d = [0.0; 14];
            Tilted.free_rhs(t, &body, &mut d);
            dydt[..14].copy_from_slice(&d);
            dydt[14] = Tilted.motor(t, &body) * body[13];
        }
    }
    let y14 = state14(
        Vector3::new(0.4, -0.3, 0.8),
        UnitQuaternion::from_euler_angles(0.3, -0.2, 0.7),
        5.0,
    );
    let mut y0 = [0.0; 15];
    y0[..14].copy_from_slice(&y14);
    let e0 = Tilted.energy(&y14);
    let mut ode = Dop853::new(WithWork, 0.0, y0, tight()).unwrap();
    for t in [1.0, 4.0, 10.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        let mut body = [0.0; 14];
        body.copy_from_slice(&y[..14]);
        let de = Tilted.energy(&body) - e0;
        assert!(y[14].abs() > 1.0, "the motor did little work: {}", y[14]);
        assert_relative_eq!(de, y[14], max_relative = 1e-10);
        // And the generated power is that rate.
        assert_relative_eq!(
            Tilted.power(t, &body),
            Tilted.motor(t, &body) * body[13],
            max_relative = 1e-13
        );
    }
}

/// With the motor off the wheel is not held: nothing turns it, so its own axial momentum
/// J (â·ω + Ω) stays put while Ω itself changes as the body's ω moves. Only when â·ω̇ = 0
/// (a wheel on the symmetry axis of a torque-free symmetric body) does the coasting wheel
/// keep its rate and the body move as with the constant-rate rotor: checked there.
#[test]
fn a_coasting_wheel_keeps_its_axial_momentum_and_matches_a_held_one_on_a_symmetry_axis() {
    let q0 = UnitQuaternion::from_euler_angles(0.2, 0.1, 0.0);
    let w0 = Vector3::new(0.5, -0.4, 1.0);
    let y0 = state14(w0, q0, 0.0);
    let mut ode = Dop853::new(FreeSystem(&CoastingTilted), 0.0, y0, tight()).unwrap();
    let a = Vector3::new(0.0, 1.0, 1.0) / 2f64.sqrt();
    let axial0 = 0.5 * (a.dot(&w0) + y0[13]);
    let mut rate_moved = 0.0f64;
    for t in [1.0, 3.0, 10.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        assert_relative_eq!(0.5 * (a.dot(&omega_of(y)) + y[13]), axial0, epsilon = 1e-12);
        rate_moved = rate_moved.max(y[13].abs());
    }
    assert!(rate_moved > 1e-2, "the coasting wheel's rate never moved");

    let y0 = state14(w0, q0, 40.0);
    let mut held = FreeState {
        omega_principal: w0,
        attitude: q0,
        ..FreeState::at_rest()
    }
    .to_array();
    let mut coasting = Dop853::new(FreeSystem(&CoastingSymmetric), 0.0, y0, tight()).unwrap();
    let mut holding = Dop853::new(FreeSystem(&HeldSymmetric), 0.0, held, tight()).unwrap();
    for t in [2.0, 10.0] {
        coasting.advance_to(t).unwrap();
        holding.advance_to(t).unwrap();
        held = *holding.y();
        let c = coasting.y();
        assert_relative_eq!(c[13], 40.0, max_relative = 1e-12);
        for k in 6..13 {
            assert_relative_eq!(c[k], held[k], epsilon = 1e-11);
        }
    }
}

/// The same driven gyrostat built as a `FreeScene` at run time, its motor torque a parameter,
/// and interpreted: the right-hand side, energy, power and momenta agree with the generated
/// code of [`Tilted`] at a state where the motor's torque is set to the same value.
#[test]
fn the_run_time_scene_with_a_driven_rotor_matches_the_derive() {
    let mut ar = Arena::new();
    let m = ar.integer(2);
    let pr = Tilted.principal_cm();
    let moments = pr.moments.map(|v| ar.float(v).unwrap());
    let mut scene = FreeScene::new(&mut ar, m, [moments[0], moments[1], moments[2]]);
    let r = pr.rotation.matrix();
    scene.principal_rotation =
        std::array::from_fn(|i| std::array::from_fn(|j| ar.float(r[(i, j)]).unwrap()));
    let axis = [ar.integer(1), ar.integer(2), ar.integer(2)];
    let (inertia, torque) = (ar.parameter("J"), ar.parameter("u"));
    scene.driven.push(DrivenRotor {
        axis,
        inertia,
        torque,
    });
    let derivation = scene.derive(&mut ar).unwrap();
    let (t, y) = (
        0.7,
        state14(
            Vector3::new(0.4, -0.3, 0.8),
            UnitQuaternion::from_euler_angles(0.3, -0.2, 0.7),
            11.0,
        ),
    );
    let u = Tilted.motor(t, &y);
    let model = FreeModel::new(&mut ar, &derivation, &[("J", 0.05), ("u", u)]).unwrap();
    assert_eq!(model.state_len(), 14);
    let (mut a, mut b) = ([0.0; 14], [0.0; 14]);
    model.rhs(t, &y, &mut a);
    Tilted.free_rhs(t, &y, &mut b);
    for k in 0..14 {
        assert_relative_eq!(a[k], b[k], epsilon = 1e-13, max_relative = 1e-12);
    }
    assert_relative_eq!(model.energy(&y), Tilted.energy(&y), max_relative = 1e-13);
    assert_relative_eq!(model.power(&y), Tilted.power(t, &y), max_relative = 1e-13);
    assert_relative_eq!(
        model.momenta(&y).1,
        Tilted.angular_momentum_origin(&y),
        epsilon = 1e-13
    );
    // The interpreter refuses a state of the wrong length before a step.
    assert!(Dop853::new(&model, 0.0, [0.0; 13], tight()).is_err());
}

/// A wheel as heavy about its axis as the body: I − J â âᵀ is singular, which a field value
/// can only reveal at run time; `check_parameters` names the rotor and the integrators refuse
/// to start. Just below, the body is fine.
#[test]
fn a_field_inertia_that_leaves_the_body_no_moment_is_refused() {
    let body = FieldWheel { j: 3.5 };
    match body.check_parameters() {
        Err(FreeError::DrivenInertia { rotor: 0, smallest }) => {
            assert_relative_eq!(smallest, -0.5, epsilon = 1e-12);
        }
        other => panic!("expected DrivenInertia, got {other:?}"),
    }
    let y0 = state14(Vector3::zeros(), UnitQuaternion::identity(), 0.0);
    let refused = Dop853::new(FreeSystem(&body), 0.0, y0, tight());
    assert!(matches!(
        refused.err(),
        Some(OdeError::InvalidSystemParameter { .. })
    ));
    assert!(FieldWheel { j: 3.0 }.check_parameters().is_err());
    assert!(FieldWheel { j: 2.9 }.check_parameters().is_ok());
    // The run-time scene refuses the same.
    let mut ar = Arena::new();
    let (m, i) = (ar.integer(1), [ar.integer(1), ar.integer(2), ar.integer(3)]);
    let mut scene = FreeScene::new(&mut ar, m, i);
    let (z, o, j) = (ar.zero(), ar.one(), ar.parameter("J"));
    scene.driven.push(DrivenRotor {
        axis: [z, z, o],
        inertia: j,
        torque: z,
    });
    let d = scene.derive(&mut ar).unwrap();
    let model = FreeModel::new(&mut ar, &d, &[("J", 3.5)]).unwrap();
    assert!(matches!(
        model.check_driven(),
        Err(FreeError::DrivenInertia { rotor: 0, .. })
    ));
}

/// The quantities name the whole state, the rotor's rate last.
#[test]
fn the_quantities_name_the_rotor_slot() {
    let names = FreeQuantities::<SpinUp>::all_state_names();
    assert_eq!(names.len(), 14);
    assert_eq!(names[13], "rotor_0");
}
