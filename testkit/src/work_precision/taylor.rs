//! The Taylor integrator of issue 15 on every problem it applies to: (a) and (b) through
//! the recurrences `taylor_system!` generates from their equations written in the source,
//! and, for comparison, the same equations built at run time and interpreted
//! ([`TaylorTape`], the curve "Taylor, interpreted"), and the same tapes in the extended
//! mode, the low orders of each step in double-double (the curve "Taylor, extended"); (c)
//! and (d) through the recurrences the derive generates for the report's top (`taylor = 20`
//! on its `#[top]`).

use std::error::Error;

use precess::sym::{Arena, ExprId};
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape, solve};

use super::methods::{Outcome, ProblemRun, Runner};
use super::problems::{
    B5_T, B5_Y0, B5_Y20, Problem, SEP_I, SEP_M0, SEP_T, SpinningTop, TopCase, max_diff,
};

/// The highest order of the interpreted recurrences: the integrator picks ≈ 17 at 1e-14
/// and 22 at the extended mode's 1e-18.
const EXTENDED_ORDER: usize = 30;

/// The orders the extended mode carries in double-double (six is where the error on the
/// torque-free bodies stops falling: `docs/taylor-integrator.md`).
const EXTENDED_LOW_ORDERS: usize = 6;

precess::taylor_system! {
    /// Euler's torque-free equations ṁ = m × I⁻¹m in principal axes (problem (a)): each
    /// component one product of the other two, scaled by a difference of inverse moments.
    pub struct EulerBody {
        i1: f64,
        i2: f64,
        i3: f64,
    }
    state [m1, m2, m3];
    taylor = 24;
    d/dt m1 = (1.0 / i3 - 1.0 / i2) * m2 * m3;
    d/dt m2 = (1.0 / i1 - 1.0 / i3) * m3 * m1;
    d/dt m3 = (1.0 / i2 - 1.0 / i1) * m1 * m2;
}

precess::taylor_system! {
    /// DETEST B5 (problem (b)).
    pub struct B5;
    state [y1, y2, y3];
    taylor = 24;
    d/dt y1 = y2 * y3;
    d/dt y2 = -y1 * y3;
    d/dt y3 = -0.51 * y1 * y2;
}

/// The body of problem (a).
fn euler_body() -> EulerBody {
    let [i1, i2, i3] = SEP_I;
    EulerBody { i1, i2, i3 }
}

/// The same equations as [`EulerBody`] (`b5` false, with I = `SEP_I`) or [`B5`], built in
/// the engine at run time and interpreted. The constants are formed by the tape from exact
/// parameters (1/I from I, 0.51 as 51/100), so that the extended mode carries them in
/// double-double and integrates the problem its reference solves, not the f64 neighbour.
fn tape(b5: bool) -> Result<TaylorTape<3>, Box<dyn Error>> {
    let mut a = Arena::new();
    let y: [ExprId; 3] = ["y1", "y2", "y3"].map(|n| a.coordinate(n));
    // Component i is c_i · y_j · y_k for (i, j, k) cyclic.
    let scales: [ExprId; 3] = if b5 {
        let (num, den) = (a.parameter("num"), a.parameter("den"));
        let k = a.div(num, den)?;
        [a.one(), a.integer(-1), a.neg(k)]
    } else {
        let inertia = ["i1", "i2", "i3"].map(|n| a.parameter(n));
        let [r1, r2, r3] = [
            a.recip(inertia[0])?,
            a.recip(inertia[1])?,
            a.recip(inertia[2])?,
        ];
        [a.sub(r3, r2), a.sub(r1, r3), a.sub(r2, r1)]
    };
    let mut rhs = [a.zero(); 3];
    for (i, out) in rhs.iter_mut().enumerate() {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let scaled = a.mul(scales[i], y[j]);
        *out = a.mul(scaled, y[k]);
    }
    let values: &[(&str, f64)] = if b5 {
        &[("num", 51.0), ("den", 100.0)]
    } else {
        &[("i1", SEP_I[0]), ("i2", SEP_I[1]), ("i3", SEP_I[2])]
    };
    Ok(TaylorTape::new(&a, y, rhs, None, values, EXTENDED_ORDER)?)
}

fn config(tol: f64) -> TaylorConfig {
    TaylorConfig {
        max_steps: 10_000_000,
        ..TaylorConfig::with_tol(tol, tol)
    }
}

fn run<S: TaylorSystem<N>, const N: usize>(
    sys: S,
    y0: [f64; N],
    t: f64,
    tol: f64,
) -> Result<([f64; N], u64, u64), Box<dyn Error>> {
    let s = solve(sys, 0.0, y0, t, &[], config(tol))?;
    Ok((s.y, s.stats.rhs_evals, s.stats.steps))
}

/// Taylor's method on (a), (b), (c) and (d), the recurrences generated at compile time.
pub fn taylor_runs(heavy: TopCase, fast: TopCase) -> Result<Vec<ProblemRun>, Box<dyn Error>> {
    let sep: Runner = Box::new(|tol| {
        let reference = super::problems::separatrix_reference();
        let (y, e, s) = run(euler_body(), SEP_M0, SEP_T, tol)?;
        Ok(outcome(max_diff(&y, &reference), e, s))
    });
    let b5: Runner = Box::new(|tol| {
        let (y, e, s) = run(B5, B5_Y0, B5_T, tol)?;
        Ok(outcome(max_diff(&y, &B5_Y20), e, s))
    });
    let top = |case: TopCase| -> Runner {
        Box::new(move |tol| {
            let (y, e, s) = run(SpinningTop, case.angles0(), case.t_end, tol)?;
            Ok(outcome((y[1].cos() - case.u_end).abs(), e, s))
        })
    };
    Ok(problem_runs(vec![
        (Problem::Separatrix, sep),
        (Problem::B5, b5),
        (Problem::HeavyTop, top(heavy)),
        (Problem::FastTop, top(fast)),
        // (f) compares the forms of (c)'s top: Taylor runs on the angle form.
        (Problem::Forms, top(heavy)),
    ]))
}

/// Problem (e) for Taylor's method: the generated recurrences of (a) at a fixed order 12
/// and the fixed step h = 0.01 of the other methods' 10⁶ steps (with h a fiftieth of the
/// series' radius, order 12 leaves a truncation far below rounding in each step, so what
/// (e) measures is the compensated summation's drift).
pub fn long_run_fixed() -> ProblemRun {
    super::methods::long_run(|h, n| {
        let cfg = TaylorConfig {
            max_steps: n + 1,
            ..TaylorConfig::fixed(12, h)
        };
        let s = solve(euler_body(), 0.0, SEP_M0, h * n as f64, &[], cfg)?;
        Ok(s.y)
    })
}

/// Taylor's method on (a) and (b) with the same equations interpreted ([`TaylorTape`]),
/// the price of not generating them.
pub fn interpreted_runs() -> Vec<ProblemRun> {
    tape_runs(config, vec![1e-6, 1e-8, 1e-10, 1e-12, 1e-14], 1e-8)
}

/// Taylor's method on (a) and (b) with the low orders of each step in double-double (the
/// extended mode, on the interpreted recurrences): the error below the double floor.
pub fn extended_runs() -> Vec<ProblemRun> {
    let extended = |tol| config(tol).extended_orders(EXTENDED_LOW_ORDERS);
    tape_runs(extended, vec![1e-10, 1e-12, 1e-14, 1e-16, 1e-18], 1e-12)
}

/// (a) and (b) on their interpreted tapes under the configuration `cfg` makes of a
/// tolerance.
fn tape_runs(cfg: fn(f64) -> TaylorConfig, ladder: Vec<f64>, quick: f64) -> Vec<ProblemRun> {
    let sep: Runner = Box::new(move |tol| {
        let reference = super::problems::separatrix_reference();
        let s = solve(tape(false)?, 0.0, SEP_M0, SEP_T, &[], cfg(tol))?;
        Ok(outcome(
            max_diff(&s.y, &reference),
            s.stats.rhs_evals,
            s.stats.steps,
        ))
    });
    let b5: Runner = Box::new(move |tol| {
        let s = solve(tape(true)?, 0.0, B5_Y0, B5_T, &[], cfg(tol))?;
        Ok(outcome(
            max_diff(&s.y, &B5_Y20),
            s.stats.rhs_evals,
            s.stats.steps,
        ))
    });
    [(Problem::Separatrix, sep), (Problem::B5, b5)]
        .into_iter()
        .map(|(problem, run)| ProblemRun {
            problem,
            ladder: ladder.clone(),
            quick,
            run,
        })
        .collect()
}

fn problem_runs(runs: Vec<(Problem, Runner)>) -> Vec<ProblemRun> {
    let ladder = vec![1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    runs.into_iter()
        .map(|(problem, run)| ProblemRun {
            problem,
            ladder: ladder.clone(),
            quick: 1e-8,
            run,
        })
        .collect()
}

fn outcome(error: f64, evals: u64, steps: u64) -> Outcome {
    Outcome {
        error,
        evals: Some(evals),
        steps,
    }
}
