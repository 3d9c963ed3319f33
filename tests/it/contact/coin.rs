//! A coin spun on its edge about its vertical diameter, under Coulomb stick–slip and
//! pivoting friction −ℓ_p N sign(ω·γ) γ: the contact point is on the spin axis, so rolling
//! holds without friction, N = M g, and only the pivoting torque acts on the spin, about the
//! contact point through the centre, I_d ω̇ = −ℓ_p M g (I_d = M ρ²/4 the moment about a
//! diameter). The coin comes to rest in finite time, at t* = I_d ω₀ / (ℓ_p M g), where the
//! friction holds the spin and the run goes on with it held: the coin stands at rest, an
//! unstable equilibrium it leaves at the toppling rate √(4g/(5ρ)). Under a
//! linear spin resistance −c_s ω_⊥ instead, the spin only decays, e^(−c_s t / I_d), and the
//! coin never stops.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactOutcome, ContactRun, Phase};
use precess::ode::AdaptiveConfig;

use super::reference::{NumBody, NumLaw, NumTorques, disk, try_model_with};

/// A coin: a thin disk of radius 12 mm and 5.7 g.
fn coin() -> NumBody {
    disk(0.0057, 0.012)
}

/// Standing on its edge (its axis, body z, horizontal along space y), spinning at `w0`
/// about the vertical.
fn on_edge(m: &dyn ContactDynamics, w0: f64) -> [f64; 11] {
    let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2);
    m.rolling_state([0.0, 0.0], &q, &(q.inverse() * Vector3::new(0.0, 0.0, w0)))
        .unwrap()
}

#[test]
fn a_coin_with_coulomb_and_pivoting_friction_comes_to_rest_at_the_closed_form_time() {
    let body = coin();
    let (l, w0) = (2e-4, 20.0);
    let pivoting = NumTorques {
        pivoting: Some(l),
        ..NumTorques::default()
    };
    let m = try_model_with(&body, NumLaw::StickSlip(0.3), pivoting).unwrap();
    let y0 = on_edge(&m, w0);
    let t_star = body.inertia[0][0] * w0 / (l * body.mass * body.gravity);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    // The run goes on past the stop: the coin stands at rest, its spin held.
    let t_end = 2.0 * t_star;
    let out = run.advance_to(t_end).unwrap();
    assert_eq!(out, ContactOutcome::Reached { t: t_end });
    let switches = run.switches();
    let [stop] = switches.as_slice() else {
        panic!("{switches:?}")
    };
    let (t, state) = (stop.t, run.y());
    let speed = Vector3::new(state[8], state[9], state[10]).norm();
    println!(
        "coin, μ = 0.3, ℓ_p = {l} m, ω₀ = {w0} rad/s: held at t = {t} s against I_d ω₀/(ℓ_p M g) = {t_star} s; at {t_end} s |ω| {speed:e} rad/s, |v| {:e} m/s, centre at ({:e}, {:e}) m",
        state[2].hypot(state[3]),
        state[0],
        state[1]
    );
    assert_eq!(stop.witness, Some("spin"));
    assert!(!stop.spin_held_before && stop.spin_held_after, "{stop:?}");
    assert!(run.spin_held() && run.phase() == Phase::Rolling);
    assert!(((t - t_star) / t_star).abs() < 1e-8, "{t} vs {t_star}");
    assert!(speed < 1e-7 * w0, "{speed:e}");
    assert!(state[0].hypot(state[1]) < 1e-12, "{state:?}");
    // At rest on its edge: the energy is M g ρ, the centre a radius up.
    let rest = body.mass * body.gravity * 0.012;
    let e = m.energy(Phase::Rolling, state);
    assert!((e / rest - 1.0).abs() < 1e-12, "{e} vs {rest}");
    // Standing on its edge at rest is unstable: the rounding's tilt grows as e^(s t) with
    // s² = M g ρ / (I_d + M ρ²) = 4g/(5ρ), the coin toppling about the rim's tangent (on
    // which the contact point stays, so rolling holds without friction), its spin held.
    let rate = (4.0 * body.gravity / (5.0 * 0.012)).sqrt();
    let tilt = |y: &[f64; 11]| Vector3::new(y[8], y[9], y[10]).norm();
    let w1 = tilt(run.y());
    let span = 0.5 * t_star;
    run.advance_to(t_end + span).unwrap();
    let measured = (tilt(run.y()) / w1).ln() / span;
    println!(
        "  at rest on its edge, the tilt grows at {measured} 1/s against √(4g/(5ρ)) = {rate} 1/s, |ω| {w1:e} → {:e} rad/s",
        tilt(run.y())
    );
    assert!(run.spin_held());
    assert!((measured / rate - 1.0).abs() < 1e-4, "{measured} vs {rate}");

    // A linear spin resistance with the same initial torque only slows it exponentially.
    let cs = l * body.mass * body.gravity / w0;
    let linear = NumTorques {
        cs: Some(cs),
        ..NumTorques::default()
    };
    let m = try_model_with(&body, NumLaw::StickSlip(0.3), linear).unwrap();
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, on_edge(&m, w0), cfg).unwrap();
    assert_eq!(
        run.advance_to(t_star).unwrap(),
        ContactOutcome::Reached { t: t_star }
    );
    let w = m
        .contact(run.y())
        .gamma
        .dot(&Vector3::new(run.y()[8], run.y()[9], run.y()[10]));
    let expected = w0 * (-cs * t_star / body.inertia[0][0]).exp();
    println!("  linear spin resistance: ω = {w} at t* against ω₀ e^(−c_s t*/I_d) = {expected}");
    assert!((w / expected - 1.0).abs() < 1e-9, "{w} vs {expected}");
}
