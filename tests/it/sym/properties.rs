//! Property tests of the symbolic engine over thousands of random expressions: the canonical
//! constructors, expansion and differentiation keep the value, and the code generator's
//! interpreter agrees with direct evaluation.

use crate::common;

use common::tree::{Tree, arena_env, close, tree};
use precess_core::codegen::Program;
use precess_core::sym::{Arena, Node};
use proptest::prelude::*;

fn point() -> impl Strategy<Value = [f64; 3]> {
    [-1.5f64..1.5, -1.5f64..1.5, -1.5f64..1.5]
}

/// Builds `t` and evaluates it naively; `None` where the point is near a singularity or the
/// value is too large to compare meaningfully.
fn reference(t: &Tree, p: &[f64; 3]) -> Option<f64> {
    let mut min_div = f64::INFINITY;
    let v = t.eval(p, &mut min_div);
    (min_div > 1e-2 && v.is_finite() && v.abs() < 1e6).then_some(v)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn constructors_keep_the_value(t in tree(), p in point()) {
        let Some(expected) = reference(&t, &p) else { return Ok(()) };
        let mut a = Arena::new();
        let Ok(e) = t.build(&mut a) else { return Ok(()) };
        let env = arena_env(&a, &p);
        let got = a.eval(e, &env);
        prop_assert!(close(got, expected, 1e-9), "{} = {got}, naive {expected}", a.display(e));
    }

    #[test]
    fn expansion_keeps_the_value(t in tree(), p in point()) {
        let Some(expected) = reference(&t, &p) else { return Ok(()) };
        let mut a = Arena::new();
        let Ok(e) = t.build(&mut a) else { return Ok(()) };
        let x = a.expand(e);
        let env = arena_env(&a, &p);
        let got = a.eval(x, &env);
        // An expanded sum cancels where its terms are far larger than its value ((2 + x)¹⁸
        // near x = −1.5 has terms of 10⁹ for a value of 10⁻⁵): rounding of the terms, not
        // the expansion, is then the error, so the bound is relative to them too.
        let terms = match a.node(x) {
            Node::Add(children) => children.iter().map(|&c| a.eval(c, &env).abs()).sum(),
            _ => got.abs(),
        };
        prop_assert!(
            close(got, expected, 1e-8) || (got - expected).abs() <= 1e-13 * terms,
            "expand({}) = {got}, naive {expected}, terms {terms:e}",
            a.display(e)
        );
        // Expansion is idempotent: the expanded form is already canonical.
        prop_assert_eq!(a.expand(x), x);
    }

    #[test]
    fn interpreter_matches_direct_evaluation(t in tree(), p in point()) {
        let Some(expected) = reference(&t, &p) else { return Ok(()) };
        let mut a = Arena::new();
        let Ok(e) = t.build(&mut a) else { return Ok(()) };
        let prog = Program::lower(&a, &[e]);
        let env = arena_env(&a, &p);
        let got = prog.eval(&env)[0];
        prop_assert!(close(got, expected, 1e-9), "{}: program {got}, naive {expected}", a.display(e));
    }

    #[test]
    fn derivatives_match_central_differences(t in tree(), p in point(), var in 0usize..3) {
        let mut a = Arena::new();
        let Ok(e) = t.build(&mut a) else { return Ok(()) };
        let Some(s) = a.find_parameter(common::tree::VARS[var]) else { return Ok(()) };
        let d = a.diff(e, s);
        let at = |x: f64| {
            let mut q = p;
            q[var] = x;
            reference(&t, &q)
        };
        // Two step sizes: where they disagree the function is not smooth enough here
        // (near a pole) to judge a derivative by differences.
        let h = 1e-4;
        let (Some(fp), Some(fm), Some(fp2), Some(fm2)) =
            (at(p[var] + h), at(p[var] - h), at(p[var] + h / 2.0), at(p[var] - h / 2.0))
        else { return Ok(()) };
        let fd = (fp - fm) / (2.0 * h);
        let fd2 = (fp2 - fm2) / h;
        if !close(fd, fd2, 1e-5) {
            return Ok(());
        }
        // Richardson: the O(h²) error cancels, leaving O(h⁴) and rounding.
        let richardson = (4.0 * fd2 - fd) / 3.0;
        let env = arena_env(&a, &p);
        let got = a.eval(d, &env);
        prop_assert!(close(got, richardson, 1e-6), "d/d{} {} = {got}, differences {richardson}",
            common::tree::VARS[var], a.display(e));
    }

    /// Multiplying a trig polynomial by sin² + cos² (written out, not simplified) and
    /// expanding gives the same id: zero-equivalence is exact, not numerical.
    #[test]
    fn trig_polynomials_have_one_expanded_form(coeffs in proptest::collection::vec(-3i64..=3, 1..6)) {
        let mut a = Arena::new();
        let th = a.coordinate("theta");
        let phi = a.coordinate("phi");
        let (s, c, sp) = (a.sin(th), a.cos(th), a.sin(phi));
        let basis = [s, c, a.mul(s, c), a.mul(sp, s), a.mul(c, c), a.mul(sp, sp)];
        let terms: Vec<_> = coeffs.iter().zip(basis.iter().cycle())
            .map(|(&k, &b)| { let k = a.integer(k); a.mul(k, b) })
            .collect();
        let poly = a.sum(&terms);
        let s2 = a.mul(s, s);
        let c2 = a.mul(c, c);
        let one = a.add(s2, c2); // canonicalises to 1 already; build the product unexpanded too
        let times_one = a.mul(poly, one);
        let sc = a.add(s, c);
        let sq = a.powi(sc, 2).unwrap();
        let two = a.integer(2);
        let two_sc = a.product(&[two, s, c]);
        let also_one = a.sub(sq, two_sc);
        let times_also_one = a.mul(poly, also_one);
        let base = a.expand(poly);
        prop_assert_eq!(a.expand(times_one), base);
        prop_assert_eq!(a.expand(times_also_one), base);
        let diff = a.sub(times_also_one, poly);
        prop_assert_eq!(a.expand(diff), a.zero());
    }

    /// Cancelling common factors keeps the value of the quotient wherever both are defined.
    #[test]
    fn cancel_keeps_the_value(
        pc in proptest::collection::vec(-3i64..=3, 1..5),
        qc in proptest::collection::vec(-3i64..=3, 1..5),
        k in 0i64..3, j in 0i64..3, theta in 0.1f64..3.0, x in -2.0f64..2.0,
    ) {
        let mut a = Arena::new();
        let th = a.coordinate("theta");
        let xs = a.parameter("x");
        let (s, c) = (a.sin(th), a.cos(th));
        let basis = [a.one(), c, xs, a.mul(xs, c), a.mul(c, c)];
        let poly = |a: &mut Arena, coeffs: &[i64]| {
            let t: Vec<_> = coeffs.iter().zip(basis.iter()).map(|(&k, &b)| { let k = a.integer(k); a.mul(k, b) }).collect();
            a.sum(&t)
        };
        let (p, q) = (poly(&mut a, &pc), poly(&mut a, &qc));
        if a.expand(q) == a.zero() {
            return Ok(());
        }
        let sk = a.powi(s, k).unwrap();
        let sj = a.powi(s, j + 1).unwrap();
        let num = a.mul(p, sk);
        let den = a.product(&[q, sj, xs]);
        let (n, d) = a.cancel(num, den);
        let mut env = vec![0.0; a.symbol_count()];
        env[a.as_symbol(th).unwrap().index()] = theta;
        env[a.as_symbol(xs).unwrap().index()] = x;
        let (dv, before) = (a.eval(d, &env), a.eval(den, &env));
        if before.abs() <= 1e-3 || dv.abs() <= 1e-6 {
            return Ok(());
        }
        let lhs = a.eval(num, &env) / before;
        let rhs = a.eval(n, &env) / dv;
        prop_assert!(close(lhs, rhs, 1e-9), "{} / {} -> {} / {}: {lhs} vs {rhs}",
            a.display(num), a.display(den), a.display(n), a.display(d));
    }
}
