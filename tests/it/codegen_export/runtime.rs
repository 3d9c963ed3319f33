//! Scenes built at run time, exported with `ExportBuilder`: the C against the interpreter of
//! the same programs bit for bit, including libm's `pow` and `exp`; NumPy's `power` and `exp`
//! against them within one ulp (NumPy has SIMD versions of its own, which are not glibc's);
//! the text the derive writes read back exactly, and malformed text refused by line.

use super::support::{Case, run_c, run_python, worst};
use crate::common::rng::Rng;
use precess::codegen::{ExportBuilder, ExportError, Exported};
use precess::sym::{Arena, Func, Rational};

/// A damped pendulum with a real power and an exponential in its equations:
/// θ̈ = −(g/l) sin θ − c·|θ̇|^(3/2)·e^(−t) ... written over θ̇ > 0 as given, and the raw
/// `pow` and `exp` as outputs of their own.
fn scene() -> Exported {
    let mut a = Arena::new();
    let (theta, omega) = (a.input("theta"), a.input("omega"));
    let (g, l, c) = (a.parameter("g"), a.parameter("l"), a.parameter("c"));
    let t = a.time();
    let s = a.sin(theta);
    let gl = a.div(g, l).expect("g/l");
    let grav = a.mul(gl, s);
    let grav = a.neg(grav);
    let p = a
        .powr(omega, Rational::new(3, 2).expect("3/2"))
        .expect("ω^(3/2)");
    let minus_t = a.neg(t);
    let decay = a
        .apply(Func::named("exp").expect("exp registered"), minus_t)
        .expect("exp");
    let cp = a.mul(c, p);
    let drag = a.mul(cp, decay);
    let acc = a.sub(grav, drag);
    let exp_theta = a
        .apply(Func::named("exp").expect("exp"), theta)
        .expect("exp θ");
    let mut b = ExportBuilder::new("pendulum", &a, &[theta, omega]).expect("builder");
    b.function(&a, "rhs", "the state derivative", &[omega, acc], (2, 1))
        .expect("rhs");
    b.function(&a, "raw", "ω^(3/2) and e^θ", &[p, exp_theta], (2, 1))
        .expect("raw");
    b.jacobian(&mut a, "jacobian", "d(dy/dt)/dy", &[omega, acc])
        .expect("jacobian");
    b.finish()
}

fn cases(e: &Exported) -> Vec<Case> {
    let mut rng = Rng::new(7);
    (0..1000)
        .map(|_| Case {
            t: rng.uniform(0.0, 5.0),
            y: vec![rng.uniform(-3.0, 3.0), rng.uniform(0.0, 4.0)],
            u: Vec::new(),
            p: (0..e.parameters().len())
                .map(|_| rng.uniform(0.1, 2.0))
                .collect(),
        })
        .collect()
}

#[test]
fn the_c_of_a_run_time_scene_computes_the_interpreters_bits() {
    let e = scene();
    assert_eq!(e.parameters(), ["g", "l", "c"]);
    let cases = cases(&e);
    let want = |name: &str| -> Vec<Vec<f64>> {
        cases
            .iter()
            .map(|c| e.eval(name, c.t, &c.y, &c.p).expect("eval"))
            .collect()
    };
    // The interpreter against the closed form, so it is no copy of itself: θ̈ = −(g/l) sin θ
    // − c ω^(3/2) e^(−t), within rounding.
    for c in &cases {
        let (g, l, k) = (c.p[0], c.p[1], c.p[2]);
        let direct = -(g / l) * c.y[0].sin() - k * c.y[1].powf(1.5) * (-c.t).exp();
        let got = e.eval("rhs", c.t, &c.y, &c.p).expect("eval")[1];
        assert!(
            (got - direct).abs() <= 1e-14 * (1.0 + direct.abs()),
            "{got} vs {direct}"
        );
    }
    if let Some(got) = run_c("runtime", &e, &cases) {
        for name in ["rhs", "raw", "jacobian"] {
            let (w, n) = worst(&e, &got, name, &want(name));
            println!("runtime: C {name}: {n} values, worst {w} ulp");
            assert_eq!(w, 0, "C {name}");
        }
    }
    if let Some(got) = run_python("runtime", &e, &cases) {
        // NumPy's power and exp themselves: at most one ulp from libm's.
        let (w, n) = worst(&e, &got, "raw", &want("raw"));
        println!("runtime: Python raw pow and exp: {n} values, worst {w} ulp");
        assert!(w <= 1, "NumPy pow/exp differ by {w} ulp");
    }
}

#[test]
fn the_text_reads_back_the_same_scene() {
    let e = scene();
    let text = e.to_text();
    assert_eq!(Exported::from_text(&text), Ok(e.clone()));
    // Every bit of a constant survives: 0.1 is not a short binary fraction.
    let mut a = Arena::new();
    let x = a.input("x");
    let tenth = a.constant(Rational::new(1, 10).expect("1/10"));
    let f = a.mul(tenth, x);
    let mut b = ExportBuilder::new("tenth", &a, &[x]).expect("builder");
    b.function(&a, "f", "x/10", &[f], (1, 1)).expect("f");
    let back = Exported::from_text(&b.clone().finish().to_text()).expect("read back");
    assert_eq!(back.eval("f", 0.0, &[3.0], &[]), Ok(vec![0.1 * 3.0]));
    // A scene with inputs: a cart pushed by a force F the caller supplies, ẍ = F/m − c ẋ.
    let mut a = Arena::new();
    let (x, v, force) = (a.input("x"), a.input("v"), a.input("force"));
    let (m, c) = (a.parameter("m"), a.parameter("c"));
    let fm = a.div(force, m).expect("F/m");
    let cv = a.mul(c, v);
    let acc = a.sub(fm, cv);
    let mut b = ExportBuilder::with_inputs("cart", &a, &[x, v], &[force]).expect("builder");
    b.function(&a, "rhs", "dy/dt", &[v, acc], (2, 1))
        .expect("rhs");
    let e = b.finish();
    let text = e.to_text();
    assert!(
        text.contains("\nstate x v\ninputs force\nparameters m c\n"),
        "{text}"
    );
    assert_eq!(Exported::from_text(&text), Ok(e.clone()));
    // The environment is [t, y, u, p]: F = 3, m = 2, c = 0.5 at v = 1.
    assert_eq!(
        e.eval_with_inputs("rhs", 0.0, &[0.0, 1.0], &[3.0], &[2.0, 0.5]),
        Ok(vec![1.0, 1.0])
    );
    assert_eq!(
        e.eval("rhs", 0.0, &[0.0, 1.0], &[2.0, 0.5]),
        Err(ExportError::InputLength {
            what: "u",
            found: 0,
            expected: 1
        })
    );
}

#[test]
fn malformed_text_is_refused_with_its_line() {
    let text = scene().to_text();
    // An operand that is not an earlier instruction.
    let bad = text.replacen("\ni 1\n", "\n* 9 9\n", 1);
    assert!(
        matches!(
            Exported::from_text(&bad),
            Err(ExportError::Text { line: 6, .. })
        ),
        "{:?}",
        Exported::from_text(&bad)
    );
    // An input past the environment [t, θ, ω, g, l, c].
    let bad = text.replacen("\ni 1\n", "\ni 6\n", 1);
    assert!(matches!(
        Exported::from_text(&bad),
        Err(ExportError::Text { line: 6, .. })
    ));
    // No header.
    assert!(matches!(
        Exported::from_text("hello"),
        Err(ExportError::Text { line: 1, .. })
    ));
    // Outputs that do not fill the shape.
    let bad = text.replacen("\noutputs ", "\noutputs 0 ", 1);
    assert!(matches!(
        Exported::from_text(&bad),
        Err(ExportError::Text { .. })
    ));
}

#[test]
fn unbound_symbols_shapes_and_names_are_typed_errors() {
    let mut a = Arena::new();
    let x = a.input("x");
    let u = a.input("u");
    let f = a.mul(x, u);
    let mut b = ExportBuilder::new("s", &a, &[x]).expect("builder");
    assert_eq!(
        b.function(&a, "f", "", &[f], (1, 1)).err(),
        Some(ExportError::Unbound {
            function: "f".into(),
            symbol: "u".into()
        })
    );
    assert!(matches!(
        b.function(&a, "g", "", &[x, x], (1, 1)),
        Err(ExportError::Shape { outputs: 2, .. })
    ));
    b.function(&a, "g", "", &[x], (1, 1)).expect("g");
    assert!(matches!(
        b.function(&a, "g", "", &[x], (1, 1)),
        Err(ExportError::DuplicateName { .. })
    ));
    let two = a.integer(2);
    assert_eq!(
        ExportBuilder::new("s", &a, &[two]).err(),
        Some(ExportError::StateNotSymbol { index: 0 })
    );
    let e = b.finish();
    assert!(matches!(
        e.eval("g", 0.0, &[1.0, 2.0], &[]),
        Err(ExportError::InputLength {
            what: "y",
            found: 2,
            expected: 1
        })
    ));
    assert!(matches!(
        e.eval("h", 0.0, &[1.0], &[]),
        Err(ExportError::NoFunction { .. })
    ));
}
