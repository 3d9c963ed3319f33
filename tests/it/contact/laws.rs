//! The literature's contact laws against closed forms and the Newton–Euler reference:
//! pivoting friction −ℓ_p N sign(ω·γ) γ stops a spin in finite time, a linear rolling
//! resistance under stick–slip slows a rolling ball exponentially, and the normal-force-scaled
//! viscous law F = −μ N u takes the slip of a sliding ball away exponentially.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactError, ContactOutcome, ContactRun, ContactScene, ContactTorques, Phase,
};
use precess::ode::AdaptiveConfig;
use precess::sym::{Arena, Rational};

use super::reference::{
    NumBody, NumLaw, NumSurface, NumTorques, newton_euler_pivoting, offset_sphere, rattleback,
    state, try_model_with,
};

/// A uniform ball, ρ = 0.1 m, M = 2 kg, I = 2/5 M ρ², its centre of mass at its centre.
fn ball() -> NumBody {
    let (m, rho) = (2.0, 0.1);
    let i = 0.4 * m * rho * rho;
    NumBody {
        mass: m,
        center: [0.0; 3],
        inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        surface: NumSurface::Sphere { c: [0.0; 3], rho },
        gravity: 9.81,
    }
}

const TIGHT: f64 = 1e-12;

#[test]
fn pivoting_friction_stops_a_spin_at_i_omega_over_l_n() {
    // A ball spinning in place about the vertical: the contact point is on the spin axis,
    // so rolling holds with no friction, N = M g, and only the pivoting torque −ℓ_p M g acts
    // on I ω̇: the spin falls linearly and stops at t* = I ω₀ / (ℓ_p M g).
    let body = ball();
    let (l, w0) = (0.002, 30.0);
    let torques = NumTorques {
        pivoting: Some(l),
        ..NumTorques::default()
    };
    let m = try_model_with(&body, NumLaw::StickSlip(0.4), torques).unwrap();
    let i = body.inertia[2][2];
    let t_star = i * w0 / (l * body.mass * body.gravity);
    let y0 = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(0.0, 0.0, w0),
        )
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(TIGHT, TIGHT);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    // Halfway, the spin is half gone.
    run.advance_to(0.5 * t_star).unwrap();
    let half = run.y()[10];
    assert!((half / (0.5 * w0) - 1.0).abs() < 1e-11, "{half}");
    // The friction then holds the spin and the ball stays at rest: the run goes on.
    let out = run.advance_to(2.0 * t_star).unwrap();
    assert_eq!(out, ContactOutcome::Reached { t: 2.0 * t_star });
    let switches = run.switches();
    let [stop] = switches.as_slice() else {
        panic!("{switches:?}")
    };
    let y = run.y();
    let speed = Vector3::new(y[8], y[9], y[10]).norm();
    println!(
        "spin held from {} s against I ω₀/(ℓ_p M g) = {t_star} s; at {} s |ω| = {speed:e} rad/s, centre at ({:e}, {:e}) m",
        stop.t,
        run.t(),
        y[0],
        y[1]
    );
    // The witness fires where |ω₃| = δ_ω = 10⁻⁹ of the angular scale, δ_ω I/(ℓ_p M g) early.
    assert!(
        ((stop.t - t_star) / t_star).abs() < 1e-8,
        "{} vs {t_star}",
        stop.t
    );
    assert!(
        (stop.witness, stop.spin_held_after) == (Some("spin"), true),
        "{stop:?}"
    );
    assert!(run.spin_held());
    // At rest: no spin, no rolling, the centre where it started, the energy M g ρ.
    assert!(speed < 1e-12, "{speed:e}");
    assert!(
        y[0].hypot(y[1]) < 1e-15 && y[2].hypot(y[3]) < 1e-15,
        "{y:?}"
    );
    let rest = body.mass * body.gravity * 0.1;
    assert!((m.energy(Phase::Rolling, y) / rest - 1.0).abs() < 1e-14);
}

#[test]
fn a_spin_the_friction_cannot_hold_passes_through_zero() {
    // The rattleback's spin reverses on its own: its pivoting friction, small against the
    // torque the rolling motion puts on the spin, lets the spin through zero, where the run
    // goes on with the spin on the far side.
    let body = rattleback();
    let torques = NumTorques {
        pivoting: Some(1e-6),
        ..NumTorques::default()
    };
    let m = try_model_with(&body, super::reference::ROLLING, torques).unwrap();
    let q = UnitQuaternion::from_euler_angles(0.0, 0.05, 0.0);
    let y0 = m
        .rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 0.0, -2.0))
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-11, 1e-13);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let out = run.advance_to(8.0).unwrap();
    assert_eq!(out, ContactOutcome::Reached { t: 8.0 });
    let through: Vec<_> = run
        .switches()
        .into_iter()
        .filter(|s| s.witness == Some("spin"))
        .collect();
    println!(
        "rattleback, ℓ_p = 1e-6 m: spin {} → {}, {} passes through zero",
        y0[10],
        run.y()[10],
        through.len()
    );
    assert!(!through.is_empty(), "the spin never reversed");
    for s in &through {
        let (before, after) = (s.state, s.after);
        let spin = |y: &[f64; 11]| m.contact(y).gamma.dot(&Vector3::new(y[8], y[9], y[10]));
        assert!(
            spin(&before) * spin(&after) < 0.0,
            "{} → {}",
            spin(&before),
            spin(&after)
        );
        // No energy added at the pass.
        let (e0, e1) = (
            m.energy(Phase::Rolling, &before),
            m.energy(Phase::Rolling, &after),
        );
        assert!(e1 - e0 <= 1e-15 * e0.abs(), "{e0} → {e1}");
    }
}

#[test]
fn pivoting_and_normal_viscous_friction_match_newton_euler() {
    // Random states of the eccentric sphere, each phase's ω̇, acceleration and N against the
    // Newton–Euler solve with N among its unknowns.
    let body = offset_sphere();
    let l = 0.003;
    let torques = NumTorques {
        pivoting: Some(l),
        ..NumTorques::default()
    };
    let stick = try_model_with(&body, NumLaw::StickSlip(0.3), torques).unwrap();
    let viscous = try_model_with(&body, NumLaw::NormalViscous(0.4), torques).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..40 {
        let x = k as f64;
        let q = UnitQuaternion::from_euler_angles(0.7 * x.sin(), 0.9 * (1.3 * x).cos(), x);
        let w = Vector3::new(3.0 * (2.1 * x).sin(), 2.0 * x.cos(), 20.0 * (0.7 * x).cos());
        let rolling = stick.rolling_state([0.1, 0.2], &q, &w).unwrap();
        let sliding = state([0.1, 0.2], [0.3 * x.cos(), -0.2 * x.sin()], &q, &w);
        for (model, law, phase, y) in [
            (
                &stick,
                NumLaw::Rolling { cr: None, cs: None },
                Phase::Rolling,
                rolling,
            ),
            (
                &viscous,
                NumLaw::NormalViscous(0.4),
                Phase::Sliding,
                sliding,
            ),
        ] {
            let reference = newton_euler_pivoting(&body, law, Some(l), &y);
            let d = model.accelerations(phase, 0.0, &y).unwrap();
            let n = model.reaction(phase, &y).normal;
            let scale = reference.omega_dot.norm() + 1.0;
            for j in 0..3 {
                worst = worst.max((d[8 + j] - reference.omega_dot[j]).abs() / scale);
            }
            worst = worst.max((n - reference.force.z).abs() / reference.force.z.abs());
            worst = worst.max((d[2] - reference.accel.x).abs() / (reference.accel.norm() + 1.0));
        }
    }
    println!("pivoting and F = −μ N u against Newton–Euler: worst relative gap {worst:e}");
    assert!(worst < 1e-11, "{worst:e}");
}

#[test]
fn a_rolling_resistance_under_stick_slip_slows_a_ball_at_the_closed_form_rate() {
    // A ball rolling along x under −c_r ω_∥: (I + M ρ²) ω̇ = −c_r ω, so
    // ω(t) = ω₀ exp(−c_r t/(I + M ρ²)); the friction it needs, M ρ |ω̇|, is far inside μ N.
    let body = ball();
    let cr = 0.01;
    let torques = NumTorques {
        cr: Some(cr),
        ..NumTorques::default()
    };
    let m = try_model_with(&body, NumLaw::StickSlip(0.3), torques).unwrap();
    let (w0, rho) = (20.0, 0.1);
    let y0 = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(0.0, w0, 0.0),
        )
        .unwrap();
    let rate = cr / (body.inertia[1][1] + body.mass * rho * rho);
    let cfg = AdaptiveConfig::with_tol(TIGHT, TIGHT);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=10 {
        let t = 0.5 * k as f64;
        run.advance_to(t).unwrap();
        let y = run.y();
        let expected = w0 * (-rate * t).exp();
        // The ball's attitude turns, so ω is read in space: its y component.
        let w_space = precess::contact::attitude_of(y) * Vector3::new(y[8], y[9], y[10]);
        worst = worst.max((w_space.y / expected - 1.0).abs());
        // The centre rolls: x = ρ ∫ω = ρ ω₀ (1 − e^(−rate t))/rate.
        let x = rho * w0 * (1.0 - (-rate * t).exp()) / rate;
        worst = worst.max((y[0] / x - 1.0).abs());
    }
    println!(
        "rolling resistance c_r = {cr}: worst relative gap {worst:e} over 5 s, rate {rate} 1/s"
    );
    assert!(run.switches().is_empty(), "{:?}", run.switches());
    assert!(worst < 1e-10, "{worst:e}");
}

#[test]
fn normal_viscous_friction_takes_a_sliding_balls_slip_away_at_seven_halves_mu_g() {
    // A ball sliding without spin under F = −μ N u, N = M g: v̇ = −μ g u and
    // ω̇ × r = (M ρ²/I) v̇ for the contact point below the centre, so u̇ = −(1 + Mρ²/I) μ g u
    // = −(7/2) μ g u for a uniform ball: the slip decays exponentially, never stopping.
    let body = ball();
    let mu = 0.5;
    let m = try_model_with(&body, NumLaw::NormalViscous(mu), NumTorques::default()).unwrap();
    let v0 = 2.0;
    let y0 = state(
        [0.0, 0.0],
        [v0, 0.0],
        &UnitQuaternion::identity(),
        &Vector3::zeros(),
    );
    let rate = 3.5 * mu * body.gravity;
    let cfg = AdaptiveConfig::with_tol(TIGHT, TIGHT);
    let mut run = ContactRun::new(&m, Phase::Sliding, 0.0, y0, cfg).unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=10 {
        let t = 0.1 * k as f64;
        assert_eq!(run.advance_to(t).unwrap(), ContactOutcome::Reached { t });
        let u = m.contact(run.y()).velocity;
        worst = worst.max((u.x / (v0 * (-rate * t).exp()) - 1.0).abs());
        assert!(u.y.abs() < 1e-15, "{}", u.y);
    }
    // It ends rolling at 5/7 v₀, as the Coulomb ball does, but only in the limit.
    let v_end = run.y()[2];
    println!(
        "F = −μ N u, μ = {mu} s/m: slip decays at (7/2) μ g = {rate} 1/s to {worst:e}; v → {v_end} (5/7 v₀ = {})",
        5.0 / 7.0 * v0
    );
    // The tolerance is absolute below 10⁻¹² m/s: the slip falls to 7e-8 m/s by 1 s.
    assert!(worst < 1e-7, "{worst:e}");
    assert!((v_end / (5.0 / 7.0 * v0) - 1.0).abs() < 1e-6);
}

#[test]
fn negative_coefficients_and_a_missing_couple_are_typed_errors() {
    let body = ball();
    for torques in [
        NumTorques {
            pivoting: Some(-0.001),
            ..NumTorques::default()
        },
        NumTorques {
            cr: Some(-0.1),
            ..NumTorques::default()
        },
    ] {
        let e = try_model_with(&body, NumLaw::StickSlip(0.3), torques).unwrap_err();
        assert!(
            matches!(e, ContactError::NegativeCoefficient { value, .. } if value < 0.0),
            "{e}"
        );
    }
    let e = try_model_with(&body, NumLaw::NormalViscous(-0.2), NumTorques::default()).unwrap_err();
    assert!(
        matches!(e, ContactError::NegativeCoefficient { name: "normal_viscous", value } if value == -0.2),
        "{e}"
    );
    // A user couple the interpreted model is not given.
    let mut a = Arena::new();
    let scene = ball_scene(&mut a);
    let u = [a.input("u1"), a.input("u2"), a.input("u3")];
    let torques = ContactTorques {
        user: Some(u),
        ..ContactTorques::default()
    };
    let d = scene.derive_with(&mut a, &torques).unwrap();
    let e = precess::contact::ContactModel::new(&mut a, &d, &[]).unwrap_err();
    assert!(matches!(e, ContactError::UserTorque { .. }), "{e}");
    // A resistance declared by the rolling law and again as a further torque.
    let scene = ContactScene {
        law: precess::contact::ContactLaw::Rolling {
            rolling_resistance: Some(a.one()),
            spin_resistance: None,
        },
        ..scene
    };
    let twice = ContactTorques {
        rolling_resistance: Some(a.one()),
        ..ContactTorques::default()
    };
    let e = scene.derive_with(&mut a, &twice).unwrap_err();
    assert_eq!(
        e,
        ContactError::DeclaredTwice {
            name: "rolling_resistance"
        }
    );
}

/// A literal ball on the table under stick–slip: M = 2, ρ = 1/10, I = 1/125, μ = 3/10.
fn ball_scene(a: &mut Arena) -> ContactScene {
    let mut c = |n: i128, d: i128| a.constant(Rational::new(n, d).unwrap());
    let (m, rho, i, mu, g) = (c(2, 1), c(1, 10), c(1, 125), c(3, 10), c(981, 100));
    let z = c(0, 1);
    ContactScene {
        mass: m,
        center: [z; 3],
        inertia: [[i, z, z], [z, i, z], [z, z, i]],
        surface: precess::contact::Surface::Sphere {
            center: [z; 3],
            radius: rho,
        },
        law: precess::contact::ContactLaw::StickSlip { mu },
        gravity: g,
    }
}
