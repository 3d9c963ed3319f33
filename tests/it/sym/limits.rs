//! Every public engine function answers or returns a typed error at the limits: nesting far
//! deeper than any recursion could survive (run on a thread with a 512 KiB stack, so a
//! recursive walk left anywhere fails here), exponents of 2⁴⁰, and ids of another arena.

use precess_core::codegen::{Program, latex};
use precess_core::sym::{Arena, ExprId, SymError};

/// Depth of the nested expressions: a recursive walk overflows a 2 MiB stack near 2·10⁴
/// levels (about 100 bytes a level), so the 512 KiB stack of `on_small_stack` near 5·10³.
const DEPTH: usize = 25_000;

/// Runs `f` on a thread with a 512 KiB stack (a quarter of the default): the depth that
/// proves the walks iterative costs a quarter of the time.
fn on_small_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(512 << 10)
        .spawn(f)
        .expect("a thread starts")
        .join()
        .expect("no stack overflow or panic");
}

/// sₖ₊₁ = sin(sₖ + x) from s₀ = x, nested `depth` times. (Its derivative stays linear in
/// size; that of sin(sin(…)) is a product of `depth` cosines at every level, quadratic.)
fn nested_sin(a: &mut Arena, x: ExprId, depth: usize) -> ExprId {
    (0..depth).fold(x, |e, _| {
        let u = a.add(e, x);
        a.sin(u)
    })
}

#[test]
fn deep_nesting_walks_without_recursion() {
    on_small_stack(|| {
        let mut a = Arena::new();
        let x = a.parameter("x");
        let sx = a.as_symbol(x).unwrap();
        let e = nested_sin(&mut a, x, DEPTH);
        // Reference values by direct iteration: dₖ₊₁ = cos(sₖ + x) (dₖ + 1).
        let (mut s, mut d) = (0.7f64, 1.0f64);
        for _ in 0..DEPTH {
            d = (s + 0.7).cos() * (d + 1.0);
            s = (s + 0.7).sin();
        }
        assert!((a.eval(e, &[0.7]) - s).abs() < 1e-12);
        let de = a.diff(e, sx);
        assert!((a.eval(de, &[0.7]) - d).abs() < 1e-9 * (1.0 + d.abs()));
        let text = a.display(e);
        assert_eq!(text.matches("sin(").count(), DEPTH);
        assert_eq!(latex(&a, e).matches("\\sin").count(), DEPTH);
        assert_eq!(a.free_symbols(e), vec![sx]);
        assert_eq!(a.expand(e), e);
        assert_eq!(a.dt(e), a.zero()); // x is a parameter
        let y = a.parameter("y");
        let swapped = a.subs(e, &[(sx, y)]).unwrap();
        let sy = a.as_symbol(y).unwrap();
        assert_eq!(a.free_symbols(swapped), vec![sy]);
        let p = Program::lower(&a, &[e]);
        assert!((p.eval(&[0.7])[0] - s).abs() < 1e-12);
        let tokens = p.to_tokens(&mut |_| "x".parse().expect("an identifier"));
        assert_eq!(tokens.outputs.len(), 1);
        // A deep divisor: 1 / (2 + deep) is decided non-zero without expanding the argument
        // of every sine, and so is the power.
        let two = a.integer(2);
        let den = a.add(two, e);
        let q = a.div(x, den).unwrap();
        assert!((a.eval(q, &[0.7]) - 0.7 / (2.0 + s)).abs() < 1e-12);
        assert!(a.powi(den, -3).is_ok());
        assert_eq!(a.is_zero(den), Ok(false));
        let (n, d) = a.cancel(x, den);
        assert!((a.eval(n, &[0.7]) / a.eval(d, &[0.7]) - 0.7 / (2.0 + s)).abs() < 1e-12);
    });
}

#[test]
fn deep_sums_and_products_walk_without_recursion() {
    on_small_stack(|| {
        let mut a = Arena::new();
        let (x, y) = (a.parameter("x"), a.parameter("y"));
        // e ← √(e·y + x): alternating product, sum and root, 3·DEPTH/4 levels.
        let mut e = x;
        let mut v = 0.5f64;
        for _ in 0..DEPTH / 4 {
            let ey = a.mul(e, y);
            let s = a.add(ey, x);
            e = a.sqrt(s).unwrap();
            v = (v * 0.25 + 0.5).sqrt();
        }
        assert!((a.eval(e, &[0.5, 0.25]) - v).abs() < 1e-12);
        assert!(!a.display(e).is_empty());
        assert!(!latex(&a, e).is_empty());
        let sy = a.as_symbol(y).unwrap();
        let d = a.diff(e, sy);
        assert!(a.eval(d, &[0.5, 0.25]).is_finite());
        let p = Program::lower(&a, &[e, d]);
        assert!((p.eval(&[0.5, 0.25])[0] - v).abs() < 1e-12);
        assert_eq!(a.expand(e), a.expand(e));
    });
}

#[test]
fn huge_exponents_are_answered_or_refused() {
    let mut a = Arena::new();
    let th = a.coordinate("theta");
    let (x, y) = (a.parameter("x"), a.parameter("y"));
    let big = 1i64 << 40;
    let c = a.cos(th);
    let cb = a.powi(c, big).unwrap();
    // div_sin used to allocate 2⁴⁰ slots; cancel looped on it.
    assert_eq!(a.div_sin(cb, th), None);
    let s = a.sin(th);
    let (n, d) = a.cancel(cb, s);
    assert!(a.eval(n, &[0.5]).is_finite() && a.eval(d, &[0.5]).is_finite());
    // sin^(2⁴⁰) is (1 − cos²)^(2³⁹): kept factored, and try_expand says why.
    let sb = a.powi(s, big).unwrap();
    let kept = a.expand(sb);
    assert_eq!(a.eval(kept, &[0.0]), 0.0);
    assert!(matches!(
        a.try_expand(sb),
        Err(SymError::ExpansionTooLarge { .. })
    ));
    let xy = a.add(x, y);
    let p = a.powi(xy, big).unwrap();
    assert!(matches!(
        a.try_expand(p),
        Err(SymError::ExpansionTooLarge { .. })
    ));
    // Exponents that overflow i64 are refused, not wrapped.
    assert!(matches!(
        a.powi(p, big),
        Err(SymError::ExponentOverflow { .. })
    ));
    // A power of 2⁴⁰ lowers to 40 squarings and evaluates.
    let xb = a.powi(x, big).unwrap();
    let prog = Program::lower(&a, &[xb]);
    assert!(prog.ops().len() < 100);
    // Symbols in order made: theta, x, y.
    assert_eq!(prog.eval(&[0.0, 1.0, 1.0])[0], 1.0);
    assert!(a.display(xb).ends_with("^1099511627776"));
    assert!(latex(&a, xb).contains("1099511627776"));
    let sx = a.as_symbol(x).unwrap();
    let dx = a.diff(xb, sx);
    assert_eq!(a.eval(dx, &[0.0, 1.0, 1.0]), big as f64);
    // (x + y)^(2⁴⁰) is not zero, decided without expanding it.
    assert_eq!(a.is_zero(p), Ok(false));
    assert!(a.recip(p).is_ok());
}

#[test]
fn the_expansion_that_took_23_seconds() {
    let mut a = Arena::new();
    let vars: Vec<ExprId> = ["a", "b", "c", "d", "e"]
        .iter()
        .map(|n| a.parameter(n))
        .collect();
    let s = a.sum(&vars);
    let p = a.powi(s, 11).unwrap();
    let x = a.expand(p);
    let precess_core::sym::Node::Add(terms) = a.node(x) else {
        panic!("a sum")
    };
    // C(15, 4) monomials; the coefficients are the multinomials, which sum to 5¹¹.
    assert_eq!(terms.len(), 1365);
    assert_eq!(a.eval(x, &[1.0; 5]), 5f64.powi(11));
    assert_eq!(a.eval(x, &[1.0, -1.0, 0.0, 0.0, 0.0]), 0.0);
}

#[test]
fn ids_of_another_arena_are_never_another_expression() {
    let mut a = Arena::new();
    let mut b = Arena::new();
    let x = a.parameter("x");
    let ax = a.sin(x);
    let y = b.parameter("y");
    // Same position, different arena: b does not read a's node there.
    assert!(!b.owns(ax) && !b.owns(x) && b.owns(y));
    assert_eq!(b.display(ax), "<foreign>");
    assert!(b.eval(ax, &[1.0, 1.0, 1.0]).is_nan());
    assert!(matches!(
        b.powi(ax, 2),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.div(y, ax),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.recip(ax),
        Err(SymError::ForeignExpression { .. })
    ));
    let sy = b.as_symbol(y).unwrap();
    assert!(matches!(
        b.subs(ax, &[(sy, y)]),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.subs(y, &[(sy, ax)]),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.try_expand(ax),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.is_zero(ax),
        Err(SymError::ForeignExpression { .. })
    ));
    assert!(matches!(
        b.abbreviate("k", ax),
        Err(SymError::ForeignExpression { .. })
    ));
    // The infallible walks answer without panicking.
    let _ = (b.diff(ax, sy), b.dt(ax), b.expand(ax), b.free_symbols(ax));
    let _ = latex(&b, ax);
    let p = Program::lower(&b, &[ax]);
    assert!(p.eval(&[1.0]).iter().all(|v| v.is_nan()));
    // A clone owns the ids made before it, not those made after by either copy.
    let mut c = a.clone();
    assert!(c.owns(ax));
    let cx = c.cos(x);
    let later = a.cos(x);
    assert!(!a.owns(cx) && !c.owns(later));
    assert_eq!(c.display(cx), "cos(x)");
}
