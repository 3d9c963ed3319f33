//! Events on Taylor steps (`Run::taylor_event`): g an expression over the state, expanded
//! with each step and its polynomial's roots isolated. Against independent values: the
//! sines a system of three oscillators carries (their roots by bisection on the closed
//! form), a hidden dip that the Chebyshev scan passes over (roots by bisection on the
//! polynomial written out), arccos for a hand-written system, kπ/50 for a g of the time.

use crate::common::dips::{
    brute_roots, local_minimum, root_beside, sum_of_sines, sum_of_sines_slope,
};
use precess::ode::{Direction, Event, Run, StopReason};
use precess::sym::{Arena, ExprId};
use precess::taylor::{Taylor, TaylorConfig, TaylorEvent, TaylorTape};
use proptest::prelude::*;

/// Three oscillators carrying xᵢ = sin(ωᵢ t + φᵢ) as (xᵢ, vᵢ), xᵢ′ = ωᵢ vᵢ, vᵢ′ = −ωᵢ xᵢ,
/// from t = 0, and the event g = Σ Aᵢ xᵢ − c on their state.
struct Sines {
    system: TaylorTape<6>,
    event: TaylorEvent<6>,
    y0: [f64; 6],
}

fn sines(amps: [f64; 3], omegas: [f64; 3], phases: [f64; 3], c: f64) -> Sines {
    let mut a = Arena::new();
    let state: [ExprId; 6] = ["x0", "v0", "x1", "v1", "x2", "v2"].map(|n| a.coordinate(n));
    let w = ["w0", "w1", "w2"].map(|n| a.parameter(n));
    let amp = ["a0", "a1", "a2"].map(|n| a.parameter(n));
    let level = a.parameter("c");
    let mut rhs = state;
    for i in 0..3 {
        rhs[2 * i] = a.mul(w[i], state[2 * i + 1]);
        let wx = a.mul(w[i], state[2 * i]);
        rhs[2 * i + 1] = a.neg(wx);
    }
    let terms: Vec<ExprId> = (0..3).map(|i| a.mul(amp[i], state[2 * i])).collect();
    let sum = a.sum(&terms);
    let g = a.sub(sum, level);
    let values = [
        ("w0", omegas[0]),
        ("w1", omegas[1]),
        ("w2", omegas[2]),
        ("a0", amps[0]),
        ("a1", amps[1]),
        ("a2", amps[2]),
        ("c", c),
    ];
    let system = TaylorTape::new(&a, state, rhs, None, &values, 30).unwrap();
    let event = TaylorEvent::new(&a, state, None, g, &values).unwrap();
    let y0 = [0, 1, 2].map(|i| [phases[i].sin(), phases[i].cos()]);
    Sines {
        system,
        event,
        y0: [y0[0][0], y0[0][1], y0[1][0], y0[1][1], y0[2][0], y0[2][1]],
    }
}

/// The hits of the expanded event on [0, t_end] at tolerance `tol`: (t, direction).
fn isolated(s: &Sines, tol: f64, t_end: f64) -> Vec<(f64, Direction)> {
    let cfg = TaylorConfig::with_tol(tol, tol);
    let mut ode = Taylor::new(&s.system, 0.0, s.y0, cfg).unwrap();
    let out = Run::new(&mut ode, t_end)
        .sample_none()
        .taylor_event(Event::new("g"), &s.event)
        .integrate()
        .unwrap();
    out.events.iter().map(|h| (h.t, h.direction)).collect()
}

/// The case the sum-of-sines property test of `ode::event_roots` found: a dip of 1e-3 Σ|A|
/// between two roots 7.4 ms apart, in the beat of 26.0 and 27.1 rad/s.
const BEAT: [[f64; 3]; 3] = [
    [0.9521940533276592, 0.8342935472331764, 0.5762471339241876],
    [6.000115648719028, 27.08034854307633, 26.038471104595125],
    [5.152946613068597, 1.2810683954004747, 6.260217977937406],
];

#[test]
fn the_shallow_pair_in_a_beat_is_isolated_with_every_other_root() {
    let [amps, omegas, phases] = BEAT;
    let s = sum_of_sines(amps, omegas, phases);
    let t_m = 7.334700208708147;
    let c = s(t_m) + 0.001 * amps.iter().sum::<f64>();
    let g = move |t: f64| s(t) - c;
    let pair = [7.330994629666139, 7.3383906504342455];
    assert!(g(0.5 * (pair[0] + pair[1])) < 0.0 && g(pair[0]) >= 0.0 && g(pair[1]) >= 0.0);
    let hits = isolated(&sines(amps, omegas, phases, c), 1e-13, 10.0);
    // Every root of g on [0, 10] (the 10⁶-point scan's, which the hits match one for one),
    // in order, falling and rising in turn, within 1e-9: the state's error at 1e-13 over
    // a few hundred steps, over |g′| ≥ 0.3 at these roots.
    let reference = brute_roots(&g, 10.0, 1_000_000);
    assert!(
        pair.iter()
            .all(|r| reference.iter().any(|x| (x - r).abs() < 1e-12))
    );
    assert_eq!(hits.len(), reference.len(), "{hits:?}");
    for ((t, dir), r) in hits.iter().zip(&reference) {
        assert!((t - r).abs() < 1e-9, "{t} against {r}");
        let falling = g(r - 1e-6) > 0.0;
        assert_eq!(*dir == Direction::Falling, falling, "{t}");
    }
}

#[test]
fn a_terminal_expanded_event_stops_at_the_first_root_of_the_pair() {
    // Falling crossings only, terminal, from t = 7.2: the first is the pair's first root.
    let [amps, omegas, phases] = BEAT;
    let s = sum_of_sines(amps, omegas, phases);
    let c = s(7.334700208708147) + 0.001 * amps.iter().sum::<f64>();
    let sys = sines(amps, omegas, phases, c);
    let ds = sum_of_sines_slope(amps, omegas, phases);
    // The state at 7.2 from the closed form: xᵢ = sin(ωᵢt + φᵢ), vᵢ = cos(ωᵢt + φᵢ).
    let t0 = 7.2;
    let y0: [f64; 6] = std::array::from_fn(|j| {
        let arg = omegas[j / 2] * t0 + phases[j / 2];
        if j % 2 == 0 { arg.sin() } else { arg.cos() }
    });
    assert!(s(t0) - c > 0.0 && ds(7.330994629666139) < 0.0);
    let cfg = TaylorConfig::with_tol(1e-13, 1e-13);
    let mut ode = Taylor::new(&sys.system, t0, y0, cfg).unwrap();
    let out = Run::new(&mut ode, 10.0)
        .taylor_event(Event::new("g").falling().terminal(), &sys.event)
        .integrate()
        .unwrap();
    assert_eq!(out.stop, StopReason::Event(0));
    assert_eq!(out.events.len(), 1);
    assert!((out.t - 7.330994629666139).abs() < 1e-10, "{}", out.t);
    assert_eq!(out.events[0].direction, Direction::Falling);
    // The hit's state is the dense output there: g on it is 0 within the step's error.
    let y = out.events[0].state;
    let g_hit = amps[0] * y[0] + amps[1] * y[2] + amps[2] * y[4] - c;
    assert!(g_hit.abs() < 1e-11, "{g_hit}");
    assert_eq!(ode.t(), out.t);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// The class of `ode::event_roots`' shallow-pair test, on the expanded path: g = S −
    /// S(t_m) − δ with S a sum of three sines up to 30 rad/s, carried by the state, and
    /// t_m a local minimum of S, so that g dips to −δ (10⁻³ to 3·10⁻² of Σ|A|) between
    /// two roots a few 1e-3 to a few 1e-2 apart. Both roots are found within 1e-9, and
    /// every hit is a root of g (|g| below 1e-9 Σ|A| there). Nothing is sampled: each
    /// step's polynomial of g is isolated exactly, so no step can alias the dip away.
    #[test]
    fn a_close_pair_with_a_shallow_dip_is_isolated(
        amps in prop::array::uniform3(0.1f64..1.0),
        omegas in prop::array::uniform3(0.5f64..30.0),
        phases in prop::array::uniform3(0.0f64..6.3),
        t0 in 1.0f64..9.0,
        depth in 1e-3f64..3e-2,
    ) {
        let s = sum_of_sines(amps, omegas, phases);
        let t_m = local_minimum(sum_of_sines_slope(amps, omegas, phases), t0);
        let scale = amps.iter().sum::<f64>();
        let c = s(t_m) + depth * scale;
        let g = move |t: f64| s(t) - c;
        let pair = [root_beside(g, t_m, -1.0), root_beside(g, t_m, 1.0)];
        prop_assume!(pair[0].is_some_and(|r| r > 0.1) && pair[1].is_some_and(|r| r < 9.9));
        let pair = pair.map(|r| r.unwrap_or(f64::NAN));
        let hits = isolated(&sines(amps, omegas, phases, c), 1e-13, 10.0);
        for r in pair {
            let near = hits.iter().any(|(t, _)| (t - r).abs() < 1e-9);
            prop_assert!(near, "root {} of the pair {:?} (t_m {}) missed", r, pair, t_m);
        }
        for (t, _) in &hits {
            prop_assert!(g(*t).abs() < 1e-9 * scale, "g({}) = {}", t, g(*t));
        }
    }
}
