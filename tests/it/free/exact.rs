//! The derived free body integrated against independent closed forms: the parabola of the
//! centre of mass and the torque-free attitude (elliptic functions) under uniform gravity,
//! and the body precession of a symmetric body.

use crate::common::free_bodies;

use approx::assert_relative_eq;
use free_bodies::{T_HANDLE_MOMENTS, THandle, throw};
use precess::free::{FreeDynamics, FreeExact, FreeFlight, FreeState, FreeSystem};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;

/// A throw of the T-handle spinning near its intermediate axis (the bar, x).

#[test]
fn the_macro_finds_the_moments_summed_by_hand() {
    let p = THandle.principal_cm();
    assert_relative_eq!(
        p.moments,
        Vector3::from(T_HANDLE_MOMENTS),
        max_relative = 1e-14
    );
    assert_relative_eq!(THandle.gravity(), Vector3::new(0.0, 0.0, -9.81));
}

/// Item 4(a): DOP853 against the exact parabola and exact attitude at T = 100, to 1e-9.
///
/// The issue names rtol 1e-12, measured with the earlier PI gains (2.0e-10 rad in 134 053
/// evaluations). DOP853 now uses `dop853.f`'s gains, which take longer steps at a given
/// tolerance: 1.4e-8 rad in 86 970 evaluations at 1e-12, and 2.7e-10 rad in 130 479 at
/// 3e-14 — the same work and accuracy as before, under a different tolerance.
#[test]
fn near_the_intermediate_axis_the_integration_follows_the_exact_motion_to_1e9() {
    let s0 = throw();
    let exact = THandle.exact(0.0, &s0).unwrap();
    // Near the separatrix: it flips, several times within the span.
    let flips = exact.flip_interval().unwrap();
    assert!(100.0 / flips > 5.0, "flip interval {flips}");
    let cfg = AdaptiveConfig {
        max_steps: 1_000_000,
        ..AdaptiveConfig::with_tol(3e-14, 3e-14)
    };
    let mut flight = FreeFlight::new(FreeSystem(&THandle), 0.0, &s0, cfg).unwrap();
    let t_end = 100.0;
    flight.advance_to(t_end).unwrap();
    let got = flight.state().unwrap();
    let want = exact.at(t_end).unwrap();
    // The parabola, directly: x₀ + v₀ t + ½ g t².
    let parabola =
        s0.position + s0.velocity * t_end + Vector3::new(0.0, 0.0, -9.81) * (0.5 * t_end * t_end);
    assert_relative_eq!(want.position, parabola, max_relative = 1e-15);
    assert_relative_eq!(got.position, want.position, max_relative = 1e-9);
    assert_relative_eq!(got.velocity, want.velocity, max_relative = 1e-9);
    let attitude_error = got.attitude.angle_to(&want.attitude);
    assert!(
        attitude_error <= 1e-9,
        "attitude off by {attitude_error:e} rad"
    );
    let omega_error =
        (got.omega_principal - want.omega_principal).norm() / want.omega_principal.norm();
    assert!(omega_error <= 1e-9, "ω off by {omega_error:e}");
}

/// The exact motion keeps what the free body keeps: the spatial angular momentum about the
/// centre of mass and the rotational energy, at any time.
#[test]
fn the_exact_motion_conserves_spin_momentum_and_energy() {
    let s0 = throw();
    let exact = THandle.exact(0.0, &s0).unwrap();
    let i = Vector3::from(T_HANDLE_MOMENTS);
    let spin = |s: &FreeState| s.attitude * i.component_mul(&s.omega_principal);
    let rot = |s: &FreeState| 0.5 * s.omega_principal.dot(&i.component_mul(&s.omega_principal));
    for t in [0.3, 7.7, 55.5, 1e3] {
        let s = exact.at(t).unwrap();
        assert_relative_eq!(spin(&s), spin(&s0), max_relative = 1e-12);
        assert_relative_eq!(rot(&s), rot(&s0), max_relative = 1e-12);
    }
}

/// A symmetric body, torque-free: ω turns in the body about the symmetry axis at
/// Ω = (I3 − I1) ω3 / I1, with ω3 constant.
#[derive(RigidBody)]
#[rigid(cylinder(mass = 2.0, radius = 0.1, length = 0.05))]
#[free]
struct Coin;

#[test]
fn a_symmetric_body_precesses_in_the_body_at_the_closed_form_rate() {
    // Cylinder: I3 = ½ m r², I1 = m (3 r² + L²)/12.
    let (i1, i3) = (2.0 * (3.0 * 0.01 + 0.0025) / 12.0, 0.5 * 2.0 * 0.01);
    let (w_perp, w3) = (0.7, 12.0);
    let s0 = FreeState {
        omega_principal: Vector3::new(w_perp, 0.0, w3),
        ..FreeState::at_rest()
    };
    let rate = (i3 - i1) * w3 / i1;
    let mut flight = FreeFlight::new(
        FreeSystem(&Coin),
        0.0,
        &s0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    for t in [0.5, 2.0, 9.0] {
        flight.advance_to(t).unwrap();
        let w = flight.state().unwrap().omega_principal;
        let expected = Vector3::new(w_perp * (rate * t).cos(), w_perp * (rate * t).sin(), w3);
        assert_relative_eq!(w, expected, epsilon = 1e-9);
    }
}

/// The near-separatrix body of the references (I = (3, 5, 9), m(0) = (0, 2, 0.01)): the
/// interval between flips is 2K/λ = 59.0554435 s, in the caller's time whatever the scaling
/// the exact attitude uses inside.
#[test]
fn the_flip_interval_is_the_published_one() {
    let moments = Vector3::new(3.0, 5.0, 9.0);
    let s0 = FreeState {
        omega_principal: Vector3::new(0.0, 2.0, 0.01).component_div(&moments),
        ..FreeState::at_rest()
    };
    let exact = FreeExact::new(&moments, &Vector3::zeros(), 0.0, &s0).unwrap();
    assert_relative_eq!(
        exact.flip_interval().unwrap(),
        59.055_443_5,
        max_relative = 1e-8
    );
}
