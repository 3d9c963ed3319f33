//! Issue 26 item 4: tops whose wheels are turned by motors. With I the whole top's inertia
//! about the pivot (the wheel counted as locked), a wheel of axial moment J on the body axis
//! â at the relative rate Ω (a state slot after [q, q̇]) and its motor torque u,
//! (I − J â âᵀ) ω̇ = τ − ω × (I ω + J Ω â) − u â and Ω̇ = u/J − â·ω̇. Checked against values
//! found without the code: the closed form of a spin-up from rest, the vertical angular
//! momentum (gravity's torque about the pivot is horizontal, the motor's internal), the
//! work–energy balance with the motor's work integrated alongside, the constant-rate rotor
//! where the two must agree, the Eulerian equations written here with nalgebra (also through
//! gimbal lock with the chart switch), and the field J refused before a run.

use approx::assert_relative_eq;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use precess::ode::{AdaptiveConfig, Dop853, OdeError, System};
use precess::prelude::*;
use precess::top::{TopChart, TopError, TopQuantities};

use super::gyrostat::{b_zxz, omega_dot_zxz, random_state};
use crate::common::rng::Rng;

/// The motor torque of [`Hanging`], N m.
const U: f64 = 0.02;

/// A symmetric top hanging below its pivot (I₁ = I₂ = 0.05, I₃ = 0.02 about it) with a
/// wheel of J = 0.005 on its figure axis and a constant motor torque: gravity acts along the
/// figure axis, so the axis stays vertical. ZYX is regular there.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, -0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, angles = zyx, rotor(axis = [0, 0, 2], inertia = 0.005, torque = constant_motor))]
struct Hanging;

fn constant_motor(_: &Hanging, _t: f64, _y: &[f64]) -> f64 {
    U
}

/// An asymmetric top, its centre off every axis, with a constant-rate wheel and a driven
/// wheel on a skew axis whose motor is a speed loop pulling towards 60 rad/s plus a wobble.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.3, at = [0.04, -0.03, 0.25], inertia = [[0.9, 0.05, -0.02], [0.05, 0.7, 0.03], [-0.02, 0.03, 0.4]]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.01, rate = -20), rotor(axis = [1, 2, 2], inertia = 0.03, torque = Tilted::motor))]
struct Tilted;

/// The driven wheel's axis and J, and the constant one's momentum, as declared above.
const TILTED_AXIS: [f64; 3] = [1.0, 2.0, 2.0];
const TILTED_J: f64 = 0.03;
const TILTED_H0: [f64; 3] = [0.0, 0.0, -0.2];

impl Tilted {
    fn motor(&self, t: f64, y: &[f64]) -> f64 {
        speed_loop(t, y[Tilted::ROTOR_1])
    }
}

fn speed_loop(t: f64, rate: f64) -> f64 {
    0.05 * (60.0 - rate) + 0.3 * (3.0 * t).sin()
}

/// A symmetric Lagrange top with a wheel on its figure axis, its motor off …
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.2], inertia = diag(0.08, 0.08, 0.03), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.01, torque = motor_off))]
struct Coasting;

fn motor_off<T>(_: &T, _t: f64, _y: &[f64]) -> f64 {
    0.0
}

/// … and the same top with the wheel held at the rate the coasting one starts with.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.2], inertia = diag(0.08, 0.08, 0.03), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.01, rate = 150))]
struct Held;

/// A wheel's J read from a field, on the figure axis of a top with I₃ = 0.02 about it. The
/// field is named as the wheel's slot, which is harmless: the slot is the const `ROTOR_0`.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = rotor_0, torque = motor_off))]
struct FieldWheel {
    rotor_0: f64,
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// The inertia about the pivot, centre and weight of a top, and its driven wheel.
struct Hand {
    inertia: Matrix3<f64>,
    center: Vector3<f64>,
    mg: f64,
    axis: Vector3<f64>,
    j: f64,
    /// The constant-rate wheels' momentum, body axes.
    h0: Vector3<f64>,
}

impl Hand {
    fn tilted() -> Hand {
        Hand {
            inertia: Tilted.inertia(),
            center: Tilted.center_of_mass() - Tilted.reference_point(),
            mg: 1.3 * 9.81,
            axis: Vector3::from(TILTED_AXIS).normalize(),
            j: TILTED_J,
            h0: Vector3::from(TILTED_H0),
        }
    }

    /// ẑ·R (I ω + h₀ + J Ω â): the angular momentum about the vertical through the pivot.
    fn vertical_momentum(&self, r: &Matrix3<f64>, w: &Vector3<f64>, rate: f64) -> f64 {
        (r * (self.inertia * w + self.h0 + self.j * rate * self.axis)).z
    }

    /// ½ ωᵀ I ω + J Ω â·ω + ½ J Ω² + M g (R c)·ẑ.
    fn energy(&self, r: &Matrix3<f64>, w: &Vector3<f64>, rate: f64) -> f64 {
        0.5 * w.dot(&(self.inertia * w))
            + self.j * rate * self.axis.dot(w)
            + 0.5 * self.j * rate * rate
            + self.mg * (r * self.center).z
    }

    /// (ω̇, Ω̇) of the equations in the module's docs, at attitude `r`.
    fn rates(&self, r: &Matrix3<f64>, w: &Vector3<f64>, rate: f64, u: f64) -> (Vector3<f64>, f64) {
        let gravity = self
            .center
            .cross(&(r.transpose() * Vector3::new(0.0, 0.0, -self.mg)));
        let l = self.inertia * w + self.h0 + self.j * rate * self.axis;
        let reduced = self.inertia - self.j * self.axis * self.axis.transpose();
        let rhs = gravity - w.cross(&l) - u * self.axis;
        let w_dot = reduced.try_inverse().unwrap_or_else(Matrix3::zeros) * rhs;
        (w_dot, u / self.j - self.axis.dot(&w_dot))
    }
}

/// The Eulerian equations of [`Tilted`] written by hand: state (quaternion w, x, y, z; ω;
/// Ω), the motor's torque the same speed loop.
struct HandTilted(Hand);

impl System<8> for HandTilted {
    fn rhs(&self, t: f64, y: &[f64; 8], d: &mut [f64; 8]) {
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(y[0], y[1], y[2], y[3]));
        let w = Vector3::new(y[4], y[5], y[6]);
        let r = *q.to_rotation_matrix().matrix();
        let (w_dot, rate_dot) = self.0.rates(&r, &w, y[7], speed_loop(t, y[7]));
        let q_dot = q.into_inner() * nalgebra::Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        d[..4].copy_from_slice(&[q_dot.w, q_dot.i, q_dot.j, q_dot.k]);
        d[4..7].copy_from_slice(w_dot.as_slice());
        d[7] = rate_dot;
    }
}

/// [`Tilted`]'s state with the motor's work ∫ u Ω dt in an extra slot.
struct WithWork<'a>(TopChart<'a, Tilted>);

impl System<8> for WithWork<'_> {
    fn rhs(&self, t: f64, y: &[f64; 8], d: &mut [f64; 8]) {
        let state: [f64; 7] = std::array::from_fn(|k| y[k]);
        let mut rate = [0.0; 7];
        self.0.rhs(t, &state, &mut rate);
        d[..7].copy_from_slice(&rate);
        d[7] = Tilted.motor(t, &state) * state[Tilted::ROTOR_1];
    }
}

fn tilted_start() -> [f64; 7] {
    [0.2, 0.6, 0.3, 0.5, 0.2, 3.0, 5.0]
}

fn r_of(y: &[f64]) -> Matrix3<f64> {
    Tilted.rotation_in(AngleSequence::Zxz, &[y[0], y[1], y[2]])
}

fn w_of(y: &[f64]) -> Vector3<f64> {
    Tilted.rate_matrix_in(AngleSequence::Zxz, &[y[0], y[1], y[2]]) * Vector3::new(y[3], y[4], y[5])
}

/// From rest, hanging: the body turns back about its vertical figure axis with
/// ω₃ = −u t/(I₃ − J) and the wheel spins up with Ω = u t/J + u t/(I₃ − J) (the axial
/// momentum (I₃ − J) ω₃ + J (ω₃ + Ω) staying 0); in ZYX at zero pitch and roll, ω₃ is the
/// yaw rate.
#[test]
fn a_spin_up_from_rest_follows_the_closed_form() {
    // The slots count the driven rotors; the names, every rotor declared.
    assert_eq!((Hanging::ROTOR_0, Tilted::ROTOR_1), (6, 6));
    assert_eq!(Tilted::coordinate("rotor_1"), Some(6));
    assert_eq!(Tilted::coordinate("rotor_0"), None);
    let (i3, j) = (0.02, 0.005);
    let chart = TopChart::declared(&Hanging);
    let mut ode = Dop853::new(&chart, 0.0, [0.0; 7], tight()).unwrap();
    for t in [0.5, 2.0, 7.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        assert_relative_eq!(y[3], -U * t / (i3 - j), max_relative = 1e-12);
        assert_relative_eq!(y[6], U * t / j + U * t / (i3 - j), max_relative = 1e-12);
        assert_relative_eq!(y[0], -U * t * t / (2.0 * (i3 - j)), max_relative = 1e-12);
        for k in [1, 2, 4, 5] {
            assert_relative_eq!(y[k], 0.0, epsilon = 1e-14);
        }
    }
}

/// Gravity's torque about the pivot is horizontal and the motor's is internal, so
/// ẑ·R (I ω + h) is conserved whatever the speed loop does; the energy changes by the
/// motor's work ∫ u Ω dt integrated alongside. The generated momentum p_φ and energy are the
/// totals written by hand.
#[test]
fn vertical_momentum_is_kept_and_the_energy_gains_the_motors_work() {
    let hand = Hand::tilted();
    let y0 = tilted_start();
    let (r0, w0) = (r_of(&y0), w_of(&y0));
    let lz0 = hand.vertical_momentum(&r0, &w0, y0[6]);
    let e0 = hand.energy(&r0, &w0, y0[6]);
    assert_relative_eq!(
        Tilted.energy_in(AngleSequence::Zxz, &y0),
        e0,
        max_relative = 1e-13
    );
    let momenta = Tilted.conserved_momenta_in(&y0);
    assert_relative_eq!(momenta[0].unwrap(), lz0, max_relative = 1e-13);
    assert_eq!((momenta[1], momenta[2]), (None, None));
    let mut y0w = [0.0; 8];
    y0w[..7].copy_from_slice(&y0);
    let mut ode = Dop853::new(WithWork(TopChart::declared(&Tilted)), 0.0, y0w, tight()).unwrap();
    let mut worked = false;
    for t in [1.0, 3.0, 6.0] {
        ode.advance_to(t).unwrap();
        let y = ode.y();
        let (r, w) = (r_of(y), w_of(y));
        assert_relative_eq!(hand.vertical_momentum(&r, &w, y[6]), lz0, epsilon = 1e-10);
        let e = hand.energy(&r, &w, y[6]);
        assert_relative_eq!(e - e0, y[7], epsilon = 1e-9);
        worked |= y[7].abs() > 1.0;
    }
    assert!(worked, "the motor did almost no work");
}

/// Against the Eulerian equations written here (quaternion, ω, Ω) from the same start: the
/// attitude and the wheel's rate agree.
#[test]
fn the_angle_form_matches_the_eulerian_equations_written_by_hand() {
    let y0 = tilted_start();
    let (r0, w0) = (r_of(&y0), w_of(&y0));
    let q0 = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r0));
    let h0 = [q0.w, q0.i, q0.j, q0.k, w0.x, w0.y, w0.z, y0[6]];
    let mut top = Dop853::new(TopChart::declared(&Tilted), 0.0, y0, tight()).unwrap();
    let mut hand = Dop853::new(HandTilted(Hand::tilted()), 0.0, h0, tight()).unwrap();
    for t in [0.5, 2.0, 4.0] {
        top.advance_to(t).unwrap();
        hand.advance_to(t).unwrap();
        let (y, h) = (top.y(), hand.y());
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(h[0], h[1], h[2], h[3]));
        assert_relative_eq!(r_of(y), *q.to_rotation_matrix().matrix(), epsilon = 1e-9);
        assert_relative_eq!(w_of(y), Vector3::new(h[4], h[5], h[6]), epsilon = 1e-8);
        assert_relative_eq!(y[6], h[7], epsilon = 1e-8);
    }
}

/// Motor off on a symmetric top with the wheel on its figure axis: J (ω₃ + Ω) and I₃ ω₃
/// are both constant, so Ω is; the run equals the top with the wheel held at that rate.
#[test]
fn a_coasting_wheel_on_the_figure_axis_equals_a_held_one() {
    let start = [0.1, 0.7, 0.0, 0.4, -0.3, 12.0];
    let mut coasting_start = [0.0; 7];
    coasting_start[..6].copy_from_slice(&start);
    coasting_start[6] = 150.0;
    let coasting = TopChart::declared(&Coasting);
    let held = TopChart::declared(&Held);
    let mut a = Dop853::new(&coasting, 0.0, coasting_start, tight()).unwrap();
    let mut b = Dop853::new(&held, 0.0, start, tight()).unwrap();
    for t in [0.5, 2.0, 5.0] {
        a.advance_to(t).unwrap();
        b.advance_to(t).unwrap();
        for k in 0..6 {
            assert_relative_eq!(a.y()[k], b.y()[k], epsilon = 1e-9, max_relative = 1e-10);
        }
        assert_relative_eq!(a.y()[6], 150.0, max_relative = 1e-12);
    }
}

/// Through gimbal lock: the chart switch carries the wheel's rate over unchanged, and the
/// run still matches the Eulerian equations written by hand.
#[test]
fn the_chart_switch_carries_the_wheel_through_gimbal_lock() {
    // Upright (ZXZ singular), tumbling about the body y axis: ZYX meets its own lock when
    // the body x axis turns vertical, a quarter turn later.
    let (r0, w0, rate0) = (Matrix3::identity(), Vector3::new(0.3, 2.5, 1.0), 5.0);
    let [zxz, zyx] = TopChart::both(&Tilted);
    let mut top =
        ChartedTop::with_rotor_rates([zxz, zyx], 0.0, &r0, &w0, &[rate0], ChartConfig::default())
            .unwrap();
    let q0 = UnitQuaternion::identity();
    let h0 = [q0.w, q0.i, q0.j, q0.k, w0.x, w0.y, w0.z, rate0];
    let mut hand = Dop853::new(HandTilted(Hand::tilted()), 0.0, h0, tight()).unwrap();
    for t in [0.5, 1.5, 3.0] {
        top.advance_to(t).unwrap();
        hand.advance_to(t).unwrap();
        let h = hand.y();
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(h[0], h[1], h[2], h[3]));
        assert_relative_eq!(
            top.rotation(),
            *q.to_rotation_matrix().matrix(),
            epsilon = 1e-7
        );
        assert_relative_eq!(top.omega(), Vector3::new(h[4], h[5], h[6]), epsilon = 1e-6);
        assert_relative_eq!(top.state()[Tilted::ROTOR_1], h[7], epsilon = 1e-6);
    }
    assert!(top.switches() >= 1, "the run never switched chart");
    let wrong = ChartedTop::with_rotor_rates(
        TopChart::both(&Tilted),
        0.0,
        &r0,
        &w0,
        &[],
        ChartConfig::default(),
    );
    assert!(matches!(
        wrong,
        Err(TopError::RotorRates { expected: 1, .. })
    ));
}

/// A field J too large for the top (at least I₃ about the figure axis) is refused before a
/// run, naming the rotor and the smallest moment left; the angle-only helpers say why they
/// cannot take a driven top.
#[test]
fn a_driven_tops_parameters_and_state_are_checked() {
    let ok = FieldWheel { rotor_0: 0.005 };
    assert_eq!(ok.check_all(), Ok(()));
    assert_eq!(FieldWheel::ROTOR_0, 6);
    let bad = FieldWheel { rotor_0: 0.025 };
    match bad.check_all() {
        Err(TopError::DrivenInertia { rotor, smallest }) => {
            assert_eq!(rotor, 0);
            assert_relative_eq!(smallest, 0.02 - 0.025, epsilon = 1e-15);
        }
        other => panic!("expected DrivenInertia, got {other:?}"),
    }
    let chart = TopChart::declared(&bad);
    let run = Dop853::new(&chart, 0.0, [0.0, 0.5, 0.0, 0.0, 0.0, 1.0, 0.0], tight());
    assert!(matches!(run, Err(OdeError::InvalidSystemParameter { .. })));
    let q = ok.accelerations(0.0, &[0.0, 0.5, 0.0], &[0.0, 0.0, 1.0]);
    assert!(matches!(q, Err(TopError::DrivenState { rotors: 1, .. })));
    assert!(ok.energy(&[0.0, 0.5, 0.0], &[0.0, 0.0, 1.0]).is_nan());
    // The checked q̈ over the whole state takes it.
    let state = [0.0, 0.5, 0.0, 0.0, 0.0, 1.0, 3.0];
    assert!(ok.accelerations_in(AngleSequence::Zxz, 0.0, &state).is_ok());
}

/// The quantities of a run name the wheel's slot and count its momentum.
#[test]
fn quantities_take_a_driven_top() {
    let names = TopQuantities::<Tilted>::state_names();
    assert_eq!(names[6], "rotor_1");
    let mut quantities = TopQuantities::new(&Tilted);
    let columns = precess::ode::Quantities::<[f64; 7]>::names(&quantities);
    assert_eq!(columns, ["energy", "omega", "L", "p_phi"]);
    let y0 = tilted_start();
    let mut out = [0.0; 4];
    precess::ode::Quantities::evaluate(&mut quantities, 0.0, &y0, &mut out);
    let hand = Hand::tilted();
    let (r, w) = (r_of(&y0), w_of(&y0));
    let l = hand.inertia * w + hand.h0 + hand.j * y0[6] * hand.axis;
    assert_relative_eq!(out[0], hand.energy(&r, &w, y0[6]), max_relative = 1e-13);
    assert_relative_eq!(out[2], l.norm(), max_relative = 1e-13);
    assert_relative_eq!(
        out[3],
        hand.vertical_momentum(&r, &w, y0[6]),
        max_relative = 1e-13
    );
}

/// At random states of the ZXZ chart (the wheel's rate and so the motor's torque random
/// too), ω̇ = B q̈ + Ḃ q̇ from the generated q̈ and the generated Ω̇ equal the equations
/// written by hand, to 1e-12 of their size.
#[test]
fn the_generated_rates_equal_the_hand_equations_at_random_states() {
    let mut rng = Rng::new(2604);
    let hand = Hand::tilted();
    let mut worst = (0.0f64, 0.0f64);
    for _ in 0..2000 {
        let (q, qd) = random_state(&mut rng);
        let (t, rate) = (rng.uniform(0.0, 10.0), rng.uniform(-100.0, 100.0));
        let y = [q[0], q[1], q[2], qd[0], qd[1], qd[2], rate];
        let mut d = [0.0; 7];
        Tilted.rhs_in(AngleSequence::Zxz, t, &y, &mut d);
        assert_eq!(&d[..3], &qd);
        let qdd = [d[3], d[4], d[5]];
        let checked = Tilted.accelerations_in(AngleSequence::Zxz, t, &y).unwrap();
        assert_relative_eq!(
            Vector3::from(checked),
            Vector3::from(qdd),
            epsilon = 1e-12,
            max_relative = 1e-12
        );
        let w = b_zxz(&q) * Vector3::from(qd);
        let r = r_of(&y);
        let (w_dot, rate_dot) = hand.rates(&r, &w, rate, speed_loop(t, rate));
        let scale = w_dot.norm().max(1.0);
        worst.0 = worst
            .0
            .max((omega_dot_zxz(&q, &qd, &qdd) - w_dot).norm() / scale);
        worst.1 = worst
            .1
            .max((d[6] - rate_dot).abs() / rate_dot.abs().max(1.0));
    }
    assert!(worst.0 < 1e-12, "ω̇ off by {:e}", worst.0);
    assert!(worst.1 < 1e-12, "Ω̇ off by {:e}", worst.1);
}
