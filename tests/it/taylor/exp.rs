//! The exponential, the first primitive of the engine's registry (`precess::sym::functions`),
//! end to end against independent values: its derivative against central differences and
//! the chain rule's closed form, its canonical form (exp 0 = 1), its LaTeX, the lowered
//! program against `f64::exp`, and through `taylor_system!` and the interpreted tape:
//! y = e^(a t) (coefficients e^(a t₀) aᵏ/k!), x' = e^(−x) (x = ln(t + e^(x₀))), and the
//! extended mode's double-double coefficients of e^(1 + τ) against the digits of e.
// Reference constants are quoted with all their digits.
#![allow(clippy::excessive_precision)]

use precess::codegen::{Program, latex};
use precess::exact::Dd;
use precess::sym::functions::EXP;
use precess::sym::{Arena, ExprId, Func};
use precess::taylor::{TaylorConfig, TaylorSystem, TaylorTape};

precess::taylor_system! {
    /// y' = a e^(a t): y = e^(a t) from y(0) = 1, the exponential of the time.
    struct Growth {
        a: f64,
    }
    state [y];
    taylor = 20;
    d/dt y = a * (a * t).exp();
}

precess::taylor_system! {
    /// x' = e^(−x): x = ln(t + e^(x₀)), the exponential of the state, written as a call.
    struct Slowing;
    state [x];
    taylor = 20;
    d/dt x = exp(-x);
}

/// e as a double-double: 2.718281828459045235360287471352662497757 (the known digits),
/// split as the double nearest e and the double nearest the rest.
const E: Dd = Dd {
    hi: std::f64::consts::E,
    lo: 1.4456468917292502e-16,
};

fn exp(a: &mut Arena, u: ExprId) -> ExprId {
    a.apply(EXP, u).unwrap()
}

#[test]
fn exp_is_found_by_name() {
    assert_eq!(Func::named("exp"), Some(EXP));
    assert_eq!(EXP.name(), "exp");
}

#[test]
fn derivative_of_exp_is_the_chain_rule() {
    // d/dx e^(x² sin x) = (2x sin x + x² cos x) e^(x² sin x), against the closed form and
    // against central differences of the value.
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let s = a.as_symbol(x).unwrap();
    let x2 = a.powi(x, 2).unwrap();
    let sin = a.sin(x);
    let u = a.mul(x2, sin);
    let e = exp(&mut a, u);
    let d = a.diff(e, s);
    for v in [-1.3f64, 0.0, 0.4, 2.2] {
        let f = |v: f64| (v * v * v.sin()).exp();
        let want = (2.0 * v * v.sin() + v * v * v.cos()) * f(v);
        let got = a.eval(d, &[v]);
        assert!(
            (got - want).abs() <= 1e-14 * want.abs().max(1.0),
            "{v}: {got} vs {want}"
        );
        let h = 1e-5;
        let fd = (f(v + h) - f(v - h)) / (2.0 * h);
        assert!(
            (got - fd).abs() <= 1e-8 * fd.abs().max(1.0),
            "{v}: {got} vs {fd}"
        );
    }
    // exp is its own derivative: d/dx e^x is the node e^x itself.
    let ex = exp(&mut a, x);
    assert_eq!(a.diff(ex, s), ex);
}

#[test]
fn exp_of_zero_is_one_and_the_form_is_canonical() {
    let mut a = Arena::new();
    let x = a.parameter("x");
    let zero = a.zero();
    assert_eq!(exp(&mut a, zero), a.one());
    // x − x is zero before exp sees it.
    let diff = a.sub(x, x);
    assert_eq!(exp(&mut a, diff), a.one());
    // Equal arguments are one node; substitution refolds exp 0 = 1.
    let e1 = exp(&mut a, x);
    let e2 = exp(&mut a, x);
    assert_eq!(e1, e2);
    let d = a.sub(e1, e2);
    assert!(a.is_zero(d).unwrap());
    let xs = a.as_symbol(x).unwrap();
    let at_zero = a.subs(e1, &[(xs, zero)]).unwrap();
    assert_eq!(at_zero, a.one());
    // e^x − e^(2x/2): equal after expansion of the argument.
    let two = a.integer(2);
    let tx = a.mul(two, x);
    let half = a.div(tx, two).unwrap();
    let e3 = exp(&mut a, half);
    assert_eq!(e3, e1);
    // e^x + 1 is not zero: the opaque function is not confused with a constant.
    let one = a.one();
    let s = a.add(e1, one);
    assert!(!a.is_zero(s).unwrap());
    assert_eq!(a.display(e1), "exp(x)");
}

#[test]
fn exp_in_latex_and_lowered_code() {
    let mut a = Arena::new();
    let x = a.parameter("x");
    let y = a.parameter("y");
    let s = a.add(x, y);
    let e = exp(&mut a, s);
    let ex = exp(&mut a, x);
    assert_eq!(latex(&a, ex), "\\exp x");
    assert_eq!(latex(&a, e), "\\exp\\left(x + y\\right)");
    let p = Program::lower(&a, &[e, ex]);
    for (xv, yv) in [(0.4, 1.1), (-3.0, 0.5)] {
        let got = p.eval(&[xv, yv]);
        assert_eq!(got[0], (xv + yv).exp());
        assert_eq!(got[1], xv.exp());
    }
    let code = p.to_tokens(&mut |_| Default::default());
    assert_eq!(code.lets.to_string().matches("f64 :: exp").count(), 2);
}

#[test]
fn generated_coefficients_of_exp_of_the_time_are_powers_over_factorials() {
    // y = e^(a t) about t₀ has the coefficients e^(a t₀) aᵏ/k!.
    let sys = Growth { a: -0.8 };
    for t0 in [0.0f64, 1.3] {
        let y0 = (-0.8 * t0).exp();
        let mut c = [[0.0; 1]; 21];
        sys.coefficients(t0, &[y0], 20, &mut c);
        let mut want = y0;
        for (k, ck) in c.iter().enumerate() {
            if k > 0 {
                want *= -0.8 / k as f64;
            }
            assert!(
                (ck[0] - want).abs() <= 1e-13 * want.abs(),
                "t0 = {t0}, order {k}: {} against {want}",
                ck[0]
            );
        }
    }
}

/// The coefficients of x = ln(t + c₀) about t₀, c = t₀ + c₀: ln c, then (−1)^(k+1)/(k cᵏ).
fn slowing_coefficient(c: f64, k: usize) -> f64 {
    if k == 0 {
        return c.ln();
    }
    let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
    sign / (k as f64 * c.powi(k as i32))
}

#[test]
fn generated_coefficients_of_exp_of_the_state_are_the_logarithms() {
    let x0 = 0.3f64;
    for t0 in [0.0, 2.5] {
        let c = t0 + x0.exp();
        let mut got = [[0.0; 1]; 21];
        Slowing.coefficients(t0, &[c.ln()], 20, &mut got);
        for (k, gk) in got.iter().enumerate() {
            let want = slowing_coefficient(c, k);
            assert!(
                (gk[0] - want).abs() <= 1e-13 * want.abs(),
                "t0 = {t0}, order {k}: {} against {want}",
                gk[0]
            );
        }
    }
}

/// x' = e^(−x) in the arena, for the interpreted tape.
fn slowing_tape() -> TaylorTape<1> {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let m = a.neg(x);
    let rhs = exp(&mut a, m);
    TaylorTape::new(&a, [x], [rhs], None, &[], 20).unwrap()
}

#[test]
fn integrated_by_taylor_exp_reaches_its_closed_form() {
    // x(10) = ln(10 + e^0.3), through the generated and the interpreted recurrences.
    let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
    let exact = (10.0 + 0.3f64.exp()).ln();
    let generated = precess::taylor::solve(Slowing, 0.0, [0.3], 10.0, &[], cfg).unwrap();
    assert!(
        (generated.y[0] - exact).abs() <= 1e-14 * exact,
        "generated: {} vs {exact}",
        generated.y[0]
    );
    let tape = slowing_tape();
    let interpreted = precess::taylor::solve(&tape, 0.0, [0.3], 10.0, &[], cfg).unwrap();
    assert!(
        (interpreted.y[0] - exact).abs() <= 1e-14 * exact,
        "interpreted: {} vs {exact}",
        interpreted.y[0]
    );
}

#[test]
fn generated_and_interpreted_exp_agree_bit_for_bit() {
    // The emitted code runs the interpreter's sums in the same order.
    let tape = slowing_tape();
    let (mut c, mut d) = ([[0.0f64; 1]; 21], [[0.0f64; 1]; 21]);
    Slowing.coefficients(0.7, &[1.1], 20, &mut c);
    tape.coefficients(0.7, &[1.1], 20, &mut d);
    for (k, (ck, dk)) in c.iter().zip(&d).enumerate() {
        assert_eq!(
            ck[0].to_bits(),
            dk[0].to_bits(),
            "order {k}: {} vs {}",
            ck[0],
            dk[0]
        );
    }
}

/// (k)! as a double-double (exact: below 2¹⁰⁶ for k ≤ 13).
fn factorial(n: usize) -> Dd {
    (1..=n).fold(Dd::from(1.0), |acc, i| acc * Dd::from(i as f64))
}

#[test]
fn extended_coefficients_of_exp_carry_the_digits_of_e() {
    // y' = e^x with x' = 1 from x₀ = 1: y's order k + 1 is e/(k + 1)!, so
    // (k + 1)!·low[k + 1] = e to 30 digits, through the interpreted tape and through the
    // generated system's tables (Growth with a = 1 at t₀ = 1: y' = e^t).
    let mut a = Arena::new();
    let (x, y) = (a.coordinate("x"), a.coordinate("y"));
    let one = a.one();
    let ex = exp(&mut a, x);
    let tape = TaylorTape::new(&a, [x, y], [one, ex], None, &[], 20).unwrap();
    let mut c = [[0.0; 2]; 13];
    let mut low = vec![[Dd::default(); 2]; 13];
    let y0 = [Dd::from(1.0), Dd::from(0.0)];
    assert!(tape.coefficients_extended_into(
        &mut Vec::new(),
        Dd::from(0.0),
        &y0,
        12,
        &mut c,
        &mut low
    ));
    let mut generated = [[0.0; 1]; 13];
    let mut glow = vec![[Dd::default(); 1]; 13];
    let ok = Growth { a: 1.0 }.coefficients_extended_into(
        &mut Vec::new(),
        Dd::from(1.0),
        &[E],
        12,
        &mut generated,
        &mut glow,
    );
    assert!(ok);
    for k in 1..13 {
        let e = (low[k][1] * factorial(k) - E).to_f64();
        assert!(e.abs() < 1e-30, "interpreted order {k}: {e:e}");
        let e = (glow[k][0] * factorial(k) - E).to_f64();
        assert!(e.abs() < 1e-30, "generated order {k}: {e:e}");
    }
    // In f64 the same coefficients round to the double nearest e at best.
    assert!((c[3][1] * 6.0 - E.hi).abs() <= 4.0 * f64::EPSILON);
}
