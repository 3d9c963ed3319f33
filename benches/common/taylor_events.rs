//! What an event costs a Taylor run: the same run with no event, with the event scanned
//! (`Run::event`, Chebyshev interpolation of g along the dense output) and with it expanded
//! (`Run::taylor_event`, g's recurrences along the jet and its roots isolated), on the
//! three oscillators that carry the sines of `tests/it/taylor/events.rs` (the beat with a
//! shallow pair, 6 components, order 16 at 1e-12) to t = 10, and on the testkit's
//! oscillator (2 components) with g = x − cos 0.01 to t = 50. `-- events` runs the group;
//! the evaluations of g per step of the scanned event are printed first.

use std::cell::Cell;
use std::hint::black_box;

use criterion::Criterion;
use precess::ode::{Event, Run};
use precess::sym::{Arena, ExprId};
use precess::taylor::{Taylor, TaylorConfig, TaylorEvent, TaylorTape};
use precess_testkit::systems::Oscillator;

/// The beat: amplitudes, frequencies, phases, and the level c of g = Σ Aᵢ sin(ωᵢt + φᵢ) − c.
const AMPS: [f64; 3] = [0.9521940533276592, 0.8342935472331764, 0.5762471339241876];
const OMEGAS: [f64; 3] = [6.000115648719028, 27.08034854307633, 26.038471104595125];
const PHASES: [f64; 3] = [5.152946613068597, 1.2810683954004747, 6.260217977937406];

/// The sines system, its expanded event and its start.
fn sines() -> (TaylorTape<6>, TaylorEvent<6>, [f64; 6], f64) {
    let s = |t: f64| {
        (0..3)
            .map(|i| AMPS[i] * (OMEGAS[i] * t + PHASES[i]).sin())
            .sum::<f64>()
    };
    let c = s(7.334700208708147) + 0.001 * AMPS.iter().sum::<f64>();
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
        ("w0", OMEGAS[0]),
        ("w1", OMEGAS[1]),
        ("w2", OMEGAS[2]),
        ("a0", AMPS[0]),
        ("a1", AMPS[1]),
        ("a2", AMPS[2]),
        ("c", c),
    ];
    let system = TaylorTape::new(&a, state, rhs, None, &values, 30).expect("the sines system");
    let event = TaylorEvent::new(&a, state, None, g, &values).expect("the sines event");
    let y0 = std::array::from_fn(|j| {
        let phase = PHASES[j / 2];
        if j % 2 == 0 { phase.sin() } else { phase.cos() }
    });
    (system, event, y0, c)
}

/// g = x − cos 0.01 on the oscillator (x, v), expanded.
fn dip() -> TaylorEvent<2> {
    let mut a = Arena::new();
    let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    let level = a.parameter("level");
    let g = a.sub(x, level);
    TaylorEvent::new(&a, [x, v], None, g, &[("level", 0.01f64.cos())]).expect("the dip event")
}

/// Which event a run carries.
#[derive(Clone, Copy, Debug)]
enum Kind {
    None,
    Scanned,
    Expanded,
}

/// A run of the sines system to 10 at 1e-12: (hits, steps, evaluations of g by the scan).
fn run_sines(
    kind: Kind,
    sys: &(TaylorTape<6>, TaylorEvent<6>, [f64; 6], f64),
) -> (usize, u64, u64) {
    let (system, event, y0, c) = sys;
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut ode = Taylor::new(system, 0.0, *y0, cfg).expect("valid");
    let calls = Cell::new(0u64);
    let g = |_t: f64, y: &[f64; 6]| {
        calls.set(calls.get() + 1);
        AMPS[0] * y[0] + AMPS[1] * y[2] + AMPS[2] * y[4] - c
    };
    let r = Run::new(&mut ode, 10.0).sample_none();
    let r = match kind {
        Kind::None => r,
        Kind::Scanned => r.event(Event::new("g"), g),
        Kind::Expanded => r.taylor_event(Event::new("g"), event),
    };
    let out = r.integrate().expect("the run");
    (out.events.len(), out.stats.steps, calls.get())
}

/// A run of the oscillator to 50 at 1e-12 with g = x − cos 0.01: (hits, steps, g calls).
fn run_dip(kind: Kind, event: &TaylorEvent<2>) -> (usize, u64, u64) {
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).expect("valid");
    let calls = Cell::new(0u64);
    let level = 0.01f64.cos();
    let g = |_t: f64, y: &[f64; 2]| {
        calls.set(calls.get() + 1);
        y[0] - level
    };
    let r = Run::new(&mut ode, 50.0).sample_none();
    let r = match kind {
        Kind::None => r,
        Kind::Scanned => r.event(Event::new("g"), g),
        Kind::Expanded => r.taylor_event(Event::new("g"), event),
    };
    let out = r.integrate().expect("the run");
    (out.events.len(), out.stats.steps, calls.get())
}

/// The `events` group: each run whole, no event, scanned, expanded.
pub fn events_group(c: &mut Criterion) {
    let sys = sines();
    let dip_event = dip();
    for kind in [Kind::None, Kind::Scanned, Kind::Expanded] {
        let (hits, steps, calls) = run_sines(kind, &sys);
        println!("sines {kind:?}: {hits} hits, {steps} steps, {calls} calls of the closure g");
        let (hits, steps, calls) = run_dip(kind, &dip_event);
        println!("oscillator {kind:?}: {hits} hits, {steps} steps, {calls} calls of the closure g");
    }
    let mut g = c.benchmark_group("events");
    for kind in [Kind::None, Kind::Scanned, Kind::Expanded] {
        g.bench_function(format!("sines to 10, event {kind:?}"), |b| {
            b.iter(|| run_sines(black_box(kind), &sys))
        });
        g.bench_function(format!("oscillator to 50, event {kind:?}"), |b| {
            b.iter(|| run_dip(black_box(kind), &dip_event))
        });
    }
    g.finish();
}
