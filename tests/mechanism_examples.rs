//! Every example mechanism — the very struct its example derives, included from
//! examples/mechanisms/ — against the independent numeric Newton–Euler algorithm of
//! tests/mechanism_support/rnea.rs: q̈ at 10³ random states (and random field values where the
//! struct has fields), T and the cyclic momenta against ½ q̇ᵀ M q̇ and (M q̇)ᵢ of the reference's
//! mass matrix, and E and the cyclic momenta conserved along a short DOP853 run.
//!
//! Agreement is measured by `relative_difference`: max |generated − reference| over the
//! components, divided by max(max |reference|, 1) — relative to the largest component, with a
//! floor of 1 (rad/s², J, J·s) so a state whose every component is near zero is judged
//! absolutely.

#[path = "mechanism_support/mod.rs"]
mod mechanism_support;

#[path = "../examples/mechanisms/babyboot.rs"]
mod babyboot;
#[path = "../examples/mechanisms/chain.rs"]
mod chain;
#[path = "../examples/mechanisms/double_pendulum.rs"]
mod double_pendulum;
#[path = "../examples/mechanisms/gimballed_gyroscope.rs"]
mod gimballed_gyroscope;

use babyboot::Babyboot;
use chain::{Chain, LINKS};
use double_pendulum::DoublePendulum;
use gimballed_gyroscope::Gyroscope;
use mechanism_support::rng::Rng;
use mechanism_support::{NumBody, NumJoint, NumMechanism, relative_difference, rnea};
use nalgebra::{DMatrix, DVector, Matrix3};
use precess::mechanism::MechanismDynamics;
use precess::ode::{AdaptiveConfig, Dop853, System};

const STATES: usize = 1000;
const TOLERANCE: f64 = 1e-12;
const G: f64 = 9.81;

/// The double pendulum as the reference sees it: point masses, no inertia.
fn double_pendulum_reference(p: &DoublePendulum) -> NumMechanism {
    let mut upper = NumBody::new(None, [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    upper.mass = p.m1;
    upper.center = [0.0, 0.0, -p.l1];
    upper.inertia = Matrix3::zeros();
    let mut lower = NumBody::new(
        Some(0),
        [0.0, 0.0, -p.l1],
        NumJoint::Revolute([1.0, 0.0, 0.0]),
    );
    lower.mass = p.m2;
    lower.center = [0.0, 0.0, -p.l2];
    lower.inertia = Matrix3::zeros();
    NumMechanism {
        bodies: vec![upper, lower],
        gravity: [0.0, 0.0, -G],
    }
}

/// The gyroscope: rings of radius r normal to y (m r² about y, ½ m r² across), a thin disk
/// normal to z (½ m r² about z, ¼ m r² across) 0.04 above the centre.
fn gyroscope_reference(p: &Gyroscope) -> NumMechanism {
    let ring = |m: f64, r: f64| {
        Matrix3::from_diagonal(&[m * r * r / 2.0, m * r * r, m * r * r / 2.0].into())
    };
    let mut outer = NumBody::new(None, [0.0; 3], NumJoint::Revolute([0.0, 0.0, 1.0]));
    outer.mass = p.m_outer;
    outer.inertia = ring(p.m_outer, 0.08);
    let mut inner = NumBody::new(Some(0), [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    inner.mass = p.m_inner;
    inner.inertia = ring(p.m_inner, 0.07);
    let (m, r) = (0.4, 0.05);
    let mut rotor = NumBody::new(Some(1), [0.0; 3], NumJoint::Revolute([0.0, 0.0, 1.0]));
    rotor.mass = m;
    rotor.center = [0.0, 0.0, 0.04];
    rotor.inertia =
        Matrix3::from_diagonal(&[m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0].into());
    NumMechanism {
        bodies: vec![outer, inner, rotor],
        gravity: [0.0, 0.0, -G],
    }
}

/// The babyboot with Drake's parameters, as the example's struct writes them.
fn babyboot_reference() -> NumMechanism {
    let mut rod = NumBody::new(None, [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    rod.mass = 0.01;
    rod.center = [0.0, 0.0, -0.075];
    rod.inertia = Matrix3::from_diagonal(&[5.0e-6, 5.0e-6, 1.0e-7].into());
    let mut plate = NumBody::new(
        Some(0),
        [0.0, 0.0, -0.2],
        NumJoint::Revolute([0.0, 0.0, 1.0]),
    );
    plate.mass = 0.1;
    plate.inertia = Matrix3::from_diagonal(&[2.5e-4, 5.0e-5, 2.0e-4].into());
    NumMechanism {
        bodies: vec![rod, plate],
        gravity: [0.0, 0.0, -G],
    }
}

/// Four thin rods (1 kg, 0.5 m along z: m l²/12 across, none along) on universal joints.
fn chain_reference() -> NumMechanism {
    let across = 0.25 / 12.0;
    let bodies = (0..LINKS)
        .map(|k| {
            let (parent, at) = if k == 0 {
                (None, [0.0; 3])
            } else {
                (Some(k - 1), [0.0, 0.0, -0.5])
            };
            let mut rod = NumBody::new(
                parent,
                at,
                NumJoint::Universal([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            );
            rod.mass = 1.0;
            rod.center = [0.0, 0.0, -0.25];
            rod.inertia = Matrix3::from_diagonal(&[across, across, 0.0].into());
            rod
        })
        .collect();
    NumMechanism {
        bodies,
        gravity: [0.0, 0.0, -G],
    }
}

/// The reference's mass matrix: column j is the inverse dynamics of q̈ = e_j without bias.
fn reference_mass_matrix(m: &NumMechanism, q: &[f64]) -> DMatrix<f64> {
    let n = q.len();
    let zero = vec![0.0; n];
    let mut mass = DMatrix::zeros(n, n);
    for j in 0..n {
        let mut e = zero.clone();
        e[j] = 1.0;
        let column = rnea::inverse_dynamics(m, q, &zero, &e, false);
        for (i, v) in column.iter().enumerate() {
            mass[(i, j)] = *v;
        }
    }
    mass
}

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
        let mass = reference_mass_matrix(&reference, &q);
        let singular = mass.clone().singular_values();
        if singular.max() <= WELL_CONDITIONED * singular.min() {
            w.forward = w.forward.max(relative_difference(&derived, &expected, 1.0));
            w.judged += 1;
        }
        // The backward error: |M (q̈ − q̈_ref)| against |M| |q̈_ref|, the size of the
        // terms whose rounding any algorithm's M q̈ carries.
        let error = DVector::from_iterator(N, derived.iter().zip(&expected).map(|(a, b)| a - b));
        let scale = mass.abs() * DVector::from_iterator(N, expected.iter().map(|a| a.abs()));
        let residual = (&mass * error).amax() / scale.amax().max(1.0);
        w.residual = w.residual.max(residual);
        let v = DVector::from_column_slice(&qdot);
        let momenta = &mass * &v;
        let kinetic = 0.5 * v.dot(&momenta);
        w.kinetic = w.kinetic.max(relative_difference(
            &[mech.kinetic(&q, &qdot)],
            &[kinetic],
            1.0,
        ));
        for (i, p) in mech.cyclic_momenta(&q, &qdot).iter().enumerate() {
            if let Some(p) = p {
                w.momenta = w
                    .momenta
                    .max(relative_difference(&[*p], &[momenta[i]], 1.0));
            }
        }
    }
    w
}

fn angles<const N: usize>(rng: &mut Rng) -> [f64; N] {
    std::array::from_fn(|_| rng.uniform(-3.0, 3.0))
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
    let p0 = mech.cyclic_momenta(&q0, &v0);
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
        for (p, start) in mech.cyclic_momenta(&q, &v).iter().zip(&p0) {
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
    .cyclic_momenta(&[0.0, 0.8, 0.0], &[0.5, 0.0, 80.0]);
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

/// ∂q̈/∂(q, q̇) of the reference by the five-point stencil (f(−2h) − 8 f(−h) + 8 f(h) −
/// f(2h)) / 12h, h = 1e-3: truncation h⁴ f⁽⁵⁾/30 ≈ 1e-13 and rounding ≈ ε |q̈| / h ≈ 1e-13
/// relative for these mechanisms' smooth q̈.
fn reference_jacobian(m: &NumMechanism, q: &[f64], qdot: &[f64]) -> DMatrix<f64> {
    let n = q.len();
    let h = 1e-3;
    let state: Vec<f64> = q.iter().chain(qdot).copied().collect();
    let at = |y: &[f64]| rnea::accelerations(m, &y[..n], &y[n..]);
    DMatrix::from_fn(n, 2 * n, |i, j| {
        let shifted = |k: f64| {
            let mut y = state.clone();
            y[j] += k * h;
            at(&y)[i]
        };
        (shifted(-2.0) - 8.0 * shifted(-1.0) + 8.0 * shifted(1.0) - shifted(2.0)) / (12.0 * h)
    })
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
