//! Wheels of a mechanism rolling on the floor (`MechanismScene::derive_rolling`,
//! `RollingModel`), against closed forms: the thin disk as a mechanism (two massless
//! carriers for the contact's x and y, a universal joint for yaw and lean, a revolute for
//! the spin) against the Newton–Euler accelerations and friction of
//! `constraints::disk`; a uniform ball, which needs no friction at all; and the typed errors.

use precess::lagrange::LagrangeError;
use precess::mechanism::rolling::{
    RollingDynamics, RollingModel, RollingScene, RollingWheel, WheelSurface,
};
use precess::mechanism::{JointKind, MechanismError, MechanismScene, Parent};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::rigid::AngleSequence;
use precess::sym::Arena;
use proptest::prelude::*;

use crate::constraints::disk::{G, M, R, newton_friction, textbook};

/// Coordinates x, y (the contact), phi (yaw), theta (lean), psi (spin).
const NAMES: [&str; 5] = ["x", "y", "phi", "theta", "psi"];

/// The x and y carriers every scene here rides on.
fn carriers(a: &mut Arena) -> MechanismScene {
    let (o, z) = (a.one(), a.zero());
    let mut scene = MechanismScene::new();
    let x = JointKind::Prismatic { axis: [o, z, z] };
    let y = JointKind::Prismatic { axis: [z, o, z] };
    scene
        .bodies
        .push(MechanismScene::body(a, "cx", Parent::Ground, x, &["x"]));
    scene
        .bodies
        .push(MechanismScene::body(a, "cy", Parent::Body(0), y, &["y"]));
    scene
}

/// The thin uniform disk (mass m, radius r: moments m r²/4, m r²/2 about its axis y,
/// m r²/4) whose hub is r above the lean frame's origin, the contact.
fn disk_scene(a: &mut Arena, speeds: &[&str]) -> (MechanismScene, RollingScene) {
    let mut scene = carriers(a);
    let (o, z) = (a.one(), a.zero());
    let (m, r, g) = (a.parameter("m"), a.parameter("r"), a.parameter("g"));
    let lean = JointKind::Universal {
        axes: [[z, z, o], [o, z, z]],
    };
    scene.bodies.push(MechanismScene::body(
        a,
        "lean",
        Parent::Body(1),
        lean,
        &["phi", "theta"],
    ));
    let spin = JointKind::Revolute { axis: [z, o, z] };
    let mut wheel = MechanismScene::body(a, "wheel", Parent::Body(2), spin, &["psi"]);
    wheel.joint.at = [z, z, r];
    wheel.mass = m;
    let r2 = a.mul(r, r);
    let mr2 = a.mul(m, r2);
    let quarter = a.number("0.25").expect("a literal");
    let half = a.number("0.5").expect("a literal");
    let (thin, axial) = (a.mul(quarter, mr2), a.mul(half, mr2));
    wheel.inertia = [[thin, z, z], [z, axial, z], [z, z, thin]];
    scene.bodies.push(wheel);
    scene.gravity = Some([z, z, a.neg(g)]);
    let rolling = RollingScene {
        up: [z, z, o],
        wheels: vec![RollingWheel {
            body: 3,
            surface: WheelSurface::Disk {
                center: [z; 3],
                axle: [z, o, z],
                radius: r,
            },
        }],
        speeds: speeds.iter().map(|&s| s.to_owned()).collect(),
    };
    (scene, rolling)
}

fn disk_model() -> RollingModel<5, 2, 3> {
    let mut a = Arena::new();
    let (scene, rolling) = disk_scene(&mut a, &["phi", "theta", "psi"]);
    let d = scene.derive_rolling(&mut a, &rolling).expect("derives");
    // The joints hold the wheel on the floor: no height row, two no-slip rows.
    assert_eq!(d.rows(), 2);
    assert!(d.constraints.positions.iter().all(Option::is_none));
    assert_eq!(d.dependent, [0, 1]);
    RollingModel::new(&mut a, &d, NAMES, &[("m", M), ("r", R), ("g", G)]).expect("binds")
}

fn scale(x: &[f64]) -> f64 {
    x.iter().fold(1.0_f64, |s, v| s.max(v.abs()))
}

fn check_disk(model: &RollingModel<5, 2, 3>, q: [f64; 5], u: [f64; 3]) {
    let (rates, ud) = model.derivative(0.0, &q, &u).expect("regular");
    let want = textbook(q[3], u);
    // The numeric solve of Sᵀ M S loses digits as the disk nears flat (its terms in
    // 1/cos θ grow past their sum), so the tolerance is relative to the terms.
    let tol = 1e-13 * scale(&want).max(G / R) / q[3].cos().abs();
    for i in 0..3 {
        assert!(
            (ud[i] - want[i]).abs() <= tol,
            "u̇[{i}] = {} against {} at q = {q:?}, u = {u:?}",
            ud[i],
            want[i]
        );
    }
    // The contact moves as the spin rolls it: ẋ = r ψ̇ cos φ, ẏ = r ψ̇ sin φ.
    let (sf, cf) = q[2].sin_cos();
    assert!((rates[0] - R * u[2] * cf).abs() <= 1e-14 * R * scale(&u));
    assert!((rates[1] - R * u[2] * sf).abs() <= 1e-14 * R * scale(&u));
    assert!(model.contact_speed(&q, &rates) <= 1e-14 * R * scale(&u) * 8.0);
    let lambda = model.multipliers(0.0, &q, &u).expect("regular");
    let friction = newton_friction([q[2], q[3], q[4]], u, want);
    let tol = 1e-12 * M * R * (scale(&u).powi(2) + scale(&want));
    for i in 0..2 {
        assert!(
            (lambda[i] - friction[i]).abs() <= tol,
            "λ[{i}] = {} against m a_G = {}",
            lambda[i],
            friction[i]
        );
    }
}

#[test]
fn the_disk_as_a_mechanism_matches_newton_euler() {
    let model = disk_model();
    check_disk(&model, [0.2, -0.4, 0.3, 0.4, 1.1], [1.5, -0.7, 6.0]);
    check_disk(&model, [0.0, 0.0, -2.0, -1.2, 0.0], [-3.0, 4.0, -20.0]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any lean short of lying flat, any rates: the three accelerations, the contact's
    /// rates and zero velocity, and the friction.
    #[test]
    fn the_disk_as_a_mechanism_matches_newton_euler_anywhere(
        x in -5.0..5.0_f64, y in -5.0..5.0_f64, phi in -6.3..6.3_f64,
        theta in -1.4..1.4_f64, psi in -6.3..6.3_f64,
        u in prop::array::uniform3(-20.0..20.0_f64),
    ) {
        let model = disk_model();
        check_disk(&model, [x, y, phi, theta, psi], u);
    }
}

#[test]
fn the_disk_keeps_its_energy_and_rolls_along_a_run() {
    let model = disk_model();
    let y0 = [0.0, 0.0, 0.0, 0.3, 0.0, 1.0, 0.2, 8.0];
    let energy = |y: &[f64; 8]| {
        let q = [y[0], y[1], y[2], y[3], y[4]];
        let rates = model.rates(&q, &[y[5], y[6], y[7]]).expect("regular");
        (model.energy(&q, &rates), model.contact_speed(&q, &rates))
    };
    let (e0, _) = energy(&y0);
    let cfg = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let mut ode = Dop853::new(model.rolling_system::<8>(), 0.0, y0, cfg).expect("starts");
    let mut worst = 0.0_f64;
    for k in 1..=40 {
        ode.advance_to(k as f64 * 0.5).expect("integrates");
        let (e, slip) = energy(ode.y());
        worst = worst.max(((e - e0) / e0).abs());
        assert!(slip < 1e-13, "slip {slip:e} at t = {}", ode.t());
    }
    println!("rolling disk mechanism: energy drift {worst:e} over 20 s");
    assert!(worst < 1e-12, "energy drifts by {worst:e}");
}

/// A uniform ball (mass m, radius r, moment 2 m r²/5) on a spherical joint at its centre,
/// r above the carriers: a uniform ball on a level floor rolls with no friction at all, so
/// every multiplier vanishes and the centre's velocity stays constant.
#[test]
fn a_uniform_ball_needs_no_friction() {
    let mut a = Arena::new();
    let mut scene = carriers(&mut a);
    let (o, z) = (a.one(), a.zero());
    let (m, r, g) = (a.parameter("m"), a.parameter("r"), a.parameter("g"));
    let joint = JointKind::Spherical {
        sequence: AngleSequence::Zxz,
    };
    let names = AngleSequence::Zxz.names();
    let mut ball = MechanismScene::body(&mut a, "ball", Parent::Body(1), joint, &names);
    ball.joint.at = [z, z, r];
    ball.mass = m;
    let two_fifths = a.number("0.4").expect("a literal");
    let moment = a.product(&[two_fifths, m, r, r]);
    ball.inertia = [[moment, z, z], [z, moment, z], [z, z, moment]];
    scene.bodies.push(ball);
    scene.gravity = Some([z, z, a.neg(g)]);
    let rolling = RollingScene {
        up: [z, z, o],
        wheels: vec![RollingWheel {
            body: 2,
            surface: WheelSurface::Sphere {
                center: [z; 3],
                radius: r,
            },
        }],
        speeds: names.iter().map(|&s| s.to_owned()).collect(),
    };
    let d = scene.derive_rolling(&mut a, &rolling).expect("derives");
    let coordinate_names = ["x", "y", names[0], names[1], names[2]];
    let model = RollingModel::<5, 2, 3>::new(
        &mut a,
        &d,
        coordinate_names,
        &[("m", 2.0), ("r", 0.1), ("g", 9.81)],
    )
    .expect("binds");
    let (q, u) = ([0.3, -0.2, 0.4, 1.1, -0.5], [2.0, -1.5, 3.0]);
    let lambda = model.multipliers(0.0, &q, &u).expect("regular");
    // Against the size of the inertial terms, m r |ω|².
    let size = 2.0 * 0.1 * 9.0 * 9.0;
    assert!(
        lambda.iter().all(|l| l.abs() < 1e-13 * size),
        "friction on a uniform ball: {lambda:?}"
    );
}

#[test]
fn bad_rolling_scenes_get_typed_errors() {
    let mut a = Arena::new();
    let (scene, mut rolling) = disk_scene(&mut a, &["phi", "theta"]);
    let err = scene.derive_rolling(&mut a, &rolling).unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::SpeedCount {
                got: 2,
                coordinates: 5,
                rows: 2
            }
        ),
        "{err}"
    );
    rolling.speeds = vec!["phi".into(), "phi".into(), "psi".into()];
    let err = scene.derive_rolling(&mut a, &rolling).unwrap_err();
    assert!(
        matches!(&err, MechanismError::UnknownSpeed { speed, repeated: true, .. } if speed == "phi"),
        "{err}"
    );
    rolling.speeds = vec!["phi".into(), "lean".into(), "psi".into()];
    let err = scene.derive_rolling(&mut a, &rolling).unwrap_err();
    assert!(
        matches!(&err, MechanismError::UnknownSpeed { speed, repeated: false, .. } if speed == "lean"),
        "{err}"
    );
    rolling.speeds = vec!["phi".into(), "theta".into(), "psi".into()];
    let (o, z) = (a.one(), a.zero());
    rolling.up = [o, o, z];
    let err = scene.derive_rolling(&mut a, &rolling).unwrap_err();
    assert!(matches!(err, MechanismError::FloorNotAxis), "{err}");
    rolling.up = [z, z, o];
    rolling.wheels[0].body = 7;
    let err = scene.derive_rolling(&mut a, &rolling).unwrap_err();
    assert!(
        matches!(err, MechanismError::UnknownWheelBody { body: 7, count: 4 }),
        "{err}"
    );
    rolling.wheels[0].body = 3;
    let d = scene.derive_rolling(&mut a, &rolling).expect("derives");
    let err = RollingModel::<5, 3, 2>::new(&mut a, &d, ["a"; 5], &[("m", M), ("r", R), ("g", G)])
        .unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::RollingSizes {
                coordinates: 5,
                rows: 2,
                speeds: 3,
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn bad_rolling_states_get_typed_errors() {
    let model = disk_model();
    // Lying flat: the rim's lowest point is undefined.
    let flat = [0.0, 0.0, 0.0, std::f64::consts::FRAC_PI_2, 0.0];
    let err = model.derivative(0.0, &flat, &[0.0; 3]).unwrap_err();
    assert!(
        matches!(err, MechanismError::WheelFlat { wheel: 0, tilt } if tilt.abs() < 1e-15),
        "{err}"
    );
    let err = model
        .derivative(0.0, &[0.0, f64::NAN, 0.0, 0.1, 0.0], &[0.0; 3])
        .unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::NonFinite {
                quantity: "coordinates",
                ..
            }
        ),
        "{err}"
    );
    let err = model
        .rates(&[0.0, 0.0, 0.0, 0.1, 0.0], &[0.0, f64::INFINITY, 0.0])
        .unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::NonFinite {
                quantity: "free speeds",
                ..
            }
        ),
        "{err}"
    );
    let mut model = disk_model();
    let err = model.set("r", f64::NAN).unwrap_err();
    assert!(matches!(err, MechanismError::Binding(_)), "{err}");
    // A massless disk: Sᵀ M S vanishes.
    model.set("m", 0.0).expect("finite");
    let err = model
        .derivative(0.0, &[0.0, 0.0, 0.0, 0.1, 0.0], &[1.0, 0.0, 2.0])
        .unwrap_err();
    assert!(
        matches!(
            err,
            MechanismError::Lagrange(LagrangeError::SingularReducedMass { .. })
        ),
        "{err}"
    );
}

/// A disk whose hub rides a prismatic joint along z, so that its height is a coordinate and
/// the floor a holonomic row: a start off the floor is refused, `close_contacts` puts it
/// down, and the run then starts.
#[test]
fn a_wheel_off_the_floor_is_put_down_before_a_run() {
    let mut a = Arena::new();
    let mut scene = carriers(&mut a);
    let (o, z) = (a.one(), a.zero());
    let (m, r, g) = (a.parameter("m"), a.parameter("r"), a.parameter("g"));
    let lift = JointKind::Prismatic { axis: [z, z, o] };
    scene.bodies.push(MechanismScene::body(
        &mut a,
        "lift",
        Parent::Body(1),
        lift,
        &["h"],
    ));
    let spin = JointKind::Revolute { axis: [z, o, z] };
    let mut wheel = MechanismScene::body(&mut a, "wheel", Parent::Body(2), spin, &["psi"]);
    wheel.mass = m;
    let moment = a.product(&[m, r, r]);
    wheel.inertia = [[moment, z, z], [z, moment, z], [z, z, moment]];
    scene.bodies.push(wheel);
    scene.gravity = Some([z, z, a.neg(g)]);
    let rolling = RollingScene {
        up: [z, z, o],
        wheels: vec![RollingWheel {
            body: 3,
            surface: WheelSurface::Disk {
                center: [z; 3],
                axle: [z, o, z],
                radius: r,
            },
        }],
        speeds: vec!["psi".into()],
    };
    let d = scene.derive_rolling(&mut a, &rolling).expect("derives");
    // x and y roll, h is held: three rows, one of them holonomic.
    assert_eq!(d.rows(), 3);
    let model = RollingModel::<4, 3, 1>::new(
        &mut a,
        &d,
        ["x", "y", "h", "psi"],
        &[("m", 1.0), ("r", 0.5), ("g", 9.81)],
    )
    .expect("binds");
    let mut q = [0.0, 0.0, 0.7, 0.0];
    let err = model.check_start(&q).unwrap_err();
    assert!(
        matches!(err, MechanismError::WheelOffFloor { height, .. } if (height - 0.2).abs() < 1e-15),
        "{err}"
    );
    model.close_contacts(&mut q).expect("closes");
    assert!((q[2] - 0.5).abs() < 1e-15, "hub at {}", q[2]);
    model.check_start(&q).expect("on the floor");
    // Rolling along x at ψ̇ = 2 about +y: the contact r below the hub has the velocity
    // v_hub + ψ̇ ŷ × (−r ẑ) = v_hub − r ψ̇ x̂ = 0, so ẋ = r ψ̇ and the height stays.
    let rates = model.rates(&q, &[2.0]).expect("regular");
    assert!((rates[0] - 1.0).abs() < 1e-15, "ẋ = {}", rates[0]);
    assert!(rates[2].abs() < 1e-15, "ḣ = {}", rates[2]);
}

/// Values made of parameters get the checks literals get: a negative mass or radius is
/// refused when the model is built and on `set`, which then leaves the model as it was.
#[test]
fn negative_masses_and_radii_are_refused() {
    let build = |m: f64, r: f64| {
        let mut a = Arena::new();
        let (scene, rolling) = disk_scene(&mut a, &["phi", "theta", "psi"]);
        RollingModel::<5, 2, 3>::from_scene(
            &mut a,
            &scene,
            &rolling,
            NAMES,
            &[("m", m), ("r", r), ("g", G)],
        )
    };
    let err = build(-1.0, R).unwrap_err();
    assert!(
        matches!(&err, MechanismError::NegativeParameter { owner, quantity, value }
            if owner == "body `wheel`" && quantity == "mass" && *value == -1.0),
        "{err}"
    );
    let err = build(M, -0.2).unwrap_err();
    assert!(
        matches!(&err, MechanismError::NegativeParameter { owner, quantity, .. }
            if owner == "rolling wheel `wheel`" && quantity == "radius"),
        "{err}"
    );
    let mut model = build(M, R).expect("physical");
    let (q, u) = ([0.0, 0.0, 0.3, 0.2, 0.0], [1.0, 0.5, 4.0]);
    let before = model.derivative(0.0, &q, &u).expect("regular");
    let err = model.set("m", -2.0).unwrap_err();
    assert!(
        matches!(err, MechanismError::NegativeParameter { .. }),
        "{err}"
    );
    assert_eq!(model.derivative(0.0, &q, &u).expect("regular"), before);
}

/// A disk released at rest leaning 1.2 rad falls onto its face (with any spin it would
/// turn back short of it). Integrated bare, its right-hand side is refused at the flat
/// state and DOP853 fails with a non-finite state, which names nothing; in the run loop the
/// lowest wheel's tilt is a witness, and the run halts with `WheelFlat` at a configuration
/// the contact can still be placed in.
#[test]
fn a_wheel_falling_flat_halts_the_run_by_name() {
    use precess::mechanism::rolling::{FLAT_WITNESS, RollingHalt, rolling_run};
    use precess::ode::{OdeError, Run, StopReason};
    use std::f64::consts::FRAC_PI_2;
    let model = disk_model();
    let y0 = [0.0, 0.0, 0.0, 1.2, 0.0, 0.0, 0.0, 0.0];
    let cfg = AdaptiveConfig::with_tol(1e-10, 1e-10);
    let mut bare = Dop853::new(model.rolling_system::<8>(), 0.0, y0, cfg).expect("starts");
    let err = bare.advance_to(5.0).unwrap_err();
    assert!(matches!(err, OdeError::NonFiniteState { .. }), "{err}");
    let mut run = rolling_run(&model, 0.0, y0, cfg).expect("starts");
    let out = Run::new(&mut run, 5.0)
        .sample_every(0.01)
        .integrate()
        .expect("halts");
    assert_eq!(out.stop, StopReason::Halted);
    let Some(&RollingHalt::WheelFlat { t, wheel, tilt }) = run.halt() else {
        panic!("{:?}", run.halt());
    };
    assert_eq!(wheel, 0);
    assert!(
        (FLAT_WITNESS..1.001 * FLAT_WITNESS).contains(&tilt),
        "{tilt}"
    );
    assert!(t > 0.0 && t < 5.0 && out.t == t);
    // Every sample on the way down, and the last, is a placed configuration.
    for s in out.trajectory.states().iter().chain([&out.state]) {
        let q: [f64; 5] = s.x[..5].try_into().expect("five coordinates");
        assert!(model.check_configuration(&q).is_ok());
        assert!(s.x[3].abs() < FRAC_PI_2);
    }
}
