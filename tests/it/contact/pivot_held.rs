//! A spin that pivoting friction −ℓ_p N sign(ω·γ) γ holds at zero: the run goes on with
//! ω·γ = 0 kept by a pivot couple λγ, and lets the spin go where |λ| reaches ℓ_p N. The
//! held motion and its couple against a Newton–Euler solve with λ among the unknowns and
//! Ω̇_z = 0 among the equations; a ball rolling without spin against straight rolling's
//! closed form; a body whose needed couple outgrows ℓ_p N breaking loose at the root of
//! ℓ_p N − |λ|.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactError, ContactOutcome, ContactRun, Phase, attitude_of, held_spin,
};
use precess::ode::AdaptiveConfig;

use super::reference::{
    NumBody, NumLaw, NumSurface, NumTorques, chaplygin_ball, newton_euler_held, offset_sphere,
    rattleback, state, try_model_with,
};

fn pivoting(l: f64) -> NumTorques {
    NumTorques {
        pivoting: Some(l),
        ..NumTorques::default()
    }
}

fn spin(m: &dyn ContactDynamics, y: &[f64; 11]) -> f64 {
    m.contact(y).gamma.dot(&Vector3::new(y[8], y[9], y[10]))
}

#[test]
fn the_held_motion_and_its_couple_match_newton_euler_with_the_couple_unknown() {
    // Random states of the eccentric sphere and the rattleback, rolling (stick–slip) and
    // sliding (F = −μ N u): ω̇, N and λ of the held motion against the solve of
    // Newton–Euler with λ ẑ an unknown couple and Ω̇_z = 0 a further equation.
    let mut worst: f64 = 0.0;
    let mut largest_couple: f64 = 0.0;
    for body in [offset_sphere(), rattleback()] {
        let l = 0.003;
        let stick = try_model_with(&body, NumLaw::StickSlip(0.3), pivoting(l)).unwrap();
        let viscous = try_model_with(&body, NumLaw::NormalViscous(0.4), pivoting(l)).unwrap();
        for k in 0..30 {
            let x = k as f64;
            let q = UnitQuaternion::from_euler_angles(0.3 * x.sin(), 0.4 * (1.3 * x).cos(), x);
            let w = Vector3::new(3.0 * (2.1 * x).sin(), 2.0 * x.cos(), 5.0 * (0.7 * x).cos());
            // The held motion is the one through the state with its spin set to zero.
            let gamma = q.inverse() * Vector3::z();
            let w = w - gamma * gamma.dot(&w);
            let rolling = stick.rolling_state([0.1, 0.2], &q, &w).unwrap();
            let sliding = state([0.1, 0.2], [0.3 * x.cos(), -0.2 * x.sin()], &q, &w);
            for (model, law, phase, y) in [
                (&stick, NumLaw::StickSlip(0.3), Phase::Rolling, rolling),
                (
                    &viscous,
                    NumLaw::NormalViscous(0.4),
                    Phase::Sliding,
                    sliding,
                ),
            ] {
                let (reference, couple) = newton_euler_held(&body, law, &y);
                let held = held_spin(model, phase, 0.0, &y).unwrap();
                let scale = reference.omega_dot.norm() + 1.0;
                for j in 0..3 {
                    worst = worst.max((held.rates[8 + j] - reference.omega_dot[j]).abs() / scale);
                }
                let n = reference.force.z;
                worst = worst.max((held.reaction.normal - n).abs() / n.abs());
                // λ and the margin against the scale of the couples at play, ℓ_p N and λ.
                let couples = l * n.abs() + couple.abs();
                worst = worst.max((held.couple - couple).abs() / couples);
                worst = worst.max((held.margin - (l * n - couple.abs())).abs() / couples);
                largest_couple = largest_couple.max(couple.abs() / (l * n));
            }
        }
    }
    println!(
        "held spin against Newton–Euler with λ unknown: worst relative gap {worst:e}; largest |λ|/(ℓ_p N) {largest_couple}"
    );
    // The held motion is read off the equations at spins of ±10⁻¹³ of the state's angular
    // scale, so it is the constrained one to about that, times the rattleback's quick
    // dependence of ω̇ on ω (its gaps reach 8e-12).
    assert!(worst < 5e-11, "{worst:e}");
    // The states ask for couples both within and beyond ℓ_p N.
    assert!(largest_couple > 1.0);
}

#[test]
fn a_ball_rolling_without_spin_rolls_straight_with_its_spin_held() {
    // A uniform ball rolling along x with no spin under stick–slip and pivoting friction:
    // the spin is zero at the start, the friction holds it there (the held mode from t = 0)
    // and the ball rolls on as straight rolling's closed form has it, x = ρ ω t, its energy
    // ½ (I + M ρ²) ω² + M g ρ unchanged.
    let (mass, rho) = (2.0, 0.1);
    let i = 0.4 * mass * rho * rho;
    let body = NumBody {
        mass,
        center: [0.0; 3],
        inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        surface: NumSurface::Sphere { c: [0.0; 3], rho },
        gravity: 9.81,
    };
    let m = try_model_with(&body, NumLaw::StickSlip(0.3), pivoting(0.002)).unwrap();
    let w0 = 5.0;
    let y0 = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(0.0, w0, 0.0),
        )
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let energy = 0.5 * (i + mass * rho * rho) * w0 * w0 + mass * body.gravity * rho;
    let mut worst: f64 = 0.0;
    let mut spin_worst: f64 = 0.0;
    for k in 1..=8 {
        let t = 0.25 * k as f64;
        assert_eq!(run.advance_to(t).unwrap(), ContactOutcome::Reached { t });
        let y = run.y();
        worst = worst.max((y[0] / (rho * w0 * t) - 1.0).abs());
        worst = worst.max(y[1].abs());
        worst = worst.max((m.energy(Phase::Rolling, y) / energy - 1.0).abs());
        spin_worst = spin_worst.max(spin(&m, y).abs());
    }
    let switches = run.switches();
    println!(
        "ball rolling without spin, held from t = {:?}: worst relative gap to x = ρωt and the energy {worst:e}, |ω·γ| ≤ {spin_worst:e} rad/s",
        switches.first().map(|s| s.t)
    );
    assert!(run.spin_held());
    let [held] = switches.as_slice() else {
        panic!("{switches:?}")
    };
    assert_eq!(
        (held.t, held.witness, held.spin_held_after),
        (0.0, Some("spin"), true)
    );
    assert!(worst < 1e-11, "{worst:e}");
    assert!(spin_worst < 1e-14 * w0, "{spin_worst:e}");
}

#[test]
fn a_held_spin_does_no_work_on_a_ball_of_unequal_moments() {
    // The Chaplygin ball rolling without spin: its unequal moments need a couple λ ≠ 0 to
    // keep ω·γ = 0, but the couple's power λ ω·γ is zero, so the energy stays what it was
    // (pivoting friction large enough to hold it throughout).
    let body = chaplygin_ball();
    let m = try_model_with(&body, super::reference::ROLLING, pivoting(0.05)).unwrap();
    let q = UnitQuaternion::from_euler_angles(0.4, -0.3, 0.2);
    let gamma = q.inverse() * Vector3::z();
    let w = Vector3::new(3.0, -2.0, 4.0);
    let w = w - gamma * gamma.dot(&w);
    let y0 = m.rolling_state([0.0, 0.0], &q, &w).unwrap();
    let e0 = m.energy(Phase::Rolling, &y0);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let (mut drift, mut spin_max, mut couple_max) = (0.0_f64, 0.0_f64, 0.0_f64);
    for k in 1..=300 {
        let t = 0.01 * k as f64;
        assert_eq!(run.advance_to(t).unwrap(), ContactOutcome::Reached { t });
        let y = run.y();
        drift = drift.max((m.energy(Phase::Rolling, y) / e0 - 1.0).abs());
        spin_max = spin_max.max(spin(&m, y).abs());
        couple_max = couple_max.max(held_spin(&m, Phase::Rolling, t, y).unwrap().couple.abs());
    }
    println!(
        "Chaplygin ball held: energy drift {drift:e} over 3 s, |ω·γ| ≤ {spin_max:e} rad/s, |λ| up to {couple_max:e} N·m (ℓ_p M g = {})",
        0.05 * body.mass * body.gravity
    );
    assert!(run.spin_held() && run.switches().len() == 1);
    assert!(couple_max > 1e-3, "{couple_max:e}");
    assert!(drift < 1e-11, "{drift:e}");
    assert!(spin_max < 1e-12, "{spin_max:e}");
}

#[test]
fn a_spin_breaks_loose_where_the_couple_needed_reaches_l_p_n() {
    // The rattleback set pitching from upright without spin: its skewed inertia turns it, so
    // the couple that holds the spin at zero grows with the pitch, from 5e-7 N at the start
    // to 4e-5 N within 0.05 s (per newton of N); where it reaches ℓ_p N the spin breaks
    // loose, turning the way the couple held it from. At that switch the couple of the
    // Newton–Euler solve (λ unknown, Ω̇_z = 0) is ℓ_p N.
    let body = rattleback();
    let l = 2e-5;
    let m = try_model_with(&body, super::reference::ROLLING, pivoting(l)).unwrap();
    let q = UnitQuaternion::identity();
    let y0 = m
        .rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 0.5, 0.0))
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-13);
    let mut run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg).unwrap();
    assert_eq!(
        run.advance_to(4.0).unwrap(),
        ContactOutcome::Reached { t: 4.0 }
    );
    let switches = run.switches();
    let loose = switches
        .iter()
        .find(|s| s.witness == Some("pivot cone"))
        .copied()
        .unwrap_or_else(|| panic!("the spin never broke loose: {switches:?}"));
    assert!(
        switches[0].spin_held_after && switches[0].t == 0.0,
        "{switches:?}"
    );
    assert!(
        loose.spin_held_before && !loose.spin_held_after,
        "{loose:?}"
    );
    let (reference, couple) = newton_euler_held(&body, super::reference::ROLLING, &loose.state);
    let n = reference.force.z;
    let gap = (couple.abs() - l * n) / (l * n);
    let (before, after) = (spin(&m, &loose.state), spin(&m, &loose.after));
    println!(
        "rattleback, ℓ_p = {l} m: the spin breaks loose at t = {} s, |λ| = {:e} N·m against ℓ_p N = {:e} (gap {gap:e}); spin {before:e} → {after:e}; {} switches to 4 s, spin at 4 s {}",
        loose.t,
        couple.abs(),
        l * n,
        switches.len(),
        spin(&m, run.y())
    );
    assert!(gap.abs() < 1e-10, "{gap:e}");
    // Seeded against the couple, within a few times the spin taken as zero.
    assert!(after * couple < 0.0, "{after:e} against λ = {couple:e}");
    assert!(
        before.abs() < 1e-12 && after.abs() < 1e-6,
        "{before:e} → {after:e}"
    );
    // The seed adds no energy.
    let (e0, e1) = (
        m.energy(Phase::Rolling, &loose.state),
        m.energy(Phase::Rolling, &loose.after),
    );
    assert!(e1 <= e0 + 1e-15 * e0.abs(), "{e0} → {e1}");
    // Held before it, the couple was within the cone: the margin positive a little earlier.
    let earlier = held_spin(&m, Phase::Rolling, 0.0, &y0).unwrap();
    assert!(earlier.margin > 0.0, "{earlier:?}");
    // The held stretch did no work: the energy at the break is the start's.
    let start = m.energy(Phase::Rolling, &y0);
    assert!((e0 / start - 1.0).abs() < 1e-11, "{start} → {e0}");
    let q_end = attitude_of(run.y());
    assert!(q_end.angle().is_finite());
}

#[test]
fn holding_a_spin_needs_pivoting_friction() {
    let body = chaplygin_ball();
    let m = try_model_with(&body, super::reference::ROLLING, NumTorques::default()).unwrap();
    let y = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(1.0, 0.0, 0.0),
        )
        .unwrap();
    let e = held_spin(&m, Phase::Rolling, 0.0, &y).unwrap_err();
    assert_eq!(e, ContactError::NoPivoting { law: "rolling" });
}

#[test]
fn a_struck_ball_without_spin_slides_then_rolls_with_its_spin_held() {
    // A billiard ball struck without spin, under stick–slip (μ = 0.2) and pivoting
    // friction: held from the start, it slides for t* = 2 v₀/(7 μ g), then rolls at 5/7 v₀,
    // its spin held throughout, x(1) = v₀ t* − ½ μ g t*² + 5/7 v₀ (1 − t*).
    let (mass, rho, mu, g, v0) = (0.17, 0.1, 0.2, 9.81, 2.0);
    let i = 0.4 * mass * rho * rho;
    let body = NumBody {
        mass,
        center: [0.0; 3],
        inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        surface: NumSurface::Sphere { c: [0.0; 3], rho },
        gravity: g,
    };
    let m = try_model_with(&body, NumLaw::StickSlip(mu), pivoting(0.002)).unwrap();
    let y0 = state(
        [0.0, 0.0],
        [v0, 0.0],
        &UnitQuaternion::identity(),
        &Vector3::zeros(),
    );
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut run = ContactRun::new(&m, Phase::Sliding, 0.0, y0, cfg).unwrap();
    assert_eq!(
        run.advance_to(1.0).unwrap(),
        ContactOutcome::Reached { t: 1.0 }
    );
    let t_star = 2.0 * v0 / (7.0 * mu * g);
    let switches = run.switches();
    let [held, rolls] = switches.as_slice() else {
        panic!("{switches:?}")
    };
    let x1 = v0 * t_star - 0.5 * mu * g * t_star * t_star + 5.0 / 7.0 * v0 * (1.0 - t_star);
    println!(
        "struck ball, spin held: rolls from {} s (t* = {t_star}), v = {} (5/7 v₀ = {}), x(1) = {} ({x1})",
        rolls.t,
        run.y()[2],
        5.0 / 7.0 * v0,
        run.y()[0]
    );
    assert_eq!(
        (held.t, held.witness, held.to),
        (0.0, Some("spin"), Phase::Sliding)
    );
    assert!(held.spin_held_after);
    assert_eq!(
        (rolls.from, rolls.to, rolls.witness),
        (Phase::Sliding, Phase::Rolling, Some("slip speed"))
    );
    assert!(rolls.spin_held_before && rolls.spin_held_after && run.spin_held());
    assert!((rolls.t - t_star).abs() < 1e-9, "{} vs {t_star}", rolls.t);
    assert!((run.y()[2] - 5.0 / 7.0 * v0).abs() < 1e-9, "{}", run.y()[2]);
    assert!((run.y()[0] - x1).abs() < 1e-9, "{} vs {x1}", run.y()[0]);
    assert!(spin(&m, run.y()).abs() < 1e-15);
}

#[test]
fn a_planar_stick_slip_run_is_the_same_with_its_spin_held() {
    // The eccentric sphere rolling about a horizontal axis through its symmetry axis moves
    // in a plane and never spins, so holding the spin at zero changes nothing: under
    // stick–slip with a low μ it slips and sticks again, and the run with pivoting friction
    // (its spin held from t = 0, through every stick and slip) must switch where the run
    // without it does and end in the same state.
    let body = offset_sphere();
    let mu = 0.02;
    let free = try_model_with(&body, NumLaw::StickSlip(mu), NumTorques::default()).unwrap();
    let held = try_model_with(&body, NumLaw::StickSlip(mu), pivoting(0.001)).unwrap();
    let y0 = free
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::identity(),
            &Vector3::new(30.0, 0.0, 0.0),
        )
        .unwrap();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let t_end = 0.5;
    let mut a = ContactRun::new(&free, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let mut b = ContactRun::new(&held, Phase::Rolling, 0.0, y0, cfg).unwrap();
    let (out_a, out_b) = (a.advance_to(t_end).unwrap(), b.advance_to(t_end).unwrap());
    let (sa, sb) = (a.switches(), b.switches());
    // The held run's first switch holds the spin at t = 0; the rest are the stick–slip's.
    let (first, rest) = sb.split_first().unwrap();
    assert_eq!(
        (first.t, first.witness, first.spin_held_after),
        (0.0, Some("spin"), true)
    );
    let gap = (0..11)
        .map(|k| (a.y()[k] - b.y()[k]).abs())
        .fold(0.0, f64::max);
    println!(
        "eccentric sphere, μ = {mu}: {} stick–slip switches free, {} held ({out_a:?}, {out_b:?}); first slip at {:?} and {:?} s; end states apart by {gap:e}",
        sa.len(),
        rest.len(),
        sa.first().map(|s| s.t),
        rest.first().map(|s| s.t)
    );
    assert_eq!(out_a, out_b);
    assert!(!sa.is_empty(), "the sphere never slipped");
    assert_eq!(sa.len(), rest.len());
    for (x, y) in sa.iter().zip(rest) {
        assert_eq!((x.from, x.to, x.witness), (y.from, y.to, y.witness));
        assert!(y.spin_held_before && y.spin_held_after, "{y:?}");
        assert!((x.t - y.t).abs() < 1e-9, "{} vs {}", x.t, y.t);
    }
    assert!(b.spin_held());
    assert!(gap < 1e-8, "{gap:e}");
}
