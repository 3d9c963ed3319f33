//! Pendulums against hand-derived closed forms, and energy along integrated trajectories:
//! conserved without dampers, and changed by exactly the integrated power with them.

use crate::common::mechanism as mechanism_support;
use crate::common::mechanism::double_pendulum;

use approx::assert_relative_eq;
use mechanism_support::rng::Rng;
use mechanism_support::{NumBody, NumJoint, NumMechanism, Values, relative_difference, scene};
use precess::mechanism::{JointKind, MechanismModel, MechanismScene, Parent, Route};
use precess::ode::{AdaptiveConfig, Dop853, FnSystem};
use precess::sym::Arena;

/// The textbook double pendulum in absolute angles θ₁, θ₂ from the downward vertical:
/// with Δ = θ₁ − θ₂ and D = 2m₁ + m₂ − m₂ cos 2Δ,
/// θ̈₁ = (−g(2m₁+m₂) sin θ₁ − m₂ g sin(θ₁ − 2θ₂) − 2 sin Δ m₂ (θ̇₂² l₂ + θ̇₁² l₁ cos Δ)) / (l₁ D),
/// θ̈₂ = 2 sin Δ (θ̇₁² l₁ (m₁+m₂) + g (m₁+m₂) cos θ₁ + θ̇₂² l₂ m₂ cos Δ) / (l₂ D).
fn textbook(m: [f64; 2], l: [f64; 2], g: f64, th: [f64; 2], w: [f64; 2]) -> [f64; 2] {
    let (m1, m2, l1, l2) = (m[0], m[1], l[0], l[1]);
    let d = th[0] - th[1];
    let den = 2.0 * m1 + m2 - m2 * (2.0 * d).cos();
    let a1 = (-g * (2.0 * m1 + m2) * th[0].sin()
        - m2 * g * (th[0] - 2.0 * th[1]).sin()
        - 2.0 * d.sin() * m2 * (w[1] * w[1] * l2 + w[0] * w[0] * l1 * d.cos()))
        / (l1 * den);
    let a2 = 2.0
        * d.sin()
        * (w[0] * w[0] * l1 * (m1 + m2)
            + g * (m1 + m2) * th[0].cos()
            + w[1] * w[1] * l2 * m2 * d.cos())
        / (l2 * den);
    [a1, a2]
}

#[test]
fn double_pendulum_matches_the_textbook_formula() {
    let (m, l, g) = ([1.3, 0.7], [0.9, 0.6], 9.81);
    let values = [
        ("m0", m[0]),
        ("m1", m[1]),
        ("l0", l[0]),
        ("l1", l[1]),
        ("g", g),
    ];
    for route in [
        Route::Symbolic,
        Route::Factored,
        Route::Recursive,
        Route::Auto,
    ] {
        let mut a = Arena::new();
        let scene = double_pendulum(&mut a, None);
        let model = MechanismModel::new(&mut a, &scene, route, &values).expect("derives");
        let mut rng = Rng::new(11);
        for _ in 0..1000 {
            let q = [rng.uniform(-3.1, 3.1), rng.uniform(-3.1, 3.1)];
            let qd = [rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)];
            let ours = model.accelerations(0.0, &q, &qd).expect("regular");
            // Absolute angles: θ₁ = φ₀, θ₂ = φ₀ + φ₁.
            let th = [q[0], q[0] + q[1]];
            let w = [qd[0], qd[0] + qd[1]];
            let [a1, a2] = textbook(m, l, g, th, w);
            let reference = [a1, a2 - a1];
            let diff = relative_difference(&ours, &reference, 1.0);
            assert!(
                diff <= 1e-12,
                "{route:?} at q = {q:?}, q̇ = {qd:?}: {diff:e}"
            );
        }
    }
}

#[test]
fn single_pendulum_is_the_textbook_one() {
    // A uniform rod of length l hinged at its end: θ̈ = −(3g / 2l) sin θ.
    let mut a = Arena::new();
    let (o, z) = (a.one(), a.zero());
    let mut rod = MechanismScene::body(
        &mut a,
        "rod",
        Parent::Ground,
        JointKind::Revolute { axis: [z, o, z] },
        &["theta"],
    );
    rod.mass = a.number("2").expect("literal");
    rod.center = [z, z, a.number("-0.5").expect("literal")];
    let i = a
        .number("0.1666666666666666666666666666666667")
        .expect("literal");
    rod.inertia = [[i, z, z], [z, i, z], [z, z, z]];
    let mut scene = MechanismScene::new();
    scene.bodies.push(rod);
    scene.gravity = Some([z, z, a.number("-9.81").expect("literal")]);
    let model = MechanismModel::new(&mut a, &scene, Route::Auto, &[]).expect("derives");
    for theta in [0.1, 1.0, 2.5, -2.0] {
        let qdd = model.accelerations(0.0, &[theta], &[0.4]).expect("regular");
        // About y, a rod hanging along −z swings so that its foot moves along −x for θ > 0.
        assert_relative_eq!(qdd[0], -1.5 * 9.81 * theta.sin(), max_relative = 1e-14);
    }
}

/// A 3D chain for the trajectory checks: a universal joint, then a tilted revolute.
fn swinging_chain(damped: bool) -> NumMechanism {
    let mut root = NumBody::new(
        None,
        [0.0; 3],
        NumJoint::Universal([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    );
    root.center = [0.0, 0.1, -0.5];
    root.inertia = nalgebra::Matrix3::new(0.1, 0.0, 0.0, 0.0, 0.12, 0.01, 0.0, 0.01, 0.05);
    let mut tip = NumBody::new(
        Some(0),
        [0.0, 0.0, -1.0],
        NumJoint::Revolute([0.0, 0.6, 0.8]),
    );
    tip.mass = 0.6;
    tip.center = [0.2, 0.0, -0.3];
    if damped {
        root.loads[1].damper = Some(0.2);
        tip.loads[0].damper = Some(0.1);
        tip.loads[0].spring = Some((3.0, 0.4));
    }
    NumMechanism {
        bodies: vec![root, tip],
        gravity: [0.0, 0.0, -9.81],
    }
}

fn chain_model(m: &NumMechanism) -> MechanismModel {
    let mut a = Arena::new();
    let (s, bound) = scene(&mut a, m, Values::Literals);
    let d = s.derive(&mut a, Route::Auto).expect("derives");
    let read = d.parameters(&a);
    let pairs: Vec<(&str, f64)> = bound
        .iter()
        .filter(|(n, _)| read.contains(n))
        .map(|(n, v)| (n.as_str(), *v))
        .collect();
    MechanismModel::from_derivation(&a, &d, &pairs).expect("binds")
}

#[test]
fn energy_is_conserved_along_a_dop853_trajectory() {
    let model = chain_model(&swinging_chain(false));
    let y0 = [0.8, -0.4, 1.2, 0.5, -1.0, 2.0];
    let e0 = model.energy(0.0, &y0[..3], &y0[3..]).expect("finite");
    let system = model.system::<6>().expect("six states");
    let mut ode =
        Dop853::new(system, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12)).expect("ode");
    let mut worst: f64 = 0.0;
    for k in 1..=100 {
        ode.advance_to(0.1 * k as f64).expect("steps");
        let y = ode.y();
        let e = model.energy(ode.t(), &y[..3], &y[3..]).expect("finite");
        worst = worst.max((e - e0).abs() / e0.abs());
    }
    assert!(worst < 1e-9, "energy drift {worst:e} over 10 s");
    // The error grows with the tolerance: a loose run drifts visibly more, so the check
    // above measures the integrator, not a conserved quantity by construction.
    let mut loose =
        Dop853::new(system, 0.0, y0, AdaptiveConfig::with_tol(1e-5, 1e-5)).expect("ode");
    loose.advance_to(10.0).expect("steps");
    let y = loose.y();
    let e = model.energy(10.0, &y[..3], &y[3..]).expect("finite");
    assert!((e - e0).abs() / e0.abs() > worst);
}

#[test]
fn dampers_and_springs_change_the_energy_by_the_integrated_power() {
    let model = chain_model(&swinging_chain(true));
    // The state with the work done so far appended: d/dt W = Σ Q_i q̇_i.
    let rhs = |t: f64, y: &[f64; 7], dy: &mut [f64; 7]| {
        let (q, qd) = (&y[..3], &y[3..6]);
        let qdd = model
            .accelerations(t, q, qd)
            .unwrap_or_else(|_| vec![f64::NAN; 3]);
        dy[..3].copy_from_slice(qd);
        dy[3..6].copy_from_slice(&qdd);
        dy[6] = model.power(t, q, qd).unwrap_or(f64::NAN);
    };
    let y0 = [0.8, -0.4, 1.2, 0.5, -1.0, 2.0, 0.0];
    let e0 = model.energy(0.0, &y0[..3], &y0[3..6]).expect("finite");
    let mut ode = Dop853::new(
        FnSystem(rhs),
        0.0,
        y0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .expect("ode");
    ode.advance_to(5.0).expect("steps");
    let y = *ode.y();
    let e = model.energy(5.0, &y[..3], &y[3..6]).expect("finite");
    assert!(y[6] < -0.1, "the dampers dissipate: W = {}", y[6]);
    assert_relative_eq!(e - e0, y[6], max_relative = 1e-8);
}

/// A point mass m on a massless rod l with a damper c: θ̈ = −(g/l) sin θ − c θ̇ / (m l²).
fn damped_pendulum(a: &mut Arena) -> MechanismScene {
    let (o, z) = (a.one(), a.zero());
    let mut bob = MechanismScene::body(
        a,
        "bob",
        Parent::Ground,
        JointKind::Revolute { axis: [o, z, z] },
        &["theta"],
    );
    bob.mass = a.parameter("m");
    let l = a.parameter("l");
    bob.center = [z, z, a.neg(l)];
    bob.joint.loads[0].damper = Some(a.parameter("c"));
    let mut scene = MechanismScene::new();
    scene.bodies.push(bob);
    let g = a.parameter("g");
    scene.gravity = Some([z, z, a.neg(g)]);
    scene
}

#[test]
fn the_jacobian_of_a_damped_pendulum_is_the_closed_form() {
    let mut a = Arena::new();
    let scene = damped_pendulum(&mut a);
    let d = scene.derive(&mut a, Route::Auto).expect("derives");
    let jac = scene.jacobian(&mut a, &d);
    let (m, l, g, c, theta, rate) = (1.5, 0.8, 9.81, 0.3, 0.7, -1.1);
    let mut env = vec![f64::NAN; a.symbol_count()];
    for (name, v) in [("m", m), ("l", l), ("g", g), ("c", c)] {
        env[a.find_parameter(name).expect("read").index()] = v;
    }
    let q = a.as_symbol(d.coordinates.q[0]).expect("symbol");
    let qd = a.as_symbol(d.coordinates.rates[0]).expect("symbol");
    env[q.index()] = theta;
    env[qd.index()] = rate;
    let value: Vec<Vec<f64>> = jac
        .iter()
        .map(|row| row.iter().map(|&e| a.eval(e, &env)).collect())
        .collect();
    assert_eq!(value[0], vec![0.0, 1.0]);
    assert_relative_eq!(value[1][0], -(g / l) * theta.cos(), max_relative = 1e-14);
    assert_relative_eq!(value[1][1], -c / (m * l * l), max_relative = 1e-14);
    // The damper's power is −c θ̇², and θ is not cyclic (gravity and the damper act on it).
    let model = MechanismModel::from_derivation(&a, &d, &[("m", m), ("l", l), ("g", g), ("c", c)])
        .expect("binds");
    assert_relative_eq!(
        model.power(0.0, &[theta], &[rate]).expect("finite"),
        -c * rate * rate
    );
    assert!(d.conserved_momenta.is_empty());
}

#[test]
fn a_turntable_conserves_its_angular_momentum() {
    // A body turning about the vertical z axis under gravity along −z: the angle is cyclic
    // and p = (I_zz + m (x² + y²)) q̇ for its centre at (x, y, z).
    let mut a = Arena::new();
    let (o, z) = (a.one(), a.zero());
    let mut table = MechanismScene::body(
        &mut a,
        "table",
        Parent::Ground,
        JointKind::Revolute { axis: [z, z, o] },
        &["phi"],
    );
    table.mass = a.number("2").expect("literal");
    table.center = [
        a.number("0.3").expect("literal"),
        a.number("-0.4").expect("literal"),
        o,
    ];
    let izz = a.number("0.5").expect("literal");
    table.inertia = [[o, z, z], [z, o, z], [z, z, izz]];
    let mut scene = MechanismScene::new();
    scene.bodies.push(table);
    scene.gravity = Some([z, z, a.number("-9.81").expect("literal")]);
    let model = MechanismModel::new(&mut a, &scene, Route::Auto, &[]).expect("derives");
    let p = model
        .conserved_momenta(0.0, &[1.2], &[3.0])
        .expect("finite");
    assert_eq!(p.len(), 1);
    assert_eq!(p[0].0, 0);
    assert_relative_eq!(p[0].1, (0.5 + 2.0 * 0.25) * 3.0, max_relative = 1e-15);
}
