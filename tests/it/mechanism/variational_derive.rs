//! The variational equations `#[mechanism(variational(...))]` emits, on a double pendulum,
//! against independent values: the interpreted `VariationalSystem` of the same scene built
//! by hand at random states, central differences of the generated plain model's flow in x₀
//! and in the fields, the Liouville sum of the finite-time spectrum in (q, q̇) from the
//! closed-form det M, its ± pairing, ln T / T on a quasi-periodic orbit, and two nearby
//! trajectories' divergence rate on a chaotic one.

use nalgebra::DMatrix;
use precess::mechanism::Route;
use precess::ode::{AdaptiveConfig, Dop853, System};

use crate::common::flow::{Uniform, flow, tight};
use precess::prelude::*;
use precess::sym::Arena;
use precess::variational::{
    BenettinConfig, Layout, VariationalEquations, VariationalSystem, benettin,
};

/// Two point masses on massless rods swinging about x, θ2 relative to the upper rod, every
/// value a field, with the whole Φ and the sensitivities to the upper rod's length and the
/// lower mass: N = 4 + 16 + 8 = 28.
#[derive(Mechanism, Clone, Copy, Debug)]
#[mechanism(gravity = g, variational(sensitivities = [l1, m2]))]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -l1]), q = theta2,
       parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct Double {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
    g: f64,
}

/// The same pendulum carrying one tangent vector only, for the maximal exponent: N = 8.
#[derive(Mechanism, Clone, Copy, Debug)]
#[mechanism(gravity = 9.81, variational(tangents = 1))]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -1.0]), q = theta2,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Unit;

/// A brick thrown without gravity on a free joint in yaw, pitch, roll, its centre at the
/// joint's origin: 12 kg, 0.3 × 0.1 × 0.2 m, so I = m(b² + c², a² + c², a² + b²)/12 =
/// (0.05, 0.13, 0.10) kg m² and the body z axis is the intermediate one. One tangent:
/// N = 12 + 12 = 24.
#[derive(Mechanism)]
#[mechanism(variational(tangents = 1))]
#[body(brick, joint = free(sequence = zyx), q = [x, y, z, yaw, pitch, roll],
       parts(cuboid(mass = 12.0, size = [0.3, 0.1, 0.2])))]
struct Thrown;

/// Equal masses and lengths, g = 9.81.
const EQUAL: Double = Double {
    m1: 1.0,
    l1: 1.0,
    m2: 1.0,
    l2: 1.0,
    g: 9.81,
};

/// The interpreted equations of the same pendulum, its scene built by hand (bodies, centres,
/// joint offset and gravity as arena parameters named after the fields, not through the
/// derive's part language) and lowered by `from_mechanism`.
fn interpreted(a: &mut Arena) -> VariationalEquations {
    let scene = crate::common::mechanism::double_pendulum(a, None);
    let derivation = scene.derive(a, Route::Auto).unwrap();
    VariationalEquations::from_mechanism(a, &derivation, 4, &["l0", "m1"]).unwrap()
}

/// The hand scene's parameter names are m0, l0 (upper) and m1, l1 (lower).
fn values(p: &Double) -> [(&'static str, f64); 5] {
    [
        ("m0", p.m1),
        ("l0", p.l1),
        ("m1", p.m2),
        ("l1", p.l2),
        ("g", p.g),
    ]
}

#[test]
fn the_generated_type_has_the_interpreted_layout() {
    assert_eq!(
        DoubleVariational::LAYOUT,
        Layout {
            n: 4,
            tangents: 4,
            sensitivities: 2
        }
    );
    assert_eq!(DoubleVariational::SENSITIVITIES, ["l1", "m2"]);
    assert_eq!(UnitVariational::LAYOUT.len(), 8);
    let y0 = EQUAL
        .variational()
        .initial_state(&[0.3, 1.0, 0.2, 0.5])
        .unwrap();
    assert_eq!(y0.len(), 28);
    // x₀, then Φ = I column by column, then S = 0.
    assert_eq!(
        (y0[1], y0[4], y0[5], y0[9], y0[24]),
        (1.0, 1.0, 0.0, 1.0, 0.0)
    );
    fn shareable<T: Send + Sync>() {}
    shareable::<DoubleVariational<'static>>();
}

/// The generated right-hand side against the interpreter running the program of the hand
/// scene's equations at 100 random augmented states with random fields. The two arenas
/// build the same equations from different expressions (the derive's come through the part
/// language's mass properties), so they agree to rounding, not bit for bit.
#[test]
fn the_generated_equations_are_the_interpreted_ones() {
    let mut a = Arena::new();
    let eq = interpreted(&mut a);
    let mut rng = Uniform(29);
    let (mut worst, mut equal, mut total): (f64, usize, usize) = (0.0, 0, 0);
    for _ in 0..100 {
        let p = Double {
            m1: rng.next(0.2, 3.0),
            l1: rng.next(0.2, 2.0),
            m2: rng.next(0.2, 3.0),
            l2: rng.next(0.2, 2.0),
            g: rng.next(0.0, 10.0),
        };
        let sys = VariationalSystem::<28>::new(&a, &eq, &values(&p)).unwrap();
        let mut y = [0.0; 28];
        for v in &mut y {
            *v = rng.next(-3.0, 3.0);
        }
        let (mut generated, mut reference) = ([0.0; 28], [0.0; 28]);
        p.variational().rhs(0.0, &y, &mut generated);
        sys.rhs(0.0, &y, &mut reference);
        let scale = reference.iter().fold(1.0f64, |s, v| s.max(v.abs()));
        for (g, r) in generated.iter().zip(&reference) {
            worst = worst.max((g - r).abs() / scale);
            equal += usize::from(g.to_bits() == r.to_bits());
            total += 1;
        }
    }
    eprintln!(
        "mechanism: generated against interpreted, 100 states: worst {worst:e} of max |f|, {equal} of {total} entries bit for bit"
    );
    assert!(worst < 1e-13, "{worst:e}");
}

/// Φ(2) and ∂x(2)/∂(l1, m2) of the equal double pendulum from the generated type against
/// central differences of the flow of the generated plain model (`System<4>` on the struct)
/// in each initial coordinate and in each field.
#[test]
fn the_generated_transition_matrix_and_sensitivities_match_finite_differences() {
    let p = EQUAL;
    let var = p.variational();
    let x0 = [0.8, -0.4, 0.3, 0.5];
    let t = 2.0;
    let y = flow(var, var.initial_state(&x0).unwrap(), t);
    let layout = DoubleVariational::LAYOUT;
    let (phi, s) = (layout.transition(&y), layout.sensitivities(&y));
    let h = 1e-5;
    let mut fd = DMatrix::zeros(4, 4);
    for j in 0..4 {
        let (mut up, mut down) = (x0, x0);
        up[j] += h;
        down[j] -= h;
        let (yu, yd) = (flow(p, up, t), flow(p, down, t));
        for i in 0..4 {
            fd[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
        }
    }
    let err_phi = (&phi - &fd).amax() / phi.amax();
    let mut fd_s = DMatrix::zeros(4, 2);
    let fields: [fn(&mut Double) -> &mut f64; 2] = [|p| &mut p.l1, |p| &mut p.m2];
    for (j, field) in fields.iter().enumerate() {
        let (mut up, mut down) = (p, p);
        *field(&mut up) += h;
        *field(&mut down) -= h;
        let (yu, yd) = (flow(up, x0, t), flow(down, x0, t));
        for i in 0..4 {
            fd_s[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
        }
    }
    let err_s = (&s - &fd_s).amax() / s.amax();
    eprintln!(
        "mechanism: generated Φ(2) against differences: {err_phi:e} of max |Φ| = {}; S: {err_s:e} of max |S| = {}",
        phi.amax(),
        s.amax()
    );
    assert!(err_phi < 1e-7, "{err_phi:e}");
    assert!(err_s < 1e-7, "{err_s:e}");
    // x itself is the plain model's flow.
    let x = flow(p, x0, t);
    for k in 0..4 {
        assert!(
            (y[k] - x[k]).abs() < 1e-11,
            "{k}: {} against {}",
            y[k],
            x[k]
        );
    }
}

/// det M of the double pendulum in (θ1, θ2 relative), by hand from
/// M = [[(m1 + m2) l1² + m2 l2² + 2 m2 l1 l2 cos θ2, m2 l2² + m2 l1 l2 cos θ2], [·, m2 l2²]]:
/// m2 l1² l2² (m1 + m2 sin²θ2).
fn det_mass(p: &Double, theta2: f64) -> f64 {
    p.m2 * p.l1 * p.l1 * p.l2 * p.l2 * (p.m1 + p.m2 * theta2.sin().powi(2))
}

/// The four finite-time exponents of a chaotic double pendulum from the start (no
/// transient, so they sum to (1/T) ln |det Φ(T)|): conservative, with the energy its one
/// integral, so they pair as ±λ with two near zero (the flow and the energy), and Liouville's
/// theorem in (q, p = M(q) q̇) makes the sum exact in (q, q̇):
/// det Φ = det M(q₀) / det M(q(T)), Σλ = (1/T) ln (det M(q₀) / det M(q(T))).
#[test]
fn the_generated_spectrum_pairs_and_sums_to_liouville() {
    let p = EQUAL;
    let var = p.variational();
    let x0 = [2.0, 0.5, 0.0, 0.0];
    let duration = 200.0;
    let cfg = BenettinConfig {
        interval: 0.25,
        duration,
        transient: 0.0,
    };
    let tol = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(var, 0.0, var.initial_state(&x0).unwrap(), tol).unwrap();
    let run = benettin(&mut ode, DoubleVariational::LAYOUT, &cfg).unwrap();
    let l = &run.exponents;
    let sum: f64 = l.iter().sum();
    assert!((ode.t() - duration).abs() < 1e-9);
    let theta2_t = ode.y()[1];
    let liouville = (det_mass(&p, x0[1]) / det_mass(&p, theta2_t)).ln() / duration;
    eprintln!("mechanism: double pendulum spectrum {l:?}, sum {sum:e}, Liouville {liouville:e}");
    assert!(l[0] > 0.5, "{l:?}");
    assert!(
        (sum - liouville).abs() < 1e-8,
        "{sum:e} against {liouville:e}"
    );
    assert!((l[0] + l[3]).abs() < 0.05 * l[0], "{l:?}");
    for k in [1, 2] {
        assert!(l[k].abs() < 0.05 * l[0], "{l:?}");
    }
}

/// The maximal exponent of a run of `duration` after a transient of 20, from the
/// one-tangent type.
fn lambda_1(x0: [f64; 4], duration: f64) -> f64 {
    let var = Unit.variational();
    let cfg = BenettinConfig {
        interval: 0.25,
        duration,
        transient: 20.0,
    };
    let tol = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(var, 0.0, var.initial_state(&x0).unwrap(), tol).unwrap();
    benettin(&mut ode, UnitVariational::LAYOUT, &cfg)
        .unwrap()
        .exponents[0]
}

/// A small oscillation (0.1 rad) lies on a torus: nearby orbits part at most linearly in
/// time (the frequencies shear with the amplitude), so the finite-time λ₁ stays under
/// ln T / T and falls with T, not to a positive limit (the chaotic one below is 1.4).
#[test]
fn a_quasi_periodic_double_pendulum_has_a_vanishing_exponent() {
    let x0 = [0.1, -0.05, 0.0, 0.0];
    let (short, long) = (250.0, 2000.0);
    let (l_short, l_long) = (lambda_1(x0, short), lambda_1(x0, long));
    let bound = |t: f64| t.ln() / t;
    eprintln!(
        "mechanism: quasi-periodic λ₁ {l_short:e} at T = {short} (ln T/T = {:e}), {l_long:e} at T = {long} (ln T/T = {:e})",
        short.ln() / short,
        long.ln() / long
    );
    assert!(l_short.abs() < bound(short), "{l_short:e}");
    assert!(l_long.abs() < bound(long), "{l_long:e}");
    assert!(l_long < 0.6 * l_short, "{l_long:e} against {l_short:e}");
}

/// A chaotic double pendulum (released from rest at θ1 = 2, θ2 = 0.5): λ₁ clearly positive,
/// and equal to the divergence rate of two orbits of the plain model d₀ = 1e-8 apart,
/// measured directly along the same reference orbit as the tangent vector and brought back
/// to d₀ at each interval (the two-trajectory form of Benettin's method, with no tangent
/// equations). Two separate runs of a chaotic orbit part after a few e-folding times, so
/// the reference orbit is the variational run's own, restarted at each interval as
/// `benettin` restarts it; `benettin`'s λ₁ on its own orbit is then the same finite-time
/// average to within its fluctuation.
#[test]
fn a_chaotic_double_pendulum_has_the_divergence_rate_of_nearby_orbits() {
    let x0 = [2.0, 0.5, 0.0, 0.0];
    let (interval, transient, duration) = (0.25, 20.0, 400.0);
    let lambda = lambda_1(x0, duration);
    let var = Unit.variational();
    let layout = UnitVariational::LAYOUT;
    let tol = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let d0 = 1e-8;
    let mut y = var.initial_state(&x0).unwrap();
    let (mut tangent_logs, mut pair_logs) = (0.0, 0.0);
    let steps = ((transient + duration) / interval).round() as usize;
    let averaged_from = (transient / interval).round() as usize;
    for k in 0..steps {
        let (t, next) = (k as f64 * interval, (k + 1) as f64 * interval);
        let mut ode = Dop853::new(var, t, y, tol).unwrap();
        ode.advance_to(next).unwrap();
        let end = *ode.y();
        // The neighbour starts d₀ along the current tangent direction.
        let mut near = [0.0; 4];
        for i in 0..4 {
            near[i] = y[i] + d0 * y[layout.tangent(0)][i];
        }
        let mut pair =
            Dop853::new(&EQUAL, t, near, AdaptiveConfig::with_tol(1e-13, 1e-13)).unwrap();
        pair.advance_to(next).unwrap();
        let apart = (0..4)
            .map(|i| (pair.y()[i] - end[i]).powi(2))
            .sum::<f64>()
            .sqrt();
        let v = &end[layout.tangent(0)];
        let grown = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if k >= averaged_from {
            tangent_logs += grown.ln();
            pair_logs += (apart / d0).ln();
        }
        y = end;
        for i in layout.tangent(0) {
            y[i] /= grown;
        }
    }
    let (tangent, direct) = (tangent_logs / duration, pair_logs / duration);
    eprintln!(
        "mechanism: chaotic λ₁ Benettin {lambda}, tangent on the reference orbit {tangent}, nearby orbits {direct}"
    );
    assert!(lambda > 0.5, "{lambda}");
    assert!(
        (tangent - direct).abs() < 1e-3 * tangent,
        "{tangent} against {direct}"
    );
    assert!(
        (lambda - direct).abs() < 0.1 * lambda,
        "{lambda} against {direct}"
    );
}

/// A free joint's rotation is three angles of its declared sequence, a chart like the
/// top's (no quaternion, so no spurious norm direction): spinning at ω about the
/// intermediate axis z with pitch = roll = 0 is an equilibrium of the angle equations (yaw
/// cyclic, the translations at rest and decoupled, the centre on the joint), so Benettin's
/// λ₁ is exactly the growth rate λ = ω√((I2 − I1)(I3 − I2)/(I1 I3)) with the moments sorted,
/// here (0.05, 0.10, 0.13), once the transient has aligned the vector.
#[test]
fn a_free_joint_has_the_exact_intermediate_axis_exponent() {
    let w = 2.0;
    let (i1, i2, i3): (f64, f64, f64) = (0.05, 0.10, 0.13);
    let lambda = w * ((i2 - i1) * (i3 - i2) / (i1 * i3)).sqrt();
    let var = Thrown.variational();
    let mut x0 = [0.0; 12];
    x0[9] = w;
    let cfg = BenettinConfig {
        interval: 0.5,
        duration: 20.0,
        transient: 30.0,
    };
    let mut ode = Dop853::new(var, 0.0, var.initial_state(&x0).unwrap(), tight()).unwrap();
    let run = benettin(&mut ode, ThrownVariational::LAYOUT, &cfg).unwrap();
    eprintln!(
        "mechanism: free joint, intermediate axis: λ = {lambda}, Benettin {:?}",
        run.exponents
    );
    assert!(
        (run.exponents[0] - lambda).abs() < 1e-8 * lambda,
        "{:?} against {lambda}",
        run.exponents
    );
}

/// The mechanism's own checks guard the generated type: a NaN or negative field is refused
/// when an integrator is built, with the plain model's error.
#[test]
fn the_generated_type_checks_the_fields() {
    let bad = [
        Double {
            g: f64::NAN,
            ..EQUAL
        },
        Double { m1: -1.0, ..EQUAL },
    ];
    for p in &bad {
        let var = p.variational();
        let y0 = var.initial_state(&[0.3, 1.0, 0.2, 0.5]).unwrap();
        let plain = Dop853::new(p, 0.0, [0.0; 4], tight()).err();
        let generated = Dop853::new(var, 0.0, y0, tight()).err();
        assert!(generated.is_some(), "{p:?}");
        assert_eq!(
            generated.map(|e| e.to_string()),
            plain.map(|e| e.to_string())
        );
    }
}
