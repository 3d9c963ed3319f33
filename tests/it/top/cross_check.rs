//! The central cross-check: the Euler-angle Lagrangian equations derived by precess's own
//! engine against the Eulerian form written independently with nalgebra (the testkit's
//! `eulerian_top`, optimised),
//! ω̇ = I⁻¹ (τ − ω × I ω), τ = c × (Rᵀ(−M g ẑ)) + G_body + Rᵀ G_space − k ω + u.
//! At 10⁴ random states per scene, ω̇ from q̈ (ω̇ = B q̈ + Ḃ q̇) must equal it to 1e-10.

use crate::common;

use common::rng::Rng;
use nalgebra::{Matrix3, Vector3};
use precess_core::codegen::Program;
use precess_core::rigid::AngleSequence;
use precess_core::sym::{Arena, ExprId, Rational};
use precess_core::top::TopScene;
use precess_testkit::eulerian_top::{NumTop as Scene, attitude};

fn base(name: &'static str, inertia: Matrix3<f64>, center: Vector3<f64>) -> Scene {
    Scene {
        name,
        sequence: AngleSequence::Zxz,
        inertia,
        mass: 1.3,
        center,
        gravity: Some(9.81),
        body_torque: None,
        space_torque: None,
        damping: None,
        user_torque: None,
    }
}

fn scenes() -> Vec<Scene> {
    let sym = Matrix3::from_diagonal(&Vector3::new(0.8, 0.8, 0.3));
    let asym = Matrix3::from_diagonal(&Vector3::new(0.9, 0.7, 0.4));
    // A full tensor (products of inertia), positive definite.
    let full = Matrix3::new(0.9, 0.05, -0.02, 0.05, 0.7, 0.03, -0.02, 0.03, 0.4);
    let on_axis = Vector3::new(0.0, 0.0, 0.25);
    let off_axis = Vector3::new(0.04, -0.03, 0.25);
    let mut out = vec![
        base("symmetric, centre on axis", sym, on_axis),
        base("symmetric, centre off axis", sym, off_axis),
        base("asymmetric, centre on axis", asym, on_axis),
        base("asymmetric, centre off axis", asym, off_axis),
        base("full tensor, centre off axis", full, off_axis),
    ];
    let mut s = base("asymmetric + body torque", asym, off_axis);
    s.body_torque = Some(Vector3::new(0.1, -0.2, 0.05));
    out.push(s);
    let mut s = base("asymmetric + space torque", asym, off_axis);
    s.space_torque = Some(Vector3::new(-0.3, 0.1, 0.2));
    out.push(s);
    let mut s = base("asymmetric + damping", asym, off_axis);
    s.damping = Some(0.07);
    out.push(s);
    let mut s = base("asymmetric + user torque", asym, off_axis);
    s.user_torque = Some(Vector3::new(0.02, 0.3, -0.1));
    out.push(s);
    let mut s = base("torque-free asymmetric", asym, Vector3::zeros());
    s.gravity = None;
    out.push(s);
    let mut s = base("ZYX angles, all torques", full, off_axis);
    s.sequence = AngleSequence::Zyx;
    s.body_torque = Some(Vector3::new(0.1, -0.2, 0.05));
    s.space_torque = Some(Vector3::new(-0.3, 0.1, 0.2));
    s.damping = Some(0.07);
    s.user_torque = Some(Vector3::new(0.02, 0.3, -0.1));
    out.push(s);
    out
}

fn exact(a: &mut Arena, x: f64) -> ExprId {
    a.constant(Rational::from_f64(x).expect("test values are representable"))
}

fn vec_expr(a: &mut Arena, v: &Vector3<f64>) -> [ExprId; 3] {
    [exact(a, v.x), exact(a, v.y), exact(a, v.z)]
}

/// The scene for the symbolic side; the user torque is three input symbols.
fn symbolic(a: &mut Arena, s: &Scene) -> (TopScene, Option<[ExprId; 3]>) {
    let mut inertia = [[a.zero(); 3]; 3];
    for (i, row) in inertia.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = exact(a, s.inertia[(i, j)]);
        }
    }
    let mut scene = TopScene::free(a, inertia);
    scene.sequence = s.sequence;
    scene.mass = exact(a, s.mass);
    scene.center = vec_expr(a, &s.center);
    scene.gravity = s.gravity.map(|g| exact(a, g));
    scene.body_torque = s.body_torque.map(|v| vec_expr(a, &v));
    scene.space_torque = s.space_torque.map(|v| vec_expr(a, &v));
    scene.damping = s.damping.map(|k| exact(a, k));
    let user = s
        .user_torque
        .map(|_| [a.parameter("u_1"), a.parameter("u_2"), a.parameter("u_3")]);
    scene.user_torque = user;
    (scene, user)
}

/// A random state away from the chart's singularity (|sin θ| ≥ 0.2 or |cos pitch| ≥ 0.2).
fn random_state(rng: &mut Rng, seq: AngleSequence) -> ([f64; 3], [f64; 3]) {
    let mut q = [rng.uniform(-3.0, 3.0), 0.0, rng.uniform(-3.0, 3.0)];
    q[1] = match seq {
        AngleSequence::Zxz => rng.uniform(0.2, std::f64::consts::PI - 0.2),
        AngleSequence::Zyx => rng.uniform(-1.37, 1.37),
    };
    let qd = [
        rng.uniform(-5.0, 5.0),
        rng.uniform(-5.0, 5.0),
        rng.uniform(-20.0, 20.0),
    ];
    (q, qd)
}

#[test]
fn lagrangian_and_eulerian_forms_agree_at_random_states() {
    let mut rng = Rng::new(7);
    for s in scenes() {
        let mut a = Arena::new();
        let (scene, user) = symbolic(&mut a, &s);
        let top = scene.derive(&mut a).expect("scene derives");
        let omega_dot = top.omega_dot(&mut a);
        let accel = Program::lower(&a, &top.accelerations.accel);
        let wdot = Program::lower(&a, &omega_dot);
        let c = top.coords().clone();
        let idx = |e: ExprId| a.as_symbol(e).expect("symbol").index();
        let mut env = vec![f64::NAN; a.symbol_count()];
        if let (Some(u), Some(uv)) = (user, s.user_torque) {
            for k in 0..3 {
                env[idx(u[k])] = uv[k];
            }
        }
        let mut worst: f64 = 0.0;
        for _ in 0..10_000 {
            let (q, qd) = random_state(&mut rng, s.sequence);
            for k in 0..3 {
                env[idx(c.q[k])] = q[k];
                env[idx(c.rates[k])] = qd[k];
            }
            let qdd = accel.eval(&env);
            for k in 0..3 {
                env[idx(c.accels[k])] = qdd[k];
            }
            let lagrangian = wdot.eval(&env);
            let (r, w) = attitude(s.sequence, q, qd);
            let expected = s.omega_dot(&r, &w);
            // Relative to the size of the terms that make up ω̇ (|ω|² I/I), not to ω̇
            // itself, which can pass through zero.
            let scale = 1.0 + w.norm_squared() + expected.norm();
            for k in 0..3 {
                let err = (lagrangian[k] - expected[k]).abs() / scale;
                worst = worst.max(err);
            }
        }
        assert!(worst < 1e-10, "{}: worst relative error {worst:e}", s.name);
        eprintln!("{:32} worst relative error {worst:.1e}", s.name);
    }
}

#[test]
fn symbolic_eulerian_form_matches_nalgebra() {
    let mut rng = Rng::new(11);
    for s in scenes() {
        let mut a = Arena::new();
        let (scene, user) = symbolic(&mut a, &s);
        let names = [
            ["R_00", "R_01", "R_02"],
            ["R_10", "R_11", "R_12"],
            ["R_20", "R_21", "R_22"],
        ];
        let rot = names.map(|row| row.map(|n| a.parameter(n)));
        let w = [a.parameter("w_1"), a.parameter("w_2"), a.parameter("w_3")];
        let rhs = scene
            .eulerian_rhs(&mut a, &rot, &w)
            .expect("invertible inertia");
        let prog = Program::lower(&a, &rhs);
        let idx = |e: ExprId| a.as_symbol(e).expect("symbol").index();
        let mut env = vec![f64::NAN; a.symbol_count()];
        if let (Some(u), Some(uv)) = (user, s.user_torque) {
            for k in 0..3 {
                env[idx(u[k])] = uv[k];
            }
        }
        for _ in 0..1000 {
            let (q, qd) = random_state(&mut rng, s.sequence);
            let (r, wv) = attitude(s.sequence, q, qd);
            for i in 0..3 {
                for j in 0..3 {
                    env[idx(rot[i][j])] = r[(i, j)];
                }
                env[idx(w[i])] = wv[i];
            }
            let got = prog.eval(&env);
            let expected = s.omega_dot(&r, &wv);
            let scale = 1.0 + wv.norm_squared() + expected.norm();
            for k in 0..3 {
                assert!(
                    (got[k] - expected[k]).abs() / scale < 1e-12,
                    "{}: {got:?} vs {expected}",
                    s.name
                );
            }
        }
    }
}
