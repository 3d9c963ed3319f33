//! Item 4(d): a body under every kind of force the attribute declares. The generated wrench,
//! energy and momenta agree with the same quantities written by hand from the declared data,
//! and along a trajectory dE/dt = F'·v + τ·ω, dP/dt = F and dL/dt = x × F + R τ hold in
//! their integrated form.

use approx::assert_relative_eq;
use precess::free::{FreeDynamics, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Dop853, System};
use precess::prelude::*;

/// A box with a point mass off-centre (its principal frame is tilted from the description
/// axes and its centre of mass is off the origin), under everything at once.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.5, size = [0.2, 0.3, 0.4]),
    particle(mass = 0.2, at = [0.1, 0.0, 0.1]),
)]
#[free(
    gravity = [0.5, -0.2, -9.81],
    body_force(force = [0.0, 0.3, 1.0], at = [0.1, 0.05, -0.2]),
    space_force(force = [0.2, 0.0, thrust], at = [-0.1, 0.1, 0.0]),
    body_force(force = [0.4, 0.0, 0.0], at = center),
    body_torque = [0.01, 0.0, -0.02],
    space_torque = [0.0, 0.015, 0.0],
    drag = c,
    damping = 0.002,
    force = wind,
    torque = twist,
)]
struct Everything {
    c: f64,
    thrust: f64,
}

/// A gust in space axes, and a drag of its own on the vertical speed.
fn wind(_: &Everything, t: f64, s: &FreeState) -> Vector3<f64> {
    Vector3::new(0.1 * t.sin(), 0.0, -0.05 * s.velocity.z)
}

/// A torque in description axes that depends on time and on the spin.
fn twist(_: &Everything, t: f64, s: &FreeState) -> Vector3<f64> {
    Vector3::new(0.0, 0.001 * (2.0 * t).cos(), -0.001 * s.omega_principal.x)
}

const BODY: Everything = Everything {
    c: 0.03,
    thrust: -0.1,
};

/// The same wrench written out by hand: (force in space axes, torque in principal axes).
fn by_hand(t: f64, s: &FreeState) -> (Vector3<f64>, Vector3<f64>) {
    let b = &BODY;
    let pr = b.principal_cm();
    let to_p = pr.rotation.inverse();
    let c = b.center_of_mass();
    let r = s.attitude;
    let lever = |p: [f64; 3]| to_p * (Vector3::from(p) - c);
    let m = b.mass();
    let mut f = Vector3::new(0.5, -0.2, -9.81) * m;
    let mut tau = Vector3::zeros();
    let fb = to_p * Vector3::new(0.0, 0.3, 1.0);
    f += r * fb;
    tau += lever([0.1, 0.05, -0.2]).cross(&fb);
    let fs = Vector3::new(0.2, 0.0, b.thrust);
    f += fs;
    tau += lever([-0.1, 0.1, 0.0]).cross(&(r.inverse() * fs));
    f += r * (to_p * Vector3::new(0.4, 0.0, 0.0));
    tau += to_p * Vector3::new(0.01, 0.0, -0.02);
    tau += r.inverse() * Vector3::new(0.0, 0.015, 0.0);
    f -= b.c * s.velocity;
    tau -= 0.002 * s.omega_principal;
    f += wind(b, t, s);
    tau += to_p * twist(b, t, s);
    (f, tau)
}

fn sample(k: u32) -> FreeState {
    let x = f64::from(k);
    FreeState {
        position: Vector3::new(0.3 * x, -1.0 + x, 2.0 - 0.5 * x),
        velocity: Vector3::new(1.0 - x, 0.2 * x, 3.0),
        attitude: UnitQuaternion::from_euler_angles(0.7 * x, 0.3 - 0.2 * x, -1.1 + x),
        omega_principal: Vector3::new(2.0 * x - 1.0, 4.0, -0.3 * x),
    }
}

#[test]
fn the_generated_wrench_energy_and_momenta_match_the_declared_data() {
    let b = &BODY;
    b.check_parameters().unwrap();
    let pr = b.principal_cm();
    assert!(pr.rotation.angle() > 1e-3, "the frame should be tilted");
    let i = pr.moments;
    for k in 0..4 {
        let (t, s) = (0.37 * f64::from(k), sample(k));
        let y = s.to_array();
        let w = b.wrench(t, &y);
        let (f, tau) = by_hand(t, &s);
        assert_relative_eq!(w.force_space, f, max_relative = 1e-13, epsilon = 1e-13);
        assert_relative_eq!(
            w.torque_principal,
            tau,
            max_relative = 1e-12,
            epsilon = 1e-14
        );
        let m = b.mass();
        let g = Vector3::new(0.5, -0.2, -9.81);
        let iw = i.component_mul(&s.omega_principal);
        let e = 0.5 * m * s.velocity.norm_squared() + 0.5 * s.omega_principal.dot(&iw)
            - m * g.dot(&s.position);
        assert_relative_eq!(b.energy(&y), e, max_relative = 1e-14);
        assert_relative_eq!(b.linear_momentum(&y), s.velocity * m, max_relative = 1e-15);
        let l = s.position.cross(&(s.velocity * m)) + s.attitude * iw;
        assert_relative_eq!(b.angular_momentum_origin(&y), l, max_relative = 1e-13);
        let power = (f - g * m).dot(&s.velocity) + tau.dot(&s.omega_principal);
        assert_relative_eq!(b.power(t, &y), power, max_relative = 1e-12);
    }
}

/// The free body with the integrals of the power, the force and the torque about the origin
/// carried along: `[y (13), W, ∫F (3), ∫τ_O (3)]`.
struct WithBalances<'a>(&'a Everything);

impl System<20> for WithBalances<'_> {
    fn rhs(&self, t: f64, z: &[f64; 20], d: &mut [f64; 20]) {
        let mut y = [0.0; 13];
        y.copy_from_slice(&z[..13]);
        let mut dy = [0.0; 13];
        FreeSystem(self.0).rhs(t, &y, &mut dy);
        d[..13].copy_from_slice(&dy);
        let w = self.0.wrench(t, &y);
        let s = FreeState::from_array_unchecked(&y);
        d[13] = self.0.power(t, &y);
        d[14..17].copy_from_slice(w.force_space.as_slice());
        let tau_o = s.position.cross(&w.force_space) + s.attitude * w.torque_principal;
        d[17..20].copy_from_slice(tau_o.as_slice());
    }
}

#[test]
fn energy_and_momenta_balance_along_a_trajectory() {
    let b = &BODY;
    let s0 = FreeState {
        position: Vector3::new(0.0, 0.0, 1.0),
        velocity: Vector3::new(2.0, 1.0, 6.0),
        attitude: UnitQuaternion::from_euler_angles(0.2, 0.4, -0.3),
        omega_principal: Vector3::new(1.0, 9.0, 0.5),
    };
    let y0 = s0.to_array();
    let mut z0 = [0.0; 20];
    z0[..13].copy_from_slice(&y0);
    let mut ode = Dop853::new(
        WithBalances(b),
        0.0,
        z0,
        AdaptiveConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    ode.advance_to(3.0).unwrap();
    let z = *ode.y();
    let mut y = [0.0; 13];
    y.copy_from_slice(&z[..13]);
    let scale = b.energy(&y0).abs().max(b.energy(&y).abs());
    assert_relative_eq!(b.energy(&y) - b.energy(&y0), z[13], epsilon = 1e-10 * scale);
    // Work is done: the balance is not 0 = 0.
    assert!(z[13].abs() > 1e-3 * scale, "W = {}", z[13]);
    let dp = b.linear_momentum(&y) - b.linear_momentum(&y0);
    assert_relative_eq!(dp, Vector3::new(z[14], z[15], z[16]), epsilon = 1e-9);
    let dl = b.angular_momentum_origin(&y) - b.angular_momentum_origin(&y0);
    assert_relative_eq!(dl, Vector3::new(z[17], z[18], z[19]), epsilon = 1e-9);
}
