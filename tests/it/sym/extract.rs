//! `Arena::extract`: the nodes some roots reach copied into an arena of their own, against
//! the arena they came from, over random expressions built among others left behind. The
//! copy evaluates each root to the same bits, differentiates to the same values, and is
//! canonical: every copied node the constructors rebuild from its children in the source is
//! rebuilt to the copied node itself in the copy.

use crate::common;

use common::tree::{Tree, VARS, arena_env, close, tree};
use precess_core::sym::{Arena, ExprId, Node};
use proptest::prelude::*;

/// `id` built again from its children by the constructor of its kind (`None` for a leaf).
fn rebuilt(a: &mut Arena, id: ExprId) -> Option<ExprId> {
    match a.node(id).clone() {
        Node::Add(c) => Some(a.sum(&c)),
        Node::Mul(c) => Some(a.product(&c)),
        Node::Pow(b, n) => a.powi(b, n).ok(),
        Node::Sqrt(u) => a.sqrt(u).ok(),
        Node::Sin(u) => Some(a.sin(u)),
        Node::Cos(u) => Some(a.cos(u)),
        _ => None,
    }
}

/// Where the naive evaluation of `t` is well away from a pole.
fn regular(t: &Tree, p: &[f64; 3]) -> bool {
    let mut min_div = f64::INFINITY;
    let v = t.eval(p, &mut min_div);
    min_div > 1e-2 && v.is_finite() && v.abs() < 1e6
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn an_extracted_arena_is_the_roots_alone_and_canonical(
        left in tree(),
        kept in tree(),
        also in tree(),
        p in [-1.5f64..1.5, -1.5f64..1.5, -1.5f64..1.5],
    ) {
        let mut a = Arena::new();
        let Ok(junk) = left.build(&mut a) else { return Ok(()) };
        let _ = a.expand(junk);
        let (Ok(e), Ok(f)) = (kept.build(&mut a), also.build(&mut a)) else { return Ok(()) };
        let order = a.post_order(&[e, f]);
        let (mut b, moved) = a.extract(&order).expect("owned");
        prop_assert!(b.len() <= a.len());
        prop_assert_eq!(b.symbol_count(), a.symbol_count());
        // The same symbols under the same ids: one environment serves both.
        let env = arena_env(&a, &p);
        for (&from, &to) in order.iter().zip(&moved) {
            let (x, y) = (a.eval(from, &env), b.eval(to, &env));
            prop_assert!(x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()), "{x} against {y}");
        }
        for (&from, &to) in order.iter().zip(&moved) {
            let again = rebuilt(&mut a, from);
            if again == Some(from) {
                prop_assert_eq!(rebuilt(&mut b, to), Some(to), "{}", b.display(to));
            }
        }
        let roots = [(e, &kept), (f, &also)];
        for (i, (root, t)) in roots.iter().enumerate() {
            if !regular(t, &p) {
                continue;
            }
            let to = moved[order.iter().position(|x| x == root).expect("a root")];
            for name in VARS {
                let Some(s) = a.find_parameter(name) else { continue };
                let (da, db) = (a.diff(*root, s), b.diff(to, s));
                let (x, y) = (a.eval(da, &env), b.eval(db, &env));
                prop_assert!(close(x, y, 1e-12), "root {i}, d/d{name}: {x} against {y}");
            }
        }
    }
}
