//! Tops in motion: the angle form against the Eulerian form along trajectories, the
//! conserved quantities, and the published heavy-top values (steady precession, fast-top
//! nutation, the sleeping-top threshold).

use crate::common;

use common::eulerian::Eulerian;
use nalgebra::{Matrix3, Matrix4, Rotation3, Vector3};
use precess_core::codegen::Program;
use precess_core::ode::{AdaptiveConfig, Dop853};
use precess_core::rigid::AngleSequence;
use precess_core::sym::{Arena, ExprId};
use precess_core::top::{TopDerivation, TopModel, TopScene};

/// I1 = 1, I3 = 1/2 about the pivot, M g l = 1 (M = g = l = 1): the reference top.
fn reference_top(a: &mut Arena, sequence: AngleSequence) -> TopDerivation {
    let (one, half, z) = (a.one(), a.number("0.5").unwrap(), a.zero());
    let mut scene = TopScene::free(a, [[one, z, z], [z, one, z], [z, z, half]]);
    scene.sequence = sequence;
    scene.center = [z, z, one];
    scene.gravity = Some(one);
    scene.derive(a).unwrap()
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// Steady precession at θ = 60°, ω3 = 10 (REFERENCES: Ω = 0.204168476687 slow,
/// 9.795831523313 fast): θ̈ vanishes there, and θ stays put along a 10 s simulation.
#[test]
fn steady_precession_rates_are_equilibria() {
    let mut a = Arena::new();
    let top = reference_top(&mut a, AngleSequence::Zxz);
    let model = TopModel::new(&mut a, &top, &[]).unwrap();
    let theta = std::f64::consts::FRAC_PI_3;
    for omega_p in [0.204168476687, 9.795831523313] {
        let w3 = 10.0;
        let state = [0.0, theta, 0.0, omega_p, 0.0, w3 - omega_p * theta.cos()];
        let acc = model.accelerations(&state).unwrap();
        // 12 published digits: θ̈ ∝ the precession equation's residual, ~1e-11 here.
        assert!(acc[1].abs() < 1e-10, "Ω = {omega_p}: θ̈ = {:e}", acc[1]);
        let mut ode = Dop853::new(&model, 0.0, state, tight()).unwrap();
        ode.advance_to(10.0).unwrap();
        assert!(
            (ode.y()[1] - theta).abs() < 1e-8,
            "θ drifted to {}",
            ode.y()[1]
        );
        assert!((ode.y()[0] - 10.0 * omega_p).abs() < 1e-7);
    }
    // A rate off the root is not an equilibrium (the check can fail).
    let acc = model
        .accelerations(&[0.0, theta, 0.0, 0.25, 0.0, 10.0 - 0.25 * theta.cos()])
        .unwrap();
    assert!(acc[1].abs() > 1e-3);
}

/// Released at rest from θ0 = 60°: θ oscillates between θ0 and θ0 + amplitude with the
/// published amplitude and period (REFERENCES: ω3 = 20 → 1.7580e-2 rad, 0.634549 s;
/// ω3 = 50 → 2.7779e-3 rad, 0.251729 s), and φ precesses at about Mgl/(I3 ω3).
#[test]
fn fast_top_nutation_amplitude_and_period() {
    let mut a = Arena::new();
    let top = reference_top(&mut a, AngleSequence::Zxz);
    let model = TopModel::new(&mut a, &top, &[]).unwrap();
    let theta0 = std::f64::consts::FRAC_PI_3;
    for (w3, amplitude, period) in [(20.0, 1.7580e-2, 0.634549), (50.0, 2.7779e-3, 0.251729)] {
        let mut ode = Dop853::new(&model, 0.0, [0.0, theta0, 0.0, 0.0, 0.0, w3], tight()).unwrap();
        // Sample finely through three periods; the bottoms of θ are the θ̇ sign changes
        // from + to −, located by bisection on the dense output.
        let dt = period / 400.0;
        let (mut t, mut prev) = (0.0, [0.0; 6]);
        let mut max_theta: f64 = 0.0;
        let mut returns = Vec::new();
        prev.copy_from_slice(ode.y());
        while t < 3.2 * period {
            t += dt;
            ode.advance_to(t).unwrap();
            let y = *ode.y();
            max_theta = max_theta.max(y[1]);
            if prev[4] < 0.0 && y[4] >= 0.0 {
                // θ̇ from − to +: back at the top turning point θ0. Refine by secant.
                returns.push(t - dt * y[4] / (y[4] - prev[4]));
            }
            prev = y;
        }
        let measured_amp = max_theta - theta0;
        assert!(
            (measured_amp - amplitude).abs() / amplitude < 2e-4,
            "ω3 = {w3}: amplitude {measured_amp:e}, published {amplitude:e}"
        );
        let measured_period = returns[0];
        assert!(
            (measured_period - period).abs() / period < 2e-5,
            "ω3 = {w3}: period {measured_period}, published {period}"
        );
        let mean_precession = ode.y()[0] / t;
        assert!((mean_precession - 1.0 / (0.5 * w3)).abs() / (1.0 / (0.5 * w3)) < 0.05);
    }
}

/// Energy and the momenta the derivation marks as conserved stay constant; the ones it
/// does not mark are exactly the ones a torque or an asymmetry breaks.
#[test]
fn conserved_quantities() {
    let mut a = Arena::new();
    let top = reference_top(&mut a, AngleSequence::Zxz);
    assert!(top.conserved_momenta[0].is_some() && top.conserved_momenta[2].is_some());
    assert!(top.conserved_momenta[1].is_none());
    let model = TopModel::new(&mut a, &top, &[]).unwrap();
    let y0 = [0.1, 0.7, -0.2, 0.8, -0.5, 12.0];
    let (e0, p0) = (model.energy(&y0), model.momenta(&y0));
    let mut ode = Dop853::new(&model, 0.0, y0, tight()).unwrap();
    ode.advance_to(20.0).unwrap();
    let y = *ode.y();
    assert!((model.energy(&y) - e0).abs() / e0.abs() < 1e-10);
    let p = model.momenta(&y);
    assert!((p[0] - p0[0]).abs() < 1e-10 * p0[0].abs().max(1.0));
    assert!((p[2] - p0[2]).abs() < 1e-10 * p0[2].abs().max(1.0));
    // The published closed forms of the conserved quantities (REFERENCES), evaluated
    // independently of the engine: p_ψ = I3 ω3, p_φ = I1 sin²θ φ̇ + I3 ω3 cos θ, E.
    let (th, dphi, dth, dpsi) = (y[1], y[3], y[4], y[5]);
    let w3 = dpsi + dphi * th.cos();
    assert!((p[2] - 0.5 * w3).abs() < 1e-12);
    assert!((p[0] - (th.sin().powi(2) * dphi + 0.5 * w3 * th.cos())).abs() < 1e-12);
    let energy = 0.5 * (dth * dth + dphi * dphi * th.sin().powi(2)) + 0.25 * w3 * w3 + th.cos();
    assert!((model.energy(&y) - energy).abs() < 1e-12);

    // An asymmetric top with an off-axis centre keeps only E and p_φ (gravity is vertical).
    let mut b = Arena::new();
    let (i1, i2, i3) = (
        b.number("0.9").unwrap(),
        b.number("0.7").unwrap(),
        b.number("0.4").unwrap(),
    );
    let z = b.zero();
    let mut scene = TopScene::free(&mut b, [[i1, z, z], [z, i2, z], [z, z, i3]]);
    scene.center = [b.number("0.03").unwrap(), z, b.number("0.2").unwrap()];
    scene.gravity = Some(b.number("9.81").unwrap());
    let asym = scene.derive(&mut b).unwrap();
    assert!(asym.conserved_momenta[0].is_some());
    assert!(asym.conserved_momenta[1].is_none() && asym.conserved_momenta[2].is_none());
    let model = TopModel::new(&mut b, &asym, &[]).unwrap();
    let y0 = [0.0, 0.9, 0.3, 0.5, 0.2, 15.0];
    let (e0, p0) = (model.energy(&y0), model.momenta(&y0)[0]);
    let mut ode = Dop853::new(&model, 0.0, y0, tight()).unwrap();
    ode.advance_to(10.0).unwrap();
    assert!((model.energy(ode.y()) - e0).abs() / e0.abs() < 1e-10);
    assert!((model.momenta(ode.y())[0] - p0).abs() < 1e-10 * p0.abs().max(1.0));

    // With damping, energy only decreases.
    let mut c = Arena::new();
    let (one, half, z) = (c.one(), c.number("0.5").unwrap(), c.zero());
    let mut scene = TopScene::free(&mut c, [[one, z, z], [z, one, z], [z, z, half]]);
    scene.center = [z, z, one];
    scene.gravity = Some(one);
    scene.damping = Some(c.number("0.05").unwrap());
    let damped = scene.derive(&mut c).unwrap();
    assert!(damped.conserved_momenta.iter().all(Option::is_none));
    let model = TopModel::new(&mut c, &damped, &[]).unwrap();
    let mut ode = Dop853::new(&model, 0.0, [0.0, 0.8, 0.0, 0.5, 0.0, 10.0], tight()).unwrap();
    let mut last = model.energy(ode.y());
    for k in 1..=50 {
        ode.advance_to(0.2 * k as f64).unwrap();
        let e = model.energy(ode.y());
        assert!(
            e < last,
            "energy rose under damping at t = {}",
            0.2 * k as f64
        );
        last = e;
    }
}

/// Both forms, integrated side by side over several nutation periods of an asymmetric top
/// with an off-axis centre of mass, stay together.
#[test]
fn trajectories_of_both_forms_agree() {
    let mut a = Arena::new();
    let (i1, i2, i3) = (
        a.number("0.9").unwrap(),
        a.number("0.7").unwrap(),
        a.number("0.4").unwrap(),
    );
    let z = a.zero();
    let mut scene = TopScene::free(&mut a, [[i1, z, z], [z, i2, z], [z, z, i3]]);
    let (cx, cz) = (a.number("0.03").unwrap(), a.number("0.2").unwrap());
    scene.center = [cx, z, cz];
    scene.gravity = Some(a.number("9.81").unwrap());
    let top = scene.derive(&mut a).unwrap();
    let model = TopModel::new(&mut a, &top, &[]).unwrap();
    let y0 = [0.2, 0.9, 0.3, 0.5, 0.2, 15.0];
    let euler = Eulerian {
        inertia: Matrix3::from_diagonal(&Vector3::new(0.9, 0.7, 0.4)),
        weight_lever: Vector3::new(0.03, 0.0, 0.2) * 9.81,
    };
    let (x, zx) = (Vector3::x_axis(), Vector3::z_axis());
    let r0 = Rotation3::from_axis_angle(&zx, y0[0])
        * Rotation3::from_axis_angle(&x, y0[1])
        * Rotation3::from_axis_angle(&zx, y0[2]);
    let e0 = Eulerian::state(r0.matrix(), &Vector3::from(model.omega(&y0)));
    let mut angle_ode = Dop853::new(&model, 0.0, y0, tight()).unwrap();
    let mut euler_ode = Dop853::new(&euler, 0.0, e0, tight()).unwrap();
    let mut worst: f64 = 0.0;
    for k in 1..=40 {
        let t = 0.25 * k as f64;
        angle_ode.advance_to(t).unwrap();
        euler_ode.advance_to(t).unwrap();
        let y = *angle_ode.y();
        let e = *euler_ode.y();
        let r = Rotation3::from_axis_angle(&zx, y[0])
            * Rotation3::from_axis_angle(&x, y[1])
            * Rotation3::from_axis_angle(&zx, y[2]);
        let attitude_gap = (r.matrix() - Eulerian::rotation(&e)).abs().max();
        let w = model.omega(&y);
        let rate_gap = (Vector3::from(w) - Vector3::new(e[4], e[5], e[6])).norm() / 15.0;
        worst = worst.max(attitude_gap).max(rate_gap);
    }
    assert!(worst < 1e-8, "forms drifted apart by {worst:e} over 10 s");
}

/// The sleeping top (upright, spinning at ω3) is stable iff ω3² > 4 I1 Mgl / I3². The
/// Jacobian of the derived q̈ at the upright state (ZYX chart, regular there) gives the
/// threshold, and below it the published growth rate √(4 I1 Mgl − I3² ω3²)/(2 I1).
#[test]
fn sleeping_top_threshold_from_the_linearisation() {
    let mut a = Arena::new();
    let top = reference_top(&mut a, AngleSequence::Zyx);
    let jac = top.jacobian(&mut a);
    let flat: Vec<ExprId> = jac.iter().flatten().copied().collect();
    let prog = Program::lower(&a, &flat);
    let c = top.coords().clone();
    let idx = |e: ExprId| a.as_symbol(e).unwrap().index();
    let growth = |w3: f64| -> f64 {
        let mut env = vec![f64::NAN; a.symbol_count()];
        for k in 0..3 {
            env[idx(c.q[k])] = 0.0;
            env[idx(c.rates[k])] = 0.0;
        }
        env[idx(c.rates[0])] = w3; // yaw rate = spin at the upright state
        let j = prog.eval(&env);
        // The tilt subsystem (pitch, roll, their rates): d/dt q = q̇, d/dt q̇ = J (q, q̇).
        // Yaw is cyclic and left out (its zero rows would make the matrix defective).
        let tilt = [1, 2, 4, 5];
        let mut m = Matrix4::zeros();
        for (r, &k) in [1usize, 2].iter().enumerate() {
            m[(r, 2 + r)] = 1.0;
            for (col, &l) in tilt.iter().enumerate() {
                m[(2 + r, col)] = j[6 * k + l];
            }
        }
        let schur = m.try_schur(1e-14, 10_000).expect("Schur form converges");
        schur
            .complex_eigenvalues()
            .iter()
            .map(|z| z.re)
            .fold(f64::MIN, f64::max)
    };
    // Published threshold: ω3 = √(4·1·1)/0.5 = 4. Bisect on the sign of the growth rate.
    let (mut lo, mut hi) = (1.0, 8.0);
    assert!(growth(lo) > 1e-6 && growth(hi) < 1e-6);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if growth(mid) > 1e-6 {
            lo = mid
        } else {
            hi = mid
        }
    }
    assert!((hi - 4.0).abs() / 4.0 < 0.01, "threshold at ω3 = {hi}");
    for w3 in [0.0, 1.0, 2.0, 3.0] {
        let expected = (4.0f64 - 0.25 * w3 * w3).sqrt() / 2.0;
        assert!(
            (growth(w3) - expected).abs() < 1e-9,
            "ω3 = {w3}: {} vs {expected}",
            growth(w3)
        );
    }
}
