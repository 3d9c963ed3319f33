//! The paper form on small expressions whose printed form is known by hand.

use super::{paper_equation, paper_latex};
use crate::sym::{Arena, ExprId};

/// An arena with θ, φ and their rates, and parameters a, b.
struct Fixture {
    a: Arena,
    theta: ExprId,
    phi_dot: ExprId,
    theta_dot: ExprId,
    pa: ExprId,
    pb: ExprId,
}

fn fixture() -> Fixture {
    let mut a = Arena::new();
    let phi = a.coordinate("phi");
    let theta = a.coordinate("theta");
    let phi_dot = a.rate(phi).unwrap_or(phi);
    let theta_dot = a.rate(theta).unwrap_or(theta);
    let (pa, pb) = (a.parameter("a"), a.parameter("b"));
    Fixture {
        a,
        theta,
        phi_dot,
        theta_dot,
        pa,
        pb,
    }
}

fn pow(a: &mut Arena, e: ExprId, n: i64) -> ExprId {
    a.powi(e, n).unwrap_or(e)
}

/// a (1 − cos² θ) is shorter as a sin² θ; a cos² θ alone is shorter as it is.
#[test]
fn the_shorter_of_sin_squared_and_one_minus_cos_squared() {
    let mut f = fixture();
    let a = &mut f.a;
    let c = a.cos(f.theta);
    let c2 = pow(a, c, 2);
    let t = a.mul(f.pa, c2);
    let e = a.sub(f.pa, t);
    assert_eq!(paper_latex(a, e), r"a \sin^{2}\theta");
    assert_eq!(paper_latex(a, t), r"a \cos^{2}\theta");
    // 1 + cos² θ and 2 − sin² θ print alike in length: the engine's form stays.
    let one = a.one();
    let e = a.add(one, c2);
    assert_eq!(paper_latex(a, e), r"1 + \cos^{2}\theta");
}

/// Terms with the same parameters share one group, their common factor outside.
#[test]
fn terms_group_by_parameter_with_the_common_factor_outside() {
    let mut f = fixture();
    let a = &mut f.a;
    let s = a.sin(f.theta);
    let c = a.cos(f.theta);
    // b φ̇ θ̇ sin θ + b φ̇² sin θ cos θ + a θ̇² = a θ̇² + b φ̇ sin θ (θ̇ + φ̇ cos θ).
    let t1 = a.product(&[f.pb, f.phi_dot, f.theta_dot, s]);
    let w2 = pow(a, f.phi_dot, 2);
    let t2 = a.product(&[f.pb, w2, s, c]);
    let th2 = pow(a, f.theta_dot, 2);
    let t3 = a.mul(f.pa, th2);
    let e = a.sum(&[t1, t2, t3]);
    assert_eq!(
        paper_latex(a, e),
        r"a \dot{\theta}^{2} + b \dot{\phi} \sin\theta \left(\dot{\theta} + \dot{\phi} \cos\theta\right)"
    );
    // A group whose first term is negative takes the sign outside.
    let e = a.neg(e);
    assert_eq!(
        paper_latex(a, e),
        r"-a \dot{\theta}^{2} - b \dot{\phi} \sin\theta \left(\dot{\theta} + \dot{\phi} \cos\theta\right)"
    );
}

/// ½ b (θ̇ ± φ̇ cos θ)² expanded prints as the square.
#[test]
fn perfect_squares_print_as_squares() {
    let mut f = fixture();
    let a = &mut f.a;
    let c = a.cos(f.theta);
    let half = a.number("0.5").unwrap_or(f.pa);
    for (sign, shown) in [(1, "+"), (-1, "-")] {
        let k = a.integer(sign);
        let w = a.product(&[k, f.phi_dot, c]);
        let inner = a.add(f.theta_dot, w);
        let sq = pow(a, inner, 2);
        let e = a.product(&[half, f.pb, sq]);
        let e = a.expand(e);
        assert_eq!(
            paper_latex(a, e),
            format!(
                r"\frac{{1}}{{2}} b \left(\dot{{\theta}} {shown} \dot{{\phi}} \cos\theta\right)^{{2}}"
            )
        );
    }
}

/// A rational factor comes out of a group only when it leaves small integers inside.
#[test]
fn small_rational_factors_come_out() {
    let mut f = fixture();
    let a = &mut f.a;
    let (k1, k2) = (
        a.number("0.03").unwrap_or(f.pa),
        a.number("0.0007").unwrap_or(f.pa),
    );
    let t1 = a.product(&[k1, f.pa, f.theta_dot]);
    let t2 = a.product(&[k2, f.pa, f.phi_dot]);
    let e = a.add(t1, t2);
    // 3/100 and 7/10000 would leave 300 and 7 behind 1/10000: kept on the terms instead.
    assert_eq!(
        paper_latex(a, e),
        r"a \left(\frac{7}{10000} \dot{\phi} + \frac{3}{100} \dot{\theta}\right)"
    );
    let (h1, h2) = (
        a.number("0.5").unwrap_or(f.pa),
        a.number("1.5").unwrap_or(f.pa),
    );
    let t1 = a.product(&[h1, f.pa, f.theta_dot]);
    let t2 = a.product(&[h2, f.pa, f.phi_dot]);
    let e = a.add(t1, t2);
    assert_eq!(
        paper_latex(a, e),
        r"\frac{1}{2} a \left(3 \dot{\phi} + \dot{\theta}\right)"
    );
}

/// A product of sums and inverse powers prints as one fraction, its sign outside when the
/// numerator is one negative group.
#[test]
fn quotients_print_as_one_fraction() {
    let mut f = fixture();
    let a = &mut f.a;
    let s = a.sin(f.theta);
    let num = a.add(f.theta_dot, f.phi_dot);
    let den = a.mul(f.pa, s);
    let inv = a.recip(den).unwrap_or(den);
    let neg = a.integer(-2);
    let e = a.product(&[neg, f.pb, num, inv]);
    assert_eq!(
        paper_latex(a, e),
        r"-\frac{2 b \left(\dot{\phi} + \dot{\theta}\right)}{a \sin\theta}"
    );
    let lhs = a.mul(f.pa, f.theta_dot);
    assert_eq!(paper_equation(a, lhs, e).split(" = ").count(), 2);
}

/// Deep nesting prints without recursion; a high power, or a product of sums with more
/// terms than the limit, stays whole.
#[test]
fn deep_and_large_expressions_print() {
    let mut f = fixture();
    let a = &mut f.a;
    let mut e = f.theta_dot;
    for _ in 0..300 {
        let one = a.one();
        let inner = a.add(one, e);
        e = a.mul(f.phi_dot, inner);
    }
    assert!(paper_latex(a, e).contains(r"\dot{\phi}^{300}"));
    let mut e = f.theta;
    for _ in 0..20_000 {
        e = a.sin(e);
    }
    assert_eq!(paper_latex(a, e).matches(r"\sin").count(), 20_000);
    let sum = a.sum(&[f.pa, f.pb, f.theta_dot, f.phi_dot]);
    let high = pow(a, sum, 13);
    let e = a.mul(high, f.pa);
    assert!(paper_latex(a, e).contains("^{13}"));
    // Two sums of 70 terms: 4900 products, past the limit of 4096.
    let p: Vec<ExprId> = (0..70).map(|i| a.parameter(&format!("p{i}"))).collect();
    let q: Vec<ExprId> = (0..70).map(|i| a.parameter(&format!("q{i}"))).collect();
    let (sp, sq) = (a.sum(&p), a.sum(&q));
    let e = a.product(&[sp, sq, f.theta_dot]);
    assert_eq!(paper_latex(a, e).matches(r"\left(").count(), 2);
}

/// ½ a (θ̇ cos φ + φ̇ sin φ sin θ)², a square only modulo sin² + cos² = 1 (its engine form
/// has six terms), prints as the square.
#[test]
fn squares_modulo_the_trigonometric_identity_print_as_squares() {
    let mut f = fixture();
    let a = &mut f.a;
    let phi = a.coordinate("phi");
    let (cp, sp, st) = (a.cos(phi), a.sin(phi), a.sin(f.theta));
    let x = a.mul(f.theta_dot, cp);
    let y = a.product(&[f.phi_dot, st, sp]);
    let w = a.add(x, y);
    let w2 = pow(a, w, 2);
    let half = a.number("0.5").unwrap_or(f.pa);
    let e = a.product(&[half, f.pa, w2]);
    let e = a.expand(e);
    assert_eq!(
        paper_latex(a, e),
        r"\frac{1}{2} a \left(\dot{\theta} \cos\phi + \dot{\phi} \sin\phi \sin\theta\right)^{2}"
    );
}

/// Powers past what the view holds (or whose product would overflow) print in the engine's
/// form rather than wrapping or looping.
#[test]
fn huge_powers_fall_back_to_the_engine_form() {
    let mut f = fixture();
    let a = &mut f.a;
    let big = pow(a, f.pa, i64::MAX);
    let e = a.mul(big, f.theta_dot);
    let printed = paper_latex(a, e);
    assert!(printed.contains(&i64::MAX.to_string()), "{printed}");
    let sum = a.add(f.pa, f.theta_dot);
    let inv = pow(a, sum, -(1 << 40));
    let e = a.product(&[inv, sum, f.pb]);
    assert!(!paper_latex(a, e).is_empty());
}
