//! `linalg::StateSpace::second_order` over a mechanism's derived Jacobian (exact, no
//! differencing): a double pendulum of two equal bobs with a torque at each hinge, hanging
//! and inverted, against its closed forms: ω² = (g/l)(2 ∓ √2), and B = [0; M⁻¹] with
//! M = m l² [[5, 2], [2, 1]] in the hinge angles (the second measured from the first link).

use precess::linalg::{SecondOrder, StateSpace, StateSpaceError};
use precess::nalgebra::DMatrix;
use precess::prelude::*;

#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, joint = revolute(axis = x), q = alpha,
       parts(particle(mass = 1.5, at = [0.0, 0.0, -0.8])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.8]), q = beta,
       parts(particle(mass = 1.5, at = [0.0, 0.0, -0.8])))]
struct TwoBobs;

const M: f64 = 1.5;
const L: f64 = 0.8;
const G: f64 = 9.81;

/// A and B at rest at q, the hinge torques as inputs, from the derived Jacobian and the
/// mass matrix read off the momenta (p = M q̇).
fn linearise(q: [f64; 2]) -> Result<StateSpace, StateSpaceError> {
    let qdot = [0.0; 2];
    let (by_q, by_qdot) = TwoBobs
        .acceleration_jacobian(0.0, &q, &qdot)
        .expect("jacobian");
    let by_q = DMatrix::from_fn(2, 2, |r, c| by_q[r][c]);
    let by_qdot = DMatrix::from_fn(2, 2, |r, c| by_qdot[r][c]);
    let mass = DMatrix::from_fn(2, 2, |r, c| {
        let mut unit = [0.0; 2];
        unit[c] = 1.0;
        TwoBobs.momenta(&q, &unit)[r]
    });
    let accelerations = TwoBobs.accelerations_unchecked(0.0, &q, &qdot);
    StateSpace::second_order(&SecondOrder {
        accelerations: &accelerations,
        by_q: &by_q,
        by_qdot: &by_qdot,
        mass: &mass,
        inputs: &DMatrix::identity(2, 2),
    })
}

#[test]
fn hanging_and_inverted_double_pendulum_against_closed_forms() {
    let s2 = 2.0_f64.sqrt();
    let want = [G / L * (2.0 + s2), G / L * (2.0 - s2)];
    for (q, sign) in [([0.0, 0.0], -1.0), ([std::f64::consts::PI, 0.0], 1.0)] {
        let lin = linearise(q).expect("an equilibrium");
        // λ² = −ω² hanging, +ω² inverted.
        let mut squares: Vec<f64> = lin
            .eigenvalues()
            .expect("eigenvalues")
            .iter()
            .map(|z| sign * (z * z).re)
            .collect();
        squares.sort_by(f64::total_cmp);
        squares.dedup_by(|a, b| (*a - *b).abs() < 1e-9 * b.abs());
        assert_eq!(squares.len(), 2, "{squares:?}");
        for (got, w) in squares.iter().rev().zip(want) {
            assert!(((got - w) / w).abs() < 1e-13, "{got} vs {w}");
        }
        let m_inv = DMatrix::from_row_slice(2, 2, &[1.0, -2.0, -2.0, 5.0]) / (M * L * L);
        let err = (lin.b.view((2, 0), (2, 2)) - &m_inv).amax() / m_inv.amax();
        assert!(err < 1e-14, "B off by {err:e}");
        assert_eq!(lin.b.view((0, 0), (2, 2)).amax(), 0.0);
    }
}

#[test]
fn a_displaced_pendulum_at_rest_is_refused_with_its_acceleration() {
    match linearise([0.3, 0.0]) {
        Err(StateSpaceError::NotOperatingPoint {
            quantity,
            component,
            residual,
            ..
        }) => {
            // Q = −m g l sin α (3, 1) and M⁻¹ = [[1, −2], [−2, 5]] / (m l²), so
            // q̈ = (g/l) sin α (−1, 1): both components of the same size.
            assert_eq!(quantity, "q̈");
            let want = G / L * 0.3_f64.sin() * if component == 0 { -1.0 } else { 1.0 };
            assert!(
                (residual - want).abs() < 1e-12,
                "{component}: {residual} vs {want}"
            );
        }
        other => panic!("{other:?}"),
    }
}
