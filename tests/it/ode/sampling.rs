//! Sample grids that cannot be kept: an interval below the resolution of t, a grid of more
//! samples than the cap or than fit in a count, and a trajectory pushed back in time are
//! typed errors naming the numbers; every grid that is accepted has strictly increasing
//! times t0 + k·dt.

use precess_core::ode::{
    Control, FixedStepConfig, FnSystem, MAX_SAMPLES, MIN_SAMPLE_SPACINGS, OdeError, Rk4, Run,
    Trajectory,
};
use proptest::prelude::*;

/// y' = 1: RK4 and its dense output are exact for it, and it costs nothing.
fn clock() -> FnSystem<impl Fn(f64, &[f64; 1], &mut [f64; 1])> {
    FnSystem(|_t: f64, _y: &[f64; 1], d: &mut [f64; 1]| d[0] = 1.0)
}

/// RK4 from `t0` with steps of at most `h`.
fn rk4(t0: f64, h: f64) -> Rk4<impl precess_core::ode::System<1>, 1> {
    let cfg = FixedStepConfig {
        h,
        ..FixedStepConfig::default()
    };
    Rk4::new(clock(), t0, [0.0], cfg).unwrap()
}

/// The spacing of the doubles at t (one ulp of |t|).
fn ulp(t: f64) -> f64 {
    t.abs().next_up() - t.abs()
}

#[test]
fn an_interval_below_the_resolution_of_t_is_refused_by_name() {
    // From t0 = 1e9 s doubles are 1.19e-7 apart: every 1e-8 s gave 87 repeated times of 96.
    let mut ode = rk4(1e9, 1.0);
    let err = Run::new(&mut ode, 1e9 + 1e-6)
        .sample_every(1e-8)
        .integrate()
        .unwrap_err();
    assert_eq!(
        err,
        OdeError::SampleIntervalBelowResolution {
            dt: 1e-8,
            t: 1e9 + 1e-6,
            spacing: ulp(1e9),
        }
    );
    assert_eq!(ulp(1e9), 1.1920928955078125e-7);
    let message = err.to_string();
    assert!(message.contains("dt = 1e-8") && message.contains("1.1920928955078125e-7"));
    // The interval is judged at the larger end of the run: at 1e10 s, 1e-10 s (which
    // overflowed the sample count before) is refused before any work.
    let mut ode = rk4(0.0, 1.0);
    let err = Run::new(&mut ode, 1e10)
        .sample_every(1e-10)
        .integrate()
        .unwrap_err();
    assert_eq!(
        err,
        OdeError::SampleIntervalBelowResolution {
            dt: 1e-10,
            t: 1e10,
            spacing: ulp(1e10),
        }
    );
}

#[test]
fn more_samples_than_the_cap_are_refused_before_any_work() {
    // 10⁵ s every millisecond is 10⁸ + 1 samples, ten times the cap. The observer stops
    // the run after the first step, so without the check the run "succeeds" with the first
    // second's thousand samples.
    let mut ode = rk4(0.0, 1.0);
    let out = Run::new(&mut ode, 1e5)
        .sample_every(1e-3)
        .observe(|_, _| Control::Stop)
        .integrate();
    assert_eq!(
        out.map(|o| o.trajectory.len()),
        Err(OdeError::TooManySamples {
            samples: 1e8 + 1.0,
            max: MAX_SAMPLES,
        })
    );
    assert_eq!(MAX_SAMPLES, 10_000_000);
    // Exactly at the cap is allowed: 10⁷ samples over [0, 10⁷ − 1] every second.
    let mut ode = rk4(0.0, 1.0);
    let out = Run::new(&mut ode, 9_999_999.0)
        .sample_every(1.0)
        .observe(|_, _| Control::Stop)
        .integrate()
        .unwrap();
    assert_eq!(out.trajectory.times(), [0.0, 1.0]);
}

#[test]
fn a_count_that_does_not_fit_is_refused() {
    // The span overflows f64: the count is ∞, which the old cast saturated to usize::MAX
    // and then overflowed by one (a panic in debug, no samples at all in release).
    let mut ode = rk4(-1e308, 1e300);
    let err = Run::new(&mut ode, 1e308)
        .sample_every(1e300)
        .integrate()
        .unwrap_err();
    assert_eq!(
        err,
        OdeError::TooManySamples {
            samples: f64::INFINITY,
            max: MAX_SAMPLES,
        }
    );
    assert!(err.to_string().contains("inf samples"), "{err}");
}

#[test]
fn a_trajectory_does_not_go_back_in_time() {
    let mut tr: Trajectory<()> = Trajectory::new(vec!["e".into()]);
    tr.push(1.0, (), &[0.5]).unwrap();
    // A repeat is kept (a sample_at list may name a time twice).
    tr.push(1.0, (), &[0.5]).unwrap();
    assert_eq!(
        tr.push(0.5, (), &[0.5]),
        Err(OdeError::DecreasingTime {
            t: 0.5,
            previous: 1.0
        })
    );
    assert!(matches!(
        tr.push(f64::NAN, (), &[0.5]),
        Err(OdeError::NonFiniteTime { t }) if t.is_nan()
    ));
    assert_eq!(tr.times(), [1.0, 1.0]);
}

#[test]
fn a_trajectory_holds_at_most_the_cap() {
    let mut tr: Trajectory<()> = Trajectory::new(Vec::new());
    for k in 0..MAX_SAMPLES {
        tr.push(k as f64, (), &[]).unwrap();
    }
    assert_eq!(
        tr.push(MAX_SAMPLES as f64, (), &[]),
        Err(OdeError::TooManySamples {
            samples: (MAX_SAMPLES + 1) as f64,
            max: MAX_SAMPLES,
        })
    );
    assert_eq!(tr.len(), MAX_SAMPLES);
}

/// A start time between 1e-3 and 1e12 in magnitude, either sign (or zero).
fn start_time() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        (-3.0f64..12.0, any::<bool>()).prop_map(|(e, neg)| {
            let t = 10f64.powf(e);
            if neg { -t } else { t }
        }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Any t0 and any dt from a hundredth of the spacing of doubles at t0 to a thousand
    /// times it: the run either refuses dt by name or records strictly increasing times
    /// t0 + k·dt, as many as fit up to t_end.
    #[test]
    fn sample_times_never_repeat(
        t0 in start_time(),
        spacings in -2.0f64..3.0,
        n in 1usize..200,
    ) {
        let dt = ulp(t0).max(1e-300) * 10f64.powf(spacings);
        let t_end = t0 + n as f64 * dt;
        prop_assume!(t_end.is_finite() && t_end > t0);
        let mut ode = rk4(t0, t_end - t0);
        match Run::new(&mut ode, t_end).sample_every(dt).integrate() {
            Err(OdeError::SampleIntervalBelowResolution { dt: d, t, spacing }) => {
                prop_assert_eq!(d, dt);
                prop_assert_eq!(spacing, ulp(t));
                prop_assert!(dt < MIN_SAMPLE_SPACINGS * spacing);
            }
            Err(e) => prop_assert!(false, "unexpected error {e}"),
            Ok(out) => {
                let times = out.trajectory.times();
                prop_assert_eq!(times[0], t0);
                prop_assert!(
                    times.windows(2).all(|w| w[0] < w[1]),
                    "repeated or decreasing times from t0 = {t0:e}, dt = {dt:e}: {times:?}"
                );
                prop_assert!(*times.last().unwrap() <= t_end);
                // t_end = t0 + n dt rounded, so the grid has n + 1 times, give or take the
                // one that rounding puts beyond t_end.
                prop_assert!(times.len() == n + 1 || times.len() == n, "{} for n = {n}", times.len());
            }
        }
    }
}
