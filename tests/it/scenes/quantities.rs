//! The scenes' quantities as trajectory columns. A free body's: the space components of its
//! angular momentum about the origin against x × M v + R I ω formed by hand from the
//! cuboid's moments, conserved along a tumbling run (no force, no torque), and the state's
//! names in the CSV header. A mechanism's: a double pendulum's kinetic and potential energy
//! against ½ m |v|² and m g z of its bobs by hand, every generalised momentum against the
//! closed form of M(q) q̇ and against ∂L/∂q̇ of the hand-written L by differences, along a
//! run that keeps the energy, with the CSV header.

use approx::assert_relative_eq;
use precess::free::{FreeQuantities, FreeState, FreeSystem};
use precess::mechanism::{MechanismDynamics, MechanismQuantities};
use precess::ode::{AdaptiveConfig, Dop853, Quantities, Run};
use precess::prelude::*;
use proptest::prelude::*;

use crate::common::mechanism::examples::double_pendulum::DoublePendulum;

/// A 2 kg box of 10 × 20 × 30 cm, force-free.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free]
struct Box3;

#[test]
fn a_tumbling_box_keeps_the_angular_momentum_formed_by_hand() {
    let m = 2.0;
    // I = m (b² + c²)/12 and cyclic, about the centre, on the box's own axes.
    let i = Vector3::new(
        m * (0.04 + 0.09) / 12.0,
        m * (0.01 + 0.09) / 12.0,
        m * (0.01 + 0.04) / 12.0,
    );
    let s0 = FreeState {
        position: Vector3::new(1.0, 0.0, 0.0),
        velocity: Vector3::new(0.0, 0.5, 0.0),
        attitude: UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3),
        // Near the intermediate axis: the box flips over and over.
        omega_principal: Vector3::new(0.01, 5.0, 0.01),
    };
    let l0 =
        s0.position.cross(&(m * s0.velocity)) + s0.attitude * i.component_mul(&s0.omega_principal);
    let e0 = 0.5 * m * s0.velocity.norm_squared()
        + 0.5
            * i.component_mul(&s0.omega_principal)
                .dot(&s0.omega_principal);

    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(FreeSystem(&Box3), 0.0, s0.to_array(), tight).expect("valid box");
    let mut out = Run::new(&mut ode, 10.0)
        .sample_every(0.5)
        .quantities(FreeQuantities::new(&Box3))
        .integrate()
        .expect("a force-free run");
    let trajectory = &mut out.trajectory;
    let column = |name: &str| trajectory.column(name).expect("a named column");
    let (lx, ly, lz, l, e) = (
        column("L_x"),
        column("L_y"),
        column("L_z"),
        column("L"),
        column("energy"),
    );
    assert_eq!(lx.len(), 21);
    for k in 0..lx.len() {
        assert_relative_eq!(lx[k], l0.x, epsilon = 1e-10 * l0.norm());
        assert_relative_eq!(ly[k], l0.y, epsilon = 1e-10 * l0.norm());
        assert_relative_eq!(lz[k], l0.z, epsilon = 1e-10 * l0.norm());
        assert_relative_eq!(l[k], l0.norm(), max_relative = 1e-10);
        assert_relative_eq!(e[k], e0, max_relative = 1e-10);
    }
    // The body flipped: ω₂ changed sign at least once, so L stayed put while ω did not.
    let omega_2: Vec<f64> = trajectory.states().iter().map(|y| y[11]).collect();
    assert!(omega_2.iter().any(|&w| w < 0.0), "{omega_2:?}");

    trajectory
        .set_state_names(FreeQuantities::<Box3>::state_names())
        .expect("13 names for 13 components");
    let csv = trajectory.to_csv();
    assert!(
        csv.starts_with(
            "t,x,y,z,vx,vy,vz,qw,qx,qy,qz,omega_1,omega_2,omega_3,energy,power,p,L,L_x,L_y,L_z\n"
        ),
        "{}",
        &csv[..120]
    );
}

// The double pendulum of `examples/double_pendulum.rs` (relative angles: θ1 of the upper
// rod from the downward vertical, θ2 of the lower rod from the upper one; point masses).
const PENDULUM: DoublePendulum = DoublePendulum {
    m1: 1.3,
    l1: 0.9,
    m2: 0.7,
    l2: 0.6,
};
const G: f64 = 9.81;

/// The bobs' positions and velocities in the (y, z) plane, by hand: a rotation θ about x
/// takes (0, −l) to (l sin θ, −l cos θ).
fn bobs(p: &DoublePendulum, q: [f64; 2], qd: [f64; 2]) -> [([f64; 2], [f64; 2]); 2] {
    let (a, b) = (q[0], q[0] + q[1]);
    let (ad, bd) = (qd[0], qd[0] + qd[1]);
    let r1 = [p.l1 * a.sin(), -p.l1 * a.cos()];
    let v1 = [p.l1 * ad * a.cos(), p.l1 * ad * a.sin()];
    let r2 = [r1[0] + p.l2 * b.sin(), r1[1] - p.l2 * b.cos()];
    let v2 = [v1[0] + p.l2 * bd * b.cos(), v1[1] + p.l2 * bd * b.sin()];
    [(r1, v1), (r2, v2)]
}

/// T and V summed over the bobs by hand: ½ m |v|² and m g z.
fn energies_by_hand(p: &DoublePendulum, q: [f64; 2], qd: [f64; 2]) -> (f64, f64) {
    let [(r1, v1), (r2, v2)] = bobs(p, q, qd);
    let t =
        0.5 * p.m1 * (v1[0].powi(2) + v1[1].powi(2)) + 0.5 * p.m2 * (v2[0].powi(2) + v2[1].powi(2));
    (t, G * (p.m1 * r1[1] + p.m2 * r2[1]))
}

/// ∂L/∂q̇ of the hand-written L = T − V by central differences with one Richardson step
/// (error O(h⁴): L is quadratic in q̇, so this is exact up to rounding, and independent of
/// the derive's T).
fn momenta_by_differences(p: &DoublePendulum, q: [f64; 2], qd: [f64; 2]) -> [f64; 2] {
    let lagrangian = |qd: [f64; 2]| {
        let (t, v) = energies_by_hand(p, q, qd);
        t - v
    };
    std::array::from_fn(|i| {
        let d = |h: f64| {
            let (mut up, mut down) = (qd, qd);
            up[i] += h;
            down[i] -= h;
            (lagrangian(up) - lagrangian(down)) / (2.0 * h)
        };
        let h = 1e-3;
        (4.0 * d(h / 2.0) - d(h)) / 3.0
    })
}

#[test]
fn a_double_pendulums_energies_and_momenta_at_a_state_match_the_hand_values() {
    let (q, qd) = ([0.7, -1.1], [1.9, -0.4]);
    let (t, v) = energies_by_hand(&PENDULUM, q, qd);
    let mut quantities = MechanismQuantities::new(&PENDULUM);
    let names = Quantities::<[f64; 4]>::names(&quantities);
    assert_eq!(
        names,
        [
            "energy",
            "kinetic",
            "potential",
            "power",
            "p_theta1",
            "p_theta2"
        ]
    );
    let mut out = [0.0; 6];
    quantities.evaluate(0.0, &[q[0], q[1], qd[0], qd[1]], &mut out);
    assert_relative_eq!(out[0], t + v, max_relative = 1e-14);
    assert_relative_eq!(out[1], t, max_relative = 1e-14);
    assert_relative_eq!(out[2], v, max_relative = 1e-14);
    assert_eq!(out[3], 0.0, "no load beyond gravity and the hinges");
    // The closed form of M(q) q̇ for relative angles.
    let DoublePendulum { m1, l1, m2, l2 } = PENDULUM;
    let c = q[1].cos();
    let p1 = (m1 + m2) * l1 * l1 * qd[0]
        + m2 * (l2 * l2 * (qd[0] + qd[1]) + l1 * l2 * c * (2.0 * qd[0] + qd[1]));
    let p2 = m2 * (l2 * l2 * (qd[0] + qd[1]) + l1 * l2 * c * qd[0]);
    let fd = momenta_by_differences(&PENDULUM, q, qd);
    for (k, p) in [p1, p2].into_iter().enumerate() {
        assert_relative_eq!(out[4 + k], p, max_relative = 1e-14);
        assert_relative_eq!(fd[k], p, max_relative = 1e-9);
    }
}

proptest! {
    /// At any state, every momentum the derived mechanism reports is ∂L/∂q̇ of the
    /// hand-written Lagrangian, and T, V are the hand values.
    #[test]
    fn a_double_pendulums_momenta_are_the_lagrangians_rate_derivatives(
        q in proptest::array::uniform2(-4.0..4.0f64),
        qd in proptest::array::uniform2(-20.0..20.0f64),
    ) {
        let p = PENDULUM.momenta(&q, &qd);
        let fd = momenta_by_differences(&PENDULUM, q, qd);
        let scale = 1.0 + qd[0].abs() + qd[1].abs();
        for k in 0..2 {
            prop_assert!((p[k] - fd[k]).abs() <= 1e-8 * scale, "{p:?} against {fd:?}");
        }
        let (t, v) = energies_by_hand(&PENDULUM, q, qd);
        prop_assert!((PENDULUM.kinetic(&q, &qd) - t).abs() <= 1e-12 * (1.0 + t));
        prop_assert!((PENDULUM.potential(&q) - v).abs() <= 1e-12 * (1.0 + v.abs()));
    }
}

#[test]
fn a_double_pendulum_run_keeps_its_energy_and_its_columns_read_the_hand_values() {
    let y0 = [2.0, -0.5, 0.0, 3.0];
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(&PENDULUM, 0.0, y0, tight).expect("a valid pendulum");
    let mut out = Run::new(&mut ode, 10.0)
        .sample_every(0.25)
        .quantities(MechanismQuantities::new(&PENDULUM))
        .integrate()
        .expect("a conservative run");
    let trajectory = &mut out.trajectory;
    let (t0, v0) = energies_by_hand(&PENDULUM, [y0[0], y0[1]], [y0[2], y0[3]]);
    let e0 = t0 + v0;
    assert_eq!(trajectory.states().len(), 41);
    let mut swapped = 0.0_f64;
    for (k, y) in trajectory.states().iter().enumerate() {
        let row = trajectory.quantities(k).expect("a row per sample");
        let (q, qd) = ([y[0], y[1]], [y[2], y[3]]);
        let (t, v) = energies_by_hand(&PENDULUM, q, qd);
        assert_relative_eq!(row[0], e0, epsilon = 1e-9 * e0.abs());
        assert_relative_eq!(row[1], t, epsilon = 1e-12 * e0.abs());
        assert_relative_eq!(row[2], v, epsilon = 1e-12 * e0.abs());
        let fd = momenta_by_differences(&PENDULUM, q, qd);
        assert_relative_eq!(row[4], fd[0], epsilon = 1e-8);
        assert_relative_eq!(row[5], fd[1], epsilon = 1e-8);
        // Energy moves between T and V along the run; the columns are not the total split
        // by a fixed ratio.
        swapped = swapped.max((t - t0).abs());
    }
    assert!(swapped > 1.0, "T varied by {swapped} only");
    trajectory
        .set_state_names(MechanismQuantities::<DoublePendulum, 2>::state_names())
        .expect("4 names for 4 components");
    let csv = trajectory.to_csv();
    let header =
        "t,theta1,theta2,theta1_dot,theta2_dot,energy,kinetic,potential,power,p_theta1,p_theta2\n";
    assert!(csv.starts_with(header), "{}", &csv[..120]);
}
