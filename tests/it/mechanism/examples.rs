//! Every example mechanism — the very struct its example derives, included from
//! examples/mechanisms/ — against the independent numeric Newton–Euler algorithm of
//! the testkit's `mechanism::rnea`: q̈ at 10³ random states (and random field values where the
//! struct has fields), T and the cyclic momenta against ½ q̇ᵀ M q̇ and (M q̇)ᵢ of the reference's
//! mass matrix, and E and the cyclic momenta conserved along a short DOP853 run.
//!
//! Agreement is measured by `relative_difference`: max |generated − reference| over the
//! components, divided by max(max |reference|, 1) — relative to the largest component, with a
//! floor of 1 (rad/s², J, J·s) so a state whose every component is near zero is judged
//! absolutely.

use crate::common::mechanism as mechanism_support;

use crate::common::mechanism::examples;

use examples::babyboot::Babyboot;
use examples::chain::Chain;
use examples::double_pendulum::DoublePendulum;
use examples::gimballed_gyroscope::Gyroscope;
use examples::{
    angles, babyboot_reference, chain_reference, double_pendulum_reference, gyroscope_reference,
};
use mechanism_support::rng::Rng;
use mechanism_support::{NumMechanism, relative_difference, rnea};
use nalgebra::DVector;
use precess::mechanism::MechanismDynamics;
use precess::ode::{AdaptiveConfig, Dop853, System};

const STATES: usize = 1000;
const TOLERANCE: f64 = 1e-12;

/// Above this condition number of M the forward error of q̈ (≈ cond(M)·ε in any algorithm)
/// says nothing of the code; such states (a thin rod turned about its own axis, gimbal
/// lock) are judged by the residual alone.
const WELL_CONDITIONED: f64 = 1e4;

/// The worst disagreements over random states, each by `relative_difference`.
struct Worst {
    /// q̈ against the reference's, at the states with cond(M) ≤ [`WELL_CONDITIONED`].
    forward: f64,
    /// |M (q̈ − q̈_ref)|∞ / max(| |M| |q̈_ref| |∞, 1) (a backward error), at every state.
    residual: f64,
    /// T against ½ q̇ᵀ M q̇.
    kinetic: f64,
    /// Each cyclic momentum against (M q̇)ᵢ.
    momenta: f64,
    /// How many states were well conditioned.
    judged: usize,
}

/// Draws [`STATES`] states (with the struct and its reference) and compares the derived q̈,
/// T and cyclic momenta with the reference's.
fn worst<const N: usize, M: MechanismDynamics<N>>(
    rng: &mut Rng,
    mut draw: impl FnMut(&mut Rng) -> (M, NumMechanism, [f64; N], [f64; N]),
) -> Worst {
    let mut w = Worst {
        forward: 0.0,
        residual: 0.0,
        kinetic: 0.0,
        momenta: 0.0,
        judged: 0,
    };
    for _ in 0..STATES {
        let (mech, reference, q, qdot) = draw(rng);
        let derived = mech.accelerations(0.0, &q, &qdot).expect("regular state");
        let expected = rnea::accelerations(&reference, &q, &qdot);
        let mass = rnea::mass_matrix(&reference, &q);
        if rnea::condition(&mass) <= WELL_CONDITIONED {
            w.forward = w.forward.max(relative_difference(&derived, &expected, 1.0));
            w.judged += 1;
        }
        w.residual = w
            .residual
            .max(rnea::backward_error(&mass, &derived, &expected));
        let v = DVector::from_column_slice(&qdot);
        let momenta = &mass * &v;
        let kinetic = 0.5 * v.dot(&momenta);
        w.kinetic = w.kinetic.max(relative_difference(
            &[mech.kinetic(&q, &qdot)],
            &[kinetic],
            1.0,
        ));
        for (i, p) in mech.conserved_momenta(&q, &qdot).iter().enumerate() {
            if let Some(p) = p {
                w.momenta = w
                    .momenta
                    .max(relative_difference(&[*p], &[momenta[i]], 1.0));
            }
        }
    }
    w
}

fn assert_agrees(name: &str, w: Worst) {
    println!(
        "{name}: worst q̈ {:.1e} ({} of {STATES} states with cond(M) ≤ 1e4), residual {:.1e}, T {:.1e}, cyclic momenta {:.1e}",
        w.forward, w.judged, w.residual, w.kinetic, w.momenta
    );
    assert!(
        w.judged >= STATES / 2,
        "{name}: only {} well-conditioned states",
        w.judged
    );
    for (what, d) in [
        ("q̈", w.forward),
        ("M (q̈ − q̈_ref)", w.residual),
        ("T", w.kinetic),
        ("cyclic momenta", w.momenta),
    ] {
        assert!(
            d <= TOLERANCE,
            "{name}: {what} differs from Newton–Euler by {d:e}"
        );
    }
}

#[test]
fn double_pendulum_matches_newton_euler_at_random_states_and_lengths() {
    let mut rng = Rng::new(41);
    let w = worst(&mut rng, |rng| {
        let p = DoublePendulum {
            m1: rng.uniform(0.2, 3.0),
            l1: rng.uniform(0.2, 2.0),
            m2: rng.uniform(0.2, 3.0),
            l2: rng.uniform(0.2, 2.0),
        };
        let reference = double_pendulum_reference(&p);
        (p, reference, angles(rng), angles(rng))
    });
    assert_agrees("double pendulum", w);
}

#[test]
fn gyroscope_matches_newton_euler_at_random_states_and_gimbal_masses() {
    let mut rng = Rng::new(42);
    let w = worst(&mut rng, |rng| {
        // Massless gimbals included: then M is the top's, regular away from gimbal lock.
        let p = Gyroscope {
            m_outer: rng.uniform(0.0, 0.5).max(0.05) - 0.05,
            m_inner: rng.uniform(0.0, 0.5).max(0.05) - 0.05,
        };
        let reference = gyroscope_reference(&p);
        let mut q: [f64; 3] = angles(rng);
        // θ in [0.3, π − 0.3] or its mirror: away from the lock at θ = 0, π.
        q[Gyroscope::THETA] = rng.uniform(0.3, std::f64::consts::PI - 0.3)
            * if rng.uniform(-1.0, 1.0) < 0.0 {
                -1.0
            } else {
                1.0
            };
        let mut qdot: [f64; 3] = angles(rng);
        qdot[Gyroscope::PSI] = rng.uniform(-100.0, 100.0);
        (p, reference, q, qdot)
    });
    assert_agrees("gimballed gyroscope", w);
}

#[test]
fn babyboot_matches_newton_euler_at_random_states() {
    let mut rng = Rng::new(43);
    let w = worst(&mut rng, |rng| {
        (Babyboot, babyboot_reference(), angles(rng), angles(rng))
    });
    assert_agrees("babyboot", w);
}

#[test]
fn chain_matches_newton_euler_at_random_states() {
    let mut rng = Rng::new(44);
    let w = worst(&mut rng, |rng| {
        (Chain, chain_reference(), angles(rng), angles(rng))
    });
    assert_agrees("chain", w);
}

/// The largest drift of E and of each cyclic momentum from its start along a DOP853 run at
/// rtol 1e-12, relative to max(|start|, `floor`).
fn drifts<const N: usize, const S: usize, M>(
    mech: M,
    y0: [f64; S],
    end: f64,
    floor: f64,
) -> (f64, f64)
where
    M: MechanismDynamics<N> + System<S> + Clone,
{
    let split = |y: &[f64; S]| precess::mechanism::split_state::<N, S>(y).expect("S = 2N");
    let (q0, v0) = split(&y0);
    let e0 = mech.energy(&q0, &v0);
    let p0 = mech.conserved_momenta(&q0, &v0);
    let mut ode = Dop853::new(
        mech.clone(),
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .expect("starts");
    let (mut energy, mut momenta) = (0.0f64, 0.0f64);
    for k in 1..=50 {
        ode.advance_to(end * k as f64 / 50.0).expect("integrates");
        let (q, v) = split(ode.y());
        energy = energy.max((mech.energy(&q, &v) - e0).abs() / e0.abs().max(floor));
        for (p, start) in mech.conserved_momenta(&q, &v).iter().zip(&p0) {
            if let (Some(p), Some(start)) = (p, start) {
                momenta = momenta.max((p - start).abs() / start.abs().max(floor));
            }
        }
    }
    (energy, momenta)
}

#[test]
fn energy_and_cyclic_momenta_are_conserved_along_dop853_runs() {
    let dp = DoublePendulum {
        m1: 1.0,
        l1: 1.0,
        m2: 1.0,
        l2: 1.0,
    };
    let (e, _) = drifts::<2, 4, _>(dp, [2.0, -1.0, 0.0, 1.0], 5.0, 1.0);
    println!("double pendulum: energy drift {e:.1e}");
    assert!(e < 1e-9, "double pendulum energy drift {e:e}");

    let gyro = Gyroscope {
        m_outer: 0.1,
        m_inner: 0.05,
    };
    let (e, p) = drifts::<3, 6, _>(gyro, [0.0, 0.8, 0.0, 0.5, 0.0, 80.0], 2.0, 1e-3);
    println!("gyroscope: energy drift {e:.1e}, cyclic momenta drift {p:.1e}");
    assert!(
        e < 1e-9 && p < 1e-9,
        "gyroscope drifts: energy {e:e}, momenta {p:e}"
    );
    let cyclic = Gyroscope {
        m_outer: 0.1,
        m_inner: 0.05,
    }
    .conserved_momenta(&[0.0, 0.8, 0.0], &[0.5, 0.0, 80.0]);
    assert!(
        cyclic[Gyroscope::PHI].is_some()
            && cyclic[Gyroscope::PSI].is_some()
            && cyclic[Gyroscope::THETA].is_none()
    );

    let (e, _) = drifts::<2, 4, _>(
        Babyboot,
        [90f64.to_radians(), 1f64.to_radians(), 0.0, 0.0],
        2.0,
        1e-3,
    );
    println!("babyboot: energy drift {e:.1e}");
    assert!(e < 1e-9, "babyboot energy drift {e:e}");

    let mut y0 = [0.0; 16];
    for (k, v) in y0.iter_mut().take(8).enumerate() {
        *v = 0.3 * (k as f64 + 1.0).sin();
    }
    let (e, _) = drifts::<8, 16, _>(Chain, y0, 2.0, 1.0);
    println!("chain: energy drift {e:.1e}");
    assert!(e < 1e-9, "chain energy drift {e:e}");
}
