//! Events against closed-form event times: a falling point reaching the floor, the zeros of
//! sin t by direction, the heavy top's turning points (θ̇ = 0) a nutation half-period apart,
//! and ω2 changing sign at the flips of a body near its intermediate axis, 2K(k)/λ apart;
//! for the adaptive pairs, RK4 and the splittings. Then terminal stops and bad input.

use crate::common;

use approx::assert_relative_eq;
use common::tops::ReferenceTop;
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::prelude::TopDynamics;
use precess_core::ode::{
    AdaptiveConfig, Direction, Dop853, Dopri5, Event, FixedStepConfig, FixedStepper, FnSystem,
    OdeError, Rk4, Run, Stepper, StopReason, Vern9,
};
use precess_core::rigid::{
    BodyMomentum, ExactFreeFlow, FreeBodySplitting, Gravity, PotentialSplitting, SplittingOrder,
};
use precess_core::top::{HeavyTopTheory, TopChart};
use precess_testkit::systems::FreeBody;
use std::f64::consts::{FRAC_PI_3, PI};

const G: f64 = 9.81;

/// z̈ = −g from rest at 10 m: z = 10 − g t²/2, at the floor at √(20/g).
fn falling() -> FnSystem<impl Fn(f64, &[f64; 2], &mut [f64; 2])> {
    FnSystem(|_t: f64, y: &[f64; 2], d: &mut [f64; 2]| *d = [y[1], -G])
}

/// Runs `stepper` to 5 s with a terminal floor event and checks the closed form: every
/// method here is exact on a quadratic, so the event is as exact as its location.
fn lands_on_the_floor<S: Stepper<State = [f64; 2]>>(mut stepper: S) {
    let out = Run::new(&mut stepper, 5.0)
        .event(Event::new("floor").falling().terminal(), |_t, y| y[0])
        .integrate()
        .unwrap();
    let t_floor = (20.0 / G).sqrt();
    assert_eq!(out.stop, StopReason::Event(0));
    assert_eq!(out.events.len(), 1);
    let hit = &out.events[0];
    assert_eq!(hit.direction, Direction::Falling);
    assert!(hit.terminal);
    assert_relative_eq!(hit.t, t_floor, max_relative = 1e-14);
    assert_relative_eq!(hit.state[1], -G * t_floor, max_relative = 1e-13);
    assert!(hit.state[0].abs() < 1e-12, "z = {}", hit.state[0]);
    // The run and the stepper end at the event; the last sample is the event.
    assert_eq!((out.t, stepper.t()), (hit.t, hit.t));
    assert_eq!(out.trajectory.times().last(), Some(&hit.t));
}

#[test]
fn a_falling_point_stops_at_the_floor_with_every_stepper() {
    let y0 = [10.0, 0.0];
    let cfg = AdaptiveConfig::default();
    lands_on_the_floor(Dopri5::new(falling(), 0.0, y0, cfg).unwrap());
    lands_on_the_floor(Dop853::new(falling(), 0.0, y0, cfg).unwrap());
    // Verner's interpolant has coefficients up to 1e4 that cancel, so its round-off is a
    // few 1e-12 of h |f|: with the 0.5 s to 4.5 s steps this problem lets the controller
    // take, 2e-12 in t. Steps of 0.1 s keep it near 1e-15 (docs/trajectories.md).
    let bounded = AdaptiveConfig { h_max: 0.1, ..cfg };
    lands_on_the_floor(Vern9::new(falling(), 0.0, y0, bounded).unwrap());
    lands_on_the_floor(Rk4::new(falling(), 0.0, y0, FixedStepConfig::with_step(0.1)).unwrap());
}

/// ÿ = −y from (0, 1): y = sin t, rising through 0 at 2π k, falling at π (2k + 1).
fn oscillator() -> FnSystem<impl Fn(f64, &[f64; 2], &mut [f64; 2])> {
    FnSystem(|_t: f64, y: &[f64; 2], d: &mut [f64; 2]| *d = [y[1], -y[0]])
}

#[test]
fn directions_filter_the_zeros_of_sin() {
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-15);
    let mut ode = Dop853::new(oscillator(), 0.0, [0.0, 1.0], tight).unwrap();
    let out = Run::new(&mut ode, 4.0 * PI + 1.0)
        .event(Event::new("up").rising(), |_t, y| y[0])
        .event(Event::new("down").falling(), |_t, y| y[0])
        .event(Event::new("any"), |_t, y| y[0])
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::End);
    let times = |i: usize| out.hits(i).map(|h| h.t).collect::<Vec<_>>();
    let (up, down, any) = (times(0), times(1), times(2));
    // The start, where y = 0, is no crossing.
    assert_eq!(up.len(), 2);
    assert_eq!(down.len(), 2);
    assert_eq!(any.len(), 4);
    for (t, k) in up.iter().zip([2.0, 4.0]) {
        assert_relative_eq!(*t, k * PI, max_relative = 1e-12);
    }
    for (t, k) in down.iter().zip([1.0, 3.0]) {
        assert_relative_eq!(*t, k * PI, max_relative = 1e-12);
    }
    for (t, k) in any.iter().zip(1..) {
        assert_relative_eq!(*t, f64::from(k) * PI, max_relative = 1e-12);
    }
    // Hits come in time order, and say which way g crossed.
    assert!(out.events.windows(2).all(|w| w[0].t <= w[1].t));
    assert!(out.hits(2).map(|h| h.direction).eq([
        Direction::Falling,
        Direction::Rising,
        Direction::Falling,
        Direction::Rising
    ]));
}

#[test]
fn rk4_locates_on_its_own_partial_steps() {
    // RK4 with h = 0.01 is accurate to ~1e-10 here; the event time follows it, not the
    // 0.01 grid, and g at the reported state is 0 to the resolution of t.
    let mut rk = Rk4::new(
        oscillator(),
        0.0,
        [0.0, 1.0],
        FixedStepConfig::with_step(0.01),
    )
    .unwrap();
    let out = Run::new(&mut rk, 7.0)
        .event(Event::new("zero"), |_t, y| y[0])
        .integrate()
        .unwrap();
    let ts: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    assert_eq!(ts.len(), 2);
    assert_relative_eq!(ts[0], PI, max_relative = 1e-9);
    assert_relative_eq!(ts[1], 2.0 * PI, max_relative = 1e-9);
    for h in &out.events {
        // |g| ≤ |ġ| · a few ulps of t, with |ġ| = |cos t| = 1.
        assert!(
            h.state[0].abs() <= 8.0 * f64::EPSILON * h.t,
            "{}",
            h.state[0]
        );
    }
}

/// θ̇ = 0 at the turning points of the heavy top (I1 = 1, I3 = ½, M g l = 1) released at
/// rest from θ0 = 60° spinning at ω3 = 20: θ_max at T/2, θ_min at T, …, T the nutation
/// period 2K(m)/ν of the closed form.
#[test]
fn heavy_top_turning_points_are_half_a_nutation_period_apart() {
    let top = ReferenceTop;
    let motion = HeavyTopTheory::new(1.0, 0.5, 1.0)
        .unwrap()
        .motion_from_angles(&[0.0, FRAC_PI_3, 0.0], &[0.0, 0.0, 20.0])
        .unwrap();
    let period = motion.nutation_period();
    assert_relative_eq!(period, 0.634549, max_relative = 1e-6);
    let chart = TopChart::declared(&top);
    let y0 = [0.0, FRAC_PI_3, 0.0, 0.0, 0.0, 20.0];
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let mut ode = Dop853::new(&chart, 0.0, y0, tight).unwrap();
    let out = Run::new(&mut ode, 3.2 * period)
        .sample_steps()
        .event(Event::new("theta_dot = 0"), |_t, y| y[4])
        .integrate()
        .unwrap();
    let hits: Vec<_> = out.hits(0).collect();
    assert_eq!(hits.len(), 6);
    for (k, h) in hits.iter().enumerate() {
        let expected = (k + 1) as f64 * period / 2.0;
        assert_relative_eq!(h.t, expected, max_relative = 1e-12);
        // θ_max (falling θ̇) at odd multiples of T/2, θ_min at multiples of T.
        let (dir, theta) = if k % 2 == 0 {
            (Direction::Falling, motion.theta_max())
        } else {
            (Direction::Rising, motion.theta_min())
        };
        assert_eq!(h.direction, dir);
        assert_relative_eq!(h.state[1], theta, max_relative = 1e-12);
    }
    // The first two agree with the closed form's own turning times.
    let [t_max, _] = motion.turning_times().unwrap();
    assert_relative_eq!(hits[0].t, t_max, max_relative = 1e-12);
    // Located on the dense output: θ̇ at the reported state is 0 to |θ̈| times a few ulps.
    for h in &hits {
        let q = [h.state[0], h.state[1], h.state[2]];
        let theta_ddot = top.accelerations_unchecked(h.t, &q, &[h.state[3], 0.0, h.state[5]])[1];
        assert!(h.state[4].abs() <= 8.0 * f64::EPSILON * h.t * theta_ddot.abs());
    }
}

/// The same turning points with the splitting of the exact free flow and gravity kicks:
/// the axis is R e3, and θ̇ = 0 where d(cos θ)/dt = (R (ω × e3))·ẑ changes sign.
#[test]
fn heavy_top_turning_points_with_the_potential_splitting() {
    let split = PotentialSplitting {
        free: ExactFreeFlow::new([1.0, 1.0, 0.5]).unwrap(),
        potential: Gravity {
            weight: 1.0,
            c: Vector3::new(0.0, 0.0, 1.0),
        },
    };
    let q0 = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_3);
    let y0 = BodyMomentum {
        q: q0,
        m: Vector3::new(0.0, 0.0, 10.0),
    };
    let period = 0.634_549;
    let h = period / 400.0;
    let mut s = FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(h)).unwrap();
    let axis_rate = |_t: f64, y: &BodyMomentum| {
        let w = Vector3::new(y.m.x, y.m.y, y.m.z / 0.5);
        (y.q * w.cross(&Vector3::z())).z
    };
    let out = Run::new(&mut s, 2.2 * period)
        .event(Event::new("turning"), axis_rate)
        .integrate()
        .unwrap();
    let hits: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    assert_eq!(hits.len(), 4);
    for (k, t) in hits.iter().enumerate() {
        let expected = (k + 1) as f64 * period / 2.0;
        // Strang at 400 steps per period: O(h²), 4.8e-8 here.
        assert_relative_eq!(*t, expected, max_relative = 1e-6);
    }
}

/// AGM(a, b), for K(m) = π / (2 AGM(1, √(1 − m))).
fn agm(mut a: f64, mut b: f64) -> f64 {
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    a
}

/// The body I = (3, 5, 9) from m(0) = (0, 2, 0.01), close to the separatrix: m2 = A2 sn(λt +
/// K) changes sign at K/λ + j 2K/λ. λ and the complementary parameter from the
/// cancellation-free forms of D1 = G² − 2H I1, D2 = G² − 2H I2.
fn flip_times() -> (f64, f64) {
    let (i, m) = ([3.0, 5.0, 9.0], [0.0f64, 2.0, 0.01]);
    let d1 = m[1] * m[1] * (i[1] - i[0]) / i[1] + m[2] * m[2] * (i[2] - i[0]) / i[2];
    let d2 = m[2] * m[2] * (i[2] - i[1]) / i[2] - m[0] * m[0] * (i[1] - i[0]) / i[0];
    let mc = d2 * (i[2] - i[0]) / (d1 * (i[2] - i[1]));
    let k = PI / (2.0 * agm(1.0, mc.sqrt()));
    let lambda = ((i[2] - i[1]) * d1 / (i[0] * i[1] * i[2])).sqrt();
    // The published values of this case.
    assert_relative_eq!(mc, 4.16649306e-5, max_relative = 1e-8);
    assert_relative_eq!(k, 6.42927630198503, max_relative = 1e-13);
    assert_relative_eq!(lambda, 0.217736957625593, max_relative = 1e-13);
    (k / lambda, 2.0 * k / lambda)
}

#[test]
fn flips_near_the_intermediate_axis_are_2k_over_lambda_apart() {
    let (first, interval) = flip_times();
    let y0 = [0.0, 2.0, 0.01];
    let t_end = first + 2.5 * interval;
    let check = |times: &[f64], tol: f64, what: &str| {
        assert_eq!(times.len(), 3, "{what}");
        for (j, t) in times.iter().enumerate() {
            let expected = first + j as f64 * interval;
            assert_relative_eq!(*t, expected, max_relative = tol);
        }
    };
    // DOP853 on Euler's equations: ω2 = m2/I2.
    let tight = AdaptiveConfig::with_tol(1e-13, 1e-15);
    let mut ode = Dop853::new(FreeBody([3.0, 5.0, 9.0]), 0.0, y0, tight).unwrap();
    let out = Run::new(&mut ode, t_end)
        .event(Event::new("omega2"), |_t, m| m[1] / 5.0)
        .integrate()
        .unwrap();
    let ts: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    check(&ts, 5e-11, "dop853");
    // Falling only: the first and third.
    let mut ode = Dop853::new(FreeBody([3.0, 5.0, 9.0]), 0.0, y0, tight).unwrap();
    let out = Run::new(&mut ode, t_end)
        .event(Event::new("omega2 falls").falling(), |_t, m| m[1] / 5.0)
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 2);
    assert_relative_eq!(
        out.events[1].t,
        first + 2.0 * interval,
        max_relative = 5e-11
    );

    // RK4.
    let mut rk = Rk4::new(
        FreeBody([3.0, 5.0, 9.0]),
        0.0,
        y0,
        FixedStepConfig::with_step(0.02),
    )
    .unwrap();
    let out = Run::new(&mut rk, t_end)
        .event(Event::new("omega2"), |_t, m| m[1] / 5.0)
        .integrate()
        .unwrap();
    let ts: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    check(&ts, 5e-11, "rk4");

    // The free-body splitting of order 6.
    let split = FreeBodySplitting::new([3.0, 5.0, 9.0], SplittingOrder::Six).unwrap();
    let y0 = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::from(y0),
    };
    let mut s = FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(0.05)).unwrap();
    let out = Run::new(&mut s, t_end)
        .event(Event::new("omega2"), |_t, y| y.m.y / 5.0)
        .integrate()
        .unwrap();
    let ts: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    check(&ts, 5e-11, "splitting");
}

#[test]
fn a_terminal_event_drops_the_later_crossings_of_its_step() {
    // RK4 with h = 2 on y = sin t: the step [2, 4] holds y = 0.5 falling (near 5π/6) and
    // y = 0 (near π). The terminal one ends the run; the later zero is not reported.
    let rk = || {
        Rk4::new(
            oscillator(),
            0.0,
            [0.0, 1.0],
            FixedStepConfig::with_step(2.0),
        )
        .unwrap()
    };
    let mut free = rk();
    let all = Run::new(&mut free, 4.0)
        .event(Event::new("zero"), |_t, y| y[0])
        .event(Event::new("half").falling(), |_t, y| y[0] - 0.5)
        .integrate()
        .unwrap();
    let times: Vec<(usize, f64)> = all.events.iter().map(|h| (h.index, h.t)).collect();
    assert_eq!(times.len(), 2);
    assert!(times[0].0 == 1 && times[1].0 == 0, "{times:?}");
    assert!(
        times.iter().all(|(_, t)| (2.0..4.0).contains(t)),
        "{times:?}"
    );

    let mut stopped = rk();
    let out = Run::new(&mut stopped, 4.0)
        .event(Event::new("zero"), |_t, y| y[0])
        .event(Event::new("half").falling().terminal(), |_t, y| y[0] - 0.5)
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::Event(1));
    assert_eq!(out.events.len(), 1);
    assert_eq!(out.events[0].t, times[0].1);
    assert_relative_eq!(out.state[0], 0.5, epsilon = 1e-14);
    // The stepper was put back on the event and goes on from there.
    assert_eq!(stopped.t(), out.t);
    let next = Run::new(&mut stopped, 4.0)
        .event(Event::new("zero"), |_t, y| y[0])
        .integrate()
        .unwrap();
    // Steps of 2 s from the event are a new grid, so the zero moves by RK4's error there.
    assert_eq!(next.events.len(), 1);
    assert!(next.events[0].t > out.t);
    assert_relative_eq!(next.events[0].t, times[1].1, max_relative = 1e-2);
}

#[test]
fn a_symmetric_body_flips_exactly_under_the_axis_splitting() {
    // I1 = I2 = 1, I3 = 2: m1 + i m2 = e^{i t/2} from m = (1, 0, 1), and the axis splitting
    // is exact for it at any step, so the zeros of ω2 are at 2π k to the resolution of t.
    let split = FreeBodySplitting::new([1.0, 1.0, 2.0], SplittingOrder::Two).unwrap();
    let y0 = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::new(1.0, 0.0, 1.0),
    };
    let mut s = FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(0.7)).unwrap();
    let out = Run::new(&mut s, 13.0)
        .event(Event::new("omega2"), |_t, y| y.m.y)
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 2);
    for (h, k) in out.events.iter().zip([1.0, 2.0]) {
        assert_relative_eq!(h.t, 2.0 * PI * k, max_relative = 1e-14);
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let start = || Dop853::new(oscillator(), 0.0, [0.0, 1.0], AdaptiveConfig::default()).unwrap();
    // A non-finite event value at the start, and later in the run.
    let mut ode = start();
    let err = Run::new(&mut ode, 1.0)
        .event(Event::new("ok"), |_t, y| y[0])
        .event(Event::new("nan"), |_t, _y| f64::NAN)
        .integrate()
        .unwrap_err();
    assert!(matches!(err, OdeError::NonFiniteEvent { index: 1, t: 0.0, value } if value.is_nan()));
    let mut ode = start();
    let err = Run::new(&mut ode, 3.0)
        .event(Event::new("blows up"), |t, _y| {
            if t < 1.0 { 1.0 } else { f64::INFINITY }
        })
        .integrate()
        .unwrap_err();
    assert!(
        matches!(err, OdeError::NonFiniteEvent { index: 0, t, value } if t >= 1.0 && value == f64::INFINITY)
    );
    // The solution inside the last step, and nowhere else.
    let mut rk = Rk4::new(
        oscillator(),
        0.0,
        [0.0, 1.0],
        FixedStepConfig::with_step(0.1),
    )
    .unwrap();
    Stepper::step(&mut rk, 1.0).unwrap();
    let err = rk.state_at(0.2).unwrap_err();
    assert_eq!(
        err,
        OdeError::OutsideLastStep {
            t: 0.2,
            t_prev: 0.0,
            t_now: 0.1
        }
    );
    // RK4's own half step: local error h⁵/120 = 2.6e-9.
    assert_relative_eq!(rk.state_at(0.05).unwrap()[0], 0.05f64.sin(), epsilon = 3e-9);
    let err = rk.restart(0.0, [f64::NAN, 0.0]).unwrap_err();
    assert!(matches!(
        err,
        OdeError::NonFiniteInitialState { index: 0, .. }
    ));
}

#[test]
fn the_splittings_refuse_bad_states_and_name_the_failing_step() {
    let split = FreeBodySplitting::new([1.0, 2.0, 3.0], SplittingOrder::Two).unwrap();
    let bad = BodyMomentum {
        q: UnitQuaternion::new_unchecked(precess::nalgebra::Quaternion::new(2.0, 0.0, 0.0, 0.0)),
        m: Vector3::new(1.0, 0.0, 0.0),
    };
    let cfg = FixedStepConfig::with_step(0.1);
    let err = FixedStepper::new(split, 0.0, bad, cfg).unwrap_err();
    assert_eq!(err, OdeError::NotUnitQuaternion { norm: 2.0 });
    // A moment of 1e-300 turns the rotation angle to ∞: the step from t = 5 fails, named by
    // its start, and the stepper stays there.
    let tiny = FreeBodySplitting::new([1e-300, 1.0, 3.0], SplittingOrder::Two).unwrap();
    let y0 = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::new(1e300, 0.0, 1.0),
    };
    let mut s = FixedStepper::new(tiny, 5.0, y0, cfg).unwrap();
    let err = Stepper::step(&mut s, 6.0).unwrap_err();
    assert_eq!(err, OdeError::NonFiniteState { t: 5.0 });
    assert_eq!((s.t(), s.state().m), (5.0, y0.m));
}

/// y′ = 1 from 0 with the witness 3/4 − y: linear on the step, so the root's location lands
/// on a time within rounding of 3/4 where the witness is exactly 0. The loop acts at that
/// zero, not at the last point evaluated before it (which it did: here at t = 0.652, and a
/// rolling sphere's lift-off 1.3e-6 s early, with 7e-7 N of normal force left).
#[test]
fn a_witness_located_at_exactly_zero_acts_at_its_zero() {
    use precess_core::ode::{Action, Hooks, Hybrid, HybridState, System};
    struct Line;
    impl System<1> for Line {
        fn rhs(&self, _t: f64, _y: &[f64; 1], d: &mut [f64; 1]) {
            d[0] = 1.0;
        }
    }
    impl Hooks<[f64; 1]> for Line {
        type Mode = ();
        type Halt = (f64, f64);
        fn mode(&self) {}
        fn set_mode(&mut self, _: ()) {}
        fn witness_names(&self) -> &[&'static str] {
            &["three quarters"]
        }
        fn witness(&self, _: &(), _: usize, _t: f64, y: &[f64; 1]) -> f64 {
            0.75 - y[0]
        }
        fn on_witness(
            &self,
            _: usize,
            t: f64,
            s: &HybridState<(), [f64; 1]>,
            _w: f64,
        ) -> Result<Action<(), [f64; 1], (f64, f64)>, OdeError> {
            Ok(Action::Halt((t, s.x[0])))
        }
    }
    let ode = Dop853::new(Line, 0.0, [0.0], AdaptiveConfig::with_tol(1e-10, 1e-12)).unwrap();
    let mut line = Hybrid::new(ode).unwrap();
    let out = Run::new(&mut line, 2.0).sample_none().integrate().unwrap();
    assert_eq!(out.stop, StopReason::Halted);
    let (t, y) = line.halt().copied().expect("the witness halts the run");
    assert_eq!(y, 0.75, "the witness is exactly 0 where the loop acts");
    assert!((t - 0.75).abs() <= 2.0 * f64::EPSILON, "t = {t}");
}
