//! The two declarations of the disk against each other and against the closed form of the
//! rolling disk (`contact::theory::RollingDisk::accelerations`, Newton–Euler in the turning
//! frame), at random standing states; and the one flatness limit, measured.

use precess::contact::{ContactDynamics, ContactError, MIN_TILT, Phase, STATE_LEN, layout};
use precess::mechanism::MechanismError;
use precess::mechanism::rolling::RollingDynamics;
use precess::nalgebra::Vector3;
use precess_testkit::rng::Rng;

use super::scenes::{
    GRAVITY, RADIUS, TableDisk, WheelDisk, space_omega_rate, table_derivative, table_omega_rate,
    table_state, wheel_accelerations,
};
use super::theory::Standing;

/// The scale an angular acceleration is judged on: g/r and |ω|².
fn scale(omega: &Vector3<f64>) -> f64 {
    GRAVITY / RADIUS + omega.norm_squared()
}

/// The table's ω̇ (space axes) at a state.
fn table_rate(s: &Standing) -> Vector3<f64> {
    let (att, w_body) = s.table();
    let y = TableDisk.rolling_state([0.0, 0.0], &att, &w_body).unwrap();
    table_omega_rate(&y, &table_derivative(&TableDisk, &y))
}

/// A random state whose disk stands at least 0.2 rad off the table (leaning either way: the
/// yaw turns the side it leans to).
fn standing(rng: &mut Rng) -> Standing {
    Standing {
        alpha: rng.uniform(0.2, 1.5),
        yaw: rng.uniform(-3.0, 3.0),
        yaw_rate: rng.uniform(-6.0, 6.0),
        lean_rate: rng.uniform(-3.0, 3.0),
        spin: rng.uniform(-20.0, 20.0),
        turn: rng.uniform(-3.0, 3.0),
    }
}

#[test]
fn the_disk_on_a_table_and_the_wheel_have_the_same_accelerations() {
    let mut rng = Rng::new(36);
    let mut worst = [0.0_f64; 4];
    for _ in 0..24 {
        let s = standing(&mut rng);
        let f = s.frame();
        let k = scale(&f.omega);
        let want = s.omega_rate();
        // The wheel: the angles and their rates, the hub's rates from the rolling rows.
        let (q, u) = s.wheel();
        let (rates, accel) = wheel_accelerations(&WheelDisk, &q, &u);
        let wheel = space_omega_rate(&q, &rates, &accel);
        // The table at the wheel's state mapped over (its accelerations check that it rolls).
        let y = table_state(&q, &rates);
        let dy = table_derivative(&TableDisk, &y);
        let table = table_omega_rate(&y, &dy);
        // The same disk placed on the table from the closed form's variables.
        let (att, w_body) = s.table();
        let placed = TableDisk
            .rolling_state([q[0], q[1]], &att, &w_body)
            .unwrap();
        // q and −q are one attitude.
        let quaternion = layout::QUATERNION..layout::QUATERNION + 4;
        let sign = placed[quaternion.clone()]
            .iter()
            .zip(&y[quaternion.clone()])
            .map(|(a, b)| a * b)
            .sum::<f64>()
            .signum();
        for i in 0..STATE_LEN {
            let apart = if quaternion.contains(&i) {
                (placed[i] - sign * y[i]).abs()
            } else if i < layout::QUATERNION {
                (placed[i] - y[i]).abs() / (k.sqrt() * RADIUS)
            } else {
                (placed[i] - y[i]).abs() / k.sqrt()
            };
            worst[3] = worst[3].max(apart);
        }
        worst[0] = worst[0].max((table - wheel).norm() / k);
        worst[1] = worst[1].max((table - want).norm() / k);
        worst[2] = worst[2].max((wheel - want).norm() / k);
        // The centre's horizontal acceleration, against each other.
        for i in 0..2 {
            let da = (dy[layout::VELOCITY + i] - accel[i]).abs() / (k * RADIUS);
            worst[3] = worst[3].max(da);
        }
    }
    println!(
        "table vs wheel {:e}, table vs closed form {:e}, wheel vs closed form {:e}, centre {:e}",
        worst[0], worst[1], worst[2], worst[3]
    );
    assert!(
        worst[0] < 1e-12,
        "the two declarations differ by {:e}",
        worst[0]
    );
    assert!(
        worst[1] < 1e-12,
        "the table is off the closed form by {:e}",
        worst[1]
    );
    assert!(
        worst[2] < 1e-12,
        "the wheel is off the closed form by {:e}",
        worst[2]
    );
    assert!(
        worst[3] < 1e-12,
        "the states or the centres' accelerations differ by {:e}",
        worst[3]
    );
}

/// Where the one limit comes from: the table's ω̇ against the closed form, the disk placed
/// at a tilt α from lying flat exactly (the closed form's variables); the error grows as
/// 1/α, the rim's direction being divided by sin α. At 1.5 MIN_TILT it keeps 1e-10.
#[test]
fn the_flatness_limit_keeps_the_table_accurate_and_both_scenes_refuse_below_it() {
    let mut rng = Rng::new(6);
    let mut at_limit = 0.0_f64;
    for e in 1..=6 {
        let alpha = if e == 6 {
            1.5 * MIN_TILT
        } else {
            10f64.powi(-e)
        };
        let mut worst = [0.0_f64; 2];
        for _ in 0..16 {
            let mut s = standing(&mut rng);
            s.alpha = alpha;
            let k = scale(&s.frame().omega);
            let want = s.omega_rate();
            worst[0] = worst[0].max((table_rate(&s) - want).norm() / k);
            let (q, u) = s.wheel();
            let (rates, accel) = wheel_accelerations(&WheelDisk, &q, &u);
            worst[1] = worst[1].max((space_omega_rate(&q, &rates, &accel) - want).norm() / k);
        }
        println!(
            "tilt {alpha:e}: table {:e}, wheel (zyx chart) {:e}",
            worst[0], worst[1]
        );
        at_limit = worst[0];
    }
    // Measured 5.6e-12 at a tilt of 1e-6.
    assert!(at_limit < 1e-10, "the table at the limit: {at_limit:e}");
    // Below the limit both refuse, by the one constant.
    let mut s = standing(&mut rng);
    s.alpha = 0.5 * MIN_TILT;
    let (att, w_body) = s.table();
    let err = TableDisk.rolling_state([0.0, 0.0], &att, &w_body);
    assert!(
        matches!(err, Err(ContactError::FlatDisk { minimum, .. }) if minimum == MIN_TILT),
        "{err:?}"
    );
    let mut y = TableDisk.rolling_state_unchecked([0.0, 0.0], &att, &w_body);
    y[layout::VELOCITY] = 0.0;
    y[layout::VELOCITY + 1] = 0.0;
    let err = TableDisk.accelerations(Phase::Rolling, 0.0, &y);
    assert!(
        matches!(err, Err(ContactError::FlatDisk { minimum, .. }) if minimum == MIN_TILT),
        "{err:?}"
    );
    let (q, u) = s.wheel();
    let err = WheelDisk.derivative(0.0, &q, &u);
    assert!(
        matches!(err, Err(MechanismError::WheelFlat { tilt, .. }) if tilt <= MIN_TILT),
        "{err:?}"
    );
    assert_eq!(MIN_TILT, precess::mechanism::rolling::MIN_TILT);
    assert_eq!(MIN_TILT, precess::rigid::MIN_TILT);
}
