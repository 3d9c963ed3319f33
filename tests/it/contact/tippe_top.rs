//! The tippe top: an eccentric sphere (centre of mass a = 6 mm below the centre of its
//! spherical surface of radius R = 20 mm, I₃/I₁ = 0.906 within 1 ∓ a/R) spun at 150 rad/s
//! nearly upright and gliding under viscous friction turns itself upside down, raising its
//! centre of mass. Jellett's λ = −L·r holds throughout, and fixes the end state in closed
//! form: spinning upside down about the vertical, r = (R + a) e₃, so
//! λ = −I₃ ω₃ (R + a), ω₃ = −λ/(I₃ (R + a)) and E = ½ I₃ ω₃² + M g (R + a).

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactOutcome, ContactRun, Phase};
use precess::ode::AdaptiveConfig;

use super::reference::{NumLaw, model, offset_sphere, state};

#[test]
fn the_tippe_top_inverts_with_jellett_fixing_its_end_state() {
    let body = offset_sphere();
    let m = model(&body, NumLaw::Viscous(0.02));
    let (i3, a, radius) = (body.inertia[2][2], 0.006, 0.02);
    let q = UnitQuaternion::from_euler_angles(0.1, 0.05, 0.0);
    let y0 = state([0.0, 0.0], [0.0, 0.0], &q, &Vector3::new(0.0, 0.0, 150.0));
    let lambda0 = m.jellett(&y0);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);
    let mut run = ContactRun::new(&m, Phase::Sliding, 0.0, y0, cfg).unwrap();
    let mut lambda_drift: f64 = 0.0;
    let mut crossed_at = None;
    for k in 1..=400 {
        let t = 0.1 * k as f64;
        assert_eq!(run.advance_to(t).unwrap(), ContactOutcome::Reached { t });
        let y = *run.y();
        lambda_drift = lambda_drift.max(((m.jellett(&y) - lambda0) / lambda0).abs());
        if crossed_at.is_none() && m.contact(&y).gamma.z < 0.0 {
            crossed_at = Some(t);
        }
    }
    let y = *run.y();
    let w3 = -lambda0 / (i3 * (radius + a));
    let energy = 0.5 * i3 * w3 * w3 + body.mass * body.gravity * (radius + a);
    let e_end = m.energy(Phase::Sliding, &y);
    println!(
        "tippe top: γ₃ {} → {}, horizontal at t ≈ {crossed_at:?} s; λ drift {lambda_drift:e}; \
         ω₃ {} against −λ/(I₃(R + a)) = {w3}; E {} → {e_end} against {energy}",
        m.contact(&y0).gamma.z,
        m.contact(&y).gamma.z,
        y[10],
        m.energy(Phase::Sliding, &y0),
    );
    assert!(m.contact(&y).gamma.z < -0.999_999, "not inverted");
    assert!(lambda_drift < 1e-12, "{lambda_drift:e}");
    assert!(((y[10] - w3) / w3).abs() < 1e-8, "{} vs {w3}", y[10]);
    assert!(
        ((e_end - energy) / energy).abs() < 1e-8,
        "{e_end} vs {energy}"
    );
}
