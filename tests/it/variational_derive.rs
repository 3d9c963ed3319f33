//! The variational equations the derive emits (`#[top(variational(...))]`) against the
//! interpreted `VariationalSystem` of the same derivation at random states, and against
//! independent values: central differences of the generated plain model's flow in x₀ and in
//! the fields, the intermediate-axis growth rate of a torque-free body, and the ± pairing
//! and Liouville sum of a heavy top's finite-time spectrum.

use approx::assert_relative_eq;
use nalgebra::DMatrix;
use precess::ode::{AdaptiveConfig, Dop853, System};

use crate::common::flow::{Uniform, flow, tight};
use precess::prelude::*;
use precess::sym::Arena;
use precess::top::TopScene;
use precess::variational::{
    BenettinConfig, FlowMap, Layout, VariationalEquations, VariationalError, VariationalSystem,
    benettin,
};

/// A heavy top whose mass, arm, gravity and principal moments about the pivot are fields,
/// with the whole Φ and the sensitivities to m, l and g: N = 6 + 36 + 18 = 60.
#[derive(RigidBody, Clone, Copy, Debug)]
#[rigid(
    body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i2, i3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, variational(sensitivities = [m, l, g]))]
struct Heavy {
    m: f64,
    l: f64,
    g: f64,
    i1: f64,
    i2: f64,
    i3: f64,
}

/// A torque-free body in yaw, pitch, roll whose body z axis is the intermediate one
/// (I = 1, 3, 2), carrying one tangent vector: N = 12.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 0.0], inertia = diag(1.0, 3.0, 2.0), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(angles = zyx, variational(tangents = 1))]
struct Tumbler;

/// The asymmetric heavy top of the interpreted tests (I = 1, 1.5, 0.7; M g l = 1).
const ASYMMETRIC: Heavy = Heavy {
    m: 1.0,
    l: 1.0,
    g: 1.0,
    i1: 1.0,
    i2: 1.5,
    i3: 0.7,
};

/// The interpreted system of the same scene, built by hand as an arena scene with the
/// fields' names as parameters.
fn interpreted(a: &mut Arena) -> VariationalEquations {
    let z = a.zero();
    let i = ["i1", "i2", "i3"].map(|n| a.parameter(n));
    let mut scene = TopScene::free(a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    scene.mass = a.parameter("m");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let derivation = scene.derive(a).unwrap();
    VariationalEquations::from_top(a, &derivation, 6, &["m", "l", "g"]).unwrap()
}

#[test]
fn the_generated_type_has_the_interpreted_layout() {
    assert_eq!(
        HeavyVariational::LAYOUT,
        Layout {
            n: 6,
            tangents: 6,
            sensitivities: 3
        }
    );
    assert_eq!(HeavyVariational::SENSITIVITIES, ["m", "l", "g"]);
    assert_eq!(TumblerVariational::LAYOUT.len(), 12);
    let y0 = ASYMMETRIC
        .variational()
        .initial_state(&[0.3, 1.0, 0.2, 0.5, 0.3, 2.0])
        .unwrap();
    assert_eq!(y0.len(), 60);
    assert_eq!(
        (y0[6], y0[7], y0[13], y0[41], y0[42]),
        (1.0, 0.0, 1.0, 1.0, 0.0)
    );
    assert!(matches!(
        ASYMMETRIC.variational().initial_state(&[0.0; 5]),
        Err(VariationalError::InitialStateLength {
            expected: 6,
            got: 5
        })
    ));
    fn shareable<T: Send + Sync>() {}
    shareable::<HeavyVariational<'static>>();
}

/// The generated right-hand side against the interpreter running the program of the same
/// equations, at 256 random augmented states with random fields (θ kept off the chart's
/// gimbal lock): the same lowering, so they agree to the rounding of one evaluation.
#[test]
fn the_generated_equations_are_the_interpreted_ones() {
    let mut a = Arena::new();
    let eq = interpreted(&mut a);
    let mut rng = Uniform(25);
    let mut worst: f64 = 0.0;
    for _ in 0..256 {
        let top = Heavy {
            m: rng.next(0.5, 2.0),
            l: rng.next(0.2, 1.5),
            g: rng.next(0.0, 10.0),
            i1: rng.next(0.5, 2.0),
            i2: rng.next(0.5, 2.0),
            i3: rng.next(0.3, 1.0),
        };
        let values = [
            ("m", top.m),
            ("l", top.l),
            ("g", top.g),
            ("i1", top.i1),
            ("i2", top.i2),
            ("i3", top.i3),
        ];
        let sys = VariationalSystem::<60>::new(&a, &eq, &values).unwrap();
        let mut y = [0.0; 60];
        for (k, v) in y.iter_mut().enumerate() {
            *v = match k {
                1 => rng.next(0.3, 2.8),
                _ => rng.next(-2.0, 2.0),
            };
        }
        let (mut generated, mut reference) = ([0.0; 60], [0.0; 60]);
        top.variational().rhs(0.0, &y, &mut generated);
        sys.rhs(0.0, &y, &mut reference);
        let scale = reference.iter().fold(1.0f64, |s, v| s.max(v.abs()));
        for (g, r) in generated.iter().zip(&reference) {
            worst = worst.max((g - r).abs() / scale);
        }
    }
    eprintln!("generated against interpreted, 256 states: worst {worst:e} of max |f|");
    assert!(worst < 1e-13, "{worst:e}");
}

/// Φ(2) and ∂x(2)/∂(m, l, g) of the asymmetric heavy top from the generated type against
/// central differences of the flow of the generated plain model (`TopChart`), in each
/// initial coordinate and in each field.
#[test]
fn the_generated_transition_matrix_and_sensitivities_match_finite_differences() {
    let top = ASYMMETRIC;
    let var = top.variational();
    let x0 = [0.3, 1.0, 0.2, 0.5, 0.3, 2.0];
    let t = 2.0;
    let y = flow(var, var.initial_state(&x0).unwrap(), t);
    let layout = HeavyVariational::LAYOUT;
    let (phi, s) = (layout.transition(&y), layout.sensitivities(&y));
    let h = 1e-5;
    let mut fd = DMatrix::zeros(6, 6);
    for j in 0..6 {
        let (mut up, mut down) = (x0, x0);
        up[j] += h;
        down[j] -= h;
        let yu = flow(TopChart::declared(&top), up, t);
        let yd = flow(TopChart::declared(&top), down, t);
        for i in 0..6 {
            fd[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
        }
    }
    let err_phi = (&phi - &fd).amax() / phi.amax();
    let mut fd_s = DMatrix::zeros(6, 3);
    let fields: [fn(&mut Heavy) -> &mut f64; 3] = [|t| &mut t.m, |t| &mut t.l, |t| &mut t.g];
    for (j, field) in fields.iter().enumerate() {
        let (mut up, mut down) = (top, top);
        *field(&mut up) += h;
        *field(&mut down) -= h;
        let yu = flow(TopChart::declared(&up), x0, t);
        let yd = flow(TopChart::declared(&down), x0, t);
        for i in 0..6 {
            fd_s[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
        }
    }
    let err_s = (&s - &fd_s).amax() / s.amax();
    eprintln!(
        "generated Φ(2) against differences: {err_phi:e} of max |Φ| = {}; S: {err_s:e} of max |S| = {}",
        phi.amax(),
        s.amax()
    );
    assert!(err_phi < 1e-7, "{err_phi:e}");
    assert!(err_s < 1e-7, "{err_s:e}");
    // x itself is the plain model's flow, and the flow map reads it back.
    let x = flow(TopChart::declared(&top), x0, t);
    let map = FlowMap::new(layout, &y).unwrap();
    let moved = map.apply(&[0.0; 6]).unwrap();
    for k in 0..6 {
        assert_relative_eq!(y[k], x[k], epsilon = 1e-11);
        assert_relative_eq!(moved[k], x[k], epsilon = 1e-11);
    }
}

/// Spinning at ω about its intermediate body axis z, with yaw the rotation about the space
/// z axis it points along, the body is on an equilibrium of the angle equations (pitch =
/// roll = 0, only the yaw rate nonzero, yaw cyclic), so the linearisation is constant and
/// Benettin's λ₁ is exactly its growth rate λ = ω√((I2 − I1)(I3 − I2)/(I1 I3)) with the
/// moments sorted, here √((2 − 1)(3 − 2)/(1·3)) ω, once the transient has aligned the
/// vector (the neutral part, a Jordan block of the cyclic yaw, decays as t e^{−λt}).
/// The equilibrium is exact in floating point (sin 0 = 0), so the orbit stays on it.
#[test]
fn the_generated_intermediate_axis_exponent_is_exact() {
    let w = 1.5;
    let lambda = w * ((2.0f64 - 1.0) * (3.0 - 2.0) / (1.0 * 3.0)).sqrt();
    let var = Tumbler.variational();
    let y0 = var.initial_state(&[0.0, 0.0, 0.0, w, 0.0, 0.0]).unwrap();
    let cfg = BenettinConfig {
        interval: 0.5,
        duration: 20.0,
        transient: 30.0,
    };
    let mut ode = Dop853::new(var, 0.0, y0, tight()).unwrap();
    let run = benettin(&mut ode, TumblerVariational::LAYOUT, &cfg).unwrap();
    eprintln!(
        "generated intermediate axis: λ = {lambda}, Benettin {:?}",
        run.exponents
    );
    assert_relative_eq!(run.exponents[0], lambda, max_relative = 1e-8);
}

/// The asymmetric heavy top's six finite-time exponents in angles, from the start (no
/// transient, so the exponents sum to (1/T) ln |det Φ(T)|): conservative, so they pair as
/// ±λ with four near zero (the flow, the energy, the cyclic φ and its momentum), and
/// Liouville's theorem in (q, p = M(q) q̇) makes the sum exact:
/// det Φ = det M(q₀) / det M(q(T)), with det M = I1 I2 I3 sin²θ in ZXZ, so
/// Σλ = (2/T) ln |sin θ₀ / sin θ(T)|.
#[test]
fn the_generated_heavy_top_spectrum_pairs_and_sums_to_liouville() {
    let top = ASYMMETRIC;
    let var = top.variational();
    let x0 = [0.0, 1.5, 0.0, 0.3, 0.2, 0.5];
    let duration = 300.0;
    let cfg = BenettinConfig {
        interval: 0.5,
        duration,
        transient: 0.0,
    };
    let tol = AdaptiveConfig::with_tol(1e-11, 1e-11);
    let mut ode = Dop853::new(var, 0.0, var.initial_state(&x0).unwrap(), tol).unwrap();
    let run = benettin(&mut ode, HeavyVariational::LAYOUT, &cfg).unwrap();
    let l = &run.exponents;
    let sum: f64 = l.iter().sum();
    // θ(T) of the same trajectory: a second integration of a chaotic orbit would part from
    // it long before T.
    assert_relative_eq!(ode.t(), duration);
    let theta_t = ode.y()[1];
    let liouville = 2.0 / duration * (x0[1].sin() / theta_t.sin()).abs().ln();
    eprintln!(
        "generated heavy top, angles: {l:?}, sum {sum:e}, Liouville {liouville:e}, θ(T) = {theta_t}"
    );
    assert!(l[0] > 0.1, "{l:?}");
    assert!(
        (sum - liouville).abs() < 1e-8,
        "{sum:e} against {liouville:e}"
    );
    assert!((l[0] + l[5]).abs() < 0.05 * l[0], "{l:?}");
    for k in 1..5 {
        assert!(l[k].abs() < 0.15 * l[0], "{l:?}");
    }
}

/// The top's own checks guard the generated type: a NaN or negative field is refused when
/// an integrator is built, as for the plain model.
#[test]
fn the_generated_type_checks_the_fields() {
    let bad = [
        Heavy {
            g: f64::NAN,
            ..ASYMMETRIC
        },
        Heavy {
            m: -1.0,
            ..ASYMMETRIC
        },
    ];
    for top in &bad {
        let var = top.variational();
        let y0 = var.initial_state(&[0.3, 1.0, 0.2, 0.5, 0.3, 2.0]).unwrap();
        let plain = Dop853::new(TopChart::declared(top), 0.0, [0.0; 6], tight()).err();
        let generated = Dop853::new(var, 0.0, y0, tight()).err();
        assert!(generated.is_some(), "{top:?}");
        assert_eq!(
            generated.map(|e| e.to_string()),
            plain.map(|e| e.to_string())
        );
    }
}
