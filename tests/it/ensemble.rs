//! Ensembles: the same bits serially and on any number of threads, per-run errors that leave
//! the other runs whole, and a sweep of heavy tops against their closed form.

use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};

use approx::assert_relative_eq;
use precess::ensemble::rayon::{ThreadPool, ThreadPoolBuilder};
use precess::ensemble::{Ensemble, EnsembleError, EnsembleProgress, EnsembleResults};
use precess::ode::{
    AdaptiveConfig, Dop853, FixedStepConfig, FixedStepper, FnSystem, OdeError, Rk4, Stepper,
};
use precess::prelude::*;
use precess::rigid::{BodyMomentum, FreeBodySplitting, SplittingOrder};
use precess::sym::Arena;
use precess::taylor::{Taylor, TaylorConfig, TaylorTape};
use precess::top::{HeavyTopMotion, HeavyTopTheory, TopModel, TopScene};

use crate::common::tops::ReferenceTop;

/// The heavy top I1 = I2 = `i1`, I3 = `i3` about the pivot, M g l = `mgl`, in ZXZ, its moments and
/// weight as parameters bound at run time.
fn heavy_top(i1: f64, i3: f64, mgl: f64) -> Result<TopModel, TopError> {
    let mut a = Arena::new();
    let (p1, p3) = (a.parameter("I_1"), a.parameter("I_3"));
    let z = a.zero();
    let mut scene = TopScene::free(&mut a, [[p1, z, z], [z, p1, z], [z, z, p3]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.one()];
    scene.gravity = Some(a.one());
    let derivation = scene.derive(&mut a).expect("the heavy top derives");
    TopModel::new(&mut a, &derivation, &[("I_1", i1), ("I_3", i3), ("M", mgl)])
}

/// Run `i`'s start: tilts 0.3 to 1.2 rad, axial spins 3 to 6.5 rad/s, a little precession.
fn start(i: usize) -> [f64; 6] {
    let theta = 0.3 + 0.18 * (i % 6) as f64;
    let spin = 3.0 + 0.5 * (i / 6 % 8) as f64;
    let phi_dot = 0.05 * (i % 3) as f64;
    [0.0, theta, 0.0, phi_dot, 0.0, spin - phi_dot * theta.cos()]
}

/// Pools of 1, 2 and 3 threads.
fn pools() -> Vec<ThreadPool> {
    [1, 2, 3]
        .map(|k| ThreadPoolBuilder::new().num_threads(k).build().unwrap())
        .into()
}

type BoxError = Box<dyn std::error::Error + Send + Sync>;

fn bits<const N: usize>(y: &[f64; N]) -> [u64; N] {
    y.map(f64::to_bits)
}

/// Two interpreted tops shared by every thread, runs alternating between them, integrated by
/// DOP853 to t = 3: the final states are the same bits run serially in a plain loop and on
/// pools of 1, 2 and 3 threads, and a reduction of their energies is too.
#[test]
fn results_are_the_same_bits_serially_and_on_any_number_of_threads() {
    let models = [
        heavy_top(1.0, 0.5, 1.0).unwrap(),
        heavy_top(1.2, 0.7, 0.8).unwrap(),
    ];
    let run = |i: usize| -> Result<[f64; 6], OdeError> {
        let model = &models[i % 2];
        let mut ode = Dop853::new(model, 0.0, start(i), AdaptiveConfig::with_tol(1e-10, 1e-12))?;
        ode.advance_to(3.0)?;
        Ok(*ode.y())
    };
    let n = 48;
    let serial: Vec<[u64; 6]> = (0..n).map(|i| bits(&run(i).unwrap())).collect();
    let energy = |i: usize, y: &[f64; 6]| models[i % 2].energy(y);
    let serial_sum: f64 = (0..n).fold(0.0, |acc, i| acc + energy(i, &run(i).unwrap()));
    for pool in pools() {
        let threads = pool.current_num_threads();
        let results = pool.install(|| Ensemble::new(0..n).run(run));
        assert_eq!(results.len(), n);
        for (i, r) in results.iter() {
            assert_eq!(
                bits(r.as_ref().unwrap()),
                serial[i],
                "run {i} on {threads} threads"
            );
        }
        let sum = pool.install(|| {
            Ensemble::new(0..n).reduce(
                run,
                || 0.0,
                |acc, i, r| acc + energy(i, &r.unwrap()),
                |a, b| a + b,
            )
        });
        assert_eq!(sum.to_bits(), serial_sum.to_bits(), "{threads} threads");
    }
}

/// More runs than reduction blocks (10⁴ > 4096): the blocks are fixed by the count, so the
/// sum of √i comes out to the same bits on 1, 2 and 3 threads, and within rounding of the
/// serial sum.
#[test]
fn a_reduction_over_many_blocks_is_the_same_bits_on_any_number_of_threads() {
    let n = 10_000;
    let sums: Vec<u64> = pools()
        .iter()
        .map(|pool| {
            pool.install(|| {
                Ensemble::new(0..n).reduce(
                    |i| Ok::<f64, OdeError>((i as f64).sqrt()),
                    || 0.0,
                    |acc, _, r| acc + r.unwrap(),
                    |a, b| a + b,
                )
            })
            .to_bits()
        })
        .collect();
    assert!(sums.iter().all(|&s| s == sums[0]), "{sums:?}");
    let serial: f64 = (0..n).map(|i| (i as f64).sqrt()).sum();
    assert_relative_eq!(f64::from_bits(sums[0]), serial, max_relative = 1e-13);
}

/// Runs 3, 10 with NaN moments (refused by the model) and runs 5, 12 that panic: each is an
/// error naming its index and cause, and every other run's output is the same bits as the
/// run alone.
#[test]
fn failed_and_panicking_runs_are_reported_by_index_and_the_others_kept() {
    let run = |i: usize| -> Result<f64, TopError> {
        let i3 = if i % 7 == 3 {
            f64::NAN
        } else {
            0.5 + 0.01 * i as f64
        };
        if i % 7 == 5 {
            panic!("run {i} was asked to panic");
        }
        let model = heavy_top(1.0, i3, 1.0)?;
        let mut ode = Dop853::new(
            &model,
            0.0,
            start(i),
            AdaptiveConfig::with_tol(1e-10, 1e-12),
        )?;
        ode.advance_to(1.0)?;
        Ok(ode.y()[1])
    };
    let n = 14;
    let results = Ensemble::new(0..n).run(run);
    assert_eq!(results.failures(), 4);
    for (i, r) in results.iter() {
        match (i % 7, r) {
            (3, Err(EnsembleError::Run { index, source })) => {
                assert_eq!(*index, i);
                assert!(
                    matches!(source, TopError::Binding(precess::codegen::BindingError::NonFinite { name, value })
                        if name == "I_3" && value.is_nan()),
                    "{source:?}"
                );
            }
            (5, Err(e @ EnsembleError::Panicked { index, message })) => {
                assert_eq!(*index, i);
                assert_eq!(message, &format!("run {i} was asked to panic"));
                assert_eq!(e.index(), i);
                assert_eq!(
                    e.to_string(),
                    format!("run {i} panicked: run {i} was asked to panic")
                );
            }
            (_, Ok(theta)) => {
                let alone = std::panic::catch_unwind(|| run(i)).unwrap().unwrap();
                assert_eq!(theta.to_bits(), alone.to_bits(), "run {i}");
            }
            (_, other) => panic!("run {i}: {other:?}"),
        }
    }
}

/// A sweep of 24 heavy tops of one shared model, each released at its own tilt and spin:
/// at the closed form's turning times θ reaches `HeavyTopTheory`'s θ_max and then θ_min
/// (θ is stationary there, so the check does not hinge on the time; the largest errors
/// measured were 2.5e-13 and 5.5e-13 over nutations of 0.28 to 1.2 rad).
#[test]
fn an_ensemble_of_heavy_tops_nutates_between_the_closed_form_bounds() {
    let model = heavy_top(1.0, 0.5, 1.0).unwrap();
    let theory = HeavyTopTheory::new(1.0, 0.5, 1.0).unwrap();
    let results: EnsembleResults<[f64; 4], BoxError> = Ensemble::new(0..24).run(|i| {
        let y0 = start(i);
        let motion =
            HeavyTopMotion::from_angles(theory, &[y0[0], y0[1], y0[2]], &[y0[3], y0[4], y0[5]])?;
        let [t_max, _] = motion.turning_times().ok_or("the top nutates")?;
        let t_min = t_max + 0.5 * motion.nutation_period();
        let mut ode = Dop853::new(&model, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-14))?;
        ode.advance_to(t_max)?;
        let theta_at_max = ode.y()[1];
        ode.advance_to(t_min)?;
        Ok([
            theta_at_max,
            motion.theta_max(),
            ode.y()[1],
            motion.theta_min(),
        ])
    });
    assert_eq!(
        results.failures(),
        0,
        "{:?}",
        results.errors().collect::<Vec<_>>()
    );
    for (i, [at_max, theta_max, at_min, theta_min]) in results.outputs() {
        assert!(theta_max - theta_min > 1e-3, "run {i} nutates");
        assert_relative_eq!(*at_max, *theta_max, epsilon = 1e-10);
        assert_relative_eq!(*at_min, *theta_min, epsilon = 1e-10);
    }
}

/// The stepper form over RK4, DOP853 and the Taylor integrator: y′ = −k y with k = 1 + i/4
/// to t = 2 against e^(−2k); runs 2 and 7 have k = NaN and fail in their first step with
/// the ODE's error, the others keep their values.
#[test]
fn integrate_takes_any_stepper_to_the_end_time() {
    let rate = |i: usize| {
        if i == 2 || i == 7 {
            f64::NAN
        } else {
            1.0 + 0.25 * i as f64
        }
    };
    let decay = |i: usize| {
        let k = rate(i);
        FnSystem(move |_t: f64, y: &[f64; 1], d: &mut [f64; 1]| d[0] = -k * y[0])
    };
    let exact = |i: usize| (-2.0 * rate(i)).exp();
    let ensemble = Ensemble::new(0..10);
    let rk4 = ensemble.integrate(
        2.0,
        |i| Rk4::new(decay(i), 0.0, [1.0], FixedStepConfig::with_step(1e-3)),
        |_, s| s.y()[0],
    );
    let dop853 = ensemble.integrate(
        2.0,
        |i| Dop853::new(decay(i), 0.0, [1.0], AdaptiveConfig::with_tol(1e-12, 1e-14)),
        |_, s| s.y()[0],
    );
    // The Taylor integrator over an interpreted tape of y′ = −k y.
    let mut a = Arena::new();
    let (y, k) = (a.input("y"), a.parameter("k"));
    let ky = a.mul(k, y);
    let rhs = a.neg(ky);
    let tapes: Vec<Result<TaylorTape<1>, _>> = (0..10)
        .map(|i| TaylorTape::new(&a, [y], [rhs], None, &[("k", rate(i))], 20))
        .collect();
    let taylor = ensemble.integrate(
        2.0,
        |i| -> Result<_, BoxError> {
            let tape = tapes[i].as_ref().map_err(|e| e.to_string())?;
            Ok(Taylor::new(
                tape,
                0.0,
                [1.0],
                TaylorConfig::with_tol(1e-15, 1e-15),
            )?)
        },
        |_, s| s.y()[0],
    );
    for (name, results, tol) in [("RK4", &rk4, 1e-11), ("DOP853", &dop853, 1e-12)] {
        assert_eq!(results.failures(), 2, "{name}");
        for (i, r) in results.iter() {
            match r {
                Ok(y) => assert_relative_eq!(*y, exact(i), max_relative = tol),
                Err(EnsembleError::Run {
                    index,
                    source: OdeError::NonFiniteState { .. },
                }) => {
                    assert!(*index == 2 || *index == 7, "{name}: run {index}")
                }
                Err(e) => panic!("{name}: {e}"),
            }
        }
    }
    // The tape refuses a NaN parameter when it is built.
    assert_eq!(
        taylor
            .errors()
            .map(EnsembleError::index)
            .collect::<Vec<_>>(),
        [2, 7]
    );
    for (i, y) in taylor.outputs() {
        assert_relative_eq!(*y, exact(i), max_relative = 1e-13);
    }
}

/// Charted tops (not steppers) through the closure form: sleeping tops of spins 4.5 to 8.25
/// (above the threshold 4) stand exactly upright and turn as R(t) = Rz(ω3 t), the same bits
/// on 1, 2 and 3 threads.
#[test]
fn charted_tops_run_through_the_closure_form() {
    let run = |i: usize| -> Result<Matrix3<f64>, TopError> {
        let w = Vector3::new(0.0, 0.0, 4.5 + 0.25 * i as f64);
        let [zxz, zyx] = TopChart::both(&ReferenceTop);
        let mut top = ChartedTop::new(
            [&zxz, &zyx],
            0.0,
            &Matrix3::identity(),
            &w,
            ChartConfig::default(),
        )?;
        top.advance_to(5.0)?;
        Ok(top.rotation())
    };
    let results: Vec<EnsembleResults<Matrix3<f64>, TopError>> = pools()
        .iter()
        .map(|p| p.install(|| Ensemble::new(0..16).run(run)))
        .collect();
    for (i, r) in results[0].outputs() {
        let spin = 4.5 + 0.25 * i as f64;
        let truth = Rotation3::from_axis_angle(&Vector3::z_axis(), spin * 5.0);
        assert!((r - truth.matrix()).abs().max() < 1e-8, "run {i}");
    }
    assert_eq!(results[0].failures(), 0);
    for other in &results[1..] {
        assert_eq!(other, &results[0]);
    }
}

/// No runs is no error: empty results, the identity as the reduction, no progress reports;
/// a range given backwards is empty too.
#[test]
fn an_ensemble_of_no_runs_is_empty() {
    let calls = AtomicUsize::new(0);
    let report = |_: EnsembleProgress| {
        calls.fetch_add(1, Ordering::Relaxed);
    };
    let f = |i: usize| Ok::<usize, OdeError>(i);
    // A backwards range, built as a struct: the ensemble must take it as no runs.
    for runs in [5..5, Range { start: 7, end: 3 }] {
        let ensemble = Ensemble::new(runs.clone()).progress(&report);
        let results = ensemble.run(f);
        assert!(results.is_empty(), "{runs:?}");
        assert_eq!(results.runs().len(), 0);
        assert_eq!(ensemble.reduce(f, || 42, |a, _, _| a + 1, |a, b| a + b), 42);
    }
    assert_eq!(calls.load(Ordering::Relaxed), 0);
}

/// Progress is reported once per run, failed runs included, up to the total; the results
/// carry the range's own indices (a shard of a larger ensemble).
#[test]
fn progress_counts_every_run_and_a_shard_keeps_its_indices() {
    let (calls, highest) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let report = |p: EnsembleProgress| {
        assert_eq!(p.total, 100);
        calls.fetch_add(1, Ordering::Relaxed);
        highest.fetch_max(p.done, Ordering::Relaxed);
    };
    let results = Ensemble::new(1_000..1_100)
        .progress(&report)
        .run(|i| if i % 10 == 0 { Err(i) } else { Ok(2 * i) });
    assert_eq!(calls.load(Ordering::Relaxed), 100);
    assert_eq!(highest.load(Ordering::Relaxed), 100);
    assert_eq!(results.runs(), 1_000..1_100);
    assert_eq!(results.get(1_001), Some(&Ok(2_002)));
    assert_eq!(results.get(999), None);
    assert_eq!(results.get(1_100), None);
    let failed: Vec<usize> = results.errors().map(EnsembleError::index).collect();
    assert_eq!(failed, (1_000..1_100).step_by(10).collect::<Vec<_>>());
}

/// The textbook double pendulum in absolute angles θ₁, θ₂ from the downward vertical
/// (Δ = θ₁ − θ₂, D = 2m₁ + m₂ − m₂ cos 2Δ), the second formulation the mechanism runs are
/// checked against.
fn textbook_double_pendulum(m: [f64; 2], l: [f64; 2], g: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
    let ([m1, m2], [l1, l2], [t1, t2, w1, w2]) = (m, l, *y);
    let d = t1 - t2;
    let den = 2.0 * m1 + m2 - m2 * (2.0 * d).cos();
    dy[0] = w1;
    dy[1] = w2;
    dy[2] = (-g * (2.0 * m1 + m2) * t1.sin()
        - m2 * g * (t1 - 2.0 * t2).sin()
        - 2.0 * d.sin() * m2 * (w2 * w2 * l2 + w1 * w1 * l1 * d.cos()))
        / (l1 * den);
    dy[3] = 2.0
        * d.sin()
        * (w1 * w1 * l1 * (m1 + m2) + g * (m1 + m2) * t1.cos() + w2 * w2 * l2 * m2 * d.cos())
        / (l2 * den);
}

/// Mechanisms: one interpreted double pendulum shared by every thread (its right-hand side
/// goes through the thread's workspace for its run-time-long outputs), 24 releases from
/// angles up to ±1.2 rad integrated to t = 2 — the same bits on 1, 2 and 3 threads, and
/// within 1e-10 of the textbook equations integrated alike (1.1e-12 measured).
#[test]
fn an_ensemble_of_mechanisms_matches_the_textbook_pendulum() {
    let (m, l, g) = ([1.3, 0.7], [0.9, 0.6], 9.81);
    let mut a = Arena::new();
    let scene = crate::common::mechanism::double_pendulum(&mut a, None);
    let values = [
        ("m0", m[0]),
        ("m1", m[1]),
        ("l0", l[0]),
        ("l1", l[1]),
        ("g", g),
    ];
    let model = precess::mechanism::MechanismModel::new(
        &mut a,
        &scene,
        precess::mechanism::Route::Auto,
        &values,
    )
    .unwrap();
    let start = |i: usize| {
        let q0 = -1.2 + 0.1 * i as f64;
        let q1 = 0.6 - 0.05 * i as f64;
        [q0, q1, 0.0, 0.3]
    };
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let run = |i: usize| -> Result<[f64; 4], BoxError> {
        let mut ode = Dop853::new(model.system::<4>()?, 0.0, start(i), cfg)?;
        ode.advance_to(2.0)?;
        Ok(*ode.y())
    };
    let results: Vec<EnsembleResults<[f64; 4], BoxError>> = pools()
        .iter()
        .map(|p| p.install(|| Ensemble::new(0..24).run(run)))
        .collect();
    for (i, r) in results[0].iter() {
        let y = r.as_ref().unwrap();
        for other in &results[1..] {
            assert_eq!(
                bits(y),
                bits(other.get(i).unwrap().as_ref().unwrap()),
                "run {i}"
            );
        }
        // Absolute angles: θ₁ = q₀, θ₂ = q₀ + q₁.
        let [q0, q1, w0, w1] = start(i);
        let textbook = FnSystem(|_t: f64, y: &[f64; 4], dy: &mut [f64; 4]| {
            textbook_double_pendulum(m, l, g, y, dy)
        });
        let mut reference = Dop853::new(textbook, 0.0, [q0, q0 + q1, w0, w0 + w1], cfg).unwrap();
        reference.advance_to(2.0).unwrap();
        let [t1, t2, ..] = *reference.y();
        assert_relative_eq!(y[0], t1, epsilon = 1e-10);
        assert_relative_eq!(y[0] + y[1], t2, epsilon = 1e-10);
    }
}

/// The splittings through the stepper form: the GNI book's free body (Hairer, Lubich,
/// Wanner; I = (2, 1, ⅔), m(0) = (cos 1.1, 0, sin 1.1)) by the fourth- and sixth-order
/// splittings at steps 0.01 to 0.0025, every run's m(10) within 1e-8 of the published value.
#[test]
fn integrate_takes_the_splittings_too() {
    let m10 = Vector3::new(
        0.407_066_136_588_040_8,
        0.283_007_426_812_843_7,
        0.868_449_167_661_561_7,
    );
    let results = Ensemble::new(0..6).integrate(
        10.0,
        |i| {
            let order = if i % 2 == 0 {
                SplittingOrder::Four
            } else {
                SplittingOrder::Six
            };
            let split = FreeBodySplitting::new([2.0, 1.0, 2.0 / 3.0], order)?;
            let y0 = BodyMomentum {
                q: UnitQuaternion::identity(),
                m: Vector3::new(1.1f64.cos(), 0.0, 1.1f64.sin()),
            };
            let h = 0.01 / f64::from(1 << (i / 2));
            FixedStepper::new(split, 0.0, y0, FixedStepConfig::with_step(h))
        },
        |_, s| s.state().m,
    );
    assert_eq!(results.failures(), 0);
    for (i, m) in results.outputs() {
        assert!((m - m10).abs().max() < 1e-8, "run {i}: {m:?}");
    }
}

precess::taylor_system! {
    /// The pendulum ẍ = −k sin x, k a parameter.
    struct Pendulum { k: f64 }
    state [x, v];
    taylor = 24;
    d/dt x = v;
    d/dt v = -k * sin(x);
}

/// Run `i` of the lanes' ensemble, with a failure of every kind at fixed indices: a NaN
/// parameter (5), a panic (7), a start after the end (9), an error of the closure (11).
fn pendulum_run(i: usize) -> Result<Taylor<Pendulum, 2>, BoxError> {
    let k = if i == 5 {
        f64::NAN
    } else {
        1.0 + 0.1 * i as f64
    };
    assert!(i != 7, "run 7 refuses to start");
    if i == 11 {
        return Err("run 11 has no start".into());
    }
    let t0 = if i == 9 { 10.0 } else { 0.0 };
    let x0 = 0.2 + 0.1 * i as f64;
    Ok(Taylor::new(
        Pendulum { k },
        t0,
        [x0, 0.0],
        TaylorConfig::with_tol(1e-13, 1e-13),
    )?)
}

/// 23 pendulums (not a multiple of the lanes) in chunks of 4 and of 3 lanes on 1, 2 and 3
/// threads: the same outputs bit for bit and the same errors at the same indices as the
/// scalar ensemble; the energy v²/2 − k cos x of each run kept to 1e-12.
#[test]
fn lanes_give_the_scalar_ensembles_bits_on_any_number_of_threads() {
    let t_end = 6.0;
    let output = |_: usize, ode: &Taylor<Pendulum, 2>| (bits(ode.y()), ode.stats().steps);
    let scalar = Ensemble::new(0..23).integrate(t_end, pendulum_run, output);
    let scalar = format!("{scalar:?}");
    for pool in pools() {
        let four = pool.install(|| {
            Ensemble::new(0..23)
                .lanes::<4>()
                .integrate(t_end, pendulum_run, output)
        });
        assert_eq!(
            format!("{four:?}"),
            scalar,
            "4 lanes, {} threads",
            pool.current_num_threads()
        );
        let three = pool.install(|| {
            Ensemble::new(0..23)
                .lanes::<3>()
                .integrate(t_end, pendulum_run, output)
        });
        assert_eq!(
            format!("{three:?}"),
            scalar,
            "3 lanes, {} threads",
            pool.current_num_threads()
        );
    }
    let results = Ensemble::new(0..23).lanes::<4>().integrate(
        t_end,
        pendulum_run,
        |i, ode: &Taylor<Pendulum, 2>| {
            let k = 1.0 + 0.1 * i as f64;
            let energy = |x: f64, v: f64| 0.5 * v * v - k * x.cos();
            (energy(ode.y()[0], ode.y()[1]) - energy(0.2 + 0.1 * i as f64, 0.0)).abs()
        },
    );
    assert_eq!(results.outputs().count(), 19);
    for (i, drift) in results.outputs() {
        assert!(*drift < 1e-12, "run {i}: energy drifted by {drift:e}");
    }
    let failed: Vec<usize> = results.errors().map(EnsembleError::index).collect();
    assert_eq!(failed, [5, 7, 9, 11]);
    assert!(
        matches!(results.get(7), Some(Err(EnsembleError::Panicked { message, .. })) if message.contains("refuses"))
    );
    let chunks = Ensemble::new(3..3)
        .lanes::<4>()
        .integrate(t_end, pendulum_run, output);
    assert!(chunks.is_empty());
}
