//! What every contact run keeps, whatever the body, surface, law, tolerance and start: asserted
//! at every accepted step of the one run loop and at every switch it records.
//!
//! - N ≥ 0 on the table (to 10⁻⁹ M g);
//! - |F_t| ≤ μN while a stick–slip body rolls;
//! - the energy never rises under a dissipative law (beyond the integration's own error),
//!   and holds to the tolerance under rolling without resistance and frictionless sliding;
//! - the contact point is at rest while rolling;
//! - the transitions chain (each leaves the mode the one before entered, in time order), a
//!   stick–slip body slips only at the friction cone and rolls again only where its slip
//!   stopped, and a lift-off is where N reached zero.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactError, ContactModel, ContactOutcome, ContactRun, LawKind, Phase,
    STATE_LEN, layout,
};
use precess::ode::{AdaptiveConfig, Control, Run, Stepper};
use proptest::prelude::*;

use super::reference::{NumBody, NumLaw, chaplygin_ball, model, offset_sphere, rattleback};

fn bodies() -> [NumBody; 3] {
    [offset_sphere(), rattleback(), chaplygin_ball()]
}

fn law(which: usize, coefficient: f64) -> NumLaw {
    match which {
        0 => NumLaw::Rolling { cr: None, cs: None },
        1 => NumLaw::Rolling {
            cr: Some(1e-4 * coefficient),
            cs: Some(1e-4 * coefficient),
        },
        2 => NumLaw::Frictionless,
        3 => NumLaw::Viscous(0.01 * coefficient),
        4 => NumLaw::Coulomb(0.5 * coefficient),
        _ => NumLaw::StickSlip(0.5 * coefficient),
    }
}

/// Whether the law can only take energy out (and by how much the run may drift otherwise).
fn conservative(law: NumLaw) -> bool {
    matches!(
        law,
        NumLaw::Rolling { cr: None, cs: None } | NumLaw::Frictionless
    )
}

/// A start for `m`: rolling for the laws that roll, else sliding with the horizontal
/// velocity `v` (so that a Coulomb law has a slip).
fn start(
    m: &ContactModel,
    q: &UnitQuaternion<f64>,
    w: Vector3<f64>,
    v: [f64; 2],
) -> [f64; STATE_LEN] {
    let mut y = m.rolling_state([0.0; 2], q, &w).unwrap();
    if m.law().first_phase() == Phase::Sliding {
        y[layout::VELOCITY] += v[0];
        y[layout::VELOCITY + 1] += v[1];
    }
    y
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn every_contact_run_keeps_the_rules_of_its_contact(
        which_body in 0usize..3,
        which_law in 0usize..6,
        coefficient in 0.05f64..1.0,
        log_tol in -11.0f64..-6.0,
        yaw in -3.0f64..3.0,
        tilt in 0.0f64..0.6,
        w in prop::array::uniform3(-8.0f64..8.0),
        v in prop::array::uniform2(-0.5f64..0.5),
    ) {
        let body = bodies()[which_body];
        let num_law = law(which_law, coefficient);
        let m = model(&body, num_law);
        let q = UnitQuaternion::from_euler_angles(tilt, 0.0, yaw);
        let y0 = start(&m, &q, Vector3::from(w), v);
        let phase = m.law().first_phase();
        let tol = 10f64.powf(log_tol);
        let mut cfg = AdaptiveConfig::with_tol(tol, tol);
        cfg.max_steps = 1_000_000;
        let mut run = match ContactRun::new(&m, phase, 0.0, y0, cfg) {
            // Starts the rules refuse are not runs: N < 0, no slip to slide on.
            Err(ContactError::NotPressed { normal, .. }) => {
                prop_assert!(normal < 0.0);
                return Ok(());
            }
            Err(ContactError::ZeroSlip { .. } | ContactError::Painleve { .. }) => return Ok(()),
            other => other.unwrap(),
        };
        let values = m.values();
        let mg = values.mass * values.gravity;
        let mu = m.friction_coefficient().unwrap_or(0.0);
        let e0 = m.energy(phase, &y0);
        let mut e_min = e0;
        let mut broken: Option<String> = None;
        let out = Run::new(&mut run, 0.3)
            .sample_none()
            .observe(|t, s| {
                let r = m.reaction(s.mode.phase, &s.x);
                let e = m.energy(s.mode.phase, &s.x);
                let c = m.contact(&s.x);
                let omega = Vector3::new(s.x[8], s.x[9], s.x[10]);
                let scale = omega.norm() * c.body.norm() + 1e-3;
                let why = if r.normal < -1e-9 * mg {
                    Some(format!("N = {} at {t}", r.normal))
                } else if s.mode.phase == Phase::Rolling
                    && m.law() == LawKind::StickSlip
                    && r.friction.norm() > mu * r.normal * (1.0 + 1e-8) + 1e-12 * mg
                {
                    Some(format!("|F_t| = {} > μN = {} at {t}", r.friction.norm(), mu * r.normal))
                } else if conservative(num_law) && ((e - e0) / e0).abs() > 1e3 * tol {
                    Some(format!("energy {e0} → {e} at {t}"))
                } else if !conservative(num_law) && e > e_min + 1e3 * tol * e0.abs() {
                    Some(format!("energy rose from {e_min} to {e} at {t}"))
                } else if s.mode.phase == Phase::Rolling && c.velocity.norm() > 1e3 * tol * scale {
                    Some(format!("rolling slips at {:e} m/s at {t}", c.velocity.norm()))
                } else {
                    None
                };
                e_min = e_min.min(e);
                match why {
                    Some(w) => {
                        broken = Some(w);
                        Control::Stop
                    }
                    None => Control::Continue,
                }
            })
            .integrate();
        let out = out.map_err(|e| TestCaseError::fail(format!("{e} ({num_law:?}, tol {tol:e})")))?;
        prop_assert!(broken.is_none(), "{:?} ({num_law:?}, tol {tol:e})", broken);
        let switches = run.switches();
        let mut mode = phase;
        let mut last = 0.0;
        for s in &switches {
            prop_assert_eq!(s.from, mode);
            prop_assert!(s.t >= last);
            prop_assert!(m.reaction(s.to, &s.after).normal >= -1e-9 * mg, "{:?}", s);
            prop_assert!(m.energy(s.to, &s.after) <= m.energy(s.from, &s.state) + 1e-12 * e0.abs());
            match (s.from, s.to) {
                (Phase::Rolling, Phase::Sliding) => prop_assert_eq!(s.witness, Some("friction cone")),
                (Phase::Sliding, _) => prop_assert_eq!(s.witness, Some("slip speed")),
                other => prop_assert!(false, "{:?}", other),
            }
            mode = s.to;
            last = s.t;
        }
        prop_assert_eq!(run.phase(), mode);
        if let Some(&ContactOutcome::LiftOff { state, .. }) = run.run().halt() {
            let n = m.reaction(run.phase(), &state).normal;
            prop_assert!(n.abs() <= 1e-9 * mg, "lift-off at N = {}", n);
        }
        prop_assert!(out.t <= 0.3 && Stepper::t(&run) == out.t);
    }
}
