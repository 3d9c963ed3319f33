//! Issue 26 item 4: free gyrostats. A body carrying wheels spun at constant rates relative to
//! it obeys the Volterra–Zhukovsky equations I ω̇ = −ω × (I ω + h), h = Σ J Ω â constant in
//! the body. Checked against what is known of them independently of the code: their steady
//! rotations, their two integrals, the linear stability of a spin about the intermediate
//! axis, the body without a wheel, and the same scene built and interpreted at run time.

use approx::assert_relative_eq;
use precess::free::{FreeDynamics, FreeError, FreeModel, FreeScene, FreeState, FreeSystem, Rotor};
use precess::ode::{AdaptiveConfig, Dop853, System};
use precess::prelude::*;
use precess::sym::Arena;

/// Principal moments (1, 2, 3) along the description axes, and a wheel along (4, −3, 2) of
/// |h| = J Ω = √29, so that h = (4, −3, 2).
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [4, -3, 2], inertia = 0.5, rate = 2 * sqrt(29)))]
struct Skewed;

/// The same body with its wheel on the intermediate axis y, spun at a rate read from a field
/// (J = 1, so h = (0, spin, 0)).
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], about = center))]
#[free(rotor(axis = [0, 1, 0], inertia = j, rate = spin))]
struct OnIntermediate {
    j: f64,
    spin: f64,
}

/// An asymmetric box with a point mass off-centre (tilted principal frame), a body torque,
/// gravity and a wheel stopped at a literal rate 0 …
#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]), particle(mass = 0.2, at = [0.1, 0.0, 0.1]))]
#[free(gravity = 9.81, body_torque = [0.01, 0.0, -0.02], rotor(axis = [1, 1, 0], inertia = 0.01, rate = 0))]
struct Stopped;

/// … and the same without the wheel.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]), particle(mass = 0.2, at = [0.1, 0.0, 0.1]))]
#[free(gravity = 9.81, body_torque = [0.01, 0.0, -0.02])]
struct Wheelless;

/// The moments of `Skewed` and `OnIntermediate`.
const I: [f64; 3] = [1.0, 2.0, 3.0];

fn spinning(omega: Vector3<f64>) -> [f64; 13] {
    FreeState {
        omega_principal: omega,
        ..FreeState::at_rest()
    }
    .to_array()
}

fn omega_of(y: &[f64; 13]) -> Vector3<f64> {
    Vector3::new(y[10], y[11], y[12])
}

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// The steady rotations ω × (I ω + h) = 0 other than along a principal axis: for any μ,
/// ωᵢ = hᵢ/(μ − Iᵢ) gives I ω + h = μ ω. With h = (4, −3, 2) and μ = 5, ω = (1, −1, 1).
/// μ above every moment makes it the minimum of ½ ωᵀ I ω on the sphere |I ω + h| = const, so
/// it is stable and rounding cannot grow: ω must stay put.
#[test]
fn the_volterra_family_rotation_stays_steady() {
    let omega0 = Vector3::new(4.0 / (5.0 - I[0]), -3.0 / (5.0 - I[1]), 2.0 / (5.0 - I[2]));
    assert_eq!(omega0, Vector3::new(1.0, -1.0, 1.0));
    let mut dy = [0.0; 13];
    Skewed.free_rhs(0.0, &spinning(omega0), &mut dy);
    let rate = omega_of(&dy).norm();
    assert!(rate < 1e-14, "|ω̇| = {rate:e} at the steady rotation");
    let mut ode = Dop853::new(&FreeSystem(&Skewed), 0.0, spinning(omega0), tight()).unwrap();
    ode.advance_to(500.0).unwrap();
    let drift = (omega_of(ode.y()) - omega0).norm();
    assert!(drift < 1e-12, "ω drifted by {drift:e} over 500 s");
    // A point off the family is not steady: the check can fail.
    Skewed.free_rhs(0.0, &spinning(Vector3::new(1.0, -1.0, 1.1)), &mut dy);
    assert!(omega_of(&dy).norm() > 1e-2);
}

/// A spin along the wheel's principal axis is steady whatever h: here the major axis z of a
/// body with its wheel on y would not be, but with the wheel on y a spin about y is.
#[test]
fn a_spin_along_the_wheel_axis_stays_steady() {
    let body = OnIntermediate { j: 1.0, spin: 3.0 };
    let omega0 = Vector3::new(0.0, 0.7, 0.0);
    let system = FreeSystem(&body);
    let mut ode = Dop853::new(&system, 0.0, spinning(omega0), tight()).unwrap();
    ode.advance_to(500.0).unwrap();
    let drift = (omega_of(ode.y()) - omega0).norm();
    assert!(drift < 1e-12, "ω drifted by {drift:e}");
}

/// The two integrals of the Volterra–Zhukovsky equations, |I ω + h| and ½ ωᵀ I ω, computed
/// here from ω alone, along a generic tumbling motion; and the generated angular momentum and
/// energy are those, written by hand.
#[test]
fn the_momentum_with_the_wheel_and_the_energy_without_it_are_conserved() {
    let h = Vector3::new(4.0, -3.0, 2.0);
    let i = Vector3::from(I);
    let integrals = |w: &Vector3<f64>| {
        let l = i.component_mul(w) + h;
        (l.norm(), 0.5 * w.dot(&i.component_mul(w)))
    };
    let s0 = FreeState {
        attitude: UnitQuaternion::from_euler_angles(0.3, -0.4, 1.2),
        omega_principal: Vector3::new(0.4, 2.0, -1.3),
        ..FreeState::at_rest()
    };
    let y0 = s0.to_array();
    let (l0, e0) = integrals(&s0.omega_principal);
    assert_relative_eq!(Skewed.energy(&y0), e0, max_relative = 1e-15);
    let l_space = s0.attitude * (i.component_mul(&s0.omega_principal) + h);
    assert_relative_eq!(
        Skewed.angular_momentum_origin(&y0),
        l_space,
        max_relative = 1e-14
    );
    let mut ode = Dop853::new(&FreeSystem(&Skewed), 0.0, y0, tight()).unwrap();
    let mut moved = 0.0f64;
    for k in 1..=20 {
        ode.advance_to(10.0 * f64::from(k)).unwrap();
        let w = omega_of(ode.y());
        moved = moved.max((w - s0.omega_principal).norm());
        let (l, e) = integrals(&w);
        assert_relative_eq!(l, l0, max_relative = 1e-11);
        assert_relative_eq!(e, e0, max_relative = 1e-11);
        // The space-fixed momentum R (I ω + h) is constant as a vector.
        let l_now = Skewed.angular_momentum_origin(ode.y());
        assert!((l_now - l_space).norm() < 1e-10 * l0, "L moved to {l_now}");
    }
    assert!(moved > 0.5, "the motion should tumble, moved {moved}");
}

/// A wheel on the intermediate axis y of I = (1, 2, 3), spun so that h = (0, h, 0), and the
/// body spinning at n about y. Linearising ω = (ε₁, n, ε₃) in the equations:
///
/// I₁ ε̇₁ = [(I₂ − I₃) n + h] ε₃,  I₃ ε̇₃ = [(I₁ − I₂) n − h] ε₁,
///
/// so ε̈₁ = −k ε₁ with k = (h − (I₃ − I₂) n)(h + (I₂ − I₁) n)/(I₁ I₃). Without a wheel k < 0:
/// the intermediate axis is unstable (the Dzhanibekov flip). The spin is stable (k > 0) when
/// h > (I₃ − I₂) n or h < −(I₂ − I₁) n: for n = 1, h > 1 or h < −1. At h = 1.5, k = 5/12
/// and the small wobble has the period 2π/√k = 9.7339 s; at h = 0.5 the wobble grows as
/// e^{√(−k) t}, √(−k) = 1/2.
#[test]
fn a_large_enough_wheel_stabilises_the_intermediate_axis() {
    let n = 1.0;
    let wobble = |h: f64| {
        let body = OnIntermediate { j: 1.0, spin: h };
        let y0 = spinning(Vector3::new(1e-4, n, 0.0));
        let system = FreeSystem(&body);
        let mut ode = Dop853::new(&system, 0.0, y0, tight()).unwrap();
        let (mut largest, mut crossings, mut first, mut last) = (0.0f64, 0, None, 0.0);
        let mut previous = y0[10];
        for k in 1..=6000 {
            let t = 0.01 * f64::from(k);
            ode.advance_to(t).unwrap();
            let e1 = ode.y()[10];
            largest = largest.max(e1.abs());
            // Downward zero crossings of ε₁ mark whole periods.
            if previous > 0.0 && e1 <= 0.0 {
                crossings += 1;
                first.get_or_insert(t);
                last = t;
            }
            previous = e1;
        }
        let period = first.map(|f| (last - f) / f64::from(crossings - 1));
        (largest, period)
    };
    let (largest, period) = wobble(1.5);
    assert!(largest < 2e-4, "the stable wobble reached {largest:e}");
    let k = (1.5 - (I[2] - I[1]) * n) * (1.5 + (I[1] - I[0]) * n) / (I[0] * I[2]);
    let theory = 2.0 * std::f64::consts::PI / k.sqrt();
    assert_relative_eq!(theory, 9.733_869, max_relative = 1e-6);
    let period = period.unwrap();
    assert_relative_eq!(period, theory, max_relative = 1e-3);
    // Just below the threshold, and without a wheel, the spin about y flips.
    for h in [0.5, 0.9, 0.0] {
        let (largest, _) = wobble(h);
        assert!(
            largest > 0.05,
            "at h = {h} the wobble stayed below {largest:e}"
        );
    }
    // Just above it, and on the negative side past −(I₂ − I₁) n, it is stable.
    for h in [1.1, -1.1] {
        let (largest, _) = wobble(h);
        assert!(largest < 1e-2, "at h = {h} the wobble reached {largest:e}");
    }
}

/// A wheel at rate 0 derives the body without one, bit for bit (literal rate), and to
/// rounding when the zero comes from a field.
#[test]
fn a_stopped_wheel_is_no_wheel() {
    let s = FreeState {
        position: Vector3::new(0.1, -0.2, 3.0),
        velocity: Vector3::new(1.0, 0.5, -2.0),
        attitude: UnitQuaternion::from_euler_angles(0.7, -0.2, 1.9),
        omega_principal: Vector3::new(3.0, -1.5, 0.8),
    };
    let y = s.to_array();
    let (mut a, mut b) = ([0.0; 13], [0.0; 13]);
    Stopped.free_rhs(0.3, &y, &mut a);
    Wheelless.free_rhs(0.3, &y, &mut b);
    assert_eq!(a, b);
    assert_eq!(
        Stopped.angular_momentum_origin(&y),
        Wheelless.angular_momentum_origin(&y)
    );
    let zero = OnIntermediate { j: 1.0, spin: 0.0 };
    let w = s.omega_principal;
    zero.free_rhs(0.0, &y, &mut a);
    // Euler's torque-free equations for I = (1, 2, 3), by hand.
    let euler = Vector3::new(
        (I[1] - I[2]) * w.y * w.z / I[0],
        (I[2] - I[0]) * w.z * w.x / I[1],
        (I[0] - I[1]) * w.x * w.y / I[2],
    );
    assert_relative_eq!(omega_of(&a), euler, epsilon = 1e-15);
}

/// The same gyrostat built as a `FreeScene` at run time and interpreted: a second path
/// through the derivation agrees with the generated code.
#[test]
fn the_run_time_scene_with_a_rotor_matches_the_derive() {
    let mut ar = Arena::new();
    let m = ar.integer(1);
    let moments = [ar.integer(1), ar.integer(2), ar.integer(3)];
    let mut scene = FreeScene::new(&mut ar, m, moments);
    let axis = [ar.integer(4), ar.integer(-3), ar.integer(2)];
    let (inertia, rate) = (ar.parameter("J"), ar.parameter("Omega"));
    scene.rotors.push(Rotor {
        axis,
        inertia,
        rate,
    });
    let derivation = scene.derive(&mut ar).unwrap();
    let model = FreeModel::new(
        &mut ar,
        &derivation,
        &[("J", 0.5), ("Omega", 2.0 * 29f64.sqrt())],
    )
    .unwrap();
    let y = FreeState {
        attitude: UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3),
        omega_principal: Vector3::new(0.4, 2.0, -1.3),
        ..FreeState::at_rest()
    }
    .to_array();
    let (mut a, mut b) = ([0.0; 13], [0.0; 13]);
    model.rhs(0.0, &y, &mut a);
    Skewed.free_rhs(0.0, &y, &mut b);
    for k in 0..13 {
        assert_relative_eq!(a[k], b[k], epsilon = 1e-14, max_relative = 1e-14);
    }
    // And both are the Volterra–Zhukovsky right-hand side written out.
    let w = omega_of(&y);
    let i = Vector3::from(I);
    let h = Vector3::new(4.0, -3.0, 2.0);
    let expected = (-w.cross(&(i.component_mul(&w) + h))).component_div(&i);
    assert_relative_eq!(omega_of(&b), expected, epsilon = 1e-14);
}

/// A wheel's inertia read from a field is checked when the run starts: zero or negative is
/// refused with the rotor and the value named.
#[test]
fn a_field_inertia_that_is_not_positive_is_refused() {
    let body = OnIntermediate { j: -0.5, spin: 1.0 };
    assert_eq!(
        body.check_parameters(),
        Err(FreeError::InvalidRotor {
            rotor: 0,
            inertia: -0.5,
            axis_norm: 1.0
        })
    );
    assert!(
        OnIntermediate { j: 0.5, spin: -3.0 }
            .check_parameters()
            .is_ok()
    );
}
