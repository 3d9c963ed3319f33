//! A free body's quantities as trajectory columns: the space components of its angular
//! momentum about the origin against x × M v + R I ω formed by hand from the cuboid's
//! moments, conserved along a tumbling run (no force, no torque), and the state's names in
//! the CSV header.

use approx::assert_relative_eq;
use precess::free::{FreeQuantities, FreeState, FreeSystem};
use precess::ode::{AdaptiveConfig, Dop853, Run};
use precess::prelude::*;

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
