//! The order a tolerance gives: Jorba and Zou's rule, or the order of least work per unit
//! time under a cost model of the whole step.
//!
//! Jorba and Zou (2005) size a step of order p as h = κ(p)·ρ, ρ the radius of convergence
//! estimated from the last rows, with κ(p) = ε^(1/(p−1))·e^(−0.7/(p−1)), which keeps the
//! estimated truncation error at ε. If a step's work were all in the jet's Cauchy products,
//! W(p) ∝ p², the work per unit time W(p)/κ(p) would be least near p = 1 − ½ ln ε, their
//! order, where κ = e⁻²·e^(−0.7/(p−1)); heyoka and TIDES use it ([`OrderRule::JorbaZou`]).
//!
//! A step costs more than its products: every order writes N rows and the step's Horner sum,
//! the radius's norms and the defect check's chains are linear in p, and the radius's
//! logarithms, the commit and an event's scan are paid once a step. Counted by callgrind in
//! the generated jets of DETEST B5 (N = 3, three products) and of the heavy top in
//! Euler–Poisson form (N = 6, eight products) at the orders 12 … 24, a step's instructions
//! fit a(p² + b p + c) with b = 11.6 and 7.6, c = 111 and 66. [`OrderRule::MinimumWork`]
//! takes W(p) = p² + 10 p + 360/N and the order p ≥ the Jorba–Zou order, up to the caps,
//! that minimises W(p)/κ(p), with the step κ(p)·ρ; it is precess's default. That is about 1.5 times the Jorba–Zou
//! order: 18 on the heavy top and 19 on B5 at ε = 10⁻¹⁰, where Jorba–Zou gives 13.
//!
//! The model leaves out that ρ itself grows with p where the components are measured at
//! their own scales ([`StepScale::Componentwise`](super::StepScale::Componentwise)): a
//! component held k times tighter than the largest enters the radius as k^(1/p). There the
//! higher order gains more than the model says (docs/performance.md has the measurements).

/// How a tolerance ε chooses the order p of the Taylor steps and the step h = κ(p)·ρ, ρ the
/// radius of convergence estimated from the jet and κ(p) = ε^(1/(p−1))·e^(−0.7/(p−1)) the
/// factor that keeps the estimated truncation error at ε.
///
/// Jorba and Zou's order minimises the work per unit time of a step whose cost is all in the
/// jet's products, W ∝ p². A step also costs work linear in p (rows written, the Horner sum,
/// the radius's norms, the defect check's chains) and a fixed part (logarithms, the commit,
/// an event's scan): counted in instructions, a step of DETEST B5 (N = 3) and of the heavy top
/// in Euler–Poisson form (N = 6) fits a(p² + b p + c) with b = 11.6 and 7.6, c = 111 and 66.
/// [`OrderRule::MinimumWork`] minimises W(p)/κ(p) under W(p) = p² + 10 p + 360/N.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OrderRule {
    /// p = ⌈1 − ½ ln ε⌉ and the step e⁻²·e^(−0.7/(p−1))·ρ (Jorba and Zou, as heyoka and
    /// TIDES run it).
    JorbaZou,
    /// The order of least work per unit time under the model W(p) = p² + 10 p + 360/N of a
    /// step's cost, at least the Jorba–Zou order, with the step ε^(1/(p−1))·e^(−0.7/(p−1))·ρ
    /// that keeps the estimated truncation error at ε at that order.
    #[default]
    MinimumWork,
}

/// The Jorba–Zou order of a tolerance, p = ⌈1 − ½ ln ε⌉, at least 2, before any cap.
pub(super) fn jorba_zou(eps: f64) -> usize {
    (1.0 - 0.5 * eps.ln()).ceil().max(2.0) as usize
}

/// The step factor κ(p) = ε^(1/(p−1))·e^(−0.7/(p−1)) that keeps the estimated truncation
/// error of a step of order p at ε.
pub(super) fn balanced_factor(eps: f64, order: usize) -> f64 {
    let pm1 = (order.max(2) - 1) as f64;
    (eps.ln() / pm1).exp() * (-0.7 / pm1).exp()
}

/// The order p in [Jorba–Zou order, `cap`] that minimises W(p)/κ(p) for a system of `n`
/// components, W(p) = p² + 10 p + 360/n (`cap` itself when the Jorba–Zou order is above it).
pub(super) fn minimum_work(eps: f64, n: usize, cap: usize) -> usize {
    let fixed = 360.0 / n.max(1) as f64;
    // ln(W(p)/κ(p)) = ln W(p) − (ln ε − 0.7)/(p − 1): one logarithm an order, no exponential
    // (every `Taylor::new` of an ensemble's runs chooses its order).
    let log_eps = eps.ln() - 0.7;
    let log_work_per_time = |p: usize| {
        let pf = p as f64;
        (pf * pf + 10.0 * pf + fixed).ln() - log_eps / (pf - 1.0)
    };
    let low = jorba_zou(eps);
    if low >= cap {
        return cap;
    }
    // W/κ is convex in p over this range: walk up while it falls.
    let (mut best, mut here) = (low, log_work_per_time(low));
    while best < cap {
        let next = log_work_per_time(best + 1);
        if next >= here {
            break;
        }
        (best, here) = (best + 1, next);
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_jorba_zou_order_minimises_the_work_of_products_alone() {
        // W = p² alone: d/dp [2 ln p − (ln ε − 0.7)/(p − 1)] = 0 near p = 1 − ½ ln ε.
        for eps in [1e-6, 1e-10, 1e-14] {
            let cost = |p: usize| (p * p) as f64 / balanced_factor(eps, p);
            let p = jorba_zou(eps);
            let best = (2..60)
                .min_by(|&a, &b| cost(a).total_cmp(&cost(b)))
                .unwrap();
            assert!(
                best.abs_diff(p) <= 1,
                "eps {eps}: rule {p}, least p² work at {best}"
            );
        }
    }

    #[test]
    fn the_minimum_work_order_is_the_model_s_minimum() {
        for (eps, n) in [(1e-8, 3), (1e-10, 3), (1e-10, 6), (1e-14, 6), (1e-16, 1)] {
            let fixed = 360.0 / n as f64;
            let cost = |p: usize| {
                let pf = p as f64;
                (pf * pf + 10.0 * pf + fixed) / balanced_factor(eps, p)
            };
            let brute = (jorba_zou(eps)..=40)
                .min_by(|&a, &b| cost(a).total_cmp(&cost(b)))
                .unwrap();
            assert_eq!(minimum_work(eps, n, 40), brute, "eps {eps}, n {n}");
            assert!(brute > jorba_zou(eps), "eps {eps}: {brute}");
        }
        // The model's orders at 1e-10 (docs/performance.md measured the least work at 18–24 on
        // the heavy top and at 20 on B5).
        assert_eq!(minimum_work(1e-10, 6, 40), 18);
        assert_eq!(minimum_work(1e-10, 3, 40), 19);
        // Capped by the system or the configuration.
        assert_eq!(minimum_work(1e-10, 3, 15), 15);
        assert_eq!(minimum_work(1e-20, 3, 12), 12);
    }

    #[test]
    fn the_balanced_factor_is_e_to_the_minus_two_at_the_rule_s_exact_order() {
        // ε = e^(−2(p−1)) makes ε^(1/(p−1)) = e⁻².
        let eps = (-2.0f64 * 12.0).exp();
        let want = (-2.0f64).exp() * (-0.7f64 / 12.0).exp();
        assert!((balanced_factor(eps, 13) - want).abs() < 1e-15);
    }
}
