//! The Taylor step's defect check against a defect that vanishes at the step's end by
//! chance: x′ = cos t + a s²⁰(1 − s/h) with s = t − tₛ past tₛ (and cos t alone before),
//! tₛ and h the start and size of a step the integrator takes on cos t alone. The runs with
//! and without the bump are the same up to tₛ; the jet at tₛ has no row of the bump below
//! order 21, above the step's order, so the bump is invisible to the step size; at tₛ + h
//! its factor (1 − s/h) is zero, so the defect f − y_p′ there is that of cos t alone. The
//! exact solution from x(0) = 0 is x(tₛ + h) = sin(tₛ + h) + a h²¹/462.

use std::cell::Cell;

use precess::taylor::{OrderRule, Taylor, TaylorConfig, TaylorSystem};

/// x′ = cos t + a s²⁰ (1 − s/h), s = max(t − tₛ, 0); `a = 0` is cos t alone.
#[derive(Debug, Clone, Copy)]
struct Bump {
    a: f64,
    ts: f64,
    h: f64,
}

/// The Taylor coefficients of tⁿ about t₀, g_k = C(n, k) t₀ⁿ⁻ᵏ, for k < len.
fn power_series(n: i32, t0: f64, len: usize) -> Vec<f64> {
    let mut out = vec![0.0; len];
    let mut binomial = 1.0;
    for (k, o) in out.iter_mut().enumerate() {
        let k = k as i32;
        if k > n {
            break;
        }
        *o = binomial * t0.powi(n - k);
        binomial *= f64::from(n - k) / f64::from(k + 1);
    }
    out
}

impl TaylorSystem<1> for Bump {
    type Workspace = ();
    fn max_order(&self) -> usize {
        40
    }
    fn coefficients_into(
        &self,
        _: &mut (),
        t: f64,
        y: &[f64; 1],
        order: usize,
        c: &mut [[f64; 1]],
    ) {
        // g = cos t + a (s²⁰ − s²¹/h) about t: cos's kth coefficient is cos(t + kπ/2)/k!, the
        // bump's none before tₛ.
        let s = t - self.ts;
        let (p20, p21) = if s >= 0.0 {
            (power_series(20, s, order), power_series(21, s, order))
        } else {
            (vec![0.0; order], vec![0.0; order])
        };
        c[0] = *y;
        let mut factorial = 1.0;
        for k in 0..order {
            if k > 0 {
                factorial *= k as f64;
            }
            let cos_k = (t + k as f64 * std::f64::consts::FRAC_PI_2).cos() / factorial;
            let g_k = cos_k + self.a * (p20[k] - p21[k] / self.h);
            c[k + 1][0] = g_k / (k + 1) as f64;
        }
    }
}

/// A step of cos t alone at 1e-10 past t = 3 (the steps grown to their natural size), the
/// bump put on it: the run's error at its end was 2.2 with no step rejected; the defect's
/// slope at the end (the next jet's second row against the polynomial's) rejects it and the
/// run ends within the tolerance.
#[test]
fn a_defect_vanishing_at_the_step_s_end_is_caught_by_its_slope() {
    // Jorba and Zou's order, 13: the bump's t²⁰ is invisible to the jet, which is the case
    // the check exists for. The minimum-work order for one component is above 20 and sees it.
    let cfg = TaylorConfig {
        order_rule: OrderRule::JorbaZou,
        ..TaylorConfig::with_tol(1e-10, 1e-10)
    };
    let cos = Bump {
        a: 0.0,
        ts: 0.0,
        h: 1.0,
    };
    let mut plain = Taylor::new(cos, 0.0, [0.0], cfg).unwrap();
    while plain.t() < 3.0 {
        plain.step(100.0).unwrap();
    }
    let ts = plain.t();
    plain.step(100.0).unwrap();
    let h = plain.t() - ts;
    // An error of 2.2 in x(tₛ + h) if the bump were missed: a h²¹/462 = 2.2.
    let a = 2.2 * 462.0 / h.powi(21);
    let mut bumped = Taylor::new(Bump { a, ts, h }, 0.0, [0.0], cfg).unwrap();
    bumped.advance_to(ts + h).unwrap();
    let exact = (ts + h).sin() + a * h.powi(21) / 462.0;
    let error = (bumped.y()[0] - exact).abs();
    eprintln!(
        "bump: ts = {ts}, h = {h}, a = {a:e}, error {error:e}, {:?}",
        bumped.stats()
    );
    assert!(h > 0.5, "the step {h}");
    assert!(bumped.stats().rejections > 0);
    assert!(error < 1e-8, "error {error:e}");
}

/// x′ = y, y′ = −x (c_k from the rotation's recurrence), counting the jets asked of it and
/// the orders they were asked to.
#[derive(Debug, Default)]
struct Counted {
    jets: Cell<u64>,
    orders: Cell<u64>,
    small_jets: Cell<u64>,
}

impl TaylorSystem<2> for Counted {
    type Workspace = ();
    fn max_order(&self) -> usize {
        40
    }
    fn coefficients_into(
        &self,
        _: &mut (),
        _t: f64,
        y: &[f64; 2],
        order: usize,
        c: &mut [[f64; 2]],
    ) {
        self.jets.set(self.jets.get() + 1);
        self.orders.set(self.orders.get() + order as u64);
        if order <= 2 {
            self.small_jets.set(self.small_jets.get() + 1);
        }
        c[0] = *y;
        for k in 1..=order {
            let k1 = k as f64;
            c[k] = [c[k - 1][1] / k1, -c[k - 1][0] / k1];
        }
    }
}

/// The check reads the jet at each step's end, which is the next step's: a checked run asks
/// for one jet a step and one at its end, never a separate evaluation of f (a jet to order 1
/// or 2), and its steps, error and bits are those of the unchecked run. It asked for two
/// evaluations of f a step beside the jet before (the end and the middle).
#[test]
fn the_check_costs_no_evaluation_beyond_the_next_step_s_jet() {
    for tol in [1e-6, 1e-10, 1e-14] {
        let run = |check: bool| {
            let cfg = TaylorConfig {
                defect_check: check,
                ..TaylorConfig::with_tol(tol, tol)
            };
            let mut ode = Taylor::new(Counted::default(), 0.0, [0.0, 1.0], cfg).unwrap();
            ode.advance_to(50.0).unwrap();
            let stats = ode.stats();
            let sys = ode.system();
            let counts = (sys.jets.get(), sys.orders.get(), sys.small_jets.get());
            (*ode.y(), stats, counts)
        };
        let (y, stats, (jets, orders, small)) = run(true);
        let (y_plain, plain, (plain_jets, _, _)) = run(false);
        assert_eq!(
            small, 0,
            "tol {tol:e}: {small} evaluations of f besides the jets"
        );
        assert_eq!(stats.rejections, 0, "tol {tol:e}");
        assert_eq!(
            jets,
            stats.steps + 1,
            "tol {tol:e}: a jet a step and one at the end"
        );
        assert_eq!(plain_jets, plain.steps, "tol {tol:e}");
        assert_eq!(
            stats.rhs_evals, orders,
            "tol {tol:e}: every order asked is counted"
        );
        assert_eq!(stats.steps, plain.steps, "tol {tol:e}");
        assert_eq!(
            y.map(f64::to_bits),
            y_plain.map(f64::to_bits),
            "tol {tol:e}"
        );
        // Against the closed form (sin 50, cos 50): the tolerance met.
        let exact = [50f64.sin(), 50f64.cos()];
        let error = (y[0] - exact[0]).abs().max((y[1] - exact[1]).abs());
        assert!(error < 100.0 * tol, "tol {tol:e}: error {error:e}");
    }
}
