//! The integrals of a sphere on a table (Routh's sphere, Chaplygin's ball, Jellett's λ of the
//! tippe top) against the Newton–Euler formulation of `newton_euler`, and the tippe top's
//! inverted state against a simulated inversion.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use precess::contact::theory::{SphereBody, TippeTop};

use precess_testkit::newton_euler::{Body, Rolling, Shape, Sliding, SlidingSphere};

fn quaternion(rot: &Matrix3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*rot))
}

fn newton_euler(b: &SphereBody) -> Body {
    Body {
        mass: b.mass,
        inertia: b.inertia,
        shape: Shape::Sphere {
            centre: b.centre,
            radius: b.radius,
        },
        gravity: b.gravity,
    }
}

/// (E, λ, Q_R, K·ẑ, |K|²) of a rolling state, by the closed forms.
fn integrals(b: &SphereBody, x: &Rolling) -> [f64; 5] {
    let q = quaternion(&x.rot);
    let w = x.rot.transpose() * x.omega;
    let v = b.rolling_velocity(&q, &w);
    let k = b.contact_momentum(&q, &w);
    [
        b.energy(&q, &w, &v),
        b.jellett(&q, &w),
        b.routh(&q, &w),
        k.z,
        k.norm_squared(),
    ]
}

/// Rolls `b` for `steps` RK4 steps of `h` from a tilted spinning state; the largest relative
/// drift of each integral.
fn drifts(b: &SphereBody, omega: Vector3<f64>, steps: usize, h: f64) -> [f64; 5] {
    let ne = newton_euler(b);
    let rot = *Rotation3::from_euler_angles(0.4, -0.2, 0.3).matrix();
    let mut x = Rolling {
        rot,
        omega: rot * omega,
    };
    let start = integrals(b, &x);
    let mut worst = [0.0_f64; 5];
    for _ in 0..steps {
        x = ne.rolling_step(&x, h, &|_| Vector3::zeros());
        let now = integrals(b, &x);
        for k in 0..5 {
            worst[k] = worst[k].max((now[k] - start[k]).abs() / start[k].abs());
        }
    }
    worst
}

/// Routh's sphere (axisymmetric, centre of mass 3 cm off a 10 cm sphere's centre) rolled
/// 5 s: E, Jellett's λ and Routh's Q_R stay to 1e-9 (the RK4 error at h = 5e-4). Routh's
/// integral with I₁ and I₃ swapped in its arm terms drifts by more than 1e-4: the test
/// resolves the difference.
#[test]
fn routh_sphere_keeps_its_three_integrals() {
    let b = SphereBody {
        radius: 0.1,
        centre: Vector3::new(0.0, 0.0, 0.03),
        mass: 1.0,
        inertia: Matrix3::from_diagonal(&Vector3::new(0.004, 0.004, 0.0055)),
        gravity: 9.81,
    };
    let w = Vector3::new(1.0, -0.5, 15.0);
    let d = drifts(&b, w, 10_000, 5e-4);
    assert!(d[0] < 1e-9 && d[1] < 1e-9 && d[2] < 1e-9, "drifts {d:?}");

    // The same run with the moments swapped.
    let ne = newton_euler(&b);
    let rot = *Rotation3::from_euler_angles(0.4, -0.2, 0.3).matrix();
    let mut x = Rolling {
        rot,
        omega: rot * w,
    };
    let partial = |x: &Rolling| {
        let q = quaternion(&x.rot);
        let wb = x.rot.transpose() * x.omega;
        let a = b.contact_arm(&q);
        let k = q * Vector3::z();
        let ak = a.dot(&k);
        let across = a.cross(&k).norm_squared();
        wb.z * (0.004 * 0.0055 + 0.0055 * across + 0.004 * ak * ak).sqrt()
    };
    let start = partial(&x);
    let mut worst = 0.0_f64;
    for _ in 0..10_000 {
        x = ne.rolling_step(&x, 5e-4, &|_| Vector3::zeros());
        worst = worst.max((partial(&x) - start).abs() / start.abs());
    }
    assert!(worst > 1e-4, "the swapped integral drifts only {worst:e}");
}

/// Chaplygin's ball (centre of mass at the centre, three unequal moments) rolled 5 s: E, K·ẑ
/// and |K|² of the momentum about the contact point stay to 1e-9.
#[test]
fn chaplygin_ball_keeps_energy_and_contact_momentum() {
    let b = SphereBody {
        radius: 0.05,
        centre: Vector3::zeros(),
        mass: 0.5,
        inertia: Matrix3::from_diagonal(&Vector3::new(3e-4, 5e-4, 6.5e-4)),
        gravity: 9.81,
    };
    let d = drifts(&b, Vector3::new(4.0, -7.0, 9.0), 10_000, 5e-4);
    assert!(d[0] < 1e-9 && d[3] < 1e-9 && d[4] < 1e-9, "drifts {d:?}");
}

fn tippe_top() -> TippeTop {
    let (m, r) = (0.02, 0.02);
    TippeTop {
        radius: r,
        alpha: 0.3,
        mass: m,
        i1: 0.35 * m * r * r,
        i3: 0.4 * m * r * r,
        gravity: 9.81,
    }
}

/// λ and E of the upright and inverted states in closed form equal λ = −L·a and E evaluated
/// on those states directly; the least spin makes the two energies equal; the inversion
/// condition 1 − α < I₁/I₃ < 1 + α.
#[test]
fn tippe_top_closed_forms_on_states() {
    let t = tippe_top();
    let b = t.body();
    let n = 140.0;
    let up = UnitQuaternion::identity();
    let w_up = Vector3::new(0.0, 0.0, n);
    let lambda = b.jellett(&up, &w_up);
    assert!((lambda - t.upright_jellett(n)).abs() < 1e-15 * lambda);
    let e_up = b.energy(&up, &w_up, &Vector3::zeros());
    assert!((e_up - t.upright_energy(n)).abs() < 1e-15 * e_up);

    let down = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI);
    let spin = t.inverted_spin(lambda);
    assert!((spin - n * 0.7 / 1.3).abs() < 1e-12 * n);
    let w_down = down.inverse() * Vector3::new(0.0, 0.0, spin);
    assert!((b.jellett(&down, &w_down) - lambda).abs() < 1e-14 * lambda);
    let e_down = b.energy(&down, &w_down, &Vector3::zeros());
    assert!((e_down - t.inverted_energy(lambda)).abs() < 1e-14 * e_down);
    assert!(e_down < e_up);

    let nmin = t.min_inversion_spin();
    let gap = t.inverted_energy(t.upright_jellett(nmin)) - t.upright_energy(nmin);
    assert!(gap.abs() < 1e-14 * t.upright_energy(nmin));

    assert!(t.inverts());
    assert!(
        !TippeTop {
            i1: 0.6 * t.i3,
            ..t
        }
        .inverts()
    );
    assert!(
        !TippeTop {
            i1: 1.4 * t.i3,
            ..t
        }
        .inverts()
    );
    assert!(t.jellett_threshold().is_some_and(|l| l > 0.0 && l < lambda));
}

/// A tippe top gliding with viscous friction, simulated by Newton–Euler with its normal force
/// solved: started 0.1 rad off upright at 140 rad/s, it turns over; λ stays to 1e-9 while
/// the energy falls by a third; the final spin and energy are the closed forms' from λ.
#[test]
fn tippe_top_inverts_to_the_state_jellett_predicts() {
    let t = tippe_top();
    let b = t.body();
    let top = SlidingSphere {
        body: Body {
            mass: b.mass,
            inertia: b.inertia,
            shape: Shape::Sphere {
                centre: b.centre,
                radius: b.radius,
            },
            gravity: b.gravity,
        },
        centre: b.centre,
        radius: b.radius,
        friction: 5.0 * t.mass,
    };
    let rot = *Rotation3::from_axis_angle(&Vector3::x_axis(), 0.1).matrix();
    let mut x = Sliding {
        rot,
        omega: rot * Vector3::new(0.0, 0.0, 140.0),
        v: [0.0, 0.0],
    };
    let measure = |x: &Sliding| {
        let q = quaternion(&x.rot);
        let w = x.rot.transpose() * x.omega;
        (b.jellett(&q, &w), b.energy(&q, &w, &top.velocity(x)))
    };
    let (lambda, e0) = measure(&x);
    let mut worst = 0.0_f64;
    let h = 5e-5;
    for _ in 0..(20.0 / h) as usize {
        x = top.step(&x, h);
        worst = worst.max((measure(&x).0 - lambda).abs() / lambda);
    }
    let (_, e1) = measure(&x);
    let axis_z = x.rot.column(2).z;
    assert!(worst < 1e-9, "λ drifts {worst:e}");
    assert!(axis_z < -0.999, "not inverted: k·ẑ = {axis_z}");
    assert!(e1 < 0.7 * e0, "E {e0} → {e1}");
    let spin = x.omega.z;
    let rel_spin = (spin - t.inverted_spin(lambda)).abs() / spin;
    let rel_e = (e1 - t.inverted_energy(lambda)).abs() / e1;
    assert!(
        rel_spin < 1e-3 && rel_e < 1e-3,
        "spin {rel_spin:e}, energy {rel_e:e}"
    );
}
