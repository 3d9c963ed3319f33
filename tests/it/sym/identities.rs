//! A table of known identities and derivatives, each checked exactly (equal ids after
//! expansion), and the engine's answers to bad input.

use precess_core::sym::{Arena, ExprId, Rational, SymError, parse_decimal};

fn r(n: i128, d: i128) -> Rational {
    Rational::new(n, d).unwrap()
}

struct Fixture {
    a: Arena,
    x: ExprId,
    y: ExprId,
}

fn fixture() -> Fixture {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    let y = a.parameter("y");
    Fixture { a, x, y }
}

/// Asserts `lhs − rhs` expands to the zero node.
fn assert_identity(a: &mut Arena, lhs: ExprId, rhs: ExprId, what: &str) {
    let d = a.sub(lhs, rhs);
    let z = a.expand(d);
    assert_eq!(
        z,
        a.zero(),
        "{what}: difference expands to {}",
        a.display(z)
    );
}

#[test]
fn pythagorean_identity_is_the_zero_node_without_expansion() {
    let Fixture { mut a, x, .. } = fixture();
    let (s, c) = (a.sin(x), a.cos(x));
    let s2 = a.powi(s, 2).unwrap();
    let c2 = a.powi(c, 2).unwrap();
    let sum = a.add(s2, c2);
    let one = a.one();
    assert_eq!(a.sub(sum, one), a.zero());
}

#[test]
fn table_of_identities() {
    let Fixture { mut a, x, y } = fixture();
    let (s, c) = (a.sin(x), a.cos(x));
    let one = a.one();
    let two = a.integer(2);

    // (sin x + cos x)² − 2 sin x cos x = 1
    let sc = a.add(s, c);
    let sq = a.powi(sc, 2).unwrap();
    let two_sc = a.product(&[two, s, c]);
    let lhs = a.sub(sq, two_sc);
    assert_identity(&mut a, lhs, one, "(sin + cos)^2 - 2 sin cos");

    // sin⁴ − cos⁴ = sin² − cos²
    let s4 = a.powi(s, 4).unwrap();
    let c4 = a.powi(c, 4).unwrap();
    let lhs = a.sub(s4, c4);
    let s2 = a.powi(s, 2).unwrap();
    let c2 = a.powi(c, 2).unwrap();
    let rhs = a.sub(s2, c2);
    assert_identity(&mut a, lhs, rhs, "sin^4 - cos^4");

    // (1 − cos x)(1 + cos x) = sin² x
    let omc = a.sub(one, c);
    let opc = a.add(one, c);
    let lhs = a.mul(omc, opc);
    assert_identity(&mut a, lhs, s2, "(1 - cos)(1 + cos)");

    // 2(x + y) − 2x − 2y = 0 already in the constructors
    let xy = a.add(x, y);
    let t = a.mul(two, xy);
    let tx = a.mul(two, x);
    let ty = a.mul(two, y);
    let d1 = a.sub(t, tx);
    assert_eq!(a.sub(d1, ty), a.zero());

    // x · x⁻¹ = 1, x² · x⁻³ = x⁻¹
    let inv = a.recip(x).unwrap();
    assert_eq!(a.mul(x, inv), one);
    let x2 = a.powi(x, 2).unwrap();
    let xm3 = a.powi(x, -3).unwrap();
    assert_eq!(a.mul(x2, xm3), inv);

    // (x y)³ = x³ y³
    let p = a.mul(x, y);
    let p3 = a.powi(p, 3).unwrap();
    let x3 = a.powi(x, 3).unwrap();
    let y3 = a.powi(y, 3).unwrap();
    assert_eq!(p3, a.mul(x3, y3));

    // √(9/4) = 3/2 exactly; √u · √u = u
    let q = a.constant(r(9, 4));
    let root_q = a.sqrt(q).unwrap();
    assert_eq!(a.as_rational(root_q), Some(r(3, 2)));
    let u = a.add(x2, one);
    let root = a.sqrt(u).unwrap();
    assert_eq!(a.mul(root, root), u);

    // sin(−x) = −sin x, cos(−x) = cos x
    let mx = a.neg(x);
    let smx = a.sin(mx);
    assert_eq!(smx, a.neg(s));
    assert_eq!(a.cos(mx), c);

    // 0.1 + 0.2 = 0.3 exactly (decimal literals are exact rationals)
    let (p1, p2, p3) = (
        a.number("0.1").unwrap(),
        a.number("0.2").unwrap(),
        a.number("0.3").unwrap(),
    );
    assert_eq!(a.add(p1, p2), p3);
}

#[test]
fn table_of_derivatives() {
    let Fixture { mut a, x, y } = fixture();
    let sx = a.as_symbol(x).unwrap();
    let (s, c) = (a.sin(x), a.cos(x));
    let two = a.integer(2);
    let cases: Vec<(ExprId, ExprId, &str)> = vec![
        // d/dx sin x = cos x
        (s, c, "sin"),
        // d/dx cos x = −sin x
        (c, a.neg(s), "cos"),
        // d/dx x³ = 3x²
        (
            { a.powi(x, 3).unwrap() },
            {
                let x2 = a.powi(x, 2).unwrap();
                a.scale(r(3, 1), x2)
            },
            "x^3",
        ),
        // d/dx 1/x = −1/x²
        (
            { a.recip(x).unwrap() },
            {
                let xm2 = a.powi(x, -2).unwrap();
                a.neg(xm2)
            },
            "1/x",
        ),
        // d/dx sin² x = 2 sin x cos x
        (
            { a.powi(s, 2).unwrap() },
            { a.product(&[two, s, c]) },
            "sin^2",
        ),
        // d/dx √(x² + y) = x / √(x² + y)
        (
            {
                let x2 = a.powi(x, 2).unwrap();
                let u = a.add(x2, y);
                a.sqrt(u).unwrap()
            },
            {
                let x2 = a.powi(x, 2).unwrap();
                let u = a.add(x2, y);
                let root = a.sqrt(u).unwrap();
                a.div(x, root).unwrap()
            },
            "sqrt",
        ),
        // d/dx sin(y x) = y cos(y x)
        (
            {
                let yx = a.mul(y, x);
                a.sin(yx)
            },
            {
                let yx = a.mul(y, x);
                let cyx = a.cos(yx);
                a.mul(y, cyx)
            },
            "sin(yx)",
        ),
        // d/dx y = 0
        (y, a.zero(), "parameter"),
    ];
    for (f, expected, what) in cases {
        let d = a.diff(f, sx);
        assert_identity(&mut a, d, expected, what);
    }
}

#[test]
fn time_derivative_follows_coordinates_and_rates() {
    let mut a = Arena::new();
    let th = a.coordinate("theta");
    let m = a.parameter("m");
    let thd = a.rate(th).unwrap();
    let thdd = a.rate(thd).unwrap();
    // d/dt (m sin θ) = m cos θ θ̇
    let e = {
        let s = a.sin(th);
        a.mul(m, s)
    };
    let d = a.dt(e);
    let expected = {
        let c = a.cos(th);
        a.product(&[m, c, thd])
    };
    assert_identity(&mut a, d, expected, "d/dt m sin");
    // d/dt (½ θ̇²) = θ̇ θ̈
    let half = a.number("0.5").unwrap();
    let thd2 = a.powi(thd, 2).unwrap();
    let ke = a.mul(half, thd2);
    let d = a.dt(ke);
    let expected = a.mul(thd, thdd);
    assert_identity(&mut a, d, expected, "d/dt thetadot^2/2");
    // Parameters have no rate; names follow the coordinate.
    assert_eq!(a.rate(m), None);
    assert_eq!(a.symbol(a.as_symbol(thdd).unwrap()).name, "theta_ddot");
    assert_eq!(a.symbol(a.as_symbol(thdd).unwrap()).latex, r"\ddot{\theta}");
}

#[test]
fn decimal_literals_are_exact() {
    assert_eq!(parse_decimal("0.03").unwrap(), r(3, 100));
    assert_eq!(parse_decimal("1.5e-3").unwrap(), r(3, 2000));
    assert_eq!(parse_decimal("2E3").unwrap(), r(2000, 1));
    assert_eq!(parse_decimal("1_000.25f64").unwrap(), r(4001, 4));
    assert_eq!(parse_decimal("-9.81").unwrap(), r(-981, 100));
    assert_eq!(
        parse_decimal("6.02214076e23").unwrap(),
        r(602214076000000000000000, 1)
    );
}

#[test]
fn bad_input_is_a_typed_error() {
    let mut a = Arena::new();
    let x = a.coordinate("x");
    // A divisor that is identically zero, even when only expansion shows it.
    let (s, c) = (a.sin(x), a.cos(x));
    let sc = a.add(s, c);
    let sq = a.powi(sc, 2).unwrap();
    let one = a.one();
    let two = a.integer(2);
    let two_sc = a.product(&[two, s, c]);
    let t = a.sub(sq, two_sc);
    let zero_in_disguise = a.sub(t, one);
    assert!(matches!(
        a.div(x, zero_in_disguise),
        Err(SymError::DivisionByZero { .. })
    ));
    let z = a.zero();
    assert!(matches!(a.div(x, z), Err(SymError::DivisionByZero { .. })));
    assert_eq!(
        a.powi(z, -2),
        Err(SymError::ZeroToNegativePower { exponent: -2 })
    );
    // Non-finite floats and out-of-range or malformed literals.
    assert!(matches!(a.float(f64::NAN), Err(SymError::NonFinite { .. })));
    assert!(matches!(
        a.float(f64::INFINITY),
        Err(SymError::NonFinite { .. })
    ));
    assert!(matches!(
        a.number("1e5000"),
        Err(SymError::LiteralOutOfRange { .. })
    ));
    assert!(matches!(
        a.number("1e-5000"),
        Err(SymError::LiteralOutOfRange { .. })
    ));
    assert!(matches!(
        a.number("99999999999999999999999999999999999999999"),
        Err(SymError::LiteralOutOfRange { .. })
    ));
    assert!(matches!(
        a.number("1.2.3"),
        Err(SymError::InvalidLiteral { .. })
    ));
    assert!(matches!(
        a.number("e5"),
        Err(SymError::InvalidLiteral { .. })
    ));
    let m = a.integer(-4);
    assert!(matches!(a.sqrt(m), Err(SymError::SqrtOfNegative { value }) if value == -4.0));
    // Substitution that makes a divisor vanish.
    let inv = a.recip(x).unwrap();
    let sx = a.as_symbol(x).unwrap();
    assert!(matches!(
        a.subs(inv, &[(sx, z)]),
        Err(SymError::ZeroToNegativePower { .. })
    ));
}

#[test]
fn rational_overflow_stays_exact_instead_of_wrapping() {
    let mut a = Arena::new();
    let big = a.constant(Rational::new(i128::MAX / 2 + 1, 1).unwrap());
    // big + big leaves i128: the sum is 2¹²⁷ held exactly (never wrapped), its value right.
    let s = a.add(big, big);
    assert_ne!(a.as_rational(s), Some(Rational::new(-2, 1).unwrap()));
    let v = a.eval(s, &[]);
    let expected = 2.0 * (i128::MAX / 2 + 1) as f64;
    assert_eq!(v, expected);
    // 3^100 has an odd part beyond i128: the power stays a power.
    let three = a.integer(3);
    let p = a.powi(three, 100).unwrap();
    assert_eq!(a.as_rational(p), None);
    assert!((a.eval(p, &[]) / 5.153_775_207_320_113e47 - 1.0).abs() < 1e-15);
    // Products of huge coefficients do not wrap either.
    let x = a.parameter("x");
    let bx = a.mul(big, x);
    let bbx = a.mul(big, bx);
    let v = a.eval(bbx, &[1.0]);
    assert!((v / ((i128::MAX / 2 + 1) as f64).powi(2) - 1.0).abs() < 1e-15);
}

#[test]
fn a_parameter_and_a_coordinate_of_one_name_stay_distinct() {
    let mut a = Arena::new();
    let p = a.parameter("theta");
    let q = a.coordinate("theta");
    assert_ne!(p, q);
    assert_eq!(a.coordinate("theta"), q);
    assert_eq!(a.parameter("theta"), p);
    let sq = a.as_symbol(q).unwrap();
    assert_eq!(a.symbol(sq).kind, precess_core::sym::SymbolKind::Coordinate);
    assert_eq!(a.symbol(sq).latex, r"\theta");
    // ∂θ_parameter/∂θ_coordinate = 0.
    assert_eq!(a.diff(p, sq), a.zero());
}

#[test]
fn cancel_reduces_the_top_determinant_to_one_sine() {
    let mut a = Arena::new();
    let th = a.coordinate("theta");
    let (i1, i3, x) = (a.parameter("I_1"), a.parameter("I_3"), a.parameter("x"));
    let (s, c) = (a.sin(th), a.cos(th));
    // den = I1 I3 sin²θ, num = I3 sin θ (x cos θ + I1)
    let s2 = a.mul(s, s);
    let den = a.product(&[i1, i3, s2]);
    let xc = a.mul(x, c);
    let inner = a.add(xc, i1);
    let num = a.product(&[i3, s, inner]);
    let (n, d) = a.cancel(num, den);
    let expected_d = a.product(&[i1, s]);
    assert_eq!(d, expected_d);
    let expected_n = a.expand(inner);
    assert_eq!(n, expected_n);
    // A numerator without the factor keeps the denominator's sine.
    let (n2, d2) = a.cancel(inner, den);
    assert_eq!((n2, d2), (a.expand(inner), a.expand(den)));
    // sin³θ / sin θ = sin²θ = 1 − cos²θ, exactly.
    let s3 = a.powi(s, 3).unwrap();
    let s3 = a.expand(s3);
    let q = a.div_sin(s3, th).unwrap();
    assert_eq!(q, a.expand(s2));
    // cos θ is not divisible by sin θ.
    assert_eq!(a.div_sin(c, th), None);
}
