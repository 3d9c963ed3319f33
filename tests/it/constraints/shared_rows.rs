//! Rows kept in the form they are given (`Constraints::nonholonomic_shared`,
//! `Constraints::holonomic_shared`, what the rolling derivation uses): their entries are not
//! expanded, yet an entry that is identically zero only once multiplied out is stored as
//! the arena's zero, a row that vanishes whole is not added, and the values are the closed
//! forms' (a knife edge's sideways velocity, the rate of a circle's equation).

use precess::lagrange::{Constraints, Coordinates};
use precess::sym::{Arena, ExprId};

/// (sin u + cos u)² − 2 sin u cos u − 1: zero, though not as built (the constructors do not
/// multiply out the square).
fn pythagoras_less_one(a: &mut Arena, u: ExprId) -> ExprId {
    let (s, c) = (a.sin(u), a.cos(u));
    let sum = a.add(s, c);
    let square = a.mul(sum, sum);
    let two = a.integer(2);
    let cross = a.product(&[two, s, c]);
    let one = a.one();
    let less = a.add(cross, one);
    let out = a.sub(square, less);
    assert_ne!(out, a.zero(), "the zero is not literal as built");
    out
}

/// The value of `e` with each coordinate and rate given.
fn value(a: &Arena, c: &Coordinates, e: ExprId, q: &[f64], u: &[f64]) -> f64 {
    let mut env = vec![f64::NAN; a.symbol_count()];
    for (k, (&qk, &uk)) in c.q.iter().zip(&c.rates).enumerate() {
        env[a.as_symbol(qk).expect("a symbol").index()] = q[k];
        env[a.as_symbol(uk).expect("a symbol").index()] = u[k];
    }
    a.eval(e, &env)
}

/// A knife edge at (x, y) heading θ: the sideways velocity −ẋ sin θ + ẏ cos θ = 0, given
/// with a θ̇ term whose coefficient vanishes identically.
#[test]
fn a_knife_edges_row_keeps_its_exact_zero() {
    let mut a = Arena::new();
    let c = Coordinates::new(&mut a, &["x", "y", "theta"]);
    let th = c.q[2];
    let (s, co) = (a.sin(th), a.cos(th));
    let ms = a.neg(s);
    let hidden = pythagoras_less_one(&mut a, th);
    let row = [ms, co, hidden];
    let mut k = Constraints::new();
    let zero = a.zero();
    let added = k
        .nonholonomic_shared(&mut a, &c, &row, zero)
        .expect("linear in the rates");
    assert!(added);
    assert_eq!(k.len(), 1);
    assert_eq!(
        k.coefficients[0][2],
        a.zero(),
        "the θ̇ entry is exactly zero"
    );
    assert_eq!(k.offsets[0], a.zero());
    assert_eq!(k.positions[0], None);
    for theta in [0.0, 0.4, 2.5, -1.2] {
        let q = [0.3, -0.7, theta];
        let got = [0, 1].map(|j| value(&a, &c, k.coefficients[0][j], &q, &[0.0; 3]));
        assert!((got[0] + f64::sin(theta)).abs() < 1e-15, "{got:?}");
        assert!((got[1] - f64::cos(theta)).abs() < 1e-15, "{got:?}");
    }
    // A row whose every entry vanishes is no constraint.
    let other = pythagoras_less_one(&mut a, c.q[0]);
    let empty = [other, zero, hidden];
    let added = k
        .nonholonomic_shared(&mut a, &c, &empty, zero)
        .expect("linear in the rates");
    assert!(!added);
    assert_eq!(k.len(), 1);
    // A rate in an entry is refused, as by `nonholonomic`.
    let bad = [c.rates[0], zero, zero];
    assert!(k.nonholonomic_shared(&mut a, &c, &bad, zero).is_err());
}

/// φ = x² + ((sin y + cos y)² − 2 sin y cos y − 1) − ℓ² (a circle's equation in x with a y that it holds only
/// in form), its rate given as 2x ẋ + (the same zero) cos y ẏ: the row (2x, 0, 0), the
/// same values as `holonomic`'s expanded derivatives, with z's zero known from φ alone.
#[test]
fn a_holonomic_row_read_from_its_rate_matches_the_derivatives() {
    let mut a = Arena::new();
    let c = Coordinates::new(&mut a, &["x", "y", "z"]);
    let l = a.parameter("l");
    let (x, y) = (c.q[0], c.q[1]);
    let hidden = pythagoras_less_one(&mut a, y);
    let x2 = a.mul(x, x);
    let l2 = a.mul(l, l);
    let held = a.add(x2, hidden);
    let phi = a.sub(held, l2);
    let two = a.integer(2);
    let along_x = a.product(&[two, x, c.rates[0]]);
    let cy = a.cos(y);
    let along_y = a.product(&[hidden, cy, c.rates[1]]);
    let rate = a.add(along_x, along_y);
    let mut shared = Constraints::new();
    shared
        .holonomic_shared(&mut a, &c, phi, rate)
        .expect("no rates in φ");
    let mut expanded = Constraints::new();
    expanded.holonomic(&mut a, &c, phi).expect("no rates in φ");
    assert_eq!(
        shared.coefficients[0][1],
        a.zero(),
        "∂φ/∂y vanishes exactly"
    );
    assert_eq!(shared.coefficients[0][2], a.zero(), "φ does not hold z");
    assert_eq!(shared.offsets[0], a.zero());
    assert_eq!(shared.positions[0], Some(phi));
    assert_eq!(expanded.coefficients[0][1], a.zero());
    let mut env_q = [0.0; 3];
    for xv in [0.25, -1.5, 3.0] {
        env_q[0] = xv;
        let got = value(&a, &c, shared.coefficients[0][0], &env_q, &[0.0; 3]);
        assert!((got - 2.0 * xv).abs() < 1e-15, "{got}");
        let theirs = value(&a, &c, expanded.coefficients[0][0], &env_q, &[0.0; 3]);
        assert!((got - theirs).abs() < 1e-15);
    }
    // A rate in φ is refused, as by `holonomic`.
    let moving = a.add(phi, c.rates[2]);
    assert!(shared.holonomic_shared(&mut a, &c, moving, rate).is_err());
}
