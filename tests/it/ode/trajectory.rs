//! Trajectories: samples at chosen times against closed forms, every accepted step against
//! the observer, derived quantities, CSV read back, progress reports, and the top's standard
//! columns against its conserved quantities.

use crate::common;

use approx::assert_relative_eq;
use common::tops::ReferenceTop;
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess_core::ode::{
    AdaptiveConfig, Control, Dop853, FixedStepConfig, FixedStepper, FnSystem, OdeError, Rk4, Run,
    StopReason, Trajectory,
};
use precess_core::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
use precess_core::top::{TopChart, TopQuantities};
use std::f64::consts::FRAC_PI_3;

/// ÿ = −y from (1, 0): y = cos t, ẏ = −sin t.
fn oscillator() -> FnSystem<impl Fn(f64, &[f64; 2], &mut [f64; 2])> {
    FnSystem(|_t: f64, y: &[f64; 2], d: &mut [f64; 2]| *d = [y[1], -y[0]])
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-15)
}

#[test]
fn samples_at_chosen_times_follow_the_closed_form() {
    let times = [0.0, 0.1, 0.7, 2.5, 2.5, 6.0, 9.75];
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    let out = Run::new(&mut ode, 10.0)
        .sample_at(times)
        .integrate()
        .unwrap();
    assert_eq!(out.trajectory.times(), times);
    for (t, y) in out.trajectory.times().iter().zip(out.trajectory.states()) {
        assert_relative_eq!(y[0], t.cos(), epsilon = 1e-12);
        assert_relative_eq!(y[1], -t.sin(), epsilon = 1e-12);
    }
    // The steps are the controller's: far fewer than the samples would force.
    assert_eq!(out.t, 10.0);
    assert_relative_eq!(out.state[0], 10f64.cos(), epsilon = 1e-12);
}

#[test]
fn samples_every_dt_reach_the_end() {
    let mut ode = Dop853::new(oscillator(), 1.0, [1f64.cos(), -1f64.sin()], tight()).unwrap();
    let out = Run::new(&mut ode, 3.0)
        .sample_every(0.1)
        .integrate()
        .unwrap();
    let times = out.trajectory.times();
    assert_eq!(times.len(), 21);
    for (k, t) in times.iter().enumerate() {
        assert_eq!(*t, (1.0 + k as f64 * 0.1).min(3.0));
    }
    assert_eq!(times.last(), Some(&3.0));
    let last = out.trajectory.states().last().unwrap();
    assert_relative_eq!(last[0], 3f64.cos(), epsilon = 1e-12);
}

#[test]
fn rk4_samples_are_its_own_partial_steps() {
    // A partial step of RK4 from the step's start is RK4's answer there: compared with the
    // closed form at RK4's accuracy (h = 0.01: global error ~1e-10), not with the grid.
    let mut rk = Rk4::new(
        oscillator(),
        0.0,
        [1.0, 0.0],
        FixedStepConfig::with_step(0.01),
    )
    .unwrap();
    let out = Run::new(&mut rk, 5.0)
        .sample_at([0.123, 1.2345, 4.99999])
        .integrate()
        .unwrap();
    for (t, y) in out.trajectory.times().iter().zip(out.trajectory.states()) {
        assert_relative_eq!(y[0], t.cos(), epsilon = 1e-9);
    }
    assert_eq!(out.stats.steps, 500);
}

#[test]
fn every_step_is_recorded_and_observed() {
    let mut seen = Vec::new();
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    let out = Run::new(&mut ode, 4.0)
        .observe(|t, y| {
            seen.push((t, y[0]));
            Control::Continue
        })
        .integrate()
        .unwrap();
    let steps = out.stats.steps as usize;
    assert_eq!(seen.len(), steps);
    // The default records the start and every step.
    assert_eq!(out.trajectory.len(), steps + 1);
    assert_eq!(out.trajectory.times()[0], 0.0);
    for ((t, y0), (ts, ys)) in seen.iter().zip(
        out.trajectory.times()[1..]
            .iter()
            .zip(&out.trajectory.states()[1..]),
    ) {
        assert_eq!((*t, *y0), (*ts, ys[0]));
        assert_relative_eq!(*y0, t.cos(), epsilon = 1e-12);
    }
    assert_eq!(out.stop, StopReason::End);
}

#[test]
fn the_observer_stops_the_run() {
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    let mut count = 0;
    let out = Run::new(&mut ode, 100.0)
        .observe(|_t, _y| {
            count += 1;
            if count == 5 {
                Control::Stop
            } else {
                Control::Continue
            }
        })
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::Observer);
    assert_eq!(out.stats.steps, 5);
    assert!(out.t < 100.0);
    assert_eq!(ode.t(), out.t);
}

#[test]
fn progress_runs_from_zero_to_one() {
    let mut fractions = Vec::new();
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    let out = Run::new(&mut ode, 50.0)
        .sample_every(1.0)
        .progress(|p| fractions.push(p.fraction()))
        .integrate()
        .unwrap();
    assert_eq!(fractions.first(), Some(&0.0));
    assert_eq!(fractions.last(), Some(&1.0));
    assert!(fractions.windows(2).all(|w| w[0] <= w[1]));
    // At most one report per thousandth, plus the forced first and last.
    assert!(fractions.len() <= 1002);
    assert!(fractions.len() as u64 <= out.stats.steps + 2);
}

#[test]
fn derived_quantities_and_csv_read_back() {
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    let mut out = Run::new(&mut ode, 2.0)
        .sample_every(0.5)
        .quantity("energy", |_t, y| 0.5 * (y[0] * y[0] + y[1] * y[1]))
        .quantity("phase, rad", |t, _y| t)
        .integrate()
        .unwrap();
    let tr = &mut out.trajectory;
    // The global error over two radians is a few times rtol = 1e-13 (2.2e-13 measured).
    for e in tr.column("energy").unwrap() {
        assert_relative_eq!(e, 0.5, max_relative = 1e-12);
    }
    assert_eq!(tr.column("phase, rad").unwrap(), tr.times());
    assert!(tr.column("missing").is_none());
    tr.set_state_names(["x", "v"]).unwrap();
    let csv = tr.to_csv();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("t,x,v,energy,\"phase, rad\""));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), tr.len());
    for (i, row) in rows.iter().enumerate() {
        let state = tr.states()[i];
        let q = tr.quantities(i).unwrap();
        assert_eq!(row, &[tr.times()[i], state[0], state[1], q[0], q[1]]);
    }
    let err = tr.set_state_names(["x"]).unwrap_err();
    assert_eq!(
        err,
        OdeError::ColumnCount {
            expected: 2,
            got: 1
        }
    );
}

#[test]
fn a_non_finite_quantity_is_an_error() {
    let mut ode = Dop853::new(oscillator(), 0.0, [1.0, 0.0], tight()).unwrap();
    // acos(cos t + 0.5) is NaN while cos t > 0.5: at once.
    let err = Run::new(&mut ode, 1.0)
        .quantity("ok", |_t, y| y[0])
        .quantity("angle", |_t, y| (y[0] + 0.5).acos())
        .integrate()
        .unwrap_err();
    assert!(
        matches!(err, OdeError::NonFiniteQuantity { column: 1, t: 0.0, value } if value.is_nan())
    );
    let mut tr = Trajectory::<[f64; 1]>::new(vec!["a".into()]);
    assert_eq!(
        tr.push(0.0, [1.0], &[1.0, 2.0]).unwrap_err(),
        OdeError::ColumnCount {
            expected: 1,
            got: 2
        }
    );
}

#[test]
fn the_top_keeps_its_conserved_columns() {
    // I1 = 1, I3 = ½, M g l = 1, released at rest from θ0 = 60° with ω3 = 20:
    // E = ½ I3 ω3² + M g l cos θ0 = 100.5, p_ψ = I3 ω3 = 10, p_φ = p_ψ cos θ0 = 5, and
    // |L| = 10 at the start; |ω|² = θ̇² + φ̇² sin²θ + ω3² ≥ 400.
    let top = ReferenceTop;
    let chart = TopChart::declared(&top);
    let y0 = [0.0, FRAC_PI_3, 0.0, 0.0, 0.0, 20.0];
    let mut ode = Dop853::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12)).unwrap();
    let mut out = Run::new(&mut ode, 2.0)
        .sample_every(0.05)
        .quantities(TopQuantities::new(&top))
        .integrate()
        .unwrap();
    let tr = &mut out.trajectory;
    assert_eq!(
        tr.quantity_names(),
        ["energy", "omega", "L", "p_phi", "p_psi"]
    );
    let col = |name: &str| tr.column(name).unwrap();
    for (((e, p_phi), p_psi), w) in col("energy")
        .into_iter()
        .zip(col("p_phi"))
        .zip(col("p_psi"))
        .zip(col("omega"))
    {
        assert_relative_eq!(e, 100.5, max_relative = 1e-11);
        assert_relative_eq!(p_phi, 5.0, max_relative = 1e-10);
        assert_relative_eq!(p_psi, 10.0, max_relative = 1e-11);
        assert!(w >= 20.0 * (1.0 - 1e-12));
    }
    assert_relative_eq!(col("L")[0], 10.0, max_relative = 1e-15);
    tr.set_state_names(TopQuantities::<ReferenceTop>::state_names())
        .unwrap();
    assert!(
        tr.to_csv()
            .starts_with("t,phi,theta,psi,phi_dot,theta_dot,psi_dot,energy,omega,L,p_phi,p_psi\n")
    );
}

#[test]
fn a_splitting_trajectory_writes_its_attitude_and_momentum() {
    let split = FreeBodySplitting::new([2.0, 1.0, 2.0 / 3.0], SplittingOrder::Four).unwrap();
    let y0 = BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::new(1.1f64.cos(), 0.0, 1.1f64.sin()),
    };
    let mut s = FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(0.01)).unwrap();
    let out = Run::new(&mut s, 10.0)
        .sample_at([1.0, 10.0])
        .quantity("|m|", |_t, y| y.m.norm())
        .integrate()
        .unwrap();
    // m(1) and m(10) of the GNI book's body (Hairer, Lubich, Wanner).
    let m1 = [
        0.369_110_080_850_460_6,
        -0.372_846_321_121_433_4,
        0.851_318_606_069_889_3,
    ];
    let m10 = [
        0.407_066_136_588_040_8,
        0.283_007_426_812_843_7,
        0.868_449_167_661_561_7,
    ];
    for (y, m) in out.trajectory.states().iter().zip([m1, m10]) {
        assert_relative_eq!(y.m, Vector3::from(m), epsilon = 1e-8);
    }
    for n in out.trajectory.column("|m|").unwrap() {
        assert_relative_eq!(n, 1.0, epsilon = 1e-14);
    }
    let csv = out.trajectory.to_csv();
    assert!(csv.starts_with("t,q_w,q_x,q_y,q_z,m_1,m_2,m_3,|m|\n1,"));
    assert_eq!(csv.lines().count(), 3);
}

#[test]
fn bad_end_and_sample_times_are_typed_errors() {
    let start = || Dop853::new(oscillator(), 0.0, [1.0, 0.0], AdaptiveConfig::default()).unwrap();
    // End times.
    let mut ode = start();
    let err = Run::new(&mut ode, f64::NAN).integrate().unwrap_err();
    assert!(matches!(err, OdeError::NonFiniteTime { t } if t.is_nan()));
    let mut ode = start();
    let err = Run::new(&mut ode, -1.0).integrate().unwrap_err();
    assert_eq!(err, OdeError::StopBeforeCurrent { stop: -1.0, t: 0.0 });
    // Sample times: after the end, unsorted, not finite; a sample interval that is not > 0.
    let mut ode = start();
    let err = Run::new(&mut ode, 1.0)
        .sample_at([0.5, 2.0])
        .integrate()
        .unwrap_err();
    assert_eq!(err, OdeError::SampleAfterEnd { t: 2.0, t_end: 1.0 });
    let mut ode = start();
    let err = Run::new(&mut ode, 1.0)
        .sample_at([0.5, 0.25])
        .integrate()
        .unwrap_err();
    assert_eq!(err, OdeError::StopBeforeCurrent { stop: 0.25, t: 0.5 });
    let mut ode = start();
    let err = Run::new(&mut ode, 1.0)
        .sample_at([f64::INFINITY])
        .integrate()
        .unwrap_err();
    assert_eq!(err, OdeError::NonFiniteTime { t: f64::INFINITY });
    let mut ode = start();
    let err = Run::new(&mut ode, 1.0)
        .sample_every(0.0)
        .integrate()
        .unwrap_err();
    assert_eq!(err, OdeError::InvalidStep { h: 0.0 });
}
