//! The Taylor integrator against DOP853 and Vern9 at matched error, on DETEST B5 to t = 20,
//! the torque-free bodies I = (3, 5, 7) and (3, 5, 9) from m0 = (0, 2, 0.01) to T = 200, and
//! the heavy top of `examples/heavy_top.rs` over 10 nutation periods with its nutation maxima
//! as events, twice: in Euler–Poisson form (ω and the vertical γ in body axes: a polynomial
//! system, so its Taylor recurrences are Cauchy products written by hand here, as are B5's
//! and the free body's), and in the generated angle form (`TopAngles`: the pairs on
//! `TopChart`, Taylor on the recurrences `#[top(taylor = 20)]` generates). The Euler–Poisson
//! top is also written through `taylor_system!` (the testkit's `EulerPoissonTop`, the `HeavyTopGen…`
//! problems: the generated jet against the hand-written one in one run), with its event
//! scanned, expanded through the interpreted tape (`…Expanded`) or compiled by the macro
//! (`…Compiled`, `event ThetaRate = …;`).
//!
//! `cargo bench -p precess-benches --bench taylor` prints the table (error against the closed form, steps,
//! evaluations, the median time of one whole integration over many repeats) and then times a
//! few configurations with criterion (`-- jet` for the cost of a jet against one evaluation
//! of f, `-- step` for what a step costs besides its jet, `-- events` for what an event
//! costs, scanned or expanded with the steps). `PRECESS_TAYLOR_TABLE=0` skips the table. `scripts/heyoka_bench.py` times heyoka on
//! the same problems and tolerances.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::Criterion;
use precess::exact::{Dd, FreeBodyExact};
use precess::ode::{
    AdaptiveConfig, Direction, Dop853, Event, OdeError, Run, Stepper, System, Vern9,
};
use precess::prelude::*;
use precess::sym::{Arena, ExprId};
use precess::taylor::kernels::cauchy;
use precess::taylor::{
    EventSeries, OrderRule, StepScale, Taylor, TaylorConfig, TaylorEvent, TaylorSystem,
};
use precess::top::HeavyTopTheory;
use precess_testkit::systems::{EulerPoissonTop, SpinningTop, ThetaRate};

#[path = "common/taylor_events.rs"]
mod events;

/// DETEST B5 y(20), 30-digit reference (Hull et al. 1972).
const B5_Y20: [f64; 3] = [
    -0.939_657_079_872_920_396_19,
    -0.342_117_775_400_074_906_53,
    0.741_412_659_619_995_300_78,
];

/// The highest order of the hand-written recurrences.
const MAX_ORDER: usize = 60;

/// The series rows a hand-written system keeps in its workspace (as the generated code does).
type Rows = Vec<[f64; MAX_ORDER + 1]>;

/// The workspace's `N` rows, sized on first use, with y loaded at order 0.
fn rows<'w, const N: usize>(
    ws: &'w mut Rows,
    y: &[f64; N],
) -> Option<[&'w mut [f64; MAX_ORDER + 1]; N]> {
    if ws.len() != N {
        ws.clear();
        ws.resize(N, [0.0; MAX_ORDER + 1]);
    }
    let mut rows = ws.get_disjoint_mut(std::array::from_fn(|i| i)).ok()?;
    for (row, yi) in rows.iter_mut().zip(y) {
        row[0] = *yi;
    }
    Some(rows)
}

/// Σ_{j=0}^{k} a_j b_{k−j} for k = a.len() − 1 (the k-th coefficient of a product), with two
/// accumulators so that the additions do not wait on each other: the bench's own sum before
/// `precess::taylor::kernels::cauchy` (kept for the `jet` group's before/after).
#[inline(always)]
fn cauchy_two(a: &[f64], b: &[f64]) -> f64 {
    let (mut even, mut odd) = (0.0, 0.0);
    let mut pairs = a.iter().zip(b.iter().rev());
    while let (Some((x0, y0)), Some((x1, y1))) = (pairs.next(), pairs.next()) {
        even += x0 * y0;
        odd += x1 * y1;
    }
    if a.len() % 2 == 1
        && let (Some(x), Some(y)) = (a.last(), b.first())
    {
        even += x * y;
    }
    even + odd
}

/// Σ_{j=0}^{k} a_j b_{k−j} left to right, one accumulator: `kernels::cauchy` before it
/// summed the interior first and the boundary pair last (kept for the `jet` group's
/// before/after).
#[inline]
fn cauchy_left_to_right(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = 0.0;
    for (x, y) in a.iter().zip(b.iter().rev()) {
        acc += x * y;
    }
    acc
}

/// Coefficient series per variable (the layout the Cauchy products want), copied into the
/// order-major layout of [`TaylorSystem::coefficients`] at the end.
fn series<const N: usize>(y: &[f64; N]) -> [[f64; MAX_ORDER + 1]; N] {
    let mut s = [[0.0; MAX_ORDER + 1]; N];
    for (si, yi) in s.iter_mut().zip(y) {
        si[0] = *yi;
    }
    s
}

fn write_out<const N: usize>(s: &[[f64; MAX_ORDER + 1]; N], order: usize, c: &mut [[f64; N]]) {
    for (k, ck) in c.iter_mut().enumerate().take(order + 1) {
        for (i, v) in ck.iter_mut().enumerate() {
            *v = s[i][k];
        }
    }
}

/// DETEST B5: y' = (y2 y3, −y1 y3, −0.51 y1 y2).
struct B5;
impl System<3> for B5 {
    fn rhs(&self, _t: f64, y: &[f64; 3], d: &mut [f64; 3]) {
        *d = [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]];
    }
}
impl TaylorSystem<3> for B5 {
    type Workspace = Rows;
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        ws: &mut Rows,
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        let Some([s0, s1, s2]) = rows(ws, y) else {
            return;
        };
        c[0] = *y;
        for k in 0..order {
            let d = 1.0 / (k + 1) as f64;
            let next = [
                cauchy(&s1[..=k], &s2[..=k]) * d,
                -cauchy(&s0[..=k], &s2[..=k]) * d,
                -0.51 * cauchy(&s0[..=k], &s1[..=k]) * d,
            ];
            (s0[k + 1], s1[k + 1], s2[k + 1]) = (next[0], next[1], next[2]);
            c[k + 1] = next;
        }
    }
}

/// B5's recurrences as they were before the workspace and the kernels: the series zeroed on
/// the stack each call, two accumulators, the output copied at the end (for the `jet` group).
struct B5Before;
impl TaylorSystem<3> for B5Before {
    type Workspace = ();
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        let mut s = series(y);
        for k in 0..order {
            let d = 1.0 / (k + 1) as f64;
            let [a0, a1, a2] = [&s[0][..=k], &s[1][..=k], &s[2][..=k]];
            let next = [
                cauchy_two(a1, a2) * d,
                -cauchy_two(a0, a2) * d,
                -0.51 * cauchy_two(a0, a1) * d,
            ];
            for (si, v) in s.iter_mut().zip(next) {
                si[k + 1] = v;
            }
        }
        write_out(&s, order, c);
    }
}

/// B5's coefficients at its initial state replayed at every step: a jet that costs a copy, so
/// that an integration with it times the step itself (the `step` group).
struct Replay(Vec<[f64; 3]>);
impl Replay {
    fn b5() -> Self {
        let mut c = vec![[0.0; 3]; MAX_ORDER + 1];
        B5.coefficients_into(&mut Rows::new(), 0.0, &[0.0, 1.0, 1.0], MAX_ORDER, &mut c);
        Self(c)
    }
}
impl TaylorSystem<3> for Replay {
    type Workspace = ();
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        c[0] = *y;
        c[1..=order].copy_from_slice(&self.0[1..=order]);
    }
}

/// B5's recurrences as [`B5`] writes them, with the sums left to right (for the `jet`
/// group: the boundary-last order of `kernels::cauchy` against the plain one).
struct B5LeftToRight;
impl TaylorSystem<3> for B5LeftToRight {
    type Workspace = Rows;
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        ws: &mut Rows,
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        let Some([s0, s1, s2]) = rows(ws, y) else {
            return;
        };
        c[0] = *y;
        for k in 0..order {
            let d = 1.0 / (k + 1) as f64;
            let next = [
                cauchy_left_to_right(&s1[..=k], &s2[..=k]) * d,
                -cauchy_left_to_right(&s0[..=k], &s2[..=k]) * d,
                -0.51 * cauchy_left_to_right(&s0[..=k], &s1[..=k]) * d,
            ];
            (s0[k + 1], s1[k + 1], s2[k + 1]) = (next[0], next[1], next[2]);
            c[k + 1] = next;
        }
    }
}

/// The torque-free body in body momentum: ṁ = m × (I⁻¹ m) = (a0 m1 m2, a1 m2 m0, a2 m0 m1).
struct FreeBody([f64; 3]);
impl FreeBody {
    fn a(&self) -> [f64; 3] {
        let i = self.0;
        [
            1.0 / i[2] - 1.0 / i[1],
            1.0 / i[0] - 1.0 / i[2],
            1.0 / i[1] - 1.0 / i[0],
        ]
    }
}
impl System<3> for FreeBody {
    fn rhs(&self, _t: f64, m: &[f64; 3], d: &mut [f64; 3]) {
        let a = self.a();
        *d = [a[0] * m[1] * m[2], a[1] * m[2] * m[0], a[2] * m[0] * m[1]];
    }
}
impl TaylorSystem<3> for FreeBody {
    type Workspace = Rows;
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        ws: &mut Rows,
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        let a = self.a();
        let Some([m0, m1, m2]) = rows(ws, y) else {
            return;
        };
        c[0] = *y;
        for k in 0..order {
            let d = 1.0 / (k + 1) as f64;
            let next = [
                a[0] * d * cauchy(&m1[..=k], &m2[..=k]),
                a[1] * d * cauchy(&m2[..=k], &m0[..=k]),
                a[2] * d * cauchy(&m0[..=k], &m1[..=k]),
            ];
            (m0[k + 1], m1[k + 1], m2[k + 1]) = (next[0], next[1], next[2]);
            c[k + 1] = next;
        }
    }
}

/// The double-double orders of the "Taylor extended" rows (`TaylorConfig::extended_orders`).
const EXTENDED_ORDERS: usize = 6;

/// A system y'_p = a_p y_q y_r over the cyclic (p, q, r), B5 and the free body, with the
/// double-double low orders of the extended mode (`coefficients_extended_into`) written by
/// hand beside the `f64` jet of `plain`: the constants `a` are in double-double, so that
/// neither 0.51 nor 1/I₃ − 1/I₂ is rounded once for the run.
struct Extended<S> {
    plain: S,
    a: [Dd; 3],
}
impl Extended<B5> {
    /// B5 with −0.51 = −51/100 to 32 digits (the reference's 0.51 is decimal).
    fn b5() -> Self {
        let one = Dd::from(1.0);
        Self {
            plain: B5,
            a: [one, -one, -(Dd::from(51.0) / Dd::from(100.0))],
        }
    }
}
impl Extended<FreeBody> {
    fn free_body(inertia: [f64; 3]) -> Self {
        let inv = inertia.map(|i| Dd::from(1.0) / Dd::from(i));
        Self {
            plain: FreeBody(inertia),
            a: [inv[2] - inv[1], inv[0] - inv[2], inv[1] - inv[0]],
        }
    }
}
impl<S: System<3>> System<3> for Extended<S> {
    fn rhs(&self, t: f64, y: &[f64; 3], d: &mut [f64; 3]) {
        self.plain.rhs(t, y, d);
    }
}
impl<S: TaylorSystem<3>> TaylorSystem<3> for Extended<S> {
    type Workspace = S::Workspace;
    fn max_order(&self) -> usize {
        self.plain.max_order()
    }
    fn coefficients_into(
        &self,
        ws: &mut S::Workspace,
        t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        self.plain.coefficients_into(ws, t, y, order, c);
    }
    fn coefficients_extended_into(
        &self,
        ws: &mut S::Workspace,
        t: Dd,
        y: &[Dd; 3],
        order: usize,
        c: &mut [[f64; 3]],
        low: &mut [[Dd; 3]],
    ) -> bool {
        self.plain
            .coefficients_into(ws, t.to_f64(), &y.map(Dd::to_f64), order, c);
        let Some(last) = low.len().checked_sub(1).map(|l| l.min(order)) else {
            return true;
        };
        // The state's series are the output rows themselves: y_{k+1} = a·(y_q y_r)_k/(k+1).
        low[0] = *y;
        for k in 0..last {
            let dot = |q: usize, r: usize| Dd::dot((0..=k).map(|j| (low[j][q], low[k - j][r])));
            let d = (k + 1) as f64;
            let next = [
                (self.a[0] * dot(1, 2)).div_f64(d),
                (self.a[1] * dot(2, 0)).div_f64(d),
                (self.a[2] * dot(0, 1)).div_f64(d),
            ];
            low[k + 1] = next;
        }
        true
    }
}

/// The symmetric heavy top about its fixed tip in Euler–Poisson form, state (ω, γ) in body
/// axes, γ the upward vertical: I1 ω̇1 = (I1 − I3) ω2 ω3 + Mgl γ2,
/// I1 ω̇2 = (I3 − I1) ω3 ω1 − Mgl γ1, ω̇3 = 0, γ̇ = γ × ω. cos θ = γ3, and θ̇ has the sign
/// of γ2 ω1 − γ1 ω2.
#[derive(Clone, Copy)]
struct EulerPoisson {
    i1: f64,
    i3: f64,
    mgl: f64,
}
impl System<6> for EulerPoisson {
    fn rhs(&self, _t: f64, y: &[f64; 6], d: &mut [f64; 6]) {
        let [w1, w2, w3, g1, g2, g3] = *y;
        let (r, s) = ((self.i1 - self.i3) / self.i1, self.mgl / self.i1);
        *d = [
            r * w2 * w3 + s * g2,
            -r * w3 * w1 - s * g1,
            0.0,
            g2 * w3 - g3 * w2,
            g3 * w1 - g1 * w3,
            g1 * w2 - g2 * w1,
        ];
    }
}
impl TaylorSystem<6> for EulerPoisson {
    type Workspace = Rows;
    fn max_order(&self) -> usize {
        MAX_ORDER
    }
    fn coefficients_into(
        &self,
        ws: &mut Rows,
        _t: f64,
        y: &[f64; 6],
        order: usize,
        c: &mut [[f64; 6]],
    ) {
        let (r, sg) = ((self.i1 - self.i3) / self.i1, self.mgl / self.i1);
        let Some([w1, w2, w3, g1, g2, g3]) = rows(ws, y) else {
            return;
        };
        c[0] = *y;
        for k in 0..order {
            let d = 1.0 / (k + 1) as f64;
            let (w1k, w2k, w3k) = (&w1[..=k], &w2[..=k], &w3[..=k]);
            let (g1k, g2k, g3k) = (&g1[..=k], &g2[..=k], &g3[..=k]);
            let next = [
                (r * cauchy(w2k, w3k) + sg * g2k[k]) * d,
                (-r * cauchy(w3k, w1k) - sg * g1k[k]) * d,
                0.0,
                (cauchy(g2k, w3k) - cauchy(g3k, w2k)) * d,
                (cauchy(g3k, w1k) - cauchy(g1k, w3k)) * d,
                (cauchy(g1k, w2k) - cauchy(g2k, w1k)) * d,
            ];
            for (row, v) in [&mut *w1, &mut *w2, &mut *w3, &mut *g1, &mut *g2, &mut *g3]
                .into_iter()
                .zip(next)
            {
                row[k + 1] = v;
            }
            c[k + 1] = next;
        }
    }
}

/// The heavy top released at rest 20° from the vertical spinning at 150 rad/s: its system
/// (hand-written and generated), initial state, exact nutation period and the span of 10
/// periods.
struct HeavyTop {
    sys: EulerPoisson,
    generated: EulerPoissonTop,
    /// θ̇'s sign as an expression, for the expanded event.
    event: TaylorEvent<6>,
    y0: [f64; 6],
    period: f64,
}

impl HeavyTop {
    fn new() -> Self {
        let top = SpinningTop;
        let moments = top.principal().moments;
        let (i1, i3) = (moments[0], moments[2]);
        let mgl = top.mass() * 9.81 * top.center_of_mass().z;
        let (theta0, w3) = (20f64.to_radians(), 150.0);
        let theory = HeavyTopTheory::new(i1, i3, mgl).unwrap();
        let period = theory
            .motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, w3])
            .unwrap()
            .nutation_period();
        // ZXZ (0, θ0, 0): R = Rx(θ0), γ = Rᵀ ẑ = (0, sin θ0, cos θ0).
        let y0 = [0.0, 0.0, w3, 0.0, theta0.sin(), theta0.cos()];
        Self {
            sys: EulerPoisson { i1, i3, mgl },
            generated: EulerPoissonTop {
                r: (i1 - i3) / i1,
                s: mgl / i1,
            },
            event: theta_rate_event(),
            y0,
            period,
        }
    }
}

/// θ̇ up to a positive factor: its falling zeros are the nutation maxima.
fn theta_rate(y: &[f64; 6]) -> f64 {
    y[4] * y[0] - y[3] * y[1]
}

/// The nutation period from the maxima of θ over 10 periods (the first to the last of the
/// ten) and the work done.
fn heavy_top_period<S: Stepper<State = [f64; 6]>>(
    stepper: &mut S,
    t_end: f64,
) -> Result<(f64, u64, u64), OdeError> {
    heavy_top_period_with(stepper, t_end, theta_rate)
}

/// θ̇ up to a positive factor as an expression over the Euler–Poisson state (ω, γ), for the
/// event expanded in each step's jet, as heyoka's `nt_event` is.
fn theta_rate_event() -> TaylorEvent<6> {
    let mut a = Arena::new();
    let y: [ExprId; 6] = ["w1", "w2", "w3", "g1", "g2", "g3"].map(|n| a.coordinate(n));
    let (p, q) = (a.mul(y[4], y[0]), a.mul(y[3], y[1]));
    let g = a.sub(p, q);
    TaylorEvent::new(&a, y, None, g, &[]).unwrap()
}

/// [`heavy_top_period`] with the event expanded in the jet (`Run::taylor_event`).
fn heavy_top_period_expanded<S: TaylorSystem<6>, G: EventSeries<6>>(
    stepper: &mut Taylor<S, 6>,
    t_end: f64,
    event: &G,
) -> Result<(f64, u64, u64), OdeError> {
    let out = Run::new(stepper, t_end)
        .sample_none()
        .taylor_event(Event::new("maximum").falling(), event)
        .integrate()?;
    let maxima: Vec<f64> = out
        .events
        .iter()
        .filter(|h| h.direction == Direction::Falling)
        .map(|h| h.t)
        .collect();
    let period = match maxima.as_slice() {
        [first, .., last] => (last - first) / (maxima.len() - 1) as f64,
        _ => f64::NAN,
    };
    Ok((period, out.stats.steps, out.stats.rhs_evals))
}

/// As [`heavy_top_period`], with θ̇ (up to a positive factor) read by `rate`.
fn heavy_top_period_with<S: Stepper<State = [f64; 6]>>(
    stepper: &mut S,
    t_end: f64,
    rate: fn(&[f64; 6]) -> f64,
) -> Result<(f64, u64, u64), OdeError> {
    let out = Run::new(stepper, t_end)
        .sample_none()
        .event(Event::new("maximum").falling(), |_t, y| rate(y))
        .integrate()?;
    let maxima: Vec<f64> = out
        .events
        .iter()
        .filter(|h| h.direction == Direction::Falling)
        .map(|h| h.t)
        .collect();
    let period = match maxima.as_slice() {
        [first, .., last] => (last - first) / (maxima.len() - 1) as f64,
        _ => f64::NAN,
    };
    Ok((period, out.stats.steps, out.stats.rhs_evals))
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Problem {
    B5,
    /// The heavy top of [`Problem::HeavyTop`] without its event: what the event scan costs.
    HeavyTopBare,
    /// The heavy top of [`Problem::HeavyTop`] with its event expanded in the jet
    /// (`Run::taylor_event`, as heyoka's `nt_event`) instead of scanned on the dense output.
    HeavyTopExpanded,
    /// [`Problem::HeavyTopExpanded`] with the event compiled by `taylor_system!`
    /// (`ThetaRate`) instead of interpreted.
    HeavyTopCompiled,
    /// [`Problem::HeavyTop`] on the generated jet (`EulerPoissonTop`, Taylor only).
    HeavyTopGen,
    /// [`Problem::HeavyTopBare`] on the generated jet.
    HeavyTopGenBare,
    /// [`Problem::HeavyTopExpanded`] on the generated jet.
    HeavyTopGenExpanded,
    /// [`Problem::HeavyTopCompiled`] on the generated jet: jet and event both compiled.
    HeavyTopGenCompiled,
    Free357,
    Free359,
    HeavyTop,
    TopAngles,
}

#[derive(Clone, Copy, Debug)]
enum Method {
    /// Taylor as configured by default: the order of least work, each component at its own
    /// scale, the defect check on.
    Taylor(f64),
    /// Taylor without the defect check (the order rule's step alone).
    TaylorUnchecked(f64),
    /// Taylor with every component measured against ‖y‖∞ (heyoka's scale).
    TaylorMaxNorm(f64),
    /// Taylor at Jorba and Zou's order (`OrderRule::JorbaZou`), otherwise the default.
    TaylorJorbaZou(f64),
    /// Taylor as heyoka runs it: Jorba and Zou's order, the ‖y‖∞ scale, no defect check.
    TaylorHeyokaRule(f64),
    /// Taylor in the extended mode (B5 and the free bodies only).
    TaylorExtended(f64),
    Dop853(f64),
    Vern9(f64),
}

impl Method {
    fn label(&self) -> String {
        match self {
            Method::Taylor(t) => format!("Taylor tol {t:.0e}"),
            Method::TaylorUnchecked(t) => format!("Taylor nochk {t:.0e}"),
            Method::TaylorMaxNorm(t) => format!("Taylor maxnorm {t:.0e}"),
            Method::TaylorJorbaZou(t) => format!("Taylor jz {t:.0e}"),
            Method::TaylorHeyokaRule(t) => format!("Taylor hyrule {t:.0e}"),
            Method::TaylorExtended(t) => format!("Taylor ext tol {t:.0e}"),
            Method::Dop853(t) => format!("DOP853 tol {t:.0e}"),
            Method::Vern9(t) => format!("Vern9 tol {t:.0e}"),
        }
    }
}

/// The Taylor configuration of a Taylor method (`None` for the pairs and the extended mode).
fn taylor_config(m: Method) -> Option<TaylorConfig> {
    match m {
        Method::Taylor(tol) => Some(TaylorConfig::with_tol(tol, tol)),
        Method::TaylorUnchecked(tol) => Some(TaylorConfig {
            defect_check: false,
            ..TaylorConfig::with_tol(tol, tol)
        }),
        Method::TaylorMaxNorm(tol) => Some(TaylorConfig {
            scale: StepScale::MaxNorm,
            ..TaylorConfig::with_tol(tol, tol)
        }),
        Method::TaylorJorbaZou(tol) => Some(TaylorConfig {
            order_rule: OrderRule::JorbaZou,
            ..TaylorConfig::with_tol(tol, tol)
        }),
        Method::TaylorHeyokaRule(tol) => Some(TaylorConfig {
            order_rule: OrderRule::JorbaZou,
            scale: StepScale::MaxNorm,
            defect_check: false,
            ..TaylorConfig::with_tol(tol, tol)
        }),
        _ => None,
    }
}

/// One whole integration: (final state or period, steps, rhs evaluations).
fn integrate<S: System<N> + TaylorSystem<N>, const N: usize>(
    sys: S,
    y0: [f64; N],
    t_end: f64,
    m: Method,
) -> ([f64; N], u64, u64) {
    fn done<St: Stepper<State = [f64; N]>, const N: usize>(
        mut s: St,
        t_end: f64,
    ) -> ([f64; N], u64, u64) {
        while s.t() < t_end {
            s.step(t_end).unwrap();
        }
        let st = s.stats();
        (*s.state(), st.steps, st.rhs_evals)
    }
    if let Some(cfg) = taylor_config(m) {
        return done(Taylor::new(sys, 0.0, y0, cfg).unwrap(), t_end);
    }
    match m {
        Method::Taylor(_)
        | Method::TaylorUnchecked(_)
        | Method::TaylorMaxNorm(_)
        | Method::TaylorJorbaZou(_)
        | Method::TaylorHeyokaRule(_) => {
            unreachable!("a Taylor configuration")
        }
        Method::TaylorExtended(tol) => {
            let cfg = TaylorConfig::with_tol(tol, tol).extended_orders(EXTENDED_ORDERS);
            done(Taylor::new(sys, 0.0, y0, cfg).unwrap(), t_end)
        }
        Method::Dop853(tol) => done(
            Dop853::new(sys, 0.0, y0, AdaptiveConfig::with_tol(tol, tol)).unwrap(),
            t_end,
        ),
        Method::Vern9(tol) => done(
            Vern9::new(sys, 0.0, y0, AdaptiveConfig::with_tol(tol, tol)).unwrap(),
            t_end,
        ),
    }
}

/// Runs `m` on problem `p`: (error against the reference, steps, rhs evaluations).
fn run(p: Problem, m: Method, top: &HeavyTop, refs: &References) -> (f64, u64, u64) {
    let extended = matches!(m, Method::TaylorExtended(_));
    let free = |inertia: [f64; 3], exact: &[f64; 3]| {
        let m0 = [0.0, 2.0, 0.01];
        let (y, s, e) = if extended {
            integrate(Extended::free_body(inertia), m0, 200.0, m)
        } else {
            integrate(FreeBody(inertia), m0, 200.0, m)
        };
        (max_err(&y, exact), s, e)
    };
    match p {
        Problem::B5 => {
            let (y, s, e) = if extended {
                integrate(Extended::b5(), [0.0, 1.0, 1.0], 20.0, m)
            } else {
                integrate(B5, [0.0, 1.0, 1.0], 20.0, m)
            };
            (max_err(&y, &B5_Y20), s, e)
        }
        Problem::Free357 => free([3.0, 5.0, 7.0], &refs.free357),
        Problem::Free359 => free([3.0, 5.0, 9.0], &refs.free359),
        Problem::HeavyTopExpanded => {
            let Some(cfg) = taylor_config(m).filter(|_| !extended) else {
                return (f64::NAN, 0, 0);
            };
            let mut ode = Taylor::new(top.sys, 0.0, top.y0, cfg).unwrap();
            let (period, s, e) =
                heavy_top_period_expanded(&mut ode, 10.0 * top.period, &top.event).unwrap();
            ((period - top.period).abs() / top.period, s, e)
        }
        Problem::HeavyTopCompiled => {
            let Some(cfg) = taylor_config(m) else {
                return (f64::NAN, 0, 0);
            };
            let mut ode = Taylor::new(top.sys, 0.0, top.y0, cfg).unwrap();
            let event = ThetaRate(&top.generated);
            let (period, s, e) =
                heavy_top_period_expanded(&mut ode, 10.0 * top.period, &event).unwrap();
            ((period - top.period).abs() / top.period, s, e)
        }
        Problem::HeavyTopGen
        | Problem::HeavyTopGenBare
        | Problem::HeavyTopGenExpanded
        | Problem::HeavyTopGenCompiled => {
            // The pairs evaluate f, not the jet: the hand-written rows are theirs.
            let Some(cfg) = taylor_config(m) else {
                return (f64::NAN, 0, 0);
            };
            let mut ode = Taylor::new(top.generated, 0.0, top.y0, cfg).unwrap();
            let t_end = 10.0 * top.period;
            let (period, s, e) = match p {
                Problem::HeavyTopGenBare => {
                    let (_, s, e) = integrate(top.generated, top.y0, t_end, m);
                    return (f64::NAN, s, e);
                }
                Problem::HeavyTopGenExpanded => {
                    heavy_top_period_expanded(&mut ode, t_end, &top.event)
                }
                Problem::HeavyTopGenCompiled => {
                    heavy_top_period_expanded(&mut ode, t_end, &ThetaRate(&top.generated))
                }
                _ => heavy_top_period(&mut ode, t_end),
            }
            .unwrap();
            ((period - top.period).abs() / top.period, s, e)
        }
        Problem::HeavyTopBare => {
            // No reference without the maxima: the error column is left empty.
            if matches!(m, Method::TaylorExtended(_)) {
                return (f64::NAN, 0, 0);
            }
            let (_, s, e) = integrate(top.sys, top.y0, 10.0 * top.period, m);
            (f64::NAN, s, e)
        }
        Problem::HeavyTop => {
            let t_end = 10.0 * top.period;
            let (period, s, e) = match m {
                // The heavy tops' jets have no double-double orders (the table skips them).
                Method::TaylorExtended(_) => return (f64::NAN, 0, 0),
                Method::Taylor(_)
                | Method::TaylorUnchecked(_)
                | Method::TaylorMaxNorm(_)
                | Method::TaylorJorbaZou(_)
                | Method::TaylorHeyokaRule(_) => heavy_top_period(
                    &mut Taylor::new(top.sys, 0.0, top.y0, taylor_config(m).unwrap()).unwrap(),
                    t_end,
                ),
                Method::Dop853(tol) => heavy_top_period(
                    &mut Dop853::new(top.sys, 0.0, top.y0, AdaptiveConfig::with_tol(tol, tol))
                        .unwrap(),
                    t_end,
                ),
                Method::Vern9(tol) => heavy_top_period(
                    &mut Vern9::new(top.sys, 0.0, top.y0, AdaptiveConfig::with_tol(tol, tol))
                        .unwrap(),
                    t_end,
                ),
            }
            .unwrap();
            ((period - top.period).abs() / top.period, s, e)
        }
        Problem::TopAngles => {
            // The generated angle form (ZXZ; θ̇ = y[4]) and its generated recurrences.
            let t_end = 10.0 * top.period;
            let y0 = [0.0, 20f64.to_radians(), 0.0, 0.0, 0.0, 150.0];
            let chart = TopChart::declared(&SpinningTop);
            let (period, s, e) = match m {
                Method::TaylorExtended(_) => return (f64::NAN, 0, 0),
                Method::Taylor(_)
                | Method::TaylorUnchecked(_)
                | Method::TaylorMaxNorm(_)
                | Method::TaylorJorbaZou(_)
                | Method::TaylorHeyokaRule(_) => heavy_top_period_with(
                    &mut Taylor::new(SpinningTop, 0.0, y0, taylor_config(m).unwrap()).unwrap(),
                    t_end,
                    |y| y[4],
                ),
                Method::Dop853(tol) => heavy_top_period_with(
                    &mut Dop853::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(tol, tol)).unwrap(),
                    t_end,
                    |y| y[4],
                ),
                Method::Vern9(tol) => heavy_top_period_with(
                    &mut Vern9::new(&chart, 0.0, y0, AdaptiveConfig::with_tol(tol, tol)).unwrap(),
                    t_end,
                    |y| y[4],
                ),
            }
            .unwrap();
            ((period - top.period).abs() / top.period, s, e)
        }
    }
}

/// The exact torque-free states at T = 200.
struct References {
    free357: [f64; 3],
    free359: [f64; 3],
}

impl References {
    fn new() -> Self {
        let at = |i: [f64; 3]| -> [f64; 3] {
            FreeBodyExact::new(i, [0.0, 2.0, 0.01])
                .unwrap()
                .m_at(200.0)
                .unwrap()
                .into()
        };
        Self {
            free357: at([3.0, 5.0, 7.0]),
            free359: at([3.0, 5.0, 9.0]),
        }
    }
}

fn max_err<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// The median and the minimum over 21 batches of the time of one call, each batch at least
/// 2 ms long (on a loaded machine the minimum is the closer to the unloaded time).
fn median_time(mut f: impl FnMut()) -> (Duration, Duration) {
    let start = Instant::now();
    f();
    let once = start.elapsed().max(Duration::from_nanos(100));
    let reps = (Duration::from_millis(2).as_nanos() / once.as_nanos()).max(1) as u32;
    let mut times: Vec<Duration> = (0..21)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..reps {
                f();
            }
            start.elapsed() / reps
        })
        .collect();
    times.sort();
    (times[times.len() / 2], times[0])
}

fn methods() -> Vec<Method> {
    let tols = [1e-6, 1e-8, 1e-10, 1e-12, 1e-14];
    let mut v: Vec<Method> = tols.iter().map(|&t| Method::Taylor(t)).collect();
    v.extend([1e-15, 1e-16].map(Method::Taylor));
    v.extend(tols.map(Method::TaylorUnchecked));
    v.extend(tols.map(Method::TaylorMaxNorm));
    v.extend(tols.map(Method::TaylorJorbaZou));
    v.extend(tols.map(Method::TaylorHeyokaRule));
    v.extend([1e-15, 1e-16, 1e-17, 1e-18].map(Method::TaylorExtended));
    v.extend(tols.map(Method::Dop853));
    v.extend(tols.map(Method::Vern9));
    v.push(Method::Vern9(1e-15));
    v
}

const PROBLEMS: [Problem; 12] = [
    Problem::B5,
    Problem::Free357,
    Problem::Free359,
    Problem::HeavyTop,
    Problem::HeavyTopBare,
    Problem::HeavyTopExpanded,
    Problem::HeavyTopGen,
    Problem::HeavyTopGenBare,
    Problem::HeavyTopCompiled,
    Problem::HeavyTopGenExpanded,
    Problem::HeavyTopGenCompiled,
    Problem::TopAngles,
];

fn table(top: &HeavyTop, refs: &References) {
    println!(
        "heavy top: I1 = {:.17e}, I3 = {:.17e}, Mgl = {:.17e}, period = {:.17e}",
        top.sys.i1, top.sys.i3, top.sys.mgl, top.period
    );
    println!(
        "free body m(200): I = (3,5,7) {:?}, I = (3,5,9) {:?}",
        refs.free357, refs.free359
    );
    println!(
        "{:<16} {:<18} {:>10} {:>8} {:>9} {:>11} {:>9}",
        "problem", "method", "error", "steps", "evals", "median µs", "min µs"
    );
    // PRECESS_TAYLOR_PROBLEMS=HeavyTop,TopAngles limits the table to those problems.
    let only = std::env::var("PRECESS_TAYLOR_PROBLEMS").ok();
    for p in PROBLEMS {
        if let Some(list) = &only
            && !list.split(',').any(|name| name == format!("{p:?}"))
        {
            continue;
        }
        for m in methods() {
            if matches!(m, Method::TaylorExtended(_))
                && matches!(
                    p,
                    Problem::HeavyTop
                        | Problem::HeavyTopBare
                        | Problem::HeavyTopExpanded
                        | Problem::HeavyTopCompiled
                        | Problem::HeavyTopGen
                        | Problem::HeavyTopGenBare
                        | Problem::HeavyTopGenExpanded
                        | Problem::HeavyTopGenCompiled
                        | Problem::TopAngles
                )
            {
                continue;
            }
            if taylor_config(m).is_none()
                && matches!(
                    p,
                    Problem::HeavyTopCompiled
                        | Problem::HeavyTopGen
                        | Problem::HeavyTopGenBare
                        | Problem::HeavyTopGenExpanded
                        | Problem::HeavyTopGenCompiled
                )
            {
                continue;
            }
            // PRECESS_TAYLOR_METHODS=nochk,maxnorm keeps the methods whose label holds one.
            if let Ok(list) = std::env::var("PRECESS_TAYLOR_METHODS")
                && !list.split(',').any(|part| m.label().contains(part))
            {
                continue;
            }
            // PRECESS_TAYLOR_UNTIMED=1 runs each row once (for callgrind's counts).
            if std::env::var("PRECESS_TAYLOR_UNTIMED").as_deref() == Ok("1") {
                let (err, steps, evals) = run(p, m, top, refs);
                println!(
                    "{:<16} {:<18} {:>10.2e} {:>8} {:>9}",
                    format!("{p:?}"),
                    m.label(),
                    err,
                    steps,
                    evals
                );
                continue;
            }
            let (err, steps, evals) = run(p, m, top, refs);
            let (t, t_min) = median_time(|| {
                black_box(run(black_box(p), black_box(m), top, refs));
            });
            println!(
                "{:<16} {:<18} {:>10.2e} {:>8} {:>9} {:>11.2} {:>9.2}",
                format!("{p:?}"),
                m.label(),
                err,
                steps,
                evals,
                t.as_secs_f64() * 1e6,
                t_min.as_secs_f64() * 1e6
            );
        }
    }
}

fn main() {
    let top = HeavyTop::new();
    let refs = References::new();
    if std::env::var("PRECESS_TAYLOR_TABLE").as_deref() != Ok("0") {
        table(&top, &refs);
    }
    let mut c = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .configure_from_args();
    let mut g = c.benchmark_group("jet");
    let y = [0.3, 0.9, 0.95];
    let mut coeffs = [[0.0; 3]; 41];
    g.bench_function("B5 rhs", |b| {
        b.iter(|| {
            let mut d = [0.0; 3];
            System::rhs(&B5, 0.0, black_box(&y), &mut d);
            d
        })
    });
    let mut ws = Rows::new();
    for order in [10, 13, 20] {
        g.bench_function(format!("B5 coefficients order {order}"), |b| {
            b.iter(|| {
                B5.coefficients_into(&mut ws, 0.0, black_box(&y), order, &mut coeffs);
                coeffs[order]
            })
        });
        g.bench_function(
            format!("B5 coefficients left-to-right order {order}"),
            |b| {
                b.iter(|| {
                    B5LeftToRight.coefficients_into(
                        &mut ws,
                        0.0,
                        black_box(&y),
                        order,
                        &mut coeffs,
                    );
                    coeffs[order]
                })
            },
        );
        g.bench_function(format!("B5 coefficients before order {order}"), |b| {
            b.iter(|| {
                B5Before.coefficients_into(&mut (), 0.0, black_box(&y), order, &mut coeffs);
                coeffs[order]
            })
        });
    }
    g.finish();
    step_group(&mut c);
    events::events_group(&mut c);
    for p in PROBLEMS {
        let mut g = c.benchmark_group(format!("taylor/{p:?}"));
        for m in [
            Method::Taylor(1e-10),
            Method::Taylor(1e-15),
            Method::Dop853(1e-12),
            Method::Vern9(1e-12),
        ] {
            if taylor_config(m).is_none() && run(p, m, &top, &refs).1 == 0 {
                continue;
            }
            g.bench_function(m.label(), |b| b.iter(|| run(p, black_box(m), &top, &refs)));
        }
        if matches!(p, Problem::B5 | Problem::Free357 | Problem::Free359) {
            let m = Method::TaylorExtended(1e-16);
            g.bench_function(m.label(), |b| b.iter(|| run(p, black_box(m), &top, &refs)));
        }
        g.finish();
    }
    c.final_summary();
}

/// What a step costs besides its jet: B5 at tol 1e-10 (order 13) whole, its jets alone, the
/// same steps on replayed coefficients, and the construction.
fn step_group(c: &mut Criterion) {
    let tol = 1e-10;
    let cfg = TaylorConfig::with_tol(tol, tol);
    let mut g = c.benchmark_group("step");
    g.bench_function("B5 tol 1e-10 whole", |b| {
        b.iter(|| integrate(B5, black_box([0.0, 1.0, 1.0]), 20.0, Method::Taylor(tol)))
    });
    // The defect check's price, in the same run: the same integration with and without it
    // (its steps are the same; only the check's jet to order 1 and Horner sum differ).
    for (name, defect_check) in [("on", true), ("off", false)] {
        let cfg = TaylorConfig {
            defect_check,
            ..cfg
        };
        g.bench_function(
            format!("B5 tol 1e-10 advance_to, defect check {name}"),
            |b| {
                b.iter(|| {
                    let mut ode = Taylor::new(B5, 0.0, black_box([0.0, 1.0, 1.0]), cfg).unwrap();
                    ode.advance_to(20.0).unwrap();
                    *ode.y()
                })
            },
        );
    }
    let (_, steps, _) = integrate(B5, [0.0, 1.0, 1.0], 20.0, Method::Taylor(tol));
    let mut ws = Rows::new();
    let mut coeffs = [[0.0; 3]; MAX_ORDER + 1];
    let y = [0.3, 0.9, 0.95];
    g.bench_function(format!("B5 order 13 jets x {steps}"), |b| {
        b.iter(|| {
            for _ in 0..steps {
                B5.coefficients_into(&mut ws, 0.0, black_box(&y), 13, &mut coeffs);
            }
            coeffs[13]
        })
    });
    let replay = Replay::b5();
    // The replayed jet is not the jet of the state it is given, so the defect check would
    // refuse its steps: the replay times the rule and the sum alone, as before the check.
    let unchecked = TaylorConfig {
        defect_check: false,
        ..cfg
    };
    let mut replayed = Taylor::new(&replay, 0.0, [0.0, 1.0, 1.0], unchecked).unwrap();
    let mut replay_steps = 0;
    while replayed.t() < 20.0 {
        replayed.step(20.0).unwrap();
        replay_steps += 1;
    }
    g.bench_function(format!("B5 replayed jets, {replay_steps} steps"), |b| {
        b.iter(|| {
            let mut ode = Taylor::new(&replay, 0.0, black_box([0.0, 1.0, 1.0]), unchecked).unwrap();
            while ode.t() < 20.0 {
                ode.step(20.0).unwrap();
            }
            *ode.y()
        })
    });
    g.bench_function("Taylor::new B5", |b| {
        b.iter(|| Taylor::new(B5, 0.0, black_box([0.0, 1.0, 1.0]), cfg).unwrap())
    });
    g.finish();
}
