//! `RollingDynamics::acceleration_jacobian` (the engine's derivatives of M, f, A and Ȧq̇
//! carried through Maggi's projection by the product rule) against central differences of
//! the nonlinear free accelerations u̇(q, u), extrapolated twice by Richardson, at random
//! states of a rolling disk and of the Whipple bicycle. The differences are the less
//! accurate side (truncation O(h⁶), rounding ε|u̇|/h).

use precess::mechanism::rolling::RollingDynamics;
use precess::models::Bicycle;
use precess_testkit::rng::Rng;

use crate::rolling_once::scenes::WheelDisk;

/// u̇ at (q, u), every coordinate free (the heights not re-closed: the Jacobian's meaning).
fn free_accelerations<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
) -> [f64; K] {
    model.derivative(0.0, q, u).expect("derivative").1
}

/// ∂u̇/∂y_j, y = (q, u), by central differences at h, h/2, h/4 extrapolated twice.
fn richardson<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
    j: usize,
    h: f64,
) -> [f64; K] {
    let central = |h: f64| {
        let (mut qp, mut qm, mut up, mut um) = (*q, *q, *u, *u);
        if j < N {
            qp[j] += h;
            qm[j] -= h;
        } else {
            up[j - N] += h;
            um[j - N] -= h;
        }
        let (p, m) = (
            free_accelerations(model, &qp, &up),
            free_accelerations(model, &qm, &um),
        );
        std::array::from_fn::<f64, K, _>(|i| (p[i] - m[i]) / (2.0 * h))
    };
    let d = [central(h), central(h / 2.0), central(h / 4.0)];
    std::array::from_fn(|i| {
        let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
        let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
        (16.0 * r2 - r1) / 15.0
    })
}

/// The largest difference between the exact Jacobian and the differenced one, relative to
/// the largest entry of the exact one.
fn worst_gap<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
    h: f64,
) -> f64 {
    let (by_q, by_u) = model.acceleration_jacobian(0.0, q, u).expect("jacobian");
    let scale = by_q
        .iter()
        .chain(by_u.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut worst = 0.0_f64;
    for j in 0..N + K {
        let numeric = richardson(model, q, u, j, h);
        for (i, d) in numeric.iter().enumerate() {
            let exact = if j < N {
                by_q[(i, j)]
            } else {
                by_u[(i, j - N)]
            };
            worst = worst.max((exact - d).abs() / scale);
        }
    }
    worst
}

#[test]
fn a_rolling_disks_exact_jacobian_matches_richardson_differences() {
    // The rolling-once tests' disk (0.5 kg, radius 0.1 m): slides along x, y and z carry
    // the hub, a spherical joint turns it (6 coordinates, 3 rows, 3 free speeds).
    let coin = WheelDisk;
    let mut rng = Rng::new(39);
    let mut worst = 0.0_f64;
    for _ in 0..10 {
        // Any yaw; the roll near π/2 stands the disk up (its axle z turned horizontal), the
        // pitch turns it about the axle, away from the gimbal's lock at ±π/2; the hub put
        // at the rim's height.
        let mut q = [
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            0.1,
            rng.uniform(-3.0, 3.0),
            rng.uniform(-1.0, 1.0),
            std::f64::consts::FRAC_PI_2 + rng.uniform(-0.6, 0.6),
        ];
        coin.close_contacts(&mut q).expect("on the floor");
        let u = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-15.0, 15.0),
        ];
        worst = worst.max(worst_gap(&coin, &q, &u, 1e-3));
    }
    println!("rolling disk: worst relative gap {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
}

#[test]
fn the_bicycles_exact_jacobian_matches_richardson_differences() {
    let bike = Bicycle::benchmark();
    let mut rng = Rng::new(2007);
    let mut worst = 0.0_f64;
    for _ in 0..6 {
        let mut q: [f64; 8] = std::array::from_fn(|_| rng.uniform(-0.5, 0.5));
        q[Bicycle::THETA] = 0.0;
        bike.close_contacts(&mut q).expect("on the floor");
        let u = [
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-20.0, 20.0),
        ];
        worst = worst.max(worst_gap(&bike, &q, &u, 1e-3));
    }
    println!("bicycle: worst relative gap {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// Along `height_tangent` the wheel stays on the floor to second order (its height after a
/// step h is O(h²), against O(h) for the angle moved alone); a dependent coordinate has no
/// tangent of its own.
#[test]
fn the_height_tangent_keeps_the_wheel_on_the_floor_to_second_order() {
    use precess::mechanism::MechanismError;
    let disk = WheelDisk;
    let mut q = [0.2, -0.1, 0.1, 0.7, 0.3, std::f64::consts::FRAC_PI_2 - 0.4];
    disk.close_contacts(&mut q).expect("on the floor");
    let h = 1e-3;
    for free in 3..6 {
        let t = disk.height_tangent(&q, free).expect("a free coordinate");
        let along = |s: f64| {
            let moved: [f64; 6] = std::array::from_fn(|k| q[k] + s * t[k]);
            disk.heights(&moved)[2].abs()
        };
        let mut alone = q;
        alone[free] += h;
        let unfollowed = disk.heights(&alone)[2].abs();
        println!(
            "q[{free}]: height {:.1e} at h, {:.1e} at h/2 along the tangent; {unfollowed:.1e} \
             moved alone",
            along(h),
            along(h / 2.0)
        );
        // Second order: at most h² (the rim's curvature is 1/r = 10/m), and a quarter of it
        // at h/2 wherever the angle moves the wheel at all.
        assert!(along(h) <= h * h, "{:e}", along(h));
        if unfollowed > 0.0 {
            assert!(
                along(h) < 1e-2 * unfollowed,
                "{:e} against {unfollowed:e}",
                along(h)
            );
            let ratio = along(h) / along(h / 2.0);
            assert!((3.5..4.5).contains(&ratio), "ratio {ratio}");
        }
    }
    let dependent = disk.partition().dependent;
    assert!(matches!(
        disk.height_tangent(&q, dependent[0]),
        Err(MechanismError::NotFreeCoordinate { .. })
    ));
    assert!(disk.height_tangent(&q, 6).is_err());
}
