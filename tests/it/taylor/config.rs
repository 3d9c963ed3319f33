//! Requests the Taylor integrator cannot meet are errors, and its budgets are per run:
//! - a fixed order above `max_order` or above the system's maximum is
//!   `OdeError::TaylorOrderTooHigh`, not a silent cap;
//! - `max_steps` counts the steps towards one stop: an integrator restarted for many short
//!   runs never runs out of it (Taylor and the pairs alike), while one run that needs more
//!   still fails;
//! - `taylor_system!` takes the primitive's paths for its f64 fields, as `#[rigid]` does.

use precess::ode::{AdaptiveConfig, Dop853, OdeError, Stepper};
use precess::taylor::{Taylor, TaylorConfig, TaylorSystem};

precess::taylor_system! {
    /// The harmonic oscillator x'' = −ω²x.
    #[derive(Debug, Clone, Copy)]
    struct Oscillator {
        w: f64,
    }
    state [x, v];
    taylor = 30;
    d/dt x = v;
    d/dt v = -w * w * x;
}

precess::taylor_system! {
    /// y' = −k y with the parameter's type written as the primitive's paths.
    struct Paths {
        k: core::primitive::f64,
        scale: ::std::primitive::f64,
    }
    state [y];
    taylor = 20;
    d/dt y = -k * scale * y;
}

const OSC: Oscillator = Oscillator { w: 2.0 };

#[test]
fn a_fixed_order_above_the_caps_is_an_error() {
    // The issue: fixed(1000, h) on a taylor = 30 system ran order 30 silently.
    let err = Taylor::new(OSC, 0.0, [1.0, 0.0], TaylorConfig::fixed(1000, 0.01)).unwrap_err();
    assert_eq!(
        err,
        OdeError::TaylorOrderTooHigh {
            order: 1000,
            cap: 40,
            limit: "TaylorConfig::max_order"
        }
    );
    let cfg = TaylorConfig {
        max_order: 2000,
        ..TaylorConfig::fixed(1000, 0.01)
    };
    let err = Taylor::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap_err();
    assert_eq!(
        err,
        OdeError::TaylorOrderTooHigh {
            order: 1000,
            cap: 30,
            limit: "TaylorSystem::max_order"
        }
    );
    assert!(err.to_string().contains("1000") && err.to_string().contains("30"));
    // At the system's maximum it runs, and order 30 with h = 0.01 is exact to rounding.
    let mut ode = Taylor::new(OSC, 0.0, [1.0, 0.0], TaylorConfig::fixed(30, 0.01)).unwrap();
    ode.advance_to(1.0).unwrap();
    assert!((ode.y()[0] - 2.0f64.cos()).abs() < 1e-14);
    assert_eq!(ode.last_step().0, 30);
}

#[test]
fn a_tolerance_beyond_the_caps_is_met_with_shorter_steps() {
    // Jorba–Zou asks order 19 at 1e-15; capped at 6, the step shrinks instead and the
    // tolerance still holds (no error: the cap is documented as a step factor).
    let cfg = TaylorConfig {
        max_order: 6,
        ..TaylorConfig::with_tol(1e-13, 1e-13)
    };
    let mut ode = Taylor::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    ode.advance_to(10.0).unwrap();
    assert_eq!(ode.last_step().0, 6);
    assert!((ode.y()[0] - 20.0f64.cos()).abs() < 1e-11, "{}", ode.y()[0]);
}

#[test]
fn a_reused_taylor_integrator_has_a_budget_per_run() {
    // Each run to t + 1 takes a handful of steps; 2 000 runs take far more than the budget
    // of 50, which is per run.
    let cfg = TaylorConfig {
        max_steps: 50,
        ..TaylorConfig::with_tol(1e-12, 1e-12)
    };
    let mut ode = Taylor::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    for run in 0..2000 {
        let t = f64::from(run);
        Stepper::restart(&mut ode, t, [1.0, 0.0]).unwrap();
        ode.advance_to(t + 1.0)
            .unwrap_or_else(|e| panic!("run {run}: {e}"));
        assert!((ode.y()[0] - 2.0f64.cos()).abs() < 1e-11);
    }
    assert!(ode.stats().steps > 50 * 20, "{}", ode.stats().steps);
    // Without a restart, successive stops are runs of their own too.
    let mut ode = Taylor::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    for k in 1..=500 {
        ode.advance_to(f64::from(k)).unwrap();
    }
    // One run that needs more than its budget still fails.
    let mut ode = Taylor::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    assert!(matches!(
        ode.advance_to(1000.0),
        Err(OdeError::MaxStepsExceeded { max_steps: 50, .. })
    ));
}

#[test]
fn a_reused_pair_has_a_budget_per_run() {
    let cfg = AdaptiveConfig {
        max_steps: 50,
        ..AdaptiveConfig::with_tol(1e-10, 1e-10)
    };
    let mut ode = Dop853::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    for run in 0..500 {
        let t = f64::from(run);
        Stepper::restart(&mut ode, t, [1.0, 0.0]).unwrap();
        ode.advance_to(t + 1.0)
            .unwrap_or_else(|e| panic!("run {run}: {e}"));
    }
    assert!(ode.stats().steps > 50 * 5, "{}", ode.stats().steps);
    let mut ode = Dop853::new(OSC, 0.0, [1.0, 0.0], cfg).unwrap();
    assert!(matches!(
        ode.advance_to(1000.0),
        Err(OdeError::MaxStepsExceeded { max_steps: 50, .. })
    ));
}

#[test]
fn taylor_system_takes_the_primitive_paths_of_f64() {
    let sys = Paths { k: 0.5, scale: 2.0 };
    let mut c = [[0.0; 1]; 3];
    sys.coefficients(0.0, &[3.0], 2, &mut c);
    assert_eq!(c, [[3.0], [-3.0], [1.5]]);
}
