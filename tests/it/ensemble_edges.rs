//! Ensembles at their edges: a range that ends at `usize::MAX` in lanes, and a progress
//! callback that panics, each keeping every run's result.

use precess::ensemble::Ensemble;
use precess::ode::OdeError;
use precess::taylor::{Taylor, TaylorConfig};

precess::taylor_system! {
    /// Exponential decay ẋ = −k x, x(t) = x₀ e^(−k t).
    struct Decay { k: f64 }
    state [x];
    taylor = 24;
    d/dt x = -k * x;
}

fn decay(_: usize) -> Result<Taylor<Decay, 1>, OdeError> {
    Taylor::new(
        Decay { k: 1.0 },
        0.0,
        [1.0],
        TaylorConfig::with_tol(1e-14, 1e-14),
    )
}

/// The last two indices a range can hold, in chunks of 4 lanes: the chunk's end `lo + 4`
/// would wrap, and the ensemble returned no results. Each run ends at e⁻¹.
#[test]
fn lanes_run_the_last_indices_of_usize() {
    let runs = usize::MAX - 2..usize::MAX;
    let results = Ensemble::new(runs.clone()).lanes::<4>().integrate(
        1.0,
        decay,
        |_, ode: &Taylor<Decay, 1>| ode.y()[0],
    );
    assert_eq!(results.runs(), runs);
    let outputs: Vec<(usize, f64)> = results.outputs().map(|(i, x)| (i, *x)).collect();
    assert_eq!(outputs.len(), 2, "{results:?}");
    for (i, x) in outputs {
        assert!(runs.contains(&i));
        assert!(
            (x - (-1.0f64).exp()).abs() < 1e-13,
            "run {i}: {x} against e^-1"
        );
    }
}

/// A progress bar that panics on its third report: every run still returns its result
/// (i², directly summed for the reduction), and the callback is not called again.
#[test]
fn a_panicking_progress_callback_loses_no_result() {
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let report = |p: precess::ensemble::EnsembleProgress| {
        calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        if p.done >= 3 {
            panic!("the progress bar broke");
        }
    };
    let ensemble = Ensemble::new(0..40).progress(&report);
    let results = ensemble.run(|i| Ok::<usize, ()>(i * i));
    assert_eq!(results.failures(), 0);
    let squares: Vec<usize> = results.outputs().map(|(_, v)| *v).collect();
    assert_eq!(squares, (0..40).map(|i| i * i).collect::<Vec<_>>());
    // Reports 1 and 2 pass; the first to reach 3 panics and silences the rest (on several
    // threads, a few may have reached the callback before the first panic was recorded).
    let called = calls.load(std::sync::atomic::Ordering::Relaxed);
    assert!((3..40).contains(&called), "{called} calls");

    let sum = Ensemble::new(0..40).progress(&report).reduce(
        |i| Ok::<usize, ()>(i * i),
        || 0usize,
        |acc, _, r| acc + r.unwrap_or(0),
        |a, b| a + b,
    );
    // Σ i² for i < 40 = 39·40·79/6.
    assert_eq!(sum, 39 * 40 * 79 / 6);

    let lanes = Ensemble::new(0..10)
        .progress(&report)
        .lanes::<4>()
        .integrate(1.0, decay, |_, ode: &Taylor<Decay, 1>| ode.y()[0]);
    assert_eq!(lanes.outputs().count(), 10);
}
