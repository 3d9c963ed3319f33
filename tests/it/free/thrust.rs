//! Item 4(b): thrust through the centre of mass while spinning about a principal axis, and a
//! body torque about it, against v(t), x(t) and R(t) in closed form.

use approx::assert_relative_eq;
use precess::free::{FreeDynamics, FreeFlight, FreeState, FreeSystem};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;

/// Thrust along principal axis 3, through the centre of mass.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free(body_force(force = [0.0, 0.0, thrust], at = center))]
struct AxialRocket {
    thrust: f64,
}

/// Thrust along principal axis 1 through the centre of mass, under gravity.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free(gravity = 9.81, body_force(force = [thrust, 0.0, 0.0], at = center))]
struct SideRocket {
    thrust: f64,
}

/// A constant body torque about principal axis 3.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free(body_torque = [0.0, 0.0, tau])]
struct Spinner {
    tau: f64,
}

const M: f64 = 2.0;

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-12, 1e-12)
}

fn start(w3: f64) -> FreeState {
    FreeState {
        position: Vector3::new(1.0, -2.0, 0.5),
        velocity: Vector3::new(0.3, 0.1, -0.2),
        attitude: UnitQuaternion::from_euler_angles(0.4, -0.3, 1.1),
        omega_principal: Vector3::new(0.0, 0.0, w3),
    }
}

#[test]
fn thrust_along_the_spin_axis_accelerates_along_it() {
    let body = AxialRocket { thrust: 3.0 };
    let (w, s0) = (7.0, start(7.0));
    let axis = s0.attitude * Vector3::z();
    let mut flight = FreeFlight::new(FreeSystem(&body), 0.0, &s0, tight()).unwrap();
    for t in [0.25, 1.0, 4.0] {
        flight.advance_to(t).unwrap();
        let s = flight.state().unwrap();
        let a = 3.0 / M;
        assert_relative_eq!(s.velocity, s0.velocity + axis * (a * t), epsilon = 1e-10);
        let x = s0.position + s0.velocity * t + axis * (0.5 * a * t * t);
        assert_relative_eq!(s.position, x, epsilon = 1e-10);
        let r = s0.attitude * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), w * t);
        assert!(s.attitude.angle_to(&r) < 1e-10, "{t}");
        assert_relative_eq!(s.omega_principal, s0.omega_principal, epsilon = 1e-10);
    }
}

#[test]
fn thrust_across_the_spin_axis_turns_with_the_body() {
    let body = SideRocket { thrust: 3.0 };
    let (w, s0) = (5.0, start(5.0));
    let g = Vector3::new(0.0, 0.0, -9.81);
    let mut flight = FreeFlight::new(FreeSystem(&body), 0.0, &s0, tight()).unwrap();
    let k = 3.0 / (M * w);
    for t in [0.3, 1.7, 3.0] {
        flight.advance_to(t).unwrap();
        let s = flight.state().unwrap();
        // F(t) = F R₀ (cos ωt, sin ωt, 0): integrated once and twice in closed form.
        let (sn, cs) = (w * t).sin_cos();
        let dv = s0.attitude * Vector3::new(sn, 1.0 - cs, 0.0) * k;
        let dx = s0.attitude * Vector3::new((1.0 - cs) / w, t - sn / w, 0.0) * k;
        assert_relative_eq!(s.velocity, s0.velocity + g * t + dv, epsilon = 1e-10);
        let x = s0.position + s0.velocity * t + g * (0.5 * t * t) + dx;
        assert_relative_eq!(s.position, x, epsilon = 1e-10);
        let r = s0.attitude * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), w * t);
        assert!(s.attitude.angle_to(&r) < 1e-10, "{t}");
    }
}

#[test]
fn a_body_torque_about_a_principal_axis_spins_it_up_uniformly() {
    let body = Spinner { tau: 0.01 };
    let i3 = body.principal_cm().moments.z;
    // Cuboid: I3 = m (a² + b²)/12.
    assert_relative_eq!(i3, M * (0.01 + 0.04) / 12.0, max_relative = 1e-15);
    let (w0, s0) = (2.0, start(2.0));
    let alpha = 0.01 / i3;
    let mut flight = FreeFlight::new(FreeSystem(&body), 0.0, &s0, tight()).unwrap();
    for t in [0.5, 2.0] {
        flight.advance_to(t).unwrap();
        let s = flight.state().unwrap();
        assert_relative_eq!(s.omega_principal.z, w0 + alpha * t, max_relative = 1e-11);
        let angle = w0 * t + 0.5 * alpha * t * t;
        let r = s0.attitude * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle);
        assert!(s.attitude.angle_to(&r) < 1e-10, "{t}");
        assert_relative_eq!(s.position, s0.position + s0.velocity * t, epsilon = 1e-12);
    }
}
