//! The methods of the report, one [`Method`] each: a name, what its setting means, and one
//! [`ProblemRun`] per problem it applies to (its ladder, its cheap rung for `--quick`, and a
//! closure that runs one setting and measures it against the problem's reference).
//!
//! Adding a method is one more entry in [`methods`]; see `docs/performance.md`.

use std::error::Error;

use precess::exact::{FreeBodyExact, Jacobi};
use precess::nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess::ode::{
    AdaptiveConfig, Dop853Pair, Dopri5Pair, EmbeddedPair, FixedStepConfig, Rk4, System, Vern9Pair,
    solve,
};
use precess::prelude::*;
use precess::rigid::{
    Attitude, BodyMomentum, ExactFreeFlow, FreeBodySplitting, Gravity, PotentialSplitting, Rkmk4,
    SplittingOrder,
};
use precess::top::HeavyTopTheory;

use super::problems::{
    B5, B5_T, B5_Y0, B5_Y20, FreeAttitude, FreeBody, Problem, SEP_I, SEP_M0, SEP_T, SpinningTop,
    TopCase, TopTorque, max_diff,
};

/// What one run measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// Error against the problem's reference (NaN: the method is the reference).
    pub error: f64,
    /// Right-hand-side evaluations (`None` where the method evaluates none: the splittings,
    /// the exact flow).
    pub evals: Option<u64>,
    /// Steps taken.
    pub steps: u64,
}

/// A run of one setting.
pub type Runner = Box<dyn Fn(f64) -> Result<Outcome, Box<dyn Error>>>;

/// A method on one problem: its ladder of settings, the cheap rung of `--quick`, the run.
pub struct ProblemRun {
    /// The problem.
    pub problem: Problem,
    /// Settings, coarse to fine.
    pub ladder: Vec<f64>,
    /// The one rung `--quick` runs.
    pub quick: f64,
    /// Runs one setting.
    pub run: Runner,
}

/// What a method's setting is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setting {
    /// rtol = atol.
    Tolerance,
    /// Fixed step h.
    Step,
    /// No setting (the exact flow).
    None,
}

/// A method: its name, what its setting means, and the problems it runs.
pub struct Method {
    /// The name in tables and legends.
    pub name: &'static str,
    /// What the setting is.
    pub setting: Setting,
    /// Plain (uncompensated) variant of a compensated method: the "before" of the floor.
    pub before: bool,
    /// One entry per problem it applies to.
    pub problems: Vec<ProblemRun>,
}

type Res = Result<Outcome, Box<dyn Error>>;

fn adaptive<P: EmbeddedPair, S: System<N>, const N: usize>(
    sys: S,
    y0: [f64; N],
    t: f64,
    tol: f64,
) -> Result<([f64; N], u64, u64), Box<dyn Error>> {
    let cfg = AdaptiveConfig {
        max_steps: 10_000_000,
        ..AdaptiveConfig::with_tol(tol, tol)
    };
    let s = solve::<P, _, N>(sys, 0.0, y0, t, &[], cfg)?;
    Ok((s.y, s.stats.rhs_evals, s.stats.steps))
}

fn rk4<S: System<N>, const N: usize>(
    sys: S,
    y0: [f64; N],
    t: f64,
    h: f64,
    compensated: bool,
) -> Result<([f64; N], u64, u64), Box<dyn Error>> {
    let cfg = FixedStepConfig {
        compensated,
        ..FixedStepConfig::with_step(h)
    };
    let mut r = Rk4::new(sys, 0.0, y0, cfg)?;
    r.advance_to(t)?;
    Ok((*r.y(), r.stats().rhs_evals, r.stats().steps))
}

fn out3(y: [f64; 3], reference: &[f64; 3], evals: u64, steps: u64) -> Outcome {
    Outcome {
        error: max_diff(&y, reference),
        evals: Some(evals),
        steps,
    }
}

/// cos θ of an angle state, or of an Eulerian state's attitude.
fn cos_theta_angles(y: &[f64; 6]) -> f64 {
    y[1].cos()
}
fn attitude7(y: &[f64; 7]) -> UnitQuaternion<f64> {
    UnitQuaternion::new_normalize(Quaternion::new(y[0], y[1], y[2], y[3]))
}

fn top_outcome(case: &TopCase, u: f64, evals: Option<u64>, steps: u64) -> Outcome {
    Outcome {
        error: (u - case.u_end).abs(),
        evals,
        steps,
    }
}

/// An embedded pair on every problem it applies to: (a), (b), (c), (d) in the angle form.
fn pair_runs<P: EmbeddedPair + 'static>(
    ladder: &[f64],
    quick: f64,
    heavy: TopCase,
    fast: TopCase,
) -> Vec<ProblemRun> {
    let top_run = |case: TopCase| -> Runner {
        Box::new(move |tol| {
            let top = SpinningTop;
            let chart = TopChart::declared(&top);
            let (y, e, s) = adaptive::<P, _, 6>(&chart, case.angles0(), case.t_end, tol)?;
            Ok(top_outcome(&case, cos_theta_angles(&y), Some(e), s))
        })
    };
    let sep: Runner = Box::new(|tol| -> Res {
        let reference = super::problems::separatrix_reference();
        let (y, e, s) = adaptive::<P, _, 3>(FreeBody(SEP_I), SEP_M0, SEP_T, tol)?;
        Ok(out3(y, &reference, e, s))
    });
    let b5: Runner = Box::new(|tol| -> Res {
        let (y, e, s) = adaptive::<P, _, 3>(B5, B5_Y0, B5_T, tol)?;
        Ok(out3(y, &B5_Y20, e, s))
    });
    let runs = [
        (Problem::Separatrix, sep),
        (Problem::B5, b5),
        (Problem::HeavyTop, top_run(heavy)),
        (Problem::FastTop, top_run(fast)),
    ];
    runs.into_iter()
        .map(|(problem, run)| ProblemRun {
            problem,
            ladder: ladder.to_vec(),
            quick,
            run,
        })
        .collect()
}

/// DOP853 or Vern9 on the top in both forms (problem (f)).
fn forms_run<P: EmbeddedPair + 'static>(eulerian: bool, heavy: TopCase) -> ProblemRun {
    ProblemRun {
        problem: Problem::Forms,
        ladder: vec![1e-6, 1e-8, 1e-10, 1e-12],
        quick: 1e-8,
        run: Box::new(move |tol| {
            let top = SpinningTop;
            if eulerian {
                let y0 = EulerianTop::<SpinningTop>::state(&heavy.q0(), &heavy.omega0());
                let (y, e, s) = adaptive::<P, _, 7>(EulerianTop(&top), y0, heavy.t_end, tol)?;
                Ok(top_outcome(
                    &heavy,
                    (attitude7(&y) * Vector3::z()).z,
                    Some(e),
                    s,
                ))
            } else {
                let chart = TopChart::declared(&top);
                let (y, e, s) = adaptive::<P, _, 6>(&chart, heavy.angles0(), heavy.t_end, tol)?;
                Ok(top_outcome(&heavy, cos_theta_angles(&y), Some(e), s))
            }
        }),
    }
}

/// Steps per nutation period → h.
fn per_period(case: &TopCase, n: &[f64]) -> Vec<f64> {
    n.iter().map(|k| case.period / k).collect()
}

/// The gravity splitting of the top with the given free flow.
fn top_splitting_run<F: precess::rigid::FreeFlow + Copy + 'static>(
    problem: Problem,
    case: TopCase,
    free: F,
    per: &[f64],
) -> ProblemRun {
    let ladder = per_period(&case, per);
    ProblemRun {
        problem,
        quick: ladder[0],
        ladder,
        run: Box::new(move |h| {
            let split = PotentialSplitting {
                free,
                potential: Gravity {
                    weight: case.mass * 9.81,
                    c: Vector3::new(0.0, 0.0, case.lever),
                },
            };
            let n = (case.t_end / h).round() as u64;
            let mut y = BodyMomentum {
                q: case.q0(),
                m: Vector3::new(0.0, 0.0, case.i3 * case.omega3),
            };
            split.run(&mut y, case.t_end / n as f64, n)?;
            Ok(Outcome {
                error: case.error_q(&y.q),
                evals: None,
                steps: n,
            })
        }),
    }
}

/// A free-body splitting of `order` on (a) and (e), compensated or plain.
fn free_splitting_runs(order: SplittingOrder, compensated: bool) -> Vec<ProblemRun> {
    let (ladder, quick): (Vec<f64>, f64) = match order {
        SplittingOrder::Two => (vec![0.1, 0.03, 0.01, 3e-3, 1e-3, 3e-4], 0.1),
        SplittingOrder::Four => (vec![0.1, 0.03, 0.01, 3e-3, 1e-3], 0.1),
        SplittingOrder::Six => (vec![0.1, 0.03, 0.01, 3e-3, 1e-3], 0.1),
    };
    let split =
        move || FreeBodySplitting::new(SEP_I, order).map(|s| s.with_compensation(compensated));
    let start = || BodyMomentum {
        q: UnitQuaternion::identity(),
        m: Vector3::from(SEP_M0),
    };
    let mut runs = vec![ProblemRun {
        problem: Problem::Separatrix,
        ladder,
        quick,
        run: Box::new(move |h| {
            let reference = super::problems::separatrix_reference();
            let mut y = start();
            let stats = split()?.integrate_to(&mut y, SEP_T, h)?;
            Ok(out3([y.m.x, y.m.y, y.m.z], &reference, 0, stats.steps))
                .map(|o| Outcome { evals: None, ..o })
        }),
    }];
    if order != SplittingOrder::Six {
        runs.push(long_run(move |h, n| {
            let mut y = start();
            split()?.run(&mut y, h, n)?;
            Ok(y.m.into())
        }));
    }
    runs
}

/// Problem (e): 10⁶ steps of h = 0.01 (T = 10⁴); the error column is the larger relative
/// drift of |L| and of the energy.
pub fn long_run(
    final_m: impl Fn(f64, u64) -> Result<[f64; 3], Box<dyn Error>> + 'static,
) -> ProblemRun {
    ProblemRun {
        problem: Problem::LongRun,
        ladder: vec![1e-2],
        quick: 1e-2,
        run: Box::new(move |h| {
            let n = if super::quick_mode() {
                10_000
            } else {
                1_000_000
            };
            let m = final_m(h, n)?;
            let (g0, e0) = invariants(&SEP_M0);
            let (g, e) = invariants(&m);
            Ok(Outcome {
                error: ((g - g0) / g0).abs().max(((e - e0) / e0).abs()),
                evals: None,
                steps: n,
            })
        }),
    }
}

/// (|m|, ½ Σ mᵢ²/Iᵢ).
pub fn invariants(m: &[f64; 3]) -> (f64, f64) {
    let g = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
    let e = 0.5 * (m[0] * m[0] / SEP_I[0] + m[1] * m[1] / SEP_I[1] + m[2] * m[2] / SEP_I[2]);
    (g, e)
}

/// RK4 (compensated or plain) on (a), (b), (c), (e).
fn rk4_runs(compensated: bool, heavy: TopCase) -> Vec<ProblemRun> {
    let mut runs = vec![
        ProblemRun {
            problem: Problem::Separatrix,
            ladder: vec![0.1, 0.03, 0.01, 3e-3, 1e-3, 2e-4],
            quick: 0.1,
            run: Box::new(move |h| {
                let reference = super::problems::separatrix_reference();
                let (y, e, s) = rk4(FreeBody(SEP_I), SEP_M0, SEP_T, h, compensated)?;
                Ok(out3(y, &reference, e, s))
            }),
        },
        long_run(move |h, n| {
            let (y, _, _) = rk4(FreeBody(SEP_I), SEP_M0, h * n as f64, h, compensated)?;
            Ok(y)
        }),
    ];
    if compensated {
        runs.push(ProblemRun {
            problem: Problem::B5,
            ladder: vec![0.1, 0.03, 0.01, 3e-3, 1e-3],
            quick: 0.1,
            run: Box::new(move |h| {
                let (y, e, s) = rk4(B5, B5_Y0, B5_T, h, true)?;
                Ok(out3(y, &B5_Y20, e, s))
            }),
        });
        let ladder = per_period(&heavy, &[100.0, 300.0, 1000.0, 3000.0]);
        runs.push(ProblemRun {
            problem: Problem::HeavyTop,
            quick: ladder[0],
            ladder,
            run: Box::new(move |h| {
                let top = SpinningTop;
                let chart = TopChart::declared(&top);
                let (y, e, s) = rk4(&chart, heavy.angles0(), heavy.t_end, h, true)?;
                Ok(top_outcome(&heavy, cos_theta_angles(&y), Some(e), s))
            }),
        });
    }
    runs
}

/// RKMK4 on (a) (the attitude and ω of the free body) and (c) (gravity as a body torque).
fn rkmk4_runs(heavy: TopCase) -> Vec<ProblemRun> {
    let ladder = per_period(&heavy, &[100.0, 300.0, 1000.0, 3000.0]);
    vec![
        ProblemRun {
            problem: Problem::Separatrix,
            ladder: vec![0.1, 0.03, 0.01, 3e-3],
            quick: 0.1,
            run: Box::new(|h| {
                let reference = super::problems::separatrix_reference();
                let omega = Vector3::new(
                    SEP_M0[0] / SEP_I[0],
                    SEP_M0[1] / SEP_I[1],
                    SEP_M0[2] / SEP_I[2],
                );
                let s0 = Attitude {
                    q: UnitQuaternion::identity(),
                    omega,
                };
                let mut m =
                    Rkmk4::new(FreeAttitude(SEP_I), 0.0, s0, FixedStepConfig::with_step(h))?;
                m.advance_to(SEP_T)?;
                let w = m.state().omega;
                let y = [w.x * SEP_I[0], w.y * SEP_I[1], w.z * SEP_I[2]];
                Ok(out3(y, &reference, m.stats().rhs_evals, m.stats().steps))
            }),
        },
        ProblemRun {
            problem: Problem::HeavyTop,
            quick: ladder[0],
            ladder,
            run: Box::new(move |h| {
                let model = TopTorque {
                    inertia: [heavy.i1, heavy.i1, heavy.i3],
                    weight: heavy.mass * 9.81,
                    c: Vector3::new(0.0, 0.0, heavy.lever),
                };
                let s0 = Attitude {
                    q: heavy.q0(),
                    omega: heavy.omega0(),
                };
                let mut m = Rkmk4::new(model, 0.0, s0, FixedStepConfig::with_step(h))?;
                m.advance_to(heavy.t_end)?;
                let st = m.stats();
                Ok(top_outcome(
                    &heavy,
                    (m.state().q * Vector3::z()).z,
                    Some(st.rhs_evals),
                    st.steps,
                ))
            }),
        },
    ]
}

/// The closed forms themselves, timed (their error against the 30-digit B5 value is real;
/// elsewhere they are the reference).
fn exact_runs(heavy: TopCase) -> Vec<ProblemRun> {
    let one = |problem, run: Runner| ProblemRun {
        problem,
        ladder: vec![0.0],
        quick: 0.0,
        run,
    };
    vec![
        one(
            Problem::Separatrix,
            Box::new(|_| {
                let m = FreeBodyExact::new(SEP_I, SEP_M0)?.m_at(std::hint::black_box(SEP_T))?;
                std::hint::black_box(m);
                Ok(Outcome {
                    error: f64::NAN,
                    evals: None,
                    steps: 0,
                })
            }),
        ),
        one(
            Problem::B5,
            Box::new(|_| {
                let (s, c, d) = Jacobi::new(0.49)?.sncndn(std::hint::black_box(B5_T));
                Ok(Outcome {
                    error: max_diff(&[s, c, d], &B5_Y20),
                    evals: None,
                    steps: 0,
                })
            }),
        ),
        one(
            Problem::HeavyTop,
            Box::new(move |_| {
                let theory = HeavyTopTheory::new(heavy.i1, heavy.i3, heavy.mgl)?;
                let motion = theory
                    .motion_from_angles(&[0.0, heavy.theta0, 0.0], &[0.0, 0.0, heavy.omega3])?;
                std::hint::black_box(motion.cos_theta_at(std::hint::black_box(heavy.t_end))?);
                Ok(Outcome {
                    error: f64::NAN,
                    evals: None,
                    steps: 0,
                })
            }),
        ),
    ]
}

/// Every method of the report.
///
/// # Errors
/// When a top's closed form cannot be set up.
pub fn methods() -> Result<Vec<Method>, Box<dyn Error>> {
    let heavy = TopCase::new(150.0)?;
    let fast = TopCase::new(1000.0)?;
    let tols = [1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    let per_fast = [30.0, 100.0, 300.0];
    let per_heavy = [30.0, 100.0, 300.0, 1000.0];
    let mut dop853 = pair_runs::<Dop853Pair>(&tols, 1e-8, heavy, fast);
    dop853.push(forms_run::<Dop853Pair>(false, heavy));
    let mut vern9 = pair_runs::<Vern9Pair>(&tols, 1e-8, heavy, fast);
    vern9.push(forms_run::<Vern9Pair>(false, heavy));
    let eulerian = vec![forms_run::<Dop853Pair>(true, heavy)];
    let eulerian9 = vec![forms_run::<Vern9Pair>(true, heavy)];
    let exact_flow = ExactFreeFlow::new([heavy.i1, heavy.i1, heavy.i3])?;
    let exact_flow_fast = ExactFreeFlow::new([fast.i1, fast.i1, fast.i3])?;
    let axis_flow = FreeBodySplitting::new([heavy.i1, heavy.i1, heavy.i3], SplittingOrder::Two)?;
    let m = |name, setting, before, problems| Method {
        name,
        setting,
        before,
        problems,
    };
    Ok(vec![
        m("DOP853", Setting::Tolerance, false, dop853),
        m(
            "Taylor",
            Setting::Tolerance,
            false,
            super::taylor::taylor_runs(heavy, fast)?,
        ),
        m(
            "Taylor, interpreted",
            Setting::Tolerance,
            false,
            super::taylor::interpreted_runs(),
        ),
        m(
            "Taylor, extended",
            Setting::Tolerance,
            false,
            super::taylor::extended_runs(),
        ),
        m(
            "Taylor, order 12, fixed step",
            Setting::Step,
            false,
            vec![super::taylor::long_run_fixed()],
        ),
        m("Vern9", Setting::Tolerance, false, vern9),
        m(
            "DOPRI5",
            Setting::Tolerance,
            false,
            pair_runs::<Dopri5Pair>(&[1e-6, 1e-8, 1e-10, 1e-12], 1e-6, heavy, fast),
        ),
        m("DOP853, Eulerian form", Setting::Tolerance, false, eulerian),
        m("Vern9, Eulerian form", Setting::Tolerance, false, eulerian9),
        m("RK4", Setting::Step, false, rk4_runs(true, heavy)),
        m(
            "RK4, plain sums",
            Setting::Step,
            true,
            rk4_runs(false, heavy),
        ),
        m("RKMK4", Setting::Step, false, rkmk4_runs(heavy)),
        m(
            "split2",
            Setting::Step,
            false,
            free_splitting_runs(SplittingOrder::Two, true),
        ),
        m(
            "split2, plain sums",
            Setting::Step,
            true,
            free_splitting_runs(SplittingOrder::Two, false),
        ),
        m(
            "split4",
            Setting::Step,
            false,
            free_splitting_runs(SplittingOrder::Four, true),
        ),
        m(
            "split4, plain sums",
            Setting::Step,
            true,
            free_splitting_runs(SplittingOrder::Four, false),
        ),
        m(
            "split6",
            Setting::Step,
            false,
            free_splitting_runs(SplittingOrder::Six, true),
        ),
        m(
            "split6, plain sums",
            Setting::Step,
            true,
            free_splitting_runs(SplittingOrder::Six, false),
        ),
        m(
            "exact free flow + kicks",
            Setting::Step,
            false,
            vec![
                top_splitting_run(Problem::HeavyTop, heavy, exact_flow, &per_heavy),
                top_splitting_run(Problem::FastTop, fast, exact_flow_fast, &per_fast),
            ],
        ),
        m(
            "axis splitting + kicks",
            Setting::Step,
            false,
            vec![top_splitting_run(
                Problem::HeavyTop,
                heavy,
                axis_flow,
                &per_heavy,
            )],
        ),
        m(
            "exact (closed form)",
            Setting::None,
            false,
            exact_runs(heavy),
        ),
    ])
}
