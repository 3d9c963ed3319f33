//! The Taylor integrator of issue 15 on every problem it applies to: (a) and (b) through
//! recurrences built at run time from the right-hand side written symbolically
//! ([`TaylorTape`]), (c) and (d) through the recurrences the derive generates for the
//! report's top (`taylor = 20` on its `#[top]`).

use std::error::Error;

use precess::sym::{Arena, ExprId};
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape, solve};

use super::methods::{Outcome, ProblemRun, Runner};
use super::problems::{
    B5_T, B5_Y0, B5_Y20, Problem, SEP_I, SEP_M0, SEP_T, SpinningTop, TopCase, max_diff,
};

/// Euler's torque-free equations ṁ = m × I⁻¹m, or DETEST B5 (ẏ = (y₂y₃, −y₁y₃, −0.51 y₁y₂)),
/// as symbolic right-hand sides over three state symbols.
fn tape(b5: bool) -> Result<TaylorTape<3>, Box<dyn Error>> {
    let mut a = Arena::new();
    let y: [ExprId; 3] = ["y1", "y2", "y3"].map(|n| a.coordinate(n));
    let rhs: [ExprId; 3] = if b5 {
        let k = a.number("0.51")?;
        let p12 = a.mul(y[0], y[1]);
        let p13 = a.mul(y[0], y[2]);
        let kp12 = a.mul(k, p12);
        [a.mul(y[1], y[2]), a.neg(p13), a.neg(kp12)]
    } else {
        let inv = SEP_I.map(|i| 1.0 / i);
        let [i1, i2, i3] = ["inv_i1", "inv_i2", "inv_i3"].map(|n| a.parameter(n));
        let w = [a.mul(i1, y[0]), a.mul(i2, y[1]), a.mul(i3, y[2])];
        // ṁ = m × ω, component i = m_j ω_k − m_k ω_j for (i, j, k) cyclic.
        let cross = |a: &mut Arena, j: usize, k: usize| {
            let l = a.mul(y[j], w[k]);
            let r = a.mul(y[k], w[j]);
            a.sub(l, r)
        };
        let out = [
            cross(&mut a, 1, 2),
            cross(&mut a, 2, 0),
            cross(&mut a, 0, 1),
        ];
        let values = [("inv_i1", inv[0]), ("inv_i2", inv[1]), ("inv_i3", inv[2])];
        return Ok(TaylorTape::new(&a, y, out, None, &values, 40)?);
    };
    Ok(TaylorTape::new(&a, y, rhs, None, &[], 40)?)
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

/// Taylor's method on (a), (b), (c) and (d).
pub fn taylor_runs(heavy: TopCase, fast: TopCase) -> Result<Vec<ProblemRun>, Box<dyn Error>> {
    let ladder = vec![1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    let sep: Runner = Box::new(|tol| {
        let reference = super::problems::separatrix_reference();
        let (y, e, s) = run(tape(false)?, SEP_M0, SEP_T, tol)?;
        Ok(outcome(max_diff(&y, &reference), e, s))
    });
    let b5: Runner = Box::new(|tol| {
        let (y, e, s) = run(tape(true)?, B5_Y0, B5_T, tol)?;
        Ok(outcome(max_diff(&y, &B5_Y20), e, s))
    });
    let top = |case: TopCase| -> Runner {
        Box::new(move |tol| {
            let (y, e, s) = run(SpinningTop, case.angles0(), case.t_end, tol)?;
            Ok(outcome((y[1].cos() - case.u_end).abs(), e, s))
        })
    };
    Ok([
        (Problem::Separatrix, sep),
        (Problem::B5, b5),
        (Problem::HeavyTop, top(heavy)),
        (Problem::FastTop, top(fast)),
    ]
    .into_iter()
    .map(|(problem, run)| ProblemRun {
        problem,
        ladder: ladder.clone(),
        quick: 1e-8,
        run,
    })
    .collect())
}

fn outcome(error: f64, evals: u64, steps: u64) -> Outcome {
    Outcome {
        error,
        evals: Some(evals),
        steps,
    }
}
