//! The Jacobians of the example mechanisms (exact on the symbolic and factored routes,
//! central differences on the recursive one) against five-point differences of the
//! independent Newton–Euler q̈ (the testkit's `mechanism::rnea`), and the double pendulum's
//! linearisation about its hanging equilibrium against the closed form and its normal modes.

use crate::common::mechanism as mechanism_support;

use crate::common::mechanism::examples;

use examples::babyboot::Babyboot;
use examples::chain::Chain;
use examples::double_pendulum::DoublePendulum;
use examples::gimballed_gyroscope::Gyroscope;
use examples::{
    G, angles, babyboot_reference, chain_reference, double_pendulum_reference, gyroscope_reference,
};
use mechanism_support::rng::Rng;
use mechanism_support::{NumMechanism, rnea};
use nalgebra::DMatrix;
use precess::mechanism::MechanismDynamics;

/// ∂q̈/∂(q, q̇) of the reference by the five-point stencil at h = 1e-3: truncation and
/// rounding both ≈ 1e-13 relative for these mechanisms' smooth q̈.
fn reference_jacobian(m: &NumMechanism, q: &[f64], qdot: &[f64]) -> DMatrix<f64> {
    rnea::acceleration_jacobian(m, q, qdot, 1e-3)
}

/// The largest difference between the derived (∂q̈/∂q, ∂q̈/∂q̇) and the reference's
/// differences over `states` random states, relative to max(max |J_ref|, 1).
fn jacobian_difference<const N: usize, M: MechanismDynamics<N>>(
    mech: &M,
    reference: &NumMechanism,
    rng: &mut Rng,
    states: usize,
    draw: impl Fn(&mut Rng) -> ([f64; N], [f64; N]),
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..states {
        let (q, qdot) = draw(rng);
        let (by_q, by_qdot) = mech
            .acceleration_jacobian(0.0, &q, &qdot)
            .expect("regular state");
        let expected = reference_jacobian(reference, &q, &qdot);
        let derived =
            DMatrix::from_fn(
                N,
                2 * N,
                |i, j| if j < N { by_q[i][j] } else { by_qdot[i][j - N] },
            );
        let scale = expected.amax().max(1.0);
        worst = worst.max((derived - expected).amax() / scale);
        // The full first-order Jacobian holds the blocks under [0, I].
        let full = mech.jacobian(0.0, &q, &qdot).expect("regular state");
        for i in 0..N {
            for j in 0..N {
                assert_eq!(full[(i, j)], 0.0);
                assert_eq!(full[(i, N + j)], if i == j { 1.0 } else { 0.0 });
                assert_eq!(
                    (full[(N + i, j)], full[(N + i, N + j)]),
                    (by_q[i][j], by_qdot[i][j])
                );
            }
        }
    }
    worst
}

#[test]
fn jacobians_match_differences_of_the_newton_euler_reference() {
    let mut rng = Rng::new(45);
    let anywhere = |rng: &mut Rng| (angles(rng), angles(rng));
    // The chain's second angles within ±1.2 rad: at ±π/2 a rod turns about its own axis,
    // where it has no inertia, and cond(M) reaches 1e11, beyond any difference quotient.
    let chain_state = |rng: &mut Rng| {
        let mut q: [f64; 8] = angles(rng);
        for b in q.iter_mut().skip(1).step_by(2) {
            *b = rng.uniform(-1.2, 1.2);
        }
        (q, angles(rng))
    };
    let dp = DoublePendulum {
        m1: 1.3,
        l1: 0.9,
        m2: 0.7,
        l2: 1.2,
    };
    let gyro = Gyroscope {
        m_outer: 0.1,
        m_inner: 0.05,
    };
    // Away from gimbal lock: θ in [0.5, 2.6].
    let mut gyro_worst = 0.0f64;
    for _ in 0..20 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.5, 2.6),
            rng.uniform(-3.0, 3.0),
        ];
        let qdot: [f64; 3] = angles(&mut rng);
        let (by_q, by_qdot) = gyro.acceleration_jacobian(0.0, &q, &qdot).expect("regular");
        let expected = reference_jacobian(&gyroscope_reference(&gyro), &q, &qdot);
        let derived = DMatrix::from_fn(
            3,
            6,
            |i, j| if j < 3 { by_q[i][j] } else { by_qdot[i][j - 3] },
        );
        gyro_worst = gyro_worst.max((derived - &expected).amax() / expected.amax().max(1.0));
    }
    let results = [
        (
            DoublePendulum::ROUTE,
            jacobian_difference(&dp, &double_pendulum_reference(&dp), &mut rng, 20, anywhere),
        ),
        (Gyroscope::ROUTE, gyro_worst),
        (
            Babyboot::ROUTE,
            jacobian_difference(&Babyboot, &babyboot_reference(), &mut rng, 20, anywhere),
        ),
        (
            Chain::ROUTE,
            jacobian_difference(&Chain, &chain_reference(), &mut rng, 5, chain_state),
        ),
    ];
    for ((route, worst), name) in
        results
            .iter()
            .zip(["double pendulum", "gyroscope", "babyboot", "chain"])
    {
        println!("{name} ({route} route): Jacobian vs differences of Newton–Euler {worst:.1e}");
        // Exact derivatives agree to the reference's own differencing error; the recursive
        // route's default differences carry theirs too.
        let tolerance = if *route == "recursive" { 1e-9 } else { 1e-11 };
        assert!(*worst < tolerance, "{name}: Jacobian differs by {worst:e}");
    }
}

#[test]
fn the_double_pendulum_linearised_about_hanging_has_the_normal_mode_frequencies() {
    let p = DoublePendulum {
        m1: 1.3,
        l1: 0.9,
        m2: 0.7,
        l2: 1.2,
    };
    let jac = p.jacobian(0.0, &[0.0, 0.0], &[0.0, 0.0]).expect("regular");
    // Closed form: in absolute angles M φ̈ = −K φ with M = [[(m1 + m2) l1², m2 l1 l2],
    // [m2 l1 l2, m2 l2²]], K = diag((m1 + m2) g l1, m2 g l2); det(K − ω² M) = 0 gives
    // ω² = g (s ∓ √(s² − 4 (m1 + m2) m1 l1 l2)) / (2 m1 l1 l2), s = (m1 + m2)(l1 + l2).
    let (m1, m2, l1, l2) = (p.m1, p.m2, p.l1, p.l2);
    let s = (m1 + m2) * (l1 + l2);
    let root = (s * s - 4.0 * (m1 + m2) * m1 * l1 * l2).sqrt();
    let den = 2.0 * m1 * l1 * l2;
    let omegas = [(G * (s - root) / den).sqrt(), (G * (s + root) / den).sqrt()];
    let eig = precess::linalg::eigenvalues(&jac).expect("finite");
    let mut found: Vec<f64> = eig.iter().filter(|z| z.im > 0.0).map(|z| z.im).collect();
    found.sort_by(f64::total_cmp);
    println!("normal modes: derived {found:?}, closed form {omegas:?}");
    assert_eq!(found.len(), 2, "{eig:?}");
    for (f, w) in found.iter().zip(omegas) {
        assert!((f - w).abs() <= 1e-12 * w, "ω {f} against {w}");
    }
    // Undamped: the eigenvalues are on the imaginary axis.
    assert!(eig.iter().all(|z| z.re.abs() <= 1e-12), "{eig:?}");
    // The relative coordinates' linearised matrix, entry by entry: q̈ = −M_rel⁻¹ K_rel q with
    // M_rel = [[(m1 + m2) l1² + m2 l2² + 2 m2 l1 l2, m2 l2² + m2 l1 l2], [m2 l2² + m2 l1 l2, m2 l2²]]
    // and K_rel = g [[(m1 + m2) l1 + m2 l2, m2 l2], [m2 l2, m2 l2]].
    let m_rel = nalgebra::Matrix2::new(
        (m1 + m2) * l1 * l1 + m2 * l2 * l2 + 2.0 * m2 * l1 * l2,
        m2 * l2 * l2 + m2 * l1 * l2,
        m2 * l2 * l2 + m2 * l1 * l2,
        m2 * l2 * l2,
    );
    let k_rel = G * nalgebra::Matrix2::new((m1 + m2) * l1 + m2 * l2, m2 * l2, m2 * l2, m2 * l2);
    let a = -m_rel.try_inverse().expect("regular") * k_rel;
    for i in 0..2 {
        for j in 0..2 {
            let d = (jac[(2 + i, j)] - a[(i, j)]).abs();
            assert!(
                d <= 1e-13 * a.amax(),
                "∂q̈{i}/∂q{j}: {} against {}",
                jac[(2 + i, j)],
                a[(i, j)]
            );
            assert!(jac[(2 + i, 2 + j)].abs() <= 1e-15, "no q̇ term at rest");
        }
    }
}
