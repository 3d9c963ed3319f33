//! Constant arithmetic in values: `PI` and `TAU` under every path, `sqrt`, `powi`, and
//! decimal arithmetic folded exactly before it is rounded once.

use precess::prelude::*;
use std::f64::consts::{PI, TAU};

/// Three rods whose masses and lengths are constant expressions.
#[derive(RigidBody)]
#[rigid(
    rod(mass = PI, length = 0.1 + 0.2, axis = x),
    rod(mass = 2 * std::f64::consts::PI, length = 0.1.powi(2), axis = y),
    rod(mass = core::f64::consts::TAU / 3, length = sqrt(2) / 10, axis = z),
    rod(mass = 1, length = 2 cm + 5 mm, axis = x, at = [0, 0, 1 cm - 3 mm]),
)]
struct Constants;

fn rod(body: &impl RigidBody, k: usize) -> (f64, f64, Vector3<f64>) {
    let d = body.description();
    match &d.parts[k].shape {
        Shape::Rod { mass, length, .. } => (*mass, *length, Vector3::from(d.parts[k].at)),
        other => panic!("part {k} is {other:?}"),
    }
}

#[test]
fn pi_folds_to_the_f64_constants_and_decimals_fold_exactly() {
    let (m0, l0, _) = rod(&Constants, 0);
    let (m1, l1, _) = rod(&Constants, 1);
    let (m2, l2, _) = rod(&Constants, 2);
    let (_, l3, at3) = rod(&Constants, 3);
    assert_eq!(m0, PI);
    // 2π is exact on the f64 π: TAU to the bit.
    assert_eq!(m1, TAU);
    // One rounding of the exact TAU/3, as Rust's own division rounds.
    assert_eq!(m2, TAU / 3.0);
    // Exact decimals: f64 arithmetic would give 0.30000000000000004 and 0.010000000000000002.
    assert_eq!(l0, 0.3);
    assert_eq!(l1, 0.01);
    assert!((l2 - 2f64.sqrt() / 10.0).abs() <= f64::EPSILON * l2);
    assert_eq!(l3, 0.025);
    assert_eq!(at3, Vector3::new(0.0, 0.0, 0.007));
}
