//! Gimbal lock: the ZXZ angle form is singular at sin θ = 0. A top that passes through or
//! near the vertical is integrated by `ChartedTop`, which switches to the ZYX chart and back;
//! its motion must match the Eulerian (quaternion) form, which has no singularity.

use crate::common;
use crate::common::tops::reference_model;

use common::eulerian::Eulerian;
use common::rng::Rng;
use nalgebra::{Matrix3, Rotation3, Vector3};
use precess_core::ode::{AdaptiveConfig, Dop853};
use precess_core::rigid::{AngleSequence, angles_from_rotation};
use precess_core::rigid::{ChartConfig, ChartError};
use precess_core::top::{ChartedTop, TopError};

fn reference() -> Eulerian {
    Eulerian {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.5)),
        weight_lever: Vector3::new(0.0, 0.0, 1.0),
    }
}

fn rotation(seq: AngleSequence, q: [f64; 3]) -> Matrix3<f64> {
    let (x, y, z) = (Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis());
    let axes = match seq {
        AngleSequence::Zxz => [z, x, z],
        AngleSequence::Zyx => [z, y, x],
    };
    (Rotation3::from_axis_angle(&axes[0], q[0])
        * Rotation3::from_axis_angle(&axes[1], q[1])
        * Rotation3::from_axis_angle(&axes[2], q[2]))
    .into_inner()
}

#[test]
fn angles_from_rotation_inverts_both_sequences() {
    let mut rng = Rng::new(3);
    for seq in [AngleSequence::Zxz, AngleSequence::Zyx] {
        for _ in 0..1000 {
            let q = match seq {
                AngleSequence::Zxz => [
                    rng.uniform(-3.1, 3.1),
                    rng.uniform(0.01, 3.13),
                    rng.uniform(-3.1, 3.1),
                ],
                AngleSequence::Zyx => [
                    rng.uniform(-3.1, 3.1),
                    rng.uniform(-1.56, 1.56),
                    rng.uniform(-3.1, 3.1),
                ],
            };
            let back = angles_from_rotation(seq, &rotation(seq, q));
            for k in 0..3 {
                assert!((back[k] - q[k]).abs() < 1e-12, "{seq:?} {q:?} -> {back:?}");
            }
        }
    }
}

/// Runs the charted top and the quaternion reference side by side; returns the largest
/// attitude gap and the number of chart switches.
fn compare(r0: Matrix3<f64>, w0: Vector3<f64>, t_end: f64) -> (f64, usize, f64) {
    let (zxz, zyx) = (
        reference_model(AngleSequence::Zxz),
        reference_model(AngleSequence::Zyx),
    );
    let mut top = ChartedTop::new([&zxz, &zyx], 0.0, &r0, &w0, ChartConfig::default()).unwrap();
    let e0 = top.energy();
    let reference = reference();
    let mut euler = Dop853::new(
        &reference,
        0.0,
        Eulerian::state(&r0, &w0),
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=200 {
        let t = t_end * k as f64 / 200.0;
        top.advance_to(t).unwrap();
        euler.advance_to(t).unwrap();
        assert!(
            top.state().iter().all(|v| v.is_finite()),
            "non-finite state at t = {t}"
        );
        let gap = (top.rotation() - Eulerian::rotation(euler.y())).abs().max();
        worst = worst.max(gap);
    }
    let drift = (top.energy() - e0).abs() / e0.abs().max(1.0);
    (worst, top.switches(), drift)
}

/// A non-spinning top swung over the vertical passes exactly where ZXZ is singular.
#[test]
fn swing_through_the_vertical() {
    // θ = 1.4 with ψ = π/2, where ZXZ is the better chart (|sin θ| = 0.99 against
    // |cos pitch| = 0.17), swung back over the top with θ̇ = −2.5 (enough to pass the top,
    // 2.5²/2 > 1 − cos 1.4): ω = (θ̇ cos ψ, −θ̇ sin ψ, 0).
    let r0 = rotation(AngleSequence::Zxz, [0.0, 1.4, std::f64::consts::FRAC_PI_2]);
    let w0 = Vector3::new(0.0, 2.5, 0.0);
    let (gap, switches, drift) = compare(r0, w0, 6.0);
    eprintln!("swing: gap {gap:e} switches {switches} drift {drift:e}");
    assert!(
        switches >= 2,
        "expected to leave and re-enter the ZXZ chart, switched {switches}×"
    );
    assert!(
        gap < 1e-7,
        "attitude differs from the quaternion form by {gap:e}"
    );
    assert!(drift < 1e-8, "energy drift {drift:e}");
}

/// A sleeping top (ω3 = 6 above the threshold 4) nudged 0.02 rad off vertical: stable, it
/// stays near the vertical, always close to the ZXZ singularity.
#[test]
fn sleeping_top_nudged_off_vertical() {
    let r0 = rotation(AngleSequence::Zxz, [0.0, 0.02, 0.0]);
    let w0 = Vector3::new(0.0, 0.0, 6.0);
    let (gap, _, drift) = compare(r0, w0, 20.0);
    assert!(
        gap < 1e-7,
        "attitude differs from the quaternion form by {gap:e}"
    );
    assert!(drift < 1e-8, "energy drift {drift:e}");
}

/// A top precessing with its axis crossing the vertical while spinning fast.
#[test]
fn spinning_top_through_the_vertical() {
    let r0 = rotation(AngleSequence::Zxz, [0.3, 1.4, std::f64::consts::FRAC_PI_2]);
    let w0 = Vector3::new(0.0, 4.0, 2.0);
    let (gap, switches, drift) = compare(r0, w0, 10.0);
    eprintln!("spinning: gap {gap:e} switches {switches} drift {drift:e}");
    assert!(switches >= 2);
    assert!(
        gap < 1e-7,
        "attitude differs from the quaternion form by {gap:e}"
    );
    assert!(drift < 1e-8, "energy drift {drift:e}");
}

#[test]
fn two_charts_of_one_sequence_are_refused() {
    let m = reference_model(AngleSequence::Zxz);
    let r = ChartedTop::new(
        [&m, &m],
        0.0,
        &Matrix3::identity(),
        &Vector3::zeros(),
        ChartConfig::default(),
    );
    assert!(matches!(
        r,
        Err(TopError::Chart(ChartError::SameSequence(
            AngleSequence::Zxz
        )))
    ));
}

/// Why the switch is needed: a swing over the top with a 1e-6 rad/s out-of-plane rate
/// passes within ~1e-6 rad of the vertical, where the ZXZ rates φ̇, ψ̇ grow like 1/sin²θ.
/// ZXZ alone must then refuse (a typed error, never NaN) or grind through with many more
/// steps and a far larger error than the charted top.
#[test]
fn zxz_alone_struggles_near_the_singularity() {
    let zxz = reference_model(AngleSequence::Zxz);
    let zyx = reference_model(AngleSequence::Zyx);
    let q0 = [0.3, 1.4, std::f64::consts::FRAC_PI_2];
    let w0 = Vector3::new(1e-6, 2.5, 0.0);
    // Rates from ω = B q̇ with the textbook ZXZ B at ψ = π/2: ω = (φ̇ sθ, −θ̇, φ̇ cθ + ψ̇).
    let dphi = 1e-6 / q0[1].sin();
    let y0 = [q0[0], q0[1], q0[2], dphi, -2.5, -dphi * q0[1].cos()];
    assert!((Vector3::from(zxz.omega(&y0)) - w0).norm() < 1e-12);
    let r0 = rotation(AngleSequence::Zxz, q0);
    let reference = reference();
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut euler = Dop853::new(&reference, 0.0, Eulerian::state(&r0, &w0), tight).unwrap();
    euler.advance_to(6.0).unwrap();
    let truth = Eulerian::rotation(euler.y());

    let mut charted = ChartedTop::new([&zxz, &zyx], 0.0, &r0, &w0, ChartConfig::default()).unwrap();
    charted.advance_to(6.0).unwrap();
    let charted_gap = (charted.rotation() - truth).abs().max();
    assert!(charted_gap < 1e-8, "charted top off by {charted_gap:e}");

    let mut alone = Dop853::new(&zxz, 0.0, y0, ChartConfig::default().stepper).unwrap();
    match alone.advance_to(6.0) {
        Err(e) => eprintln!("ZXZ alone refused: {e}"),
        Ok(()) => {
            assert!(alone.y().iter().all(|v| v.is_finite()));
            let r = zxz.rotation(alone.y());
            let gap = (r - truth).abs().max();
            let (steps, charted_steps) = (alone.stats().steps, charted.stats().steps);
            eprintln!(
                "ZXZ alone: {steps} steps, error {gap:e}; charted: {charted_steps} steps, error {charted_gap:e}"
            );
            assert!(gap > 10.0 * charted_gap && steps > 5 * charted_steps);
        }
    }
}
