//! The Whipple bicycle derived by `#[derive(Mechanism)]` (examples/mechanisms/bicycle.rs)
//! against three independent sources: Table 2 and the weave and capsize speeds of
//! Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463, 2007); the same scene built
//! by hand at run time and interpreted (`RollingModel`); and testkit's `Whipple`, a second
//! formulation written out body by body in the yaw frame.

use std::sync::OnceLock;

use precess::mechanism::rolling::{
    RollingDerivation, RollingDynamics, RollingModel, RollingScene, RollingWheel, WheelSurface,
};
use precess::mechanism::{JointKind, MechanismError, MechanismScene, Parent};
use precess::nalgebra::{Complex, Matrix2, Matrix4};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;
use precess_testkit::bicycle::{
    CAPSIZE_SPEED, Linear, Parameters, STATE, TABLE_2, WEAVE_SPEED, Whipple,
};
use precess_testkit::rng::Rng;

use crate::common::mechanism::examples::bicycle::Bicycle;

const PHI: usize = Bicycle::PHI;
const DELTA: usize = Bicycle::DELTA;

/// [φ̈, δ̈] on the constraint at roll φ, steer δ, their rates, the rear wheel turning at
/// −v / r_R: the pitch put back on the floor first.
fn lateral(bike: &Bicycle, x: [f64; 4], v: f64) -> [f64; 2] {
    let mut q = [0.0; 8];
    q[PHI] = x[0];
    q[DELTA] = x[1];
    bike.close_contacts(&mut q).expect("closes");
    let (_, ud) = bike
        .derivative(0.0, &q, &[x[2], x[3], -v / bike.r_r])
        .expect("derivative");
    [ud[0], ud[1]]
}

/// ∂[φ̈, δ̈]/∂x_j at the upright run: central differences extrapolated twice by Richardson
/// (steps 10⁻², ½·10⁻², ¼·10⁻²) for the angles; for the rates one central difference of
/// step 1, exact since the accelerations are quadratic in the speeds.
fn column(bike: &Bicycle, j: usize, v: f64) -> [f64; 2] {
    let central = |h: f64| {
        let (mut xp, mut xm) = ([0.0; 4], [0.0; 4]);
        xp[j] = h;
        xm[j] = -h;
        let (p, m) = (lateral(bike, xp, v), lateral(bike, xm, v));
        [(p[0] - m[0]) / (2.0 * h), (p[1] - m[1]) / (2.0 * h)]
    };
    if j >= 2 {
        return central(1.0);
    }
    let h = 1e-2;
    let d = [central(h), central(h / 2.0), central(h / 4.0)];
    [0, 1].map(|i| {
        let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
        let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
        (16.0 * r2 - r1) / 15.0
    })
}

/// The lateral state matrix of (φ, δ, φ̇, δ̇) at speed v, from the derived bicycle alone.
fn state_matrix(bike: &Bicycle, v: f64) -> Matrix4<f64> {
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for j in 0..4 {
        let c = column(bike, j, v);
        a[(2, j)] = c[0];
        a[(3, j)] = c[1];
    }
    a
}

fn nearest(eig: &[Complex<f64>], want: Complex<f64>) -> f64 {
    eig.iter()
        .map(|z| (z - want).norm())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn eigenvalues_of_the_derived_bicycle_match_table_2() {
    let bike = Bicycle::benchmark();
    let mut worst = 0.0_f64;
    for (k, &(capsize, re, im, caster)) in TABLE_2.iter().enumerate() {
        let eig = precess::linalg::eigenvalues(&state_matrix(&bike, (k + 1) as f64))
            .expect("eigenvalues");
        for want in [
            Complex::new(capsize, 0.0),
            Complex::new(re, im),
            Complex::new(re, -im),
            Complex::new(caster, 0.0),
        ] {
            worst = worst.max(nearest(&eig, want) / want.norm());
        }
    }
    println!("largest relative eigenvalue error {worst:e}");
    // Measured 2.9e-12 relative (the table prints 14 decimals; its smallest eigenvalue,
    // −0.004 at 6 m/s, carries the Jacobian's absolute error magnified).
    assert!(
        worst < 1e-10,
        "eigenvalues off Table 2 by {worst:e} (relative)"
    );
}

/// The paper's M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0 from the derived bicycle: M is the
/// lateral block of the reduced mass matrix Sᵀ M S at the upright run, and u̇ = M⁻¹ r, so
/// the state matrix's lower half [−M⁻¹ (g K₀ + v² K₂), −v M⁻¹ C₁] is exactly quadratic and
/// linear in v: the speeds 0 and 1 fix K₀, K₂ and C₁.
fn linear() -> &'static Linear {
    static LIN: OnceLock<Linear> = OnceLock::new();
    LIN.get_or_init(|| {
        let bike = Bicycle::benchmark();
        let mut q = [0.0; 8];
        bike.close_contacts(&mut q).expect("closes");
        let (a, _) = bike.constraint_rows(&q, &[0.0; 8]);
        let s = bike
            .partition()
            .rates(&a, &[0.0; 3])
            .expect("projects")
            .projection;
        let (mass, _) = bike.mass_forcing(0.0, &q, &[0.0; 8]);
        let reduced = s.transpose() * mass * s;
        let m = Matrix2::new(
            reduced[(0, 0)],
            reduced[(0, 1)],
            reduced[(1, 0)],
            reduced[(1, 1)],
        );
        let (a0, a1) = (state_matrix(&bike, 0.0), state_matrix(&bike, 1.0));
        let block = |a: &Matrix4<f64>, c: usize| {
            Matrix2::new(a[(2, c)], a[(2, c + 1)], a[(3, c)], a[(3, c + 1)])
        };
        Linear {
            m,
            k0: -(m * block(&a0, 0)) / bike.g,
            k2: -(m * (block(&a1, 0) - block(&a0, 0))),
            c1: -(m * block(&a1, 2)),
            g: bike.g,
        }
    })
}

/// Largest entrywise error, relative where the paper's entry is nonzero, absolute where it
/// prints 0.
fn worst_entry(got: &Matrix2<f64>, want: &Matrix2<f64>) -> f64 {
    got.iter()
        .zip(want.iter())
        .map(|(g, w)| {
            if *w == 0.0 {
                g.abs()
            } else {
                ((g - w) / w).abs()
            }
        })
        .fold(0.0, f64::max)
}

#[test]
fn linearised_matrices_of_the_derived_bicycle_match_the_paper() {
    let (lin, paper) = (linear(), Linear::published());
    let errors = [
        ("M", worst_entry(&lin.m, &paper.m)),
        ("C1", worst_entry(&lin.c1, &paper.c1)),
        ("K0", worst_entry(&lin.k0, &paper.k0)),
        ("K2", worst_entry(&lin.k2, &paper.k2)),
    ];
    println!("{errors:?}");
    // Measured: M 1.4e-14, C1 5.5e-15, K0 1.3e-14, K2 3.0e-15; the paper prints 15 digits.
    for (name, e) in errors {
        assert!(e < 1e-13, "{name} off the paper by {e:e}");
    }
}

#[test]
fn weave_and_capsize_speeds_of_the_derived_bicycle_match_the_paper() {
    let lin = linear();
    // The structure in v holds: at 7.5 m/s it gives the eigenvalues a fresh Jacobian does.
    let direct = precess::linalg::eigenvalues(&state_matrix(&Bicycle::benchmark(), 7.5))
        .expect("eigenvalues");
    for z in lin.eigenvalues(7.5).expect("eigenvalues") {
        assert!(
            nearest(&direct, z) < 1e-10 * z.norm(),
            "{z} not in {direct:?}"
        );
    }
    let weave = lin.weave_speed(4.0, 5.0).expect("weave in [4, 5]");
    let capsize = lin.capsize_speed(5.5, 7.0).expect("capsize in [5.5, 7]");
    let (ew, ec) = (
        ((weave - WEAVE_SPEED) / WEAVE_SPEED).abs(),
        ((capsize - CAPSIZE_SPEED) / CAPSIZE_SPEED).abs(),
    );
    println!("weave {weave:.15} ({ew:e}), capsize {capsize:.15} ({ec:e})");
    // Measured: weave 1.7e-15, capsize 2.9e-16 relative: the paper's fifteen digits.
    assert!(ew < 1e-12 && ec < 1e-12, "weave {ew:e}, capsize {ec:e}");
}

/// The scene of examples/mechanisms/bicycle.rs built by hand, the parameters named as the
/// struct's fields.
fn hand_built(arena: &mut Arena) -> RollingDerivation {
    let a = arena;
    let (o, z) = (a.one(), a.zero());
    let mut p = |n: &str| a.parameter(n);
    let [w, c, lambda, g, r_r, m_r, i_rxx, i_ryy] =
        ["w", "c", "lambda", "g", "r_r", "m_r", "i_rxx", "i_ryy"].map(&mut p);
    let [x_b, z_b, m_b, i_bxx, i_byy, i_bzz, i_bxz] =
        ["x_b", "z_b", "m_b", "i_bxx", "i_byy", "i_bzz", "i_bxz"].map(&mut p);
    let [x_h, z_h, m_h, i_hxx, i_hyy, i_hzz, i_hxz] =
        ["x_h", "z_h", "m_h", "i_hxx", "i_hyy", "i_hzz", "i_hxz"].map(&mut p);
    let [r_f, m_f, i_fxx, i_fyy] = ["r_f", "m_f", "i_fxx", "i_fyy"].map(&mut p);
    let (x_axis, y_axis, z_axis) = ([o, z, z], [z, o, z], [z, z, o]);
    let body = MechanismScene::body;
    let mut s = MechanismScene::new();
    s.bodies.push(body(
        a,
        "rear_x",
        Parent::Ground,
        JointKind::Prismatic { axis: x_axis },
        &["x"],
    ));
    s.bodies.push(body(
        a,
        "rear_y",
        Parent::Body(0),
        JointKind::Prismatic { axis: y_axis },
        &["y"],
    ));
    let axes = [z_axis, x_axis];
    s.bodies.push(body(
        a,
        "lean",
        Parent::Body(1),
        JointKind::Universal { axes },
        &["psi", "phi"],
    ));
    let mut b = body(
        a,
        "rear_frame",
        Parent::Body(2),
        JointKind::Revolute { axis: y_axis },
        &["theta"],
    );
    b.joint.at = [z, z, a.neg(r_r)];
    b.mass = m_b;
    b.center = [x_b, z, a.add(z_b, r_r)];
    b.inertia = [[i_bxx, z, i_bxz], [z, i_byy, z], [i_bxz, z, i_bzz]];
    s.bodies.push(b);
    let mut r = body(
        a,
        "rear_wheel",
        Parent::Body(3),
        JointKind::Revolute { axis: y_axis },
        &["theta_r"],
    );
    r.mass = m_r;
    r.inertia = [[i_rxx, z, z], [z, i_ryy, z], [z, z, i_rxx]];
    s.bodies.push(r);
    let steer = [a.sin(lambda), z, a.cos(lambda)];
    let mut h = body(
        a,
        "front_frame",
        Parent::Body(3),
        JointKind::Revolute { axis: steer },
        &["delta"],
    );
    let wc = a.add(w, c);
    h.joint.at = [wc, z, r_r];
    h.mass = m_h;
    h.center = [a.sub(x_h, wc), z, z_h];
    h.inertia = [[i_hxx, z, i_hxz], [z, i_hyy, z], [i_hxz, z, i_hzz]];
    s.bodies.push(h);
    let mut f = body(
        a,
        "front_wheel",
        Parent::Body(5),
        JointKind::Revolute { axis: y_axis },
        &["theta_f"],
    );
    f.joint.at = [a.neg(c), z, a.neg(r_f)];
    f.mass = m_f;
    f.inertia = [[i_fxx, z, z], [z, i_fyy, z], [z, z, i_fxx]];
    s.bodies.push(f);
    s.gravity = Some([z, z, g]);
    let disk = |radius| WheelSurface::Disk {
        center: [z; 3],
        axle: y_axis,
        radius,
    };
    let rolling = RollingScene {
        up: [z, z, a.integer(-1)],
        wheels: vec![
            RollingWheel {
                body: 4,
                surface: disk(r_r),
            },
            RollingWheel {
                body: 6,
                surface: disk(r_f),
            },
        ],
        speeds: vec!["phi".into(), "delta".into(), "theta_r".into()],
    };
    s.derive_rolling(a, &rolling).expect("derives")
}

fn interpreted(bike: &Bicycle) -> RollingModel<8, 5, 3> {
    let mut arena = Arena::new();
    let d = hand_built(&mut arena);
    let b = bike;
    let values = [
        ("w", b.w),
        ("c", b.c),
        ("lambda", b.lambda),
        ("g", b.g),
        ("r_r", b.r_r),
        ("m_r", b.m_r),
        ("i_rxx", b.i_rxx),
        ("i_ryy", b.i_ryy),
        ("x_b", b.x_b),
        ("z_b", b.z_b),
        ("m_b", b.m_b),
        ("i_bxx", b.i_bxx),
        ("i_byy", b.i_byy),
        ("i_bzz", b.i_bzz),
        ("i_bxz", b.i_bxz),
        ("x_h", b.x_h),
        ("z_h", b.z_h),
        ("m_h", b.m_h),
        ("i_hxx", b.i_hxx),
        ("i_hyy", b.i_hyy),
        ("i_hzz", b.i_hzz),
        ("i_hxz", b.i_hxz),
        ("r_f", b.r_f),
        ("m_f", b.m_f),
        ("i_fxx", b.i_fxx),
        ("i_fyy", b.i_fyy),
    ];
    let names = [
        "x", "y", "psi", "phi", "theta", "theta_r", "delta", "theta_f",
    ];
    RollingModel::new(&mut arena, &d, names, &values).expect("binds")
}

/// A leaning, steered, moving state off the upright run, the wheels on the floor.
fn random_state(bike: &impl RollingDynamics<8, 5, 3>, rng: &mut Rng) -> ([f64; 8], [f64; 3]) {
    let mut q: [f64; 8] = std::array::from_fn(|_| rng.uniform(-0.5, 0.5));
    q[4] = 0.0;
    bike.close_contacts(&mut q).expect("closes");
    let u = [
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
        rng.uniform(-20.0, 20.0),
    ];
    (q, u)
}

fn relative(got: &[f64], want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    got.iter()
        .zip(want)
        .fold(0.0_f64, |m, (g, w)| m.max((g - w).abs() / scale))
}

#[test]
fn the_derived_bicycle_is_the_hand_built_scene_interpreted() {
    let bike = Bicycle {
        // Other values than the benchmark's, so a field read in the wrong place shows.
        m_b: 70.0,
        i_hxz: -0.01,
        r_f: 0.33,
        lambda: 0.3,
        ..Bicycle::benchmark()
    };
    let model = interpreted(&bike);
    let mut rng = Rng::new(2007);
    let mut worst = [0.0_f64; 6];
    for _ in 0..10 {
        let (mut q, u) = random_state(&model, &mut rng);
        let mut q_macro = q;
        q_macro[4] += 1e-3;
        bike.close_contacts(&mut q_macro).expect("closes");
        let (rates, ud) = model.derivative(0.0, &q, &u).expect("derivative");
        let (m0, f0) = model.mass_forcing(0.0, &q, &rates);
        let (m1, f1) = bike.mass_forcing(0.0, &q, &rates);
        let (a0, r0) = model.constraint_rows(&q, &rates);
        let (a1, r1) = bike.constraint_rows(&q, &rates);
        let (rates1, ud1) = bike.derivative(0.0, &q, &u).expect("derivative");
        worst[0] = worst[0].max(relative(m1.as_slice(), m0.as_slice()));
        worst[1] = worst[1].max(relative(f1.as_slice(), f0.as_slice()));
        worst[2] = worst[2].max(relative(a1.as_slice(), a0.as_slice()));
        worst[3] = worst[3].max(relative(r1.as_slice(), r0.as_slice()));
        worst[4] = worst[4].max(relative(&ud1, &ud).max(relative(&rates1, &rates)));
        // Both put the front wheel down at the same pitch, from different starts.
        worst[5] = worst[5].max((q_macro[4] - q[4]).abs());
        let e = (bike.energy(&q, &rates) - model.energy(&q, &rates)) / model.energy(&q, &rates);
        assert!(e.abs() < 1e-14, "energy {e:e}");
        assert_eq!(bike.lowest_tilt(&q).0, model.lowest_tilt(&q).0);
        q[0] = f64::NAN;
        assert!(bike.derivative(0.0, &q, &u).is_err());
    }
    println!("M, f, A, Ȧq̇, (q̇, u̇), pitch: {worst:?}");
    // Measured: M 2e-17, f 3e-18, A 3e-17, Ȧq̇ 0, rates and accelerations 1.2e-15 (the
    // same rounding through two different LU orders), pitch 3.7e-15 rad (Newton from two
    // starts, each stopped at its own 1e-14 m).
    for (what, e) in ["M", "f", "A", "Ȧq̇", "rates and u̇", "pitch"]
        .iter()
        .zip(worst)
    {
        assert!(e < 1e-13, "{what} differs by {e:e}");
    }
}

#[test]
fn the_derived_bicycle_agrees_with_testkits_whipple_off_the_upright_run() {
    let bike = Bicycle::benchmark();
    let whipple = Whipple::new(&Parameters::benchmark()).expect("derives");
    let mut rng = Rng::new(463);
    let mut worst = [0.0_f64; 3];
    for _ in 0..6 {
        let (q, u) = random_state(&bike, &mut rng);
        // Testkit's pitch from its own front contact.
        let mut q_t = [q[0], q[1], q[2], q[3], 0.0, q[6], q[5] + q[4], q[7]];
        whipple.close_front_contact(&mut q_t).expect("closes");
        worst[0] = worst[0].max((q_t[4] - q[4]).abs());
        let (rates, ud) = bike.derivative(0.0, &q, &u).expect("derivative");
        // θ_R = θ_r + θ: the mechanism's rear wheel turns on the pitched frame.
        let mut y = [0.0; STATE];
        y[..8].copy_from_slice(&[q[0], q[1], q[2], q[3], q[4], q[6], q[5] + q[4], q[7]]);
        y[8..].copy_from_slice(&[u[0], u[1], u[2] + rates[4]]);
        let dy = whipple.derivative(&y).expect("derivative");
        let mapped = [
            rates[0],
            rates[1],
            rates[2],
            rates[3],
            rates[4],
            rates[6],
            rates[5] + rates[4],
            rates[7],
        ];
        worst[1] = worst[1].max(relative(&dy[..8], &mapped));
        // θ̈_R = θ̈_r + θ̈, the pitch's acceleration from the full q̈.
        let partition = bike.partition();
        let (a, rate_terms) = bike.constraint_rows(&q, &rates);
        let projected = partition.rates(&a, &u).expect("projects");
        let q_ddot = partition
            .full_accelerations(&a, &rate_terms, &projected, &ud)
            .expect("accelerations");
        let want = [ud[0], ud[1], ud[2] + q_ddot[4]];
        worst[2] = worst[2].max(relative(&dy[8..], &want));
    }
    println!("pitch, rates, accelerations: {worst:?}");
    // Measured: pitch 2.1e-15 rad, rates 3.8e-16, accelerations 6.4e-14 (relative to
    // the largest of each).
    assert!(worst[0] < 1e-13, "pitch differs by {:e}", worst[0]);
    assert!(worst[1] < 1e-13, "rates differ by {:e}", worst[1]);
    assert!(worst[2] < 1e-12, "accelerations differ by {:e}", worst[2]);
}

#[test]
fn a_nonlinear_run_keeps_the_energy_and_the_wheels_rolling() {
    let bike = Bicycle::benchmark();
    let y0 = bike.upright(5.0, 0.5).expect("upright");
    let (q0, u0) = precess::mechanism::rolling::split_rolling::<8, 3, { Bicycle::STATE }>(&y0);
    let e0 = bike.energy(&q0, &bike.rates(&q0, &u0).expect("rates"));
    let system = bike.rolling_system::<{ Bicycle::STATE }>();
    let mut ode =
        Dop853::new(system, 0.0, y0, AdaptiveConfig::with_tol(1e-12, 1e-12)).expect("starts");
    let (mut drift, mut slip, mut height) = (0.0_f64, 0.0_f64, 0.0_f64);
    for k in 1..=500 {
        ode.advance_to(k as f64 * 0.02).expect("steps");
        let (q, u) =
            precess::mechanism::rolling::split_rolling::<8, 3, { Bicycle::STATE }>(ode.y());
        let rates = bike.rates(&q, &u).expect("rates");
        drift = drift.max(((bike.energy(&q, &rates) - e0) / e0).abs());
        slip = slip.max(bike.contact_speed(&q, &rates));
        height = bike.heights(&q).iter().fold(height, |m, h| m.max(h.abs()));
    }
    let lean = ode.y()[PHI];
    println!(
        "10 s at 5 m/s: energy {drift:e}, slip {slip:e} m/s, height {height:e} m, lean {lean:e}"
    );
    // Measured: energy 4.2e-15, slip 4.1e-15 m/s, the front wheel's height 2.4e-16 m
    // (the pitch is integrated, not projected), the lean 1.4e-3 rad after a push that
    // tilted it by about 0.1.
    assert!(drift < 1e-12, "energy drifted by {drift:e}");
    assert!(slip < 1e-12, "contact points slip at {slip:e} m/s");
    assert!(height < 1e-12, "a wheel left the floor by {height:e} m");
    // Inside the self-stable range the weave decays.
    assert!(lean.abs() < 1e-2, "lean {lean:e} at the end");
}

#[test]
fn a_field_value_that_breaks_a_rule_is_refused_naming_it() {
    let (q, u) = ([0.0; 8], [0.0, 0.0, -10.0]);
    let bike = Bicycle {
        r_f: -0.35,
        ..Bicycle::benchmark()
    };
    match bike.derivative(0.0, &q, &u) {
        Err(MechanismError::NonPositiveParameter {
            owner,
            quantity,
            value,
        }) => {
            assert_eq!(owner, "body `front_wheel`");
            assert_eq!(quantity, "rolling radius");
            assert_eq!(value, -0.35);
        }
        other => panic!("expected the front radius refused, got {other:?}"),
    }
    let bike = Bicycle {
        m_b: -85.0,
        ..Bicycle::benchmark()
    };
    let err = bike.derivative(0.0, &q, &u).expect_err("a negative mass");
    assert!(
        matches!(&err, MechanismError::Part { body, .. } if body == "rear_frame"),
        "{err}"
    );
    let bike = Bicycle {
        g: f64::NAN,
        ..Bicycle::benchmark()
    };
    let err = bike.derivative(0.0, &q, &u).expect_err("a NaN gravity");
    assert!(
        matches!(&err, MechanismError::NonFiniteParameter { quantity, .. } if quantity == "gravity[2]"),
        "{err}"
    );
}
