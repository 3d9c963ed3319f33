//! Batch lanes (`precess::taylor::batch`): every lane bit for bit the scalar run of the same
//! trajectory, each lane against the torque-free body's closed form, lanes with their own
//! end times, parameters, step sizes and events, and lanes of mixed failure.

use precess::exact::FreeBodyExact;
use precess::ode::{Event, OdeError, Run, StopReason};
use precess::taylor::batch::{BatchTaylor, Lanes, TaylorLanes};
use precess::taylor::{OrderRule, Taylor, TaylorConfig, TaylorSystem};
use precess_testkit::systems::SpinningTop;
use proptest::prelude::*;

precess::taylor_system! {
    /// The torque-free body ṁ = m × I⁻¹m with its three constants as parameters:
    /// a = 1/I3 − 1/I2, b = 1/I1 − 1/I3, c = 1/I2 − 1/I1.
    struct Free { a: f64, b: f64, c: f64 }
    state [m1, m2, m3];
    taylor = 30;
    d/dt m1 = a * m2 * m3;
    d/dt m2 = b * m3 * m1;
    d/dt m3 = c * m1 * m2;
}

precess::taylor_system! {
    /// A forced pendulum with a quotient, a root and the time: every kind of recurrence
    /// the lanes emit (sine–cosine, quotient, square root, real power, time series).
    struct Mixed { k: f64, w: f64 }
    state [x, v];
    taylor = 30;
    d/dt x = v;
    d/dt v = -k * sin(x) + cos(w * t) / sqrt(1.0 + v * v) - 0.1 * (1.0 + x * x).powf(0.75) * v;
}

fn free(inertia: [f64; 3]) -> Free {
    let [i1, i2, i3] = inertia;
    Free {
        a: 1.0 / i3 - 1.0 / i2,
        b: 1.0 / i1 - 1.0 / i3,
        c: 1.0 / i2 - 1.0 / i1,
    }
}

const INERTIA: [f64; 3] = [3.0, 5.0, 9.0];

/// The scalar run of one lane: its end state, and its number of steps.
fn scalar<S: TaylorSystem<N>, const N: usize>(
    sys: S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    cfg: TaylorConfig,
) -> Result<([f64; N], u64), OdeError> {
    let mut ode = Taylor::new(sys, t0, y0, cfg)?;
    ode.advance_to(t_end)?;
    Ok((*ode.y(), ode.stats().steps))
}

fn bits<const N: usize>(y: &[f64; N]) -> [u64; N] {
    y.map(f64::to_bits)
}

#[test]
fn the_generated_lane_jets_are_the_scalar_jets_bit_for_bit() {
    // Four lanes of the mixed system at unrelated points: each lane's 31 coefficients
    // against a scalar call on that lane.
    let systems = [
        Mixed { k: 1.0, w: 0.3 },
        Mixed { k: 2.5, w: 1.7 },
        Mixed { k: 0.1, w: -0.9 },
        Mixed { k: 9.0, w: 4.0 },
    ];
    let t = [0.0, 1.25, -3.5, 17.0];
    let y = [[0.3, -1.0], [2.0, 0.5], [-1.1, 3.0], [0.0, 0.0]];
    let mut lanes = vec![[Lanes::<4>::splat(0.0); 2]; 31];
    let yl = [Lanes(y.map(|y| y[0])), Lanes(y.map(|y| y[1]))];
    let refs = [&systems[0], &systems[1], &systems[2], &systems[3]];
    Mixed::lane_coefficients_into(refs, &mut Default::default(), Lanes(t), &yl, 30, &mut lanes);
    for l in 0..4 {
        let mut c = vec![[0.0; 2]; 31];
        systems[l].coefficients(t[l], &y[l], 30, &mut c);
        for k in 0..=30 {
            let lane = [lanes[k][0].0[l], lanes[k][1].0[l]];
            assert_eq!(bits(&lane), bits(&c[k]), "lane {l}, order {k}");
        }
        assert!(c[30].iter().all(|v| v.is_finite() && *v != 0.0));
    }
}

#[test]
fn lanes_end_where_scalar_runs_end_bit_for_bit_each_at_its_own_time() {
    // Four bodies with their own moments, starts and end times: different step sizes and
    // numbers of steps in every lane.
    let inertias = [
        [3.0, 5.0, 9.0],
        [1.0, 2.0, 3.0],
        [2.0, 2.5, 7.0],
        [4.0, 6.0, 6.5],
    ];
    let y0 = [
        [0.0, 2.0, 0.01],
        [1.0, 0.2, -0.5],
        [0.3, -1.5, 2.0],
        [-2.0, 0.1, 0.7],
    ];
    let t_end = [200.0, 37.5, 123.25, 5.0];
    // Under either order rule (the minimum-work order takes other orders and steps).
    let jorba_zou = TaylorConfig::with_tol(1e-12, 1e-12);
    let minimum_work = TaylorConfig {
        order_rule: OrderRule::MinimumWork,
        ..jorba_zou
    };
    for cfg in [jorba_zou, minimum_work] {
        let mut batch = BatchTaylor::new(inertias.map(free), [0.0; 4], y0, cfg);
        let ends = batch.advance_to(t_end);
        let mut steps = Vec::new();
        for l in 0..4 {
            let end = ends[l].clone().unwrap();
            let (y, n) = scalar(free(inertias[l]), 0.0, y0[l], t_end[l], cfg).unwrap();
            assert_eq!(end.t, t_end[l]);
            assert!(!end.event);
            assert_eq!(bits(&end.y), bits(&y), "lane {l}");
            let lane = batch.lane(l).unwrap().unwrap();
            assert_eq!(lane.stats().steps, n, "lane {l}");
            steps.push(n);
        }
        // The lanes really diverged: their step counts differ.
        steps.sort_unstable();
        steps.dedup();
        assert_eq!(steps.len(), 4, "{steps:?}");
    }
}

#[test]
fn each_lane_meets_the_closed_form_of_the_torque_free_body() {
    // Eight lanes of (3, 5, 9) near the unstable middle axis, to T = 200 at tol 1e-13:
    // each lane against the Jacobi-function solution.
    let y0: [[f64; 3]; 8] = core::array::from_fn(|l| [0.0, 2.0, 0.01 * (1.0 + l as f64 / 8.0)]);
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let mut batch = BatchTaylor::new([(); 8].map(|()| free(INERTIA)), [0.0; 8], y0, cfg);
    let ends = batch.advance_to([200.0; 8]);
    let mut worst = 0.0f64;
    for l in 0..8 {
        let exact = FreeBodyExact::new(INERTIA, y0[l])
            .unwrap()
            .m_at(200.0)
            .unwrap();
        let y = ends[l].clone().unwrap().y;
        for i in 0..3 {
            worst = worst.max((y[i] - exact[i]).abs());
        }
    }
    // |m| = 2 and the run passes the separatrix's neighbourhood a few times, which
    // amplifies a step's error some 10²-fold: 8.3e-12 measured.
    assert!(worst < 1e-10, "largest error {worst:e}");
}

#[test]
fn a_lane_with_nan_parameters_or_state_fails_alone() {
    let y0 = [
        [0.0, 2.0, 0.01],
        [f64::NAN, 1.0, 0.0],
        [1.0, 0.2, -0.5],
        [0.3, -1.5, 2.0],
    ];
    let mut systems = [free(INERTIA), free(INERTIA), free(INERTIA), free(INERTIA)];
    systems[2].b = f64::NAN;
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut batch = BatchTaylor::new(systems, [0.0; 4], y0, cfg);
    let ends = batch.advance_to([50.0; 4]);
    assert!(
        matches!(ends[1], Err(OdeError::NonFiniteInitialState { .. })),
        "{:?}",
        ends[1]
    );
    assert!(
        matches!(ends[2], Err(OdeError::NonFiniteState { t }) if t == 0.0),
        "{:?}",
        ends[2]
    );
    for l in [0, 3] {
        let (y, _) = scalar(free(INERTIA), 0.0, y0[l], 50.0, cfg).unwrap();
        assert_eq!(bits(&ends[l].clone().unwrap().y), bits(&y), "lane {l}");
    }
    // The failed lanes stay out; the others go on.
    let again = batch.advance_to([60.0; 4]);
    assert!(again[1].is_err() && again[2].is_err());
    assert_eq!(again[0].clone().unwrap().t, 60.0);
    assert!(batch.lane(2).unwrap().is_err());
}

#[test]
fn a_lane_whose_stop_is_behind_it_fails_alone() {
    let cfg = TaylorConfig::with_tol(1e-10, 1e-10);
    let y0 = [[0.0, 2.0, 0.01], [1.0, 0.2, -0.5]];
    let mut batch = BatchTaylor::new([free(INERTIA), free(INERTIA)], [0.0, 5.0], y0, cfg);
    let ends = batch.advance_to([3.0, 2.0]);
    assert!(
        matches!(ends[1], Err(OdeError::StopBeforeCurrent { .. })),
        "{:?}",
        ends[1]
    );
    assert_eq!(ends[0].clone().unwrap().t, 3.0);
}

#[test]
fn each_lane_stops_at_its_own_event_as_a_scalar_run_does() {
    // The event m1 = threshold(l), a different one in every lane, from four starts; the
    // scalar reference locates it with `Run`'s terminal event on the same steps.
    let y0 = [
        [0.0, 2.0, 0.01],
        [1.0, 0.2, -0.5],
        [0.3, -1.5, 2.0],
        [-2.0, 0.1, 0.7],
    ];
    let threshold = [0.5, -0.1, 0.2, 10.0];
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let mut batch = BatchTaylor::new([(); 4].map(|()| free(INERTIA)), [0.0; 4], y0, cfg);
    let ends = batch.advance_until([100.0; 4], |l, _, y| y[0] - threshold[l]);
    for l in 0..4 {
        let end = ends[l].clone().unwrap();
        let mut ode = Taylor::new(free(INERTIA), 0.0, y0[l], cfg).unwrap();
        let g = move |_t: f64, y: &[f64; 3]| y[0] - threshold[l];
        let out = Run::new(&mut ode, 100.0)
            .sample_none()
            .event(Event::new("m1").terminal(), g)
            .integrate()
            .unwrap();
        if out.stop == StopReason::End {
            // Lane 3: |m1| never reaches 10 (|m| < 2.2).
            assert!(!end.event && end.t == 100.0, "lane {l}: {end:?}");
            assert_eq!(bits(&end.y), bits(&out.state));
            continue;
        }
        assert!(end.event, "lane {l}");
        assert!(
            (end.t - out.t).abs() < 1e-12,
            "lane {l}: {} against {}",
            end.t,
            out.t
        );
        assert!(
            (end.y[0] - threshold[l]).abs() < 1e-12,
            "lane {l}: {:?}",
            end.y
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Any four starts, moments and end times: every lane is the scalar run, bit for bit.
    #[test]
    fn any_lanes_are_the_scalar_runs(
        m in prop::array::uniform4(prop::array::uniform3(-3.0f64..3.0)),
        inertia in prop::array::uniform4(prop::array::uniform3(0.5f64..10.0)),
        t_end in prop::array::uniform4(0.0f64..20.0),
        tol in prop::sample::select(vec![1e-6, 1e-10, 1e-14]),
    ) {
        let cfg = TaylorConfig::with_tol(tol, tol);
        let mut batch = BatchTaylor::new(inertia.map(free), [0.0; 4], m, cfg);
        let ends = batch.advance_to(t_end);
        for l in 0..4 {
            let want = scalar(free(inertia[l]), 0.0, m[l], t_end[l], cfg).map(|(y, _)| bits(&y));
            prop_assert_eq!(ends[l].clone().map(|e| bits(&e.y)), want, "lane {}", l);
        }
    }
}

/// The heavy symmetric top with every mass property a field, its Lagrangian state
/// [φ, θ, ψ, φ̇, θ̇, ψ̇] (ZXZ) stepped by the recurrences `#[top(taylor = K)]` generates.
#[allow(non_snake_case)]
#[derive(precess::prelude::RigidBody)]
#[rigid(
    body(mass = M, at = [0.0, 0.0, l], inertia = diag(I_1, I_1, I_3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, taylor = 16)]
struct FieldTop {
    I_1: f64,
    I_3: f64,
    M: f64,
    g: f64,
    l: f64,
}

fn field_top(l: usize) -> FieldTop {
    let x = l as f64;
    FieldTop {
        I_1: 1.0 + 0.25 * x,
        I_3: 0.5 + 0.1 * x,
        M: 1.0 + 0.5 * x,
        g: 9.81,
        l: 0.2 + 0.05 * x,
    }
}

#[test]
fn a_derived_tops_lanes_are_its_scalar_runs_bit_for_bit() {
    // Four tops with their own mass properties (the derive's symbols differ per lane) from
    // their own tilts and spins: each lane's jet against the scalar jet, then each lane's end
    // against the scalar run's, and ω₃ = ψ̇ + φ̇ cos θ, an integral of the symmetric top,
    // against its start.
    let y0: [[f64; 6]; 4] =
        core::array::from_fn(|l| [0.1, 0.3 + 0.2 * l as f64, 0.0, 0.4, 0.0, 8.0 - l as f64]);
    let systems: [FieldTop; 4] = core::array::from_fn(field_top);
    let mut jets = vec![[Lanes::<4>::splat(0.0); 6]; 17];
    let yl: [Lanes<4>; 6] = core::array::from_fn(|i| Lanes(y0.map(|y| y[i])));
    let refs = [&systems[0], &systems[1], &systems[2], &systems[3]];
    FieldTop::lane_coefficients_into(
        refs,
        &mut Default::default(),
        Lanes([0.0; 4]),
        &yl,
        16,
        &mut jets,
    );
    for l in 0..4 {
        let mut c = vec![[0.0; 6]; 17];
        systems[l].coefficients(0.0, &y0[l], 16, &mut c);
        for k in 0..=16 {
            let lane: [f64; 6] = core::array::from_fn(|i| jets[k][i].0[l]);
            assert_eq!(bits(&lane), bits(&c[k]), "lane {l}, order {k}");
        }
    }
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let t_end = [3.0, 2.5, 4.0, 1.0];
    let mut batch = BatchTaylor::new(systems, [0.0; 4], y0, cfg);
    let ends = batch.advance_to(t_end);
    let omega3 = |y: &[f64; 6]| y[5] + y[3] * y[1].cos();
    for l in 0..4 {
        let end = ends[l].clone().unwrap();
        let (y, n) = scalar(field_top(l), 0.0, y0[l], t_end[l], cfg).unwrap();
        assert_eq!(bits(&end.y), bits(&y), "lane {l}");
        assert_eq!(batch.lane(l).unwrap().unwrap().stats().steps, n, "lane {l}");
        let drift = (omega3(&end.y) - omega3(&y0[l])).abs();
        assert!(drift < 1e-10, "lane {l}: ω₃ drifted by {drift:e}");
    }
}

#[test]
fn a_derived_tops_lane_with_a_nan_field_is_refused_before_its_first_step() {
    // The scene's own check (`check_parameters`, what `Taylor::new` calls) refuses the lane,
    // naming the field's quantity, where a `taylor_system!` lane only fails at its first step
    // (above); the other lanes end as their scalar runs do.
    let mut systems: [FieldTop; 3] = core::array::from_fn(field_top);
    systems[1].M = f64::NAN;
    let y0 = [[0.1, 0.4, 0.0, 0.4, 0.0, 8.0]; 3];
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let mut batch = BatchTaylor::new(systems, [0.0; 3], y0, cfg);
    let ends = batch.advance_to([1.0; 3]);
    assert!(
        matches!(&ends[1], Err(OdeError::InvalidSystemParameter { quantity, value, .. })
            if quantity.contains("mass") && value.is_nan()),
        "{:?}",
        ends[1]
    );
    for l in [0, 2] {
        let (y, _) = scalar(field_top(l), 0.0, y0[l], 1.0, cfg).unwrap();
        assert_eq!(bits(&ends[l].clone().unwrap().y), bits(&y), "lane {l}");
    }
}

/// A derived top released at rest in lanes of 8 and 16, the widths whose jets sum by kernel
/// calls on the default target, against its scalar runs.
fn a_top_from_rest_in_lanes<const L: usize>() {
    let cfg = TaylorConfig::with_tol(1e-10, 1e-10);
    let y0 = |l: usize| [0.0, 20f64.to_radians(), 0.1 * l as f64, 0.0, 0.0, 150.0];
    let mut batch = BatchTaylor::new(
        core::array::from_fn::<_, L, _>(|_| SpinningTop),
        [0.0; L],
        core::array::from_fn(y0),
        cfg,
    );
    let ends = batch.advance_to([0.5; L]);
    for (l, end) in ends.iter().enumerate() {
        let end = end.clone().unwrap();
        let (y, n) = scalar(SpinningTop, 0.0, y0(l), 0.5, cfg).unwrap();
        assert_eq!(bits(&end.y), bits(&y), "{L} lanes, lane {l}");
        assert_eq!(
            batch.lane(l).unwrap().unwrap().stats().steps,
            n,
            "{L} lanes, lane {l}"
        );
    }
}

/// Released at rest (θ̇ = φ̇ = 0), the top's jet has rows whose largest weighted entry is not
/// the first: the lanes' weighted norm, compiled for AVX-512 by pulp's dispatch, returned
/// 6.8e18 for a row whose largest entry was 1.4e20 while `f64::max` did the comparing, the
/// first step's radius came out 20 times too small, and every lane of 8 and of 16 ended off
/// its scalar run's bits. That was in optimised builds without overflow checks (the benches,
/// a user's release build) on a processor with AVX-512; the test profile's overflow checks
/// kept LLVM from that form, so under `cargo test` this passed before the fix too, and it
/// guards the contract where `cargo test --release` runs it.
#[test]
fn a_derived_top_from_rest_in_lanes_of_8_and_16_ends_on_its_scalar_runs_bits() {
    a_top_from_rest_in_lanes::<8>();
    a_top_from_rest_in_lanes::<16>();
}
