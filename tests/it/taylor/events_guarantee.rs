//! What the expanded events of `Run::taylor_event` guarantee where the Chebyshev scan of
//! `Run::event` only estimates: a dip hidden between every point the scan looks at, found
//! on the polynomial; a hand-written system and a g of the time; a g faster than the step,
//! refused rather than taken for its polynomial; a root on a step's end, reported once.

use crate::common::dips::brute_roots;
use precess::ode::{Direction, Event, OdeError, Run};
use precess::sym::Arena;
use precess::taylor::{Taylor, TaylorConfig, TaylorEvent, TaylorTape};
use precess_testkit::systems::Oscillator;
use std::f64::consts::PI;

/// W(x) = (x² − 1) U₇(x)/128, zero at the nine points xⱼ = −cos(jπ/8) where the scan of a
/// step looks at g first (the degree-4 points and the degree-8 ones that confirm them).
fn w(x: f64) -> f64 {
    let x2 = x * x;
    x * ((((x2 - 2.5) * x2 + 2.125) * x2 - 0.6875) * x2 + 0.0625)
}

#[test]
fn a_dip_hidden_between_the_scans_points_is_isolated() {
    // One Taylor step of fixed length 1 over y = 0.05 + 0.01 x + 20 W(x), x = 2t − 1,
    // carried by the state (x′ = 2, y′ = 2 (0.01 + 20 W′(x))): at every point the scan
    // evaluates, y is the line 0.05 + 0.01 x, confirmed by the points of degree 8, and the
    // scan passes the step over as rootless (its documented blind spot). y dips below 0
    // between those points: the expanded event isolates every root of its polynomial,
    // which is y itself (degree 9, the step's order 12).
    let (level, slope, kappa) = (0.05, 0.01, 20.0);
    let y_exact = |t: f64| {
        let x = 2.0 * t - 1.0;
        level + slope * x + kappa * w(x)
    };
    let mut a = Arena::new();
    let (x, y) = (a.coordinate("x"), a.coordinate("y"));
    // W′(x) = 9x⁸ − 17.5x⁶ + 10.625x⁴ − 2.0625x² + 0.0625, its coefficients as parameters.
    let names = ["w8", "w6", "w4", "w2", "w0"];
    let cs = names.map(|n| a.parameter(n));
    let x2 = a.mul(x, x);
    let mut poly = cs[0];
    for &c in &cs[1..] {
        let times = a.mul(poly, x2);
        poly = a.add(times, c);
    }
    let (k, s, two) = (
        a.parameter("kappa"),
        a.parameter("slope"),
        a.parameter("two"),
    );
    let bent = a.mul(k, poly);
    let inner = a.add(s, bent);
    let dy = a.mul(two, inner);
    let values = [
        ("w8", 9.0),
        ("w6", -17.5),
        ("w4", 10.625),
        ("w2", -2.0625),
        ("w0", 0.0625),
        ("kappa", kappa),
        ("slope", slope),
        ("two", 2.0),
    ];
    let system = TaylorTape::new(&a, [x, y], [two, dy], None, &values, 20).unwrap();
    let event = TaylorEvent::new(&a, [x, y], None, y, &values).unwrap();
    let y0 = [-1.0, level - slope];
    let reference = brute_roots(&y_exact, 1.0, 1_000_000);
    assert!(reference.len() >= 4, "{reference:?}");
    // The scan's first points see the line: y there is 0.05 + 0.01 x within rounding.
    for j in 0..=8 {
        let xj = -(f64::from(j) * PI / 8.0).cos();
        assert!((y_exact(0.5 + 0.5 * xj) - level - slope * xj).abs() < 1e-14);
    }

    let run = |expanded: bool| {
        let mut ode = Taylor::new(&system, 0.0, y0, TaylorConfig::fixed(12, 1.0)).unwrap();
        let r = Run::new(&mut ode, 1.0).sample_none();
        let r = if expanded {
            r.taylor_event(Event::new("y"), &event)
        } else {
            r.event(Event::new("y"), |_t, s: &[f64; 2]| s[1])
        };
        let out = r.integrate().unwrap();
        assert_eq!(out.stats.steps, 1);
        out.events.iter().map(|h| h.t).collect::<Vec<_>>()
    };
    // The scan: an estimate, and here a wrong one.
    assert_eq!(run(false), Vec::<f64>::new());
    // The expanded event: every root, each within the rounding of the polynomial. Its
    // coefficients in t (x = 2t − 1 expanded: 20·2ᵏC(9, k) reaches 1e5) cancel to values
    // below 1, so they carry up to about 1e-11 of rounding, over slopes |y′| > 2 at the six
    // roots (measured: 3.6e-13 at most).
    let found = run(true);
    assert_eq!(
        found.len(),
        reference.len(),
        "{found:?} against {reference:?}"
    );
    for (t, r) in found.iter().zip(&reference) {
        assert!((t - r).abs() < 2e-11, "{t} against {r}");
    }
}

#[test]
fn a_hand_written_system_takes_an_expanded_event_over_its_state() {
    // The testkit's oscillator (x, v) = (cos t, −sin t), its coefficients written by hand:
    // the event needs only the state's order. g = x − cos δ: roots δ, 2π ∓ δ, the last two
    // inside one step, against arccos.
    let delta: f64 = 0.01;
    let mut a = Arena::new();
    let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    let level = a.parameter("level");
    let g = a.sub(x, level);
    let event = TaylorEvent::new(&a, [x, v], None, g, &[("level", delta.cos())]).unwrap();
    let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let out = Run::new(&mut ode, 7.0)
        .taylor_event(Event::new("dip"), &event)
        .integrate()
        .unwrap();
    let exact = [delta, 2.0 * PI - delta, 2.0 * PI + delta];
    let dirs = [Direction::Falling, Direction::Rising, Direction::Falling];
    assert_eq!(out.events.len(), 3, "{:?}", out.events);
    for (h, (e, d)) in out.events.iter().zip(exact.iter().zip(dirs)) {
        // |g′| = sin δ ≈ 0.01: an error ε of x is ε/0.01 in t.
        assert!((h.t - e).abs() < 1e-10, "{} against {e}", h.t);
        assert_eq!(h.direction, d);
    }
    let ends = out.trajectory.times();
    assert!(ends.windows(2).any(|w| w[0] < exact[1] && w[1] > exact[2]));
}

#[test]
fn step_ends_only_compares_the_ends_of_an_expanded_event() {
    // The opt-out holds for an expanded event too: the pair 2π ∓ δ inside one step is
    // missed as documented, and the first root, a change of sign across its step, is
    // located on the dense output (not on a polynomial of another step) within 1e-10.
    let delta: f64 = 0.01;
    let mut a = Arena::new();
    let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    let level = a.parameter("level");
    let g = a.sub(x, level);
    let event = TaylorEvent::new(&a, [x, v], None, g, &[("level", delta.cos())]).unwrap();
    let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let out = Run::new(&mut ode, 7.0)
        .sample_none()
        .taylor_event(Event::new("dip").step_ends_only(), &event)
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 1, "{:?}", out.events);
    assert!(
        (out.events[0].t - delta).abs() < 1e-10,
        "{}",
        out.events[0].t
    );
}

/// sin(k t) as an event of the time on the testkit's oscillator.
fn sine_of_time(k: f64) -> TaylorEvent<2> {
    let mut a = Arena::new();
    let (x, v, t) = (a.coordinate("x"), a.coordinate("v"), a.time());
    let kp = a.parameter("k");
    let arg = a.mul(kp, t);
    let g = a.sin(arg);
    TaylorEvent::new(&a, [x, v], Some(t), g, &[("k", k)]).unwrap()
}

#[test]
fn a_g_faster_than_the_step_is_refused_and_runs_when_the_step_is_bounded() {
    // sin(50 t) on steps of about 0.9 (the oscillator's): its Taylor polynomial of order
    // ~15 is nothing like it (50·0.9 = 45 rad), so the run refuses it at the first step.
    let event = sine_of_time(50.0);
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let err = Run::new(&mut ode, 20.0)
        .taylor_event(Event::new("sin 50t"), &event)
        .integrate()
        .unwrap_err();
    let OdeError::EventNotResolved {
        index,
        mismatch,
        limit,
        ..
    } = err
    else {
        panic!("{err:?}");
    };
    assert_eq!(index, 0);
    assert!(mismatch > limit, "{mismatch} against {limit}");
    // With the step bounded to 0.02 (1 rad of g), all 318 roots kπ/50 on (0, 20].
    let cfg = TaylorConfig {
        h_max: 0.02,
        ..TaylorConfig::with_tol(1e-12, 1e-12)
    };
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], cfg).unwrap();
    let out = Run::new(&mut ode, 20.0)
        .sample_none()
        .taylor_event(Event::new("sin 50t"), &event)
        .integrate()
        .unwrap();
    assert_eq!(out.events.len(), 318);
    for (k, h) in out.events.iter().enumerate() {
        let exact = (k + 1) as f64 * PI / 50.0;
        // 50 t rounded at t ≤ 20 (half an ulp of 1000, 6e-14) over 50.
        assert!(
            (h.t - exact).abs() < 1e-14,
            "root {}: {} against {exact}",
            k + 1,
            h.t
        );
    }
}

#[test]
fn a_root_on_a_step_end_is_reported_once() {
    // Fixed steps of 0.25 land on t = 1, where g = t − 1 is exactly 0: one rising hit at
    // 1, none from the next step, which starts on the root.
    let mut a = Arena::new();
    let (x, v, t) = (a.coordinate("x"), a.coordinate("v"), a.time());
    let one = a.parameter("one");
    let g = a.sub(t, one);
    let event = TaylorEvent::new(&a, [x, v], Some(t), g, &[("one", 1.0)]).unwrap();
    let mut ode = Taylor::new(Oscillator, 0.0, [1.0, 0.0], TaylorConfig::fixed(12, 0.25)).unwrap();
    let out = Run::new(&mut ode, 3.0)
        .taylor_event(Event::new("t = 1"), &event)
        .integrate()
        .unwrap();
    assert!(out.trajectory.times().contains(&1.0));
    let hits: Vec<_> = out.events.iter().map(|h| (h.t, h.direction)).collect();
    assert_eq!(hits, [(1.0, Direction::Rising)]);
}
