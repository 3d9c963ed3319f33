//! A crank-rocker four-bar linkage under gravity as a closed kinematic loop: three link
//! angles, two holonomic closure constraints eliminated symbolically, the loop kept closed
//! by coordinate partitioning, over ten thousand crank turns.
//!
//! ```sh
//! cargo run --release --example four_bar [plot directory]
//! ```
//!
//! Ground d = 3, crank a = 1, coupler b = 3, rocker c = 2.5 (uniform rods of 0.5, 1.5 and
//! 1.2 kg): Grashof's condition s + l < p + q holds (1 + 3 < 3 + 2.5) with the shortest link
//! the crank next to the ground, so the crank turns fully and the rocker swings. The
//! crank angle θ₁ is the free coordinate; the coupler θ₂ and rocker θ₃ follow from the loop
//! and are checked against Freudenstein's closed form
//! K₁ cos θ₃ − K₂ cos θ₁ + K₃ = cos(θ₁ − θ₃), K₁ = d/a, K₂ = d/c,
//! K₃ = (a² − b² + c² + d²)/(2ac). The energy, conserved by the equations, measures the
//! integrator's error; the loop residual |φ| is shown with partitioning (Newton on θ₂, θ₃
//! after each step), without (plain integration of the dependent angles), and with
//! Baumgarte's stabilisation ∂φ/∂q q̇ + β φ = 0 in place of the closure's derivative.

mod common;

use std::error::Error;

use common::{Axes, Series, Table, plot};
use precess::lagrange::{ConstrainedEquations, ConstrainedModel, Constraints, Coordinates};
use precess::lagrange::{EquationsOfMotion, LagrangeError, op_count};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::{Arena, ExprId};

const LINKS: [f64; 4] = [1.0, 3.0, 2.5, 3.0];
const MASSES: [f64; 3] = [0.5, 1.5, 1.2];
const G: f64 = 9.81;
const TURNS: f64 = 1e4;
/// The Baumgarte rate β [1/s] of the comparison run: a few times the crank's frequency.
const BETA: f64 = 10.0;

fn values() -> Vec<(&'static str, f64)> {
    let [a, b, c, d] = LINKS;
    let [m1, m2, m3] = MASSES;
    let names = ["a", "b", "c", "d", "m1", "m2", "m3", "g"];
    names.into_iter().zip([a, b, c, d, m1, m2, m3, G]).collect()
}

/// The Lagrangian of the three rods, the two closure constraints, the reduction with θ₁
/// free; the energy and the two residuals φ are the extra outputs. With `baumgarte` the
/// closure is imposed as the stabilised velocity constraint ∂φ/∂q q̇ + β φ = 0 (φ then
/// decays at the rate β, the parameter `beta`) instead of ∂φ/∂q q̇ = 0.
fn four_bar(
    a: &mut Arena,
    baumgarte: bool,
) -> Result<(ConstrainedEquations, Vec<ExprId>), LagrangeError> {
    let c = Coordinates::new(a, &["th1", "th2", "th3"]);
    let [la, lb, lc, ld] = ["a", "b", "c", "d"].map(|n| a.parameter(n));
    let [m1, m2, m3, g] = ["m1", "m2", "m3", "g"].map(|n| a.parameter(n));
    let cs: Vec<(ExprId, ExprId)> = c.q.iter().map(|&q| (a.cos(q), a.sin(q))).collect();
    let half = a.number("0.5")?;
    let (three, twelve) = (a.integer(3), a.integer(12));
    let (third, twelfth) = (a.recip(three)?, a.recip(twelve)?);
    // The coupler's centre a e₁ + (b/2) e₂.
    let x = [a.mul(la, cs[0].0), a.product(&[half, lb, cs[1].0])];
    let y = [a.mul(la, cs[0].1), a.product(&[half, lb, cs[1].1])];
    let (gx, gy) = (a.sum(&x), a.sum(&y));
    let (vx, vy) = (a.dt(gx), a.dt(gy));
    let [w1, w2, w3] = [c.rates[0], c.rates[1], c.rates[2]];
    let v2 = {
        let (x, y) = (a.mul(vx, vx), a.mul(vy, vy));
        a.add(x, y)
    };
    let kinetic = [
        a.product(&[half, third, m1, la, la, w1, w1]),
        a.product(&[half, m2, v2]),
        a.product(&[half, twelfth, m2, lb, lb, w2, w2]),
        a.product(&[half, third, m3, lc, lc, w3, w3]),
    ];
    let kinetic = a.sum(&kinetic);
    let potential = [
        a.product(&[m1, g, half, la, cs[0].1]),
        a.product(&[m2, g, gy]),
        a.product(&[m3, g, half, lc, cs[2].1]),
    ];
    let potential = a.sum(&potential);
    let lagrangian = a.sub(kinetic, potential);
    let energy = a.add(kinetic, potential);
    let zero = a.zero();
    let eom = EquationsOfMotion::derive(a, lagrangian, c.clone(), &[zero; 3])?;
    // φ = (a e₁ + b e₂) − (d x̂ + c e₃).
    let (cx, cy) = (a.mul(lc, cs[2].0), a.mul(lc, cs[2].1));
    let phi_x = [a.mul(la, cs[0].0), a.mul(lb, cs[1].0), a.neg(ld), a.neg(cx)];
    let phi_y = [a.mul(la, cs[0].1), a.mul(lb, cs[1].1), a.neg(cy)];
    let (phi_x, phi_y) = (a.sum(&phi_x), a.sum(&phi_y));
    let mut k = Constraints::new();
    k.holonomic(a, &c, phi_x)?.holonomic(a, &c, phi_y)?;
    if baumgarte {
        let beta = a.parameter("beta");
        let mut stabilised = Constraints::new();
        for (row, phi) in k.coefficients.iter().zip([phi_x, phi_y]) {
            let offset = a.mul(beta, phi);
            stabilised.nonholonomic(a, &c, row, offset)?;
        }
        k = stabilised;
    }
    Ok((eom.constrain(a, &k, None)?, vec![energy, phi_x, phi_y]))
}

/// Freudenstein's rocker angle θ₃ and the coupler angle θ₂ for the crank at θ₁, on the
/// assembly `branch` = ±1.
fn freudenstein(theta1: f64, branch: f64) -> (f64, f64) {
    let [a, b, c, d] = LINKS;
    let (k1, k2, k3) = (
        d / a,
        d / c,
        (a * a - b * b + c * c + d * d) / (2.0 * a * c),
    );
    let (ca, cb, cc) = (k1 - theta1.cos(), -theta1.sin(), k3 - k2 * theta1.cos());
    let t = (-cb + branch * (ca * ca + cb * cb - cc * cc).sqrt()) / (cc - ca);
    let theta3 = 2.0 * t.atan();
    let bx = d + c * theta3.cos() - a * theta1.cos();
    let by = c * theta3.sin() - a * theta1.sin();
    (by.atan2(bx), theta3)
}

/// `x − y` wrapped into (−π, π].
fn wrap(x: f64, y: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let d = (x - y).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}

struct Run {
    /// (t, max |φ| so far, (E − E₀)/E₀).
    samples: Vec<(f64, f64, f64)>,
    end: [f64; 4],
    newton: usize,
    steps: u64,
}

fn run(
    model: &ConstrainedModel,
    y0: [f64; 4],
    t_end: f64,
    partition: bool,
) -> Result<Run, Box<dyn Error>> {
    let e0 = model.outputs(0.0, &y0)?[0];
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(model.system::<4>()?, 0.0, y0, cfg)?;
    let (mut samples, mut newton, mut worst) = (Vec::new(), 0, 0.0_f64);
    let n = 400;
    for k in 1..=n {
        let t = t_end * f64::from(k) / f64::from(n);
        if partition {
            newton += model.advance_partitioned(&mut ode, t, 1e-15)?;
        } else {
            ode.advance_to(t)?;
        }
        let y = *ode.y();
        let out = model.outputs(t, &y)?;
        worst = out[1..].iter().fold(worst, |w, v| w.max(v.abs()));
        let e = out[0];
        samples.push((t, worst, (e - e0) / e0));
    }
    let steps = ode.stats().steps;
    Ok(Run {
        samples,
        end: *ode.y(),
        newton,
        steps,
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut l = LINKS;
    l.sort_by(f64::total_cmp);
    println!(
        "Grashof: s + l = {} < p + q = {} ({}); the crank a = {} is the shortest link",
        l[0] + l[3],
        l[1] + l[2],
        if l[0] + l[3] < l[1] + l[2] {
            "crank-rocker"
        } else {
            "no full turn"
        },
        LINKS[0]
    );
    let mut a = Arena::new();
    let (eqs, outputs) = four_bar(&mut a, false)?;
    let ops = op_count(&a, &eqs.rhs_outputs());
    let aug = eqs.equations.augmented(&mut a, &eqs.constraints)?;
    let aug_ops = op_count(&a, &aug);
    let model = ConstrainedModel::new(&mut a, &eqs, &outputs, &values())?;
    let (stabilised, outputs) = four_bar(&mut a, true)?;
    let mut with_beta = values();
    with_beta.push(("beta", BETA));
    let baumgarte = ConstrainedModel::new(&mut a, &stabilised, &outputs, &with_beta)?;
    println!(
        "right-hand side: {} operations reduced (θ̇₂, θ̇₃, θ̈₁), {} for the augmented 5 × 5 system (θ̈, λ)",
        ops.total(),
        aug_ops.total()
    );
    let (t2, t3) = freudenstein(0.3, 1.0);
    let y0 = [0.3, t2, t3, 6.0];
    // A crank turn takes about 0.74 s at this energy; run ten thousand.
    let period = {
        let probe = run(&model, y0, 20.0, true)?;
        20.0 / ((probe.end[0] - y0[0]) / std::f64::consts::TAU)
    };
    let t_end = TURNS * period;
    let on = run(&model, y0, t_end, true)?;
    let off = run(&model, y0, t_end, false)?;
    let stab = run(&baumgarte, y0, t_end, false)?;
    let turns = (on.end[0] - y0[0]) / std::f64::consts::TAU;
    let (f2, f3) = freudenstein(on.end[0], 1.0);
    let (g2, g3) = freudenstein(off.end[0], 1.0);
    let mut table = Table::default();
    table.row(
        "θ₃ at the end, partitioned [rad]",
        on.end[2],
        on.end[2] - wrap(on.end[2], f3),
    );
    table.row(
        "θ₂ at the end, partitioned [rad]",
        on.end[1],
        on.end[1] - wrap(on.end[1], f2),
    );
    table.row(
        "θ₃ at the end, plain [rad]",
        off.end[2],
        off.end[2] - wrap(off.end[2], g3),
    );
    table.row(
        "θ₂ at the end, plain [rad]",
        off.end[1],
        off.end[1] - wrap(off.end[1], g2),
    );
    let last = |r: &Run| r.samples.last().map_or((0.0, 0.0), |s| (s.1, s.2));
    let e0 = model.outputs(0.0, &y0)?[0];
    table.row(
        "energy at the end, partitioned [J]",
        e0 * (1.0 + last(&on).1),
        e0,
    );
    table.row(
        "energy at the end, plain [J]",
        e0 * (1.0 + last(&off).1),
        e0,
    );
    table.print(&format!(
        "Four-bar over {turns:.0} crank turns ({t_end:.0} s), DOP853 at rtol = atol = 1e-12"
    ));
    println!(
        "  max |φ| partitioned: {:.2e} ({} steps, {} Newton iterations)",
        last(&on).0,
        on.steps,
        on.newton
    );
    println!(
        "  max |φ| plain:       {:.2e} ({} steps)",
        last(&off).0,
        off.steps
    );
    println!(
        "  max |φ| Baumgarte (β = {BETA}/s): {:.2e} ({} steps), energy error at the end {:.2e}",
        last(&stab).0,
        stab.steps,
        last(&stab).1
    );
    let floor = |v: f64| v.abs().max(1e-17);
    let path = plot(
        "four_bar_residual.svg",
        &Axes {
            title: "Four-bar: loop residual max |φ| and energy error over 10⁴ crank turns",
            x: "t [s]",
            y: "max |φ| [m], |E − E₀|/E₀",
            log_x: false,
            log_y: true,
        },
        &[
            Series::line(
                "|φ| partitioned",
                on.samples.iter().map(|s| (s.0, floor(s.1))).collect(),
            ),
            Series::line(
                "|φ| plain",
                off.samples.iter().map(|s| (s.0, floor(s.1))).collect(),
            ),
            Series::line(
                "|φ| Baumgarte",
                stab.samples.iter().map(|s| (s.0, floor(s.1))).collect(),
            ),
            Series::line(
                "energy, partitioned",
                on.samples.iter().map(|s| (s.0, floor(s.2))).collect(),
            ),
            Series::line(
                "energy, plain",
                off.samples.iter().map(|s| (s.0, floor(s.2))).collect(),
            ),
        ],
    )?;
    println!("  wrote {}", path.display());
    Ok(())
}
