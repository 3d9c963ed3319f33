//! Every root of an event function inside a step, not only a change of sign between the
//! step's ends: g = sin(50 t) over steps that each hold up to 23 of its roots, against the
//! roots kπ/50 in double-double; two roots 0.02 apart inside one step of a smooth system,
//! against arccos; a terminal event stopping at the first root of a step; a root exactly at
//! a step's end reported once; and random sums of sines and polynomials with known roots,
//! against a brute-force scan and the roots themselves.

use crate::common::dips::{
    brute_roots, local_minimum, root_beside, sum_of_sines, sum_of_sines_slope,
};
use precess_core::exact::Dd;
use precess_core::ode::{
    AdaptiveConfig, Direction, Dop853, Dopri5, Event, FixedStepConfig, FnSystem, Rk4, Run, Stepper,
    StopReason, Vern9,
};
use precess_core::taylor::{Taylor, TaylorConfig};
use precess_testkit::systems::Oscillator;
use proptest::prelude::*;
use std::f64::consts::PI;

fn oscillator() -> FnSystem<impl Fn(f64, &[f64; 2], &mut [f64; 2])> {
    FnSystem(|_t: f64, y: &[f64; 2], d: &mut [f64; 2]| *d = [y[1], -y[0]])
}

/// A run to a given end time, returning what it found.
type Runner = Box<dyn FnMut(f64) -> Found>;

/// The steppers under test on the oscillator from (1, 0) at t = 0, by name.
fn steppers(tol: f64) -> Vec<(&'static str, Runner)> {
    let y0 = [1.0, 0.0];
    let cfg = AdaptiveConfig::with_tol(tol, tol);
    vec![
        (
            "taylor",
            Box::new(move |t_end| {
                let cfg = TaylorConfig::with_tol(tol, tol);
                roots(Taylor::new(Oscillator, 0.0, y0, cfg).unwrap(), t_end)
            }),
        ),
        (
            "dop853",
            Box::new(move |t_end| roots(Dop853::new(oscillator(), 0.0, y0, cfg).unwrap(), t_end)),
        ),
        (
            "dopri5",
            Box::new(move |t_end| roots(Dopri5::new(oscillator(), 0.0, y0, cfg).unwrap(), t_end)),
        ),
        (
            "vern9",
            Box::new(move |t_end| roots(Vern9::new(oscillator(), 0.0, y0, cfg).unwrap(), t_end)),
        ),
    ]
}

/// The hits of one run: (time, direction), and the steps taken.
struct Found {
    hits: Vec<(f64, Direction)>,
    steps: u64,
}

/// The crossings of sin(50 t) up to `t_end`.
fn roots<S: Stepper<State = [f64; 2]>>(mut s: S, t_end: f64) -> Found {
    let out = Run::new(&mut s, t_end)
        .sample_none()
        .event(Event::new("sin 50t"), |t, _y| (50.0 * t).sin())
        .integrate()
        .unwrap();
    Found {
        hits: out.events.iter().map(|h| (h.t, h.direction)).collect(),
        steps: out.stats.steps,
    }
}

/// kπ/50 rounded from double-double.
fn root_k(k: usize) -> f64 {
    let pi = Dd {
        hi: PI,
        lo: 1.224_646_799_147_353_2e-16,
    };
    (pi * Dd::from_f64(k as f64)).div_f64(50.0).to_f64()
}

/// |a − b| in units in the last place of b.
fn ulps(a: f64, b: f64) -> f64 {
    (a - b).abs() / (b.abs().next_up() - b.abs())
}

#[test]
fn every_zero_of_a_fast_sine_is_found_by_every_integrator() {
    // sin(50 t) on [0, 20] has 318 roots kπ/50 (20·50/π = 318.3); the start, a root, opens
    // no crossing. Before the scan, Taylor (14 steps) found 14 and DOP853 82.
    for (name, mut run) in steppers(1e-12) {
        let found = run(20.0);
        assert_eq!(found.hits.len(), 318, "{name}: {} steps", found.steps);
        let mut worst: f64 = 0.0;
        for (k, &(t, dir)) in found.hits.iter().enumerate() {
            worst = worst.max(ulps(t, root_k(k + 1)));
            // sin(50 t) falls through its odd roots and rises through its even ones.
            let expected = if k % 2 == 0 {
                Direction::Falling
            } else {
                Direction::Rising
            };
            assert_eq!(dir, expected, "{name}: root {}", k + 1);
        }
        eprintln!("{name}: {} steps, worst {worst} ulp", found.steps);
        // g's own rounding (50 t rounded: half an ulp of t) and the bracket's last ulp.
        assert!(worst <= 2.0, "{name}: {worst} ulp");
    }
}

/// cos t = cos δ near t = 2π: two roots 2δ apart around the maximum of cos.
fn dip(delta: f64) -> impl Fn(f64, &[f64; 2]) -> f64 {
    move |_t, y| y[0] - delta.cos()
}

#[test]
fn two_roots_close_together_inside_one_step_are_both_found() {
    // x = cos t; g = x − cos δ is positive at both ends of the step holding 2π ± δ.
    let delta = 0.01;
    let t_end = 7.0;
    let exact = [delta, 2.0 * PI - delta, 2.0 * PI + delta];
    let dirs = [Direction::Falling, Direction::Rising, Direction::Falling];
    let check = |hits: Vec<(f64, Direction)>, name: &str, steps: u64| {
        assert_eq!(hits.len(), 3, "{name} ({steps} steps): {hits:?}");
        for ((t, dir), (e, d)) in hits.iter().zip(exact.iter().zip(dirs)) {
            // |g′| = sin δ ≈ 0.01 at these roots: an error ε of x is ε/0.01 in t.
            assert!((t - e).abs() < 1e-10, "{name}: {t} against {e}");
            assert_eq!(*dir, d, "{name}");
        }
    };
    let y0 = [1.0, 0.0];
    let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
    let mut taylor = Taylor::new(Oscillator, 0.0, y0, cfg).unwrap();
    let out = Run::new(&mut taylor, t_end)
        .event(Event::new("dip"), dip(delta))
        .integrate()
        .unwrap();
    // The step that holds 2π holds both roots.
    let ends = out.trajectory.times().to_vec();
    assert!(ends.windows(2).any(|w| w[0] < exact[1] && w[1] > exact[2]));
    let hits = out.events.iter().map(|h| (h.t, h.direction)).collect();
    check(hits, "taylor", out.stats.steps);

    let cfg = AdaptiveConfig::with_tol(1e-14, 1e-14);
    let mut dop = Dop853::new(oscillator(), 0.0, y0, cfg).unwrap();
    let out = Run::new(&mut dop, t_end)
        .sample_none()
        .event(Event::new("dip"), dip(delta))
        .integrate()
        .unwrap();
    let hits = out.events.iter().map(|h| (h.t, h.direction)).collect();
    check(hits, "dop853", out.stats.steps);
}

#[test]
fn a_terminal_event_stops_at_the_first_root_inside_a_step() {
    // From t = 3 the step holding 2π holds 2π − δ (rising) and 2π + δ (falling), and g has
    // the same sign at its ends: the run stops at the first.
    let delta = 0.01;
    let y0 = [3f64.cos(), -3f64.sin()];
    let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
    let mut ode = Taylor::new(Oscillator, 3.0, y0, cfg).unwrap();
    let out = Run::new(&mut ode, 8.0)
        .event(Event::new("dip").terminal(), dip(delta))
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::Event(0));
    assert_eq!(out.events.len(), 1);
    assert!((out.t - (2.0 * PI - delta)).abs() < 1e-10, "{}", out.t);
    assert_eq!(out.events[0].direction, Direction::Rising);
    assert_eq!(ode.t(), out.t);

    // With g = sin(50 t), Taylor's first step holds 22 roots and g changes sign between its
    // ends: the run stops at the first, π/50, not at the root the ends bracket.
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let out = Run::new(&mut ode, 20.0)
        .event(Event::new("sin").terminal(), |t, _y| (50.0 * t).sin())
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::Event(0));
    assert!(ulps(out.t, root_k(1)) <= 2.0, "{}", out.t);
    assert_eq!(out.events[0].direction, Direction::Falling);
}

#[test]
fn step_ends_only_compares_the_ends_and_nothing_else() {
    // The opt-out: g at the start and once per step, and the pair inside one step is
    // missed as documented; the first root, a change of sign across its step, is found.
    let delta = 0.01;
    let calls = std::cell::Cell::new(0u32);
    let g = dip(delta);
    let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let out = Run::new(&mut ode, 7.0)
        .sample_none()
        .event(Event::new("dip").step_ends_only(), |t, y| {
            calls.set(calls.get() + 1);
            g(t, y)
        })
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 1);
    assert!((out.events[0].t - delta).abs() < 1e-10);
    // The start, the step ends, and the located root's evaluations (a few tens at most).
    let steps = u32::try_from(out.stats.steps).unwrap();
    assert!(
        calls.get() > steps && calls.get() <= 1 + steps + 40,
        "{}",
        calls.get()
    );
}

#[test]
fn a_root_exactly_at_a_step_end_is_reported_once() {
    // RK4 steps of 0.25 land on t = 1 exactly, where g = t − 1 is 0; then g = (t − 1)(t − 1.6)
    // with a second root inside the step [1.5, 1.75].
    let mut rk = Rk4::new(
        oscillator(),
        0.0,
        [1.0, 0.0],
        FixedStepConfig::with_step(0.25),
    )
    .unwrap();
    let out = Run::new(&mut rk, 3.0)
        .event(Event::new("linear"), |t, _y| t - 1.0)
        .event(Event::new("quadratic"), |t, _y| (t - 1.0) * (t - 1.6))
        .integrate()
        .unwrap();
    assert!(out.trajectory.times().contains(&1.0));
    let linear: Vec<_> = out.hits(0).map(|h| (h.t, h.direction)).collect();
    assert_eq!(linear, [(1.0, Direction::Rising)]);
    let quadratic: Vec<_> = out.hits(1).map(|h| (h.t, h.direction)).collect();
    assert_eq!(quadratic.len(), 2, "{quadratic:?}");
    assert_eq!(quadratic[0], (1.0, Direction::Falling));
    assert!((quadratic[1].0 - 1.6).abs() <= 4.0 * f64::EPSILON);
    assert_eq!(quadratic[1].1, Direction::Rising);
}

/// The event times of `g` (a function of t alone) on [0, t_end] with Taylor at 1e-12 and
/// DOP853 at 1e-12 on the oscillator.
fn found_by_both(g: impl Fn(f64) -> f64 + Copy, t_end: f64) -> [Vec<f64>; 2] {
    let y0 = [1.0, 0.0];
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut taylor = Taylor::new(Oscillator, 0.0, y0, cfg).unwrap();
    let a = Run::new(&mut taylor, t_end)
        .sample_none()
        .event(Event::new("g"), move |t, _y| g(t))
        .integrate()
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut dop = Dop853::new(oscillator(), 0.0, y0, cfg).unwrap();
    let b = Run::new(&mut dop, t_end)
        .sample_none()
        .event(Event::new("g"), move |t, _y| g(t))
        .integrate()
        .unwrap();
    [a, b].map(|o| o.events.iter().map(|h| h.t).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Sums of three sines up to 30 rad/s over [0, 10]: every root the brute-force scan
    /// (10⁵ points) finds whose neighbours are more than 1e-3 away and between which |g|
    /// exceeds 1e-6 of Σ|A| is found by both integrators, within 1e-9.
    #[test]
    fn every_separated_root_of_a_sum_of_sines_is_found(
        amps in prop::array::uniform3(0.1f64..1.0),
        omegas in prop::array::uniform3(0.5f64..30.0),
        phases in prop::array::uniform3(0.0f64..6.3),
    ) {
        let g = move |t: f64| {
            (0..3).map(|i| amps[i] * (omegas[i] * t + phases[i]).sin()).sum::<f64>()
        };
        let t_end = 10.0;
        let reference = brute_roots(&g, t_end, 100_000);
        let scale: f64 = amps.iter().sum();
        for found in found_by_both(g, t_end) {
            for (i, &r) in reference.iter().enumerate() {
                let before = if i == 0 { 0.0 } else { reference[i - 1] };
                let after = reference.get(i + 1).copied().unwrap_or(t_end);
                let clear = |s: f64| (r - s).abs() > 1e-3 && g(0.5 * (r + s)).abs() > 1e-6 * scale;
                if !(clear(before) && clear(after)) {
                    continue;
                }
                let near = found.iter().any(|t| (t - r).abs() < 1e-9);
                prop_assert!(near, "root {r} missed; found {} of {}", found.len(), reference.len());
            }
        }
    }

    /// Polynomials Π (t − r_i) with two to six roots in [0.2, 9.8], neighbours 1e-3 to 3
    /// apart: every root found by both integrators, within 1e-9, and no other.
    #[test]
    fn every_root_of_a_polynomial_is_found(
        first in 0.2f64..1.0,
        gaps in prop::collection::vec(1e-3f64..3.0, 1..6),
    ) {
        let mut roots = vec![first];
        for gap in &gaps {
            let next = roots[roots.len() - 1] + gap;
            if next < 9.8 {
                roots.push(next);
            }
        }
        let r = roots.clone();
        let g = move |t: f64| r.iter().map(|ri| t - ri).product::<f64>();
        let g_ref = &g;
        for found in found_by_both(g_ref, 10.0) {
            prop_assert_eq!(found.len(), roots.len(), "{:?} against {:?}", found, roots);
            for (t, r) in found.iter().zip(&roots) {
                prop_assert!((t - r).abs() < 1e-9, "{} against {}", t, r);
            }
        }
    }
}

#[test]
fn a_shallow_dip_between_two_close_roots_is_found() {
    // The case the sum-of-sines property test met: roots 7.19690… and 7.21857…, 0.0217
    // apart, with g ≈ −0.026 between them against Σ|A| ≈ 2.64. Taylor's step over the pair
    // (0.8 long) was halved, and on the half [7.08, 7.48] five points do not resolve g (ω up
    // to 28 rad/s): the degree-4 interpolant's error estimate, 0.049, was trusted and the
    // half passed over as rootless (Taylor found 72 roots; DOP853's shorter step resolved
    // g). All 74 roots on [0, 10], the 10⁵-point scan's, are asked for, the closest two
    // 0.0066 apart.
    let g = sum_of_sines(
        [
            0.965_601_480_233_750_6,
            0.779_264_346_203_232_5,
            0.891_077_081_997_368_9,
        ],
        [
            23.735_212_789_222_38,
            7.327_238_479_584_937,
            28.375_820_170_867_45,
        ],
        [
            1.744_331_903_838_407,
            4.587_526_927_167_540_5,
            2.110_934_727_802_847,
        ],
    );
    let reference = brute_roots(&g, 10.0, 100_000);
    assert_eq!(reference.len(), 74);
    assert!(reference.iter().any(|r| (r - 7.196_9).abs() < 1e-4));
    assert!(reference.iter().any(|r| (r - 7.218_6).abs() < 1e-4));
    for (name, found) in ["taylor", "dop853"].into_iter().zip(found_by_both(g, 10.0)) {
        assert_eq!(found.len(), reference.len(), "{name}: {found:?}");
        for (t, r) in found.iter().zip(&reference) {
            assert!((t - r).abs() < 1e-9, "{name}: {t} against {r}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// A planted pair: g = S − S(t_m) − δ with S a sum of three sines up to 30 rad/s and
    /// t_m a local minimum of S, so that g dips to −δ (10⁻³ to 3·10⁻² of Σ|A|) between two
    /// roots a few 1e-3 to a few 1e-2 apart, wherever the integrators' steps fall. Both
    /// roots, from bisection on g, are found by both integrators within 1e-9.
    #[test]
    fn a_close_pair_with_a_shallow_dip_is_found(
        amps in prop::array::uniform3(0.1f64..1.0),
        omegas in prop::array::uniform3(0.5f64..30.0),
        phases in prop::array::uniform3(0.0f64..6.3),
        t0 in 1.0f64..9.0,
        depth in 1e-3f64..3e-2,
    ) {
        let s = sum_of_sines(amps, omegas, phases);
        let ds = sum_of_sines_slope(amps, omegas, phases);
        let t_m = local_minimum(ds, t0);
        let delta = depth * amps.iter().sum::<f64>();
        let s_m = s(t_m);
        let g = move |t: f64| s(t) - s_m - delta;
        let pair = [root_beside(g, t_m, -1.0), root_beside(g, t_m, 1.0)];
        // S may stay below S(t_m) + δ for long on one side: no pair to plant there.
        prop_assume!(pair[0].is_some_and(|r| r > 0.1) && pair[1].is_some_and(|r| r < 9.9));
        let pair = pair.map(|r| r.unwrap_or(f64::NAN));
        for found in found_by_both(g, 10.0) {
            for r in pair {
                let near = found.iter().any(|t| (t - r).abs() < 1e-9);
                prop_assert!(near, "root {} of the pair {:?} (t_m {}) missed", r, pair, t_m);
            }
        }
    }
}

/// A case the property test above found: a dip of 1e-3 Σ|A| between two roots 7.4 ms
/// apart, inside the beat of two close frequencies (26.0 and 27.1 rad/s). DOP853's scan
/// found both roots; the Taylor integrator's, over a step 0.8 long, found neither: on five
/// points the aliased g had last coefficients 6.9e-4 of max |g| by chance, and the step
/// passed as rootless. The scan now judges a piece only once points its interpolant did not
/// see confirm it (`ode::scan`).
#[test]
fn taylor_finds_a_shallow_pair_in_a_beat() {
    let amps = [0.9521940533276592, 0.8342935472331764, 0.5762471339241876];
    let omegas = [6.000115648719028, 27.08034854307633, 26.038471104595125];
    let phases = [5.152946613068597, 1.2810683954004747, 6.260217977937406];
    let s = sum_of_sines(amps, omegas, phases);
    let t_m = 7.334700208708147;
    let delta = 0.001 * amps.iter().sum::<f64>();
    let s_m = s(t_m);
    let g = move |t: f64| s(t) - s_m - delta;
    let pair = [7.330994629666139, 7.3383906504342455];
    for found in found_by_both(g, 10.0) {
        for r in pair {
            assert!(
                found.iter().any(|t| (t - r).abs() < 1e-9),
                "root {r} missed"
            );
        }
    }
}
