//! A second of rolling along a steady circle, the disk declared both ways: the energy, the
//! contact point's path and the lean against each other and against the closed form
//! (`RollingDisk::steady_circle`: the contact point runs on a circle of radius R at the
//! precession rate Ω, the lean constant).

use precess::contact::{ContactDynamics, ContactSystem, Phase, attitude_of};
use precess::mechanism::rolling::RollingDynamics;
use precess::nalgebra::Vector3;
use precess::ode::{AdaptiveConfig, Dop853};

use super::scenes::{RADIUS, TableDisk, WheelDisk, rotation};
use super::theory::{Standing, disk};

/// The wheel's contact point: the hub less r times the unit vector in the disk's plane
/// pointing up, u = (ẑ − (ẑ·a) a)/|…| for the axis a = R ẑ.
fn wheel_contact(q: &[f64]) -> Vector3<f64> {
    let a = rotation(q[3], q[4], q[5]) * Vector3::z();
    let u = (Vector3::z() - a * a.z).normalize();
    Vector3::new(q[0], q[1], q[2]) - u * RADIUS
}

#[test]
fn a_second_of_steady_rolling_is_the_same_run_both_ways_and_the_closed_forms() {
    let (lean, path) = (0.4_f64, 0.5);
    let circle = disk().steady_circle(lean, path).expect("a steady circle");
    let s = Standing {
        alpha: std::f64::consts::FRAC_PI_2 - lean,
        yaw: 0.0,
        yaw_rate: circle.precession,
        lean_rate: 0.0,
        spin: circle.spin,
        turn: 0.3,
    };
    // Both with the contact point at the origin: the centre at r u.
    let (q0, u0) = s.wheel();
    let (att, w_body) = s.table();
    let y0 = TableDisk
        .rolling_state([q0[0], q0[1]], &att, &w_body)
        .unwrap();
    let mut w0 = [0.0; 9];
    w0[..6].copy_from_slice(&q0);
    w0[6..].copy_from_slice(&u0);
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let table_system = ContactSystem::new(&TableDisk, Phase::Rolling).expect("a physical disk");
    let mut table = Dop853::new(table_system, 0.0, y0, cfg).expect("the table starts");
    let mut wheel = Dop853::new(WheelDisk.rolling_system::<9>(), 0.0, w0, cfg).expect("starts");
    let e0 = TableDisk.energy(Phase::Rolling, &y0);
    // The circle's centre is R along h = ẑ × t from the first contact point, t = x̂.
    let centre = Vector3::new(0.0, path, 0.0);
    let mut worst = [0.0_f64; 5];
    for k in 1..=8 {
        let t = k as f64 * 0.125;
        table.advance_to(t).expect("the table integrates");
        wheel.advance_to(t).expect("the wheel integrates");
        let (y, w) = (*table.y(), *wheel.y());
        let q: [f64; 6] = std::array::from_fn(|i| w[i]);
        let u = [w[6], w[7], w[8]];
        let rates = WheelDisk.rates(&q, &u).expect("rates");
        let (e_table, e_wheel) = (
            TableDisk.energy(Phase::Rolling, &y),
            WheelDisk.energy(&q, &rates),
        );
        worst[0] = worst[0].max(((e_table - e0) / e0).abs());
        worst[1] = worst[1].max(((e_wheel - e_table) / e0).abs());
        let p_table = TableDisk.contact(&y).space;
        let p_wheel = wheel_contact(&q);
        worst[2] = worst[2].max((p_table - p_wheel).norm() / path);
        // The closed form: P(t) = C + R (sin Ωt, −cos Ωt, 0).
        let phase = circle.precession * t;
        let want = centre + Vector3::new(phase.sin(), -phase.cos(), 0.0) * path;
        worst[3] = worst[3].max((p_table - want).norm() / path);
        // The lean stays: the axis's height −sin θ.
        let axis = attitude_of(&y) * Vector3::z();
        worst[4] = worst[4].max((axis.z.abs() - lean.sin()).abs());
    }
    println!(
        "1 s of steady rolling (Ω = {:.4} rad/s): table energy {:e}, wheel − table energy {:e}, \
         contact paths apart {:e}, table path off the circle {:e}, lean {:e}",
        circle.precession, worst[0], worst[1], worst[2], worst[3], worst[4]
    );
    assert!(
        worst[0] < 1e-10,
        "the table's energy drifts by {:e}",
        worst[0]
    );
    assert!(worst[1] < 1e-10, "the energies differ by {:e}", worst[1]);
    assert!(worst[2] < 1e-9, "the contact paths part by {:e}", worst[2]);
    assert!(
        worst[3] < 1e-9,
        "the path leaves the circle by {:e}",
        worst[3]
    );
    assert!(worst[4] < 1e-9, "the lean moves by {:e}", worst[4]);
}
