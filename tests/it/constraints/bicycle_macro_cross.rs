//! The Whipple bicycle derived by `#[derive(Mechanism)]` (examples/mechanisms/bicycle.rs)
//! against two independent formulations — the same scene built by hand at run time and
//! interpreted (`RollingModel`), and testkit's `Whipple`, written out body by body in the
//! yaw frame — over a nonlinear run, and with field values that break the rules.

use precess::mechanism::MechanismError;
use precess::mechanism::rolling::{
    RollingDerivation, RollingDynamics, RollingModel, RollingPartials,
};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;
use precess_testkit::bicycle::{Parameters, STATE, Whipple, mechanism_scene};
use precess_testkit::rng::Rng;

use crate::common::mechanism::examples::bicycle::Bicycle;

const PHI: usize = Bicycle::PHI;

/// The scene of examples/mechanisms/bicycle.rs built by hand (testkit's), the parameters
/// named as the struct's fields.
fn hand_built(arena: &mut Arena) -> RollingDerivation {
    let (scene, rolling) = mechanism_scene(arena);
    scene.derive_rolling(arena, &rolling).expect("derives")
}

/// The hand-built scene lowered by `RollingModel` with the values of `bike`'s fields.
pub(super) fn interpreted(bike: &Bicycle) -> RollingModel<8, 5, 3> {
    let mut arena = Arena::new();
    let d = hand_built(&mut arena);
    let names = [
        "x", "y", "psi", "phi", "theta", "theta_r", "delta", "theta_f",
    ];
    RollingModel::new(&mut arena, &d, names, &interpreted_values(bike)).expect("binds")
}

/// `bike`'s fields as the hand-built scene's parameters.
pub(super) fn interpreted_values(b: &Bicycle) -> [(&'static str, f64); 26] {
    [
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
    ]
}

/// A leaning, steered, moving state off the upright run, the wheels on the floor.
pub(super) fn random_state(
    bike: &impl RollingDynamics<8, 5, 3>,
    rng: &mut Rng,
) -> ([f64; 8], [f64; 3]) {
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

/// The interpreted scene's exact `acceleration_jacobian` against the derived bicycle's: both
/// carry the engine's derivatives of M q̈, f, A and Ȧq̇ through the projection, the derive's
/// as straight-line code from the struct's declaration, the interpreted model's lowered at
/// run time from the scene built by hand, so the derivatives agree to rounding, and the
/// Jacobians to the rounding of the two models' solves (the Richardson differences of
/// `rolling_jacobian` are the independent check of both).
#[test]
fn the_interpreted_scenes_exact_rolling_jacobian_is_the_derived_ones() {
    let bike = Bicycle {
        // Other values than the benchmark's, as above.
        m_b: 70.0,
        i_hxz: -0.01,
        r_f: 0.33,
        lambda: 0.3,
        ..Bicycle::benchmark()
    };
    let model = interpreted(&bike);
    let mut rng = Rng::new(39);
    let (mut worst_partials, mut worst) = (0.0_f64, 0.0_f64);
    for _ in 0..6 {
        let (q, u) = random_state(&bike, &mut rng);
        let rates = bike.rates(&q, &u).expect("rates");
        let qddot: [f64; 8] = std::array::from_fn(|_| rng.uniform(-5.0, 5.0));
        let derived = bike.partials(0.0, &q, &rates, &qddot).expect("derived");
        let run_time = model
            .partials(0.0, &q, &rates, &qddot)
            .expect("interpreted");
        let flat = |p: &RollingPartials<8, 5>| -> Vec<f64> {
            let mut v: Vec<f64> = [
                &p.mass_times_accelerations,
                &p.forcing_by_q,
                &p.forcing_by_qdot,
            ]
            .iter()
            .flat_map(|m| m.iter().copied())
            .collect();
            v.extend(p.rows.iter().flat_map(|m| m.iter().copied()));
            v.extend(p.rate_terms_by_q.iter().chain(p.rate_terms_by_qdot.iter()));
            v
        };
        worst_partials = worst_partials.max(relative(&flat(&run_time), &flat(&derived)));
        let (by_q, by_u) = bike.acceleration_jacobian(0.0, &q, &u).expect("derived");
        let (dq, du) = model
            .acceleration_jacobian(0.0, &q, &u)
            .expect("interpreted");
        let derived: Vec<f64> = by_q.iter().chain(by_u.iter()).copied().collect();
        let run_time: Vec<f64> = dq.iter().chain(du.iter()).copied().collect();
        worst = worst.max(relative(&run_time, &derived));
    }
    println!(
        "interpreted against derived: partials {worst_partials:e}, Jacobian {worst:e} \
         (relative to the largest entry)"
    );
    assert!(
        worst_partials < 1e-14,
        "partials differ by {worst_partials:e}"
    );
    assert!(worst < 1e-13, "Jacobians differ by {worst:e}");
}
