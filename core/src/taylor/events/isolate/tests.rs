//! The isolation against polynomials with known roots: separated, close, at the ends,
//! multiple, none, and random products of linear factors.

use super::*;

/// Σ aₖ sᵏ by Horner.
fn eval(a: &[f64], s: f64) -> f64 {
    a.iter().rev().fold(0.0, |acc, &ak| acc * s + ak)
}

/// The monomial coefficients of c Π (s − rᵢ), lowest first.
fn from_roots(c: f64, roots: &[f64]) -> Vec<f64> {
    let mut a = vec![c];
    for &r in roots {
        let mut next = vec![0.0; a.len() + 1];
        for (k, &ak) in a.iter().enumerate() {
            next[k + 1] += ak;
            next[k] -= r * ak;
        }
        a = next;
    }
    a
}

fn pieces(a: &[f64]) -> Vec<Piece> {
    let mut out = Vec::new();
    Isolator::default().isolate(a, 0.0, &mut out);
    out
}

#[test]
fn separated_roots_are_isolated_one_per_piece() {
    // (s − 0.2)(s − 0.45)(s − 0.7)(s + 2).
    let a = from_roots(1.0, &[0.2, 0.45, 0.7, -2.0]);
    let p = pieces(&a);
    assert_eq!(p.len(), 3, "{p:?}");
    for (piece, r) in p.iter().zip([0.2, 0.45, 0.7]) {
        let Piece::Isolated(lo, hi) = *piece else {
            panic!("{piece:?}");
        };
        assert!(lo < r && r < hi, "{r} in {piece:?}");
        assert!((eval(&a, lo) < 0.0) != (eval(&a, hi) < 0.0));
    }
}

#[test]
fn a_close_pair_is_told_apart() {
    // Roots 2⁻²⁰ apart (about 1e-6; q dips 2.3e-13 between them, a thousand times its
    // rounding), q positive at both ends of [0, 1]; off the halving points.
    let (r0, r1) = (0.3, 0.3 + 2f64.powi(-20));
    let a = from_roots(1.0, &[r0, r1]);
    let p = pieces(&a);
    assert_eq!(p.len(), 2, "{p:?}");
    let Piece::Isolated(lo0, hi0) = p[0] else {
        panic!("{p:?}")
    };
    let Piece::Isolated(lo1, hi1) = p[1] else {
        panic!("{p:?}")
    };
    // The coefficients of the product are rounded: its roots are r0, r1 within 1e-12.
    assert!(lo0 < r0 + 1e-12 && r0 < hi0 + 1e-12, "{p:?}");
    assert!(hi0 <= lo1 && lo1 < r1 + 1e-12 && r1 < hi1 + 1e-12, "{p:?}");
}

#[test]
fn a_shallow_dip_that_stays_above_zero_has_no_piece() {
    // (s − 0.3)² + 1e-12: minimum 1e-12 at 0.3, far above the rounding (≈ 1e-16).
    let mut a = from_roots(1.0, &[0.3, 0.3]);
    a[0] += 1e-12;
    assert_eq!(pieces(&a), []);
    // The same dip reaching 1e-12 below 0: two roots 2e-6 apart, both isolated.
    a[0] -= 2e-12;
    let p = pieces(&a);
    assert_eq!(p.len(), 2, "{p:?}");
    assert!(p.iter().all(|x| matches!(x, Piece::Isolated(..))));
    let (r0, r1) = (0.3 - 1e-6, 0.3 + 1e-6);
    assert!(p[0].ends().0 < r0 && r0 < p[0].ends().1 + 1e-12);
    assert!(p[1].ends().0 - 1e-12 < r1 && r1 < p[1].ends().1);
}

#[test]
fn roots_at_the_ends_lie_in_pieces_that_end_there() {
    // s (s − 0.3)(s − 1): q(0) = q(1) = 0 exactly, of uncertain sign: each end is an
    // unresolved piece a few ulps wide (where |q| stays within its rounding); the middle
    // root is isolated.
    let a = from_roots(1.0, &[0.0, 0.3, 1.0]);
    let p = pieces(&a);
    assert_eq!(p.len(), 3, "{p:?}");
    assert!(
        matches!(p[0], Piece::Unresolved(0.0, hi) if hi < 1e-13),
        "{p:?}"
    );
    assert!(
        matches!(p[1], Piece::Isolated(lo, hi) if lo < 0.3 && 0.3 < hi),
        "{p:?}"
    );
    assert!(
        matches!(p[2], Piece::Unresolved(lo, 1.0) if lo > 1.0 - 1e-13),
        "{p:?}"
    );
}

#[test]
fn a_root_on_a_halving_point_is_one_narrow_piece() {
    // (s − ½)(s − 0.8)(s + 2): two sign variations on [0, 1], which is halved at the root ½,
    // so both halves have a coefficient within rounding of 0 at their common end: one
    // unresolved piece, a few ulps wide, with q of opposite signs at its ends; the root 0.8
    // isolated.
    let a = from_roots(1.0, &[0.5, 0.8, -2.0]);
    let p = pieces(&a);
    assert_eq!(p.len(), 2, "{p:?}");
    let Piece::Unresolved(lo, hi) = p[0] else {
        panic!("{p:?}")
    };
    assert!(lo < 0.5 && 0.5 < hi && hi - lo < 1e-13, "{p:?}");
    assert!(eval(&a, lo) > 0.0 && eval(&a, hi) < 0.0);
    assert!(
        matches!(p[1], Piece::Isolated(lo, hi) if lo < 0.8 && 0.8 < hi),
        "{p:?}"
    );
}

#[test]
fn a_multiple_root_is_one_unresolved_piece() {
    // A double root (touching 0, no change of sign) and a triple one (a change of sign):
    // each one piece around the root, where |q| is within its rounding (|s − r|² ≲ 1e-15,
    // |s − r|³ ≲ 1e-15), told apart by the signs at its ends.
    let double = from_roots(1.0, &[0.375, 0.375, -1.0]);
    let p = pieces(&double);
    assert_eq!(p.len(), 1, "{p:?}");
    let Piece::Unresolved(lo, hi) = p[0] else {
        panic!("{p:?}")
    };
    assert!(lo <= 0.375 && 0.375 <= hi && hi - lo < 1e-6, "{p:?}");
    assert_eq!(eval(&double, lo) < 0.0, eval(&double, hi) < 0.0);
    let triple = from_roots(1.0, &[0.625, 0.625, 0.625]);
    let p = pieces(&triple);
    assert_eq!(p.len(), 1, "{p:?}");
    let Piece::Unresolved(lo, hi) = p[0] else {
        panic!("{p:?}")
    };
    assert!(lo <= 0.625 && 0.625 <= hi && hi - lo < 1e-4, "{p:?}");
    assert!(eval(&triple, lo) < 0.0 && eval(&triple, hi) > 0.0);
}

#[test]
fn the_zero_polynomial_is_one_unresolved_piece() {
    assert_eq!(pieces(&[0.0; 8]), [Piece::Unresolved(0.0, 1.0)]);
    // A constant is rootless; a line is isolated at once.
    assert_eq!(pieces(&[-3.0]), []);
    assert_eq!(pieces(&[-1.0, 4.0]), [Piece::Isolated(0.0, 1.0)]);
}

#[test]
fn a_taylor_polynomial_of_high_degree() {
    // sin(10 s) − 0.3 to degree 50 (truncated 6e-16 from the function on [0, 1]): the
    // coefficients reach 2.8e3 and the rounding bound 1e-9, and the four roots
    // (asin 0.3 + 2πk)/10 and (π − asin 0.3 + 2πk)/10 are each isolated.
    let mut a = vec![0.0; 51];
    let mut term = 1.0;
    for (k, ak) in a.iter_mut().enumerate() {
        // 10ᵏ/k! times sin's pattern 0, 1, 0, −1.
        if k > 0 {
            term *= 10.0 / k as f64;
        }
        *ak = [0.0, term, 0.0, -term][k % 4];
    }
    a[0] -= 0.3;
    let asin = 0.3f64.asin();
    let pi = std::f64::consts::PI;
    let roots = [
        asin / 10.0,
        (pi - asin) / 10.0,
        (asin + 2.0 * pi) / 10.0,
        (3.0 * pi - asin) / 10.0,
    ];
    let p = pieces(&a);
    assert_eq!(p.len(), 4, "{p:?}");
    for (piece, r) in p.iter().zip(roots) {
        let (lo, hi) = piece.ends();
        assert!(matches!(piece, Piece::Isolated(..)), "{piece:?}");
        assert!(lo < r && r < hi, "{r} in {piece:?}");
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]

    /// Products of one to eight linear factors with roots k/32 in [−0.5, 1.5], repeated
    /// ones included, times a power of 2: every coefficient is exact, so the roots are known
    /// exactly. Every root in [0, 1] lies in a piece, each isolated piece holds exactly one
    /// (a simple one, strictly inside), and the pieces ascend without overlapping.
    #[test]
    fn every_root_of_an_exact_product_lies_in_a_piece(
        ks in proptest::collection::vec(-16i32..48, 1..9),
        exp in -20i32..20,
    ) {
        let roots: Vec<f64> = ks.iter().map(|&k| f64::from(k) / 32.0).collect();
        let a = from_roots(2f64.powi(exp), &roots);
        let p = pieces(&a);
        proptest::prop_assert!(p.windows(2).all(|w| w[0].ends().1 <= w[1].ends().0), "{:?}", p);
        for r in roots.iter().filter(|r| (0.0..=1.0).contains(*r)) {
            let covered = p.iter().any(|x| x.ends().0 <= *r && *r <= x.ends().1);
            proptest::prop_assert!(covered, "{} outside {:?}", r, p);
        }
        for piece in &p {
            if let Piece::Isolated(lo, hi) = *piece {
                let inside: Vec<_> = roots.iter().filter(|r| lo <= **r && **r <= hi).collect();
                proptest::prop_assert_eq!(inside.len(), 1, "{:?} in {:?}", inside, piece);
                proptest::prop_assert!(lo < *inside[0] && *inside[0] < hi);
            }
        }
    }

    /// Products of two to six factors with real roots in (−0.5, 1.5), neighbours at least
    /// 0.02 apart (q between two roots in [0, 1] far above its rounding): each root in
    /// (0, 1) (at least 1e-9 inside) isolated alone, and no other piece.
    #[test]
    fn separated_roots_of_a_random_product_are_isolated(
        first in -0.5f64..1.0,
        gaps in proptest::collection::vec(0.02f64..0.5, 1..6),
        scale in proptest::prop_oneof![-1e3f64..-1e-3, 1e-3f64..1e3],
    ) {
        let mut roots = vec![first];
        for g in &gaps {
            roots.push(roots[roots.len() - 1] + g);
        }
        let a = from_roots(scale, &roots);
        let inside: Vec<f64> =
            roots.iter().copied().filter(|r| *r > 1e-9 && *r < 1.0 - 1e-9).collect();
        let p = pieces(&a);
        proptest::prop_assert_eq!(p.len(), inside.len(), "{:?} against {:?}", p, inside);
        for (piece, r) in p.iter().zip(&inside) {
            let (lo, hi) = piece.ends();
            proptest::prop_assert!(matches!(piece, Piece::Isolated(..)), "{:?}", piece);
            // The rounded coefficients move a root by far less than 1e-12 here.
            proptest::prop_assert!(lo - 1e-12 < *r && *r < hi + 1e-12, "{} in {:?}", r, piece);
        }
    }
}
