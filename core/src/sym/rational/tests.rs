use proptest::prelude::*;

use super::*;

fn q(n: i128, d: i128) -> Rational {
    Rational::new(n, d).unwrap()
}

fn pow10(k: i64) -> Rational {
    Rational::from_decimal(false, 1, k).unwrap()
}

#[test]
fn normalises_and_folds() {
    let a = q(6, -4);
    assert_eq!(a.fraction(), Some((-3, 2)));
    let b = a.checked_add(q(1, 2)).unwrap();
    assert_eq!(b, Rational::integer(-1));
    assert_eq!(q(2, 3).checked_pow(-2), Some(q(9, 4)));
    assert_eq!(Rational::ZERO.checked_pow(-1), None);
    assert_eq!(q(9, 4).sqrt_exact(), Some(q(3, 2)));
    assert_eq!(q(2, 1).sqrt_exact(), None);
}

#[test]
fn leaves_i128_exactly_and_comes_back() {
    let big = q(i128::MAX, 1);
    // 2¹²⁷ is not a ratio of i128s, but it is 1 · 2¹²⁷.
    let next = big.checked_add(Rational::ONE).unwrap();
    assert_eq!(next.fraction(), None);
    assert_eq!(next.to_f64(), 2f64.powi(127));
    assert_eq!(next.checked_add(Rational::MINUS_ONE), Some(big));
    // 10⁴⁰ = 2⁴⁰ 5⁴⁰, and 10⁴⁰ / 10⁴⁰ is the plain 1 again.
    let e40 = Rational::integer(10).checked_pow(40).unwrap();
    assert_eq!(e40, pow10(40));
    assert_eq!(e40.to_string(), "1e40");
    assert_eq!(e40.checked_mul(e40.recip().unwrap()), Some(Rational::ONE));
    assert_eq!(e40.sqrt_exact(), Some(pow10(20)));
    assert!(e40.is_integer() && !e40.recip().unwrap().is_integer());
    let small = q(3, 7).checked_mul(pow10(-40)).unwrap();
    assert_eq!(small.to_string(), "3e-40/7");
    assert_eq!(
        small.to_f64(),
        "4.285714285714285714285714e-41".parse().unwrap()
    );
}

#[test]
fn overflow_is_none_not_wrap() {
    let big = q(i128::MAX, 1);
    // (2¹²⁷ − 1)² has an odd part far beyond i128.
    assert_eq!(big.checked_mul(big), None);
    assert_eq!(q(1, i128::MAX).checked_add(q(1, i128::MAX - 2)), None);
    // Exponents are bounded: 2^(2¹⁴ + 1) is refused, 2^(2¹⁴) is not.
    let two = Rational::integer(2);
    assert!(two.checked_pow(1 << 14).is_some());
    assert_eq!(two.checked_pow((1 << 14) + 1), None);
    assert_eq!(Rational::from_decimal(false, 1, 1 << 40), None);
}

#[test]
fn from_f64_is_exact_for_every_finite_value() {
    assert_eq!(Rational::from_f64(0.5), Some(q(1, 2)));
    assert_eq!(Rational::from_f64(-3.0), Some(q(-3, 1)));
    assert_eq!(Rational::from_f64(f64::NAN), None);
    assert_eq!(Rational::from_f64(f64::NEG_INFINITY), None);
    assert_eq!(Rational::from_f64(-0.0), Some(Rational::ZERO));
    let specials = [
        0.1,
        1e300,
        -1e-300,
        f64::MAX,
        f64::MIN_POSITIVE,
        f64::from_bits(1),
        f64::MIN_POSITIVE - f64::from_bits(1),
    ];
    for x in specials {
        assert_eq!(Rational::from_f64(x).unwrap().to_f64(), x, "{x:e}");
    }
    // 0.1 is the binary fraction 3602879701896397/2⁵⁵, not 1/10.
    assert_eq!(
        Rational::from_f64(0.1).unwrap().fraction(),
        Some((3_602_879_701_896_397, 1 << 55))
    );
    // Equal values, equal representation: the float 2⁻³ and the ratio 1/8.
    assert_eq!(Rational::from_f64(0.125), Some(q(1, 8)));
    assert_eq!(Rational::from_f64(1e22), Some(pow10(22)));
}

#[test]
fn order_is_exact_where_f64_cannot_tell() {
    let scale = Rational::integer(2).checked_pow(200).unwrap();
    let a = q(1_000_000_000_000_000_000_000_000_001, 1)
        .checked_mul(scale)
        .unwrap();
    let b = pow10(27).checked_mul(scale).unwrap();
    assert_eq!(a.to_f64(), b.to_f64());
    assert!(a > b && -a < -b);
    assert_eq!(a.cmp(&a), Ordering::Equal);
    assert!(pow10(-400) > Rational::ZERO && pow10(-400) < pow10(-399));
    assert!(q(-1, 3) < q(1, 1 << 100));
}

fn any_rational() -> impl Strategy<Value = Rational> {
    (-1_000_000i128..1_000_000, 1i128..1_000_000, -400i64..400)
        .prop_map(|(n, d, e)| q(n, d).checked_mul(pow10(e)).unwrap_or(Rational::ZERO))
}

proptest! {
    #[test]
    fn arithmetic_round_trips(a in any_rational(), b in any_rational()) {
        if let Some(s) = a.checked_add(b) {
            prop_assert_eq!(s.checked_add(-b), Some(a));
        }
        if let (Some(p), Some(inv)) = (a.checked_mul(b), b.recip()) {
            prop_assert_eq!(p.checked_mul(inv), Some(a));
        }
        // Exact order agrees with the rounded values wherever those differ.
        let (x, y) = (a.to_f64(), b.to_f64());
        if x != y {
            prop_assert_eq!(a.cmp(&b), x.total_cmp(&y));
        }
        prop_assert_eq!(a.cmp(&b), b.cmp(&a).reverse());
        prop_assert_eq!(a == b, a.cmp(&b) == Ordering::Equal);
    }
}
