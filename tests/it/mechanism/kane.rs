//! Kane's equations of a mechanism (`MechanismScene::kane_equations`, the route rolling
//! mechanisms take) against the independent recursive Newton–Euler algorithm of
//! the testkit's `mechanism::rnea`: q̈ = M⁻¹ f at random states of the engine tests' scenes
//! (springs, dampers, efforts, body and space torques, universal, prismatic and spherical
//! joints; past three coordinates the kinematics are the unexpanded recursive forms), with
//! literal and with parameter values.

use nalgebra::{DMatrix, DVector};
use precess::sym::{Arena, SymbolKind};

use super::engine::{double_pendulum, pendulum, random_state, spatial_chain, spherical_on_arm};
use crate::common::mechanism::rng::Rng;
use crate::common::mechanism::{NumMechanism, Values, relative_difference, rnea, scene};
use precess::rigid::AngleSequence;

/// The worst relative difference of Kane's q̈ from the RNEA's over 200 states.
fn worst(m: &NumMechanism, values: Values, seed: u64) -> f64 {
    let mut a = Arena::new();
    let (s, bound) = scene(&mut a, m, values);
    let eqs = s.kane_equations(&mut a).expect("derives");
    let n = eqs.coords.len();
    let mut env = vec![0.0; a.symbol_count()];
    for (id, symbol) in a.symbols() {
        if symbol.kind == SymbolKind::Parameter {
            let (_, v) = bound
                .iter()
                .find(|(name, _)| *name == symbol.name)
                .expect("every parameter bound");
            env[id.index()] = *v;
        }
    }
    let q_ids: Vec<usize> = eqs
        .coords
        .q
        .iter()
        .map(|&e| a.as_symbol(e).expect("a symbol").index())
        .collect();
    let qd_ids: Vec<usize> = eqs
        .coords
        .rates
        .iter()
        .map(|&e| a.as_symbol(e).expect("a symbol").index())
        .collect();
    let mut rng = Rng::new(seed);
    let mut worst: f64 = 0.0;
    for _ in 0..200 {
        let (q, qd) = random_state(m, &mut rng);
        for i in 0..n {
            env[q_ids[i]] = q[i];
            env[qd_ids[i]] = qd[i];
        }
        let mass = DMatrix::from_fn(n, n, |i, j| a.eval(eqs.mass[i][j], &env));
        let forcing = DVector::from_fn(n, |i, _| a.eval(eqs.forcing[i], &env));
        let qdd = mass.lu().solve(&forcing).expect("regular");
        let reference = rnea::accelerations(m, &q, &qd);
        worst = worst.max(relative_difference(qdd.as_slice(), &reference, 1.0));
    }
    worst
}

#[test]
fn kanes_equations_agree_with_newton_euler() {
    let mut rng = Rng::new(31);
    let scenes = [
        ("pendulum", pendulum()),
        ("double pendulum", double_pendulum()),
        ("spatial chain", spatial_chain(&mut rng)),
        (
            "zxz ball on an arm",
            spherical_on_arm(AngleSequence::Zxz, &mut rng),
        ),
        (
            "zyx ball on an arm",
            spherical_on_arm(AngleSequence::Zyx, &mut rng),
        ),
    ];
    for (k, (name, m)) in scenes.iter().enumerate() {
        for values in [Values::Literals, Values::Parameters] {
            let w = worst(m, values, 40 + k as u64);
            assert!(w <= 1e-12, "{name}, {values:?}: worst {w:e}");
        }
    }
}
