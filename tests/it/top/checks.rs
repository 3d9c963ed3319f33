//! The tops' run-time checks: one rule for when an angle chart is singular (derived and
//! interpreted tops alike), the angle form refusing gimbal lock by name while the charted top
//! goes through it, and typed errors for a bad attitude, ω, stop time, parameter or
//! quaternion.

use crate::common;
use crate::common::tops::ReferenceTop;
use crate::common::tops::reference_model;

use std::f64::consts::{FRAC_PI_2, PI};

use approx::assert_relative_eq;
use common::eulerian::Eulerian;
use nalgebra::{Matrix3, Rotation3, Vector3};
use precess::prelude::*;
use precess_core::codegen::BindingError;
use precess_core::ode::{AdaptiveConfig, Dop853, OdeError};
use precess_core::sym::Arena;
use precess_core::top::{AngleChart, TopModel, TopScene};

/// The same top in ZYX angles.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0, angles = zyx)]
struct HeavyZyx;

/// The textbook inverse of ω = B q̇: ZXZ φ̇ = (ω₁ sψ + ω₂ cψ)/sθ, θ̇ = ω₁ cψ − ω₂ sψ,
/// ψ̇ = ω₃ − φ̇ cθ; ZYX (yaw ψ, pitch θ, roll φ) ψ̇ = (ω₂ sφ + ω₃ cφ)/cθ,
/// θ̇ = ω₂ cφ − ω₃ sφ, φ̇ = ω₁ + ψ̇ sθ.
fn closed_form_rates(seq: AngleSequence, q: [f64; 3], w: Vector3<f64>) -> [f64; 3] {
    match seq {
        AngleSequence::Zxz => {
            let (st, ct) = q[1].sin_cos();
            let (sp, cp) = q[2].sin_cos();
            let phi = (w.x * sp + w.y * cp) / st;
            [phi, w.x * cp - w.y * sp, w.z - phi * ct]
        }
        AngleSequence::Zyx => {
            let (st, ct) = q[1].sin_cos();
            let (sr, cr) = q[2].sin_cos();
            let yaw = (w.y * sr + w.z * cr) / ct;
            [yaw, w.y * cr - w.z * sr, w.x + yaw * st]
        }
    }
}

/// The derived top's and the interpreted model's rates agree on where each chart is singular:
/// at the singular angle, within 1e-12 of it (refused), and 1e-9 and 1e-3 away (solved,
/// matching the textbook inverse).
#[test]
fn one_rule_for_when_a_chart_is_singular() {
    let w = Vector3::new(0.4, -0.7, 3.0);
    let cases = [
        (
            AngleSequence::Zxz,
            vec![0.0, PI, 1e-13, PI - 1e-13],
            vec![1e-9, 1e-3, PI - 1e-9],
        ),
        (
            AngleSequence::Zyx,
            vec![FRAC_PI_2, -FRAC_PI_2, FRAC_PI_2 - 1e-13],
            vec![FRAC_PI_2 - 1e-9, -FRAC_PI_2 + 1e-3],
        ),
    ];
    for (seq, singular, regular) in cases {
        let interpreted = reference_model(seq);
        let derived = |q: &[f64; 3]| match seq {
            AngleSequence::Zxz => ReferenceTop.rates_from_omega(q, &w),
            AngleSequence::Zyx => HeavyZyx.rates_from_omega(q, &w),
        };
        for middle in singular {
            let q = [0.3, middle, 0.7];
            for (path, r) in [
                ("derived", derived(&q)),
                ("interpreted", interpreted.rates_at(&q, &w)),
            ] {
                assert!(
                    matches!(r, Err(TopError::Chart(ChartError::SingularChart { sequence, .. })) if sequence == seq),
                    "{path} {seq:?} at {q:?}: {r:?}"
                );
            }
        }
        for middle in regular {
            let q = [0.3, middle, 0.7];
            let expected = closed_form_rates(seq, q, w);
            for (path, r) in [
                ("derived", derived(&q)),
                ("interpreted", interpreted.rates_at(&q, &w)),
            ] {
                let r = r.unwrap_or_else(|e| panic!("{path} {seq:?} at {q:?}: {e}"));
                for k in 0..3 {
                    assert_relative_eq!(r[k], expected[k], max_relative = 1e-9);
                }
            }
        }
    }
}

/// ZXZ at θ = 0 and ZYX at pitch = π/2: the checked angle form says the chart is singular
/// and points to the charted top, on the derived and the interpreted path alike.
#[test]
fn angle_form_says_the_chart_is_singular_there() {
    let cases = [
        (AngleSequence::Zxz, [0.2, 0.0, 0.1]),
        (AngleSequence::Zxz, [0.2, PI, 0.1]),
        (AngleSequence::Zyx, [0.2, FRAC_PI_2, 0.1]),
    ];
    for (seq, q) in cases {
        let q_dot = [1.0, 0.5, 4.0];
        let state = [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]];
        let derived = match seq {
            AngleSequence::Zxz => ReferenceTop.accelerations(0.0, &q, &q_dot),
            AngleSequence::Zyx => HeavyZyx.accelerations(0.0, &q, &q_dot),
        };
        let interpreted = reference_model(seq).accelerations(&state);
        for (path, r) in [("derived", derived), ("interpreted", interpreted)] {
            let err = r.expect_err(path);
            assert!(
                matches!(err, TopError::Chart(ChartError::SingularChart { sequence, det, .. }) if sequence == seq && det < 1e-12),
                "{path}: {err:?}"
            );
            let message = err.to_string();
            assert!(
                message.contains("singular") && message.contains("ChartedTop"),
                "{message}"
            );
        }
    }
    // A little away from it both paths answer, and agree with the unchecked form.
    let (q, q_dot) = ([0.2, 1e-3, 0.1], [1.0, 0.5, 4.0]);
    let checked = ReferenceTop.accelerations(0.0, &q, &q_dot).unwrap();
    assert_eq!(
        checked,
        ReferenceTop.accelerations_unchecked(0.0, &q, &q_dot)
    );
    let interpreted = reference_model(AngleSequence::Zxz)
        .accelerations(&[q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]])
        .unwrap();
    for k in 0..3 {
        assert_relative_eq!(checked[k], interpreted[k], max_relative = 1e-9);
    }
    assert!(matches!(
        ReferenceTop.accelerations(0.0, &q, &[f64::NAN, 0.0, 0.0]),
        Err(TopError::NonFinite {
            quantity: "rates q̇",
            ..
        })
    ));
}

fn rz(angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Vector3::z_axis(), angle).matrix()
}

/// A sleeping top stands exactly at θ = 0 (ω3 = 6, above the threshold 4): the charted top
/// runs in ZYX and follows the closed form R(t) = Rz(ω3 t), derived and interpreted alike.
#[test]
fn charted_top_runs_a_top_standing_exactly_at_theta_zero() {
    let w0 = Vector3::new(0.0, 0.0, 6.0);
    let [zxz, zyx] = TopChart::both(&ReferenceTop);
    let mut derived = ChartedTop::new(
        [&zxz, &zyx],
        0.0,
        &Matrix3::identity(),
        &w0,
        ChartConfig::default(),
    )
    .unwrap();
    let (mzxz, mzyx) = (
        reference_model(AngleSequence::Zxz),
        reference_model(AngleSequence::Zyx),
    );
    let mut interpreted = ChartedTop::new(
        [&mzxz, &mzyx],
        0.0,
        &Matrix3::identity(),
        &w0,
        ChartConfig::default(),
    )
    .unwrap();
    assert_eq!(derived.sequence(), AngleSequence::Zyx);
    for k in 1..=10 {
        let t = k as f64;
        derived.advance_to(t).unwrap();
        interpreted.advance_to(t).unwrap();
        let truth = rz(6.0 * t);
        assert!((derived.rotation() - truth).abs().max() < 1e-9, "t = {t}");
        assert!(
            (interpreted.rotation() - truth).abs().max() < 1e-9,
            "t = {t}"
        );
    }
}

/// Started exactly at θ = 0 with a transverse ω, the top falls away from the vertical: the
/// charted top matches an independent quaternion integration of the same top.
#[test]
fn charted_top_starts_exactly_at_theta_zero_and_leaves_it() {
    let w0 = Vector3::new(1.5, 0.0, 3.0);
    let [zxz, zyx] = TopChart::both(&ReferenceTop);
    let mut top = ChartedTop::new(
        [&zxz, &zyx],
        0.0,
        &Matrix3::identity(),
        &w0,
        ChartConfig::default(),
    )
    .unwrap();
    let reference = Eulerian {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.5)),
        weight_lever: Vector3::new(0.0, 0.0, 1.0),
    };
    let y0 = Eulerian::state(&Matrix3::identity(), &w0);
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut euler = Dop853::new(&reference, 0.0, y0, tight).unwrap();
    for k in 1..=50 {
        let t = 0.1 * k as f64;
        top.advance_to(t).unwrap();
        euler.advance_to(t).unwrap();
        let gap = (top.rotation() - Eulerian::rotation(euler.y())).abs().max();
        assert!(gap < 1e-7, "t = {t}: attitude off by {gap:e}");
    }
    assert!(top.switches() >= 1, "expected to leave ZYX for ZXZ");
}

fn charted(r: &Matrix3<f64>, w: &Vector3<f64>, config: ChartConfig) -> Result<(), ChartError> {
    let [zxz, zyx] = TopChart::both(&ReferenceTop);
    match ChartedTop::new([&zxz, &zyx], 0.0, r, w, config) {
        Ok(_) => Ok(()),
        Err(TopError::Chart(e)) => Err(e),
        Err(e) => panic!("expected a chart error, got {e:?}"),
    }
}

#[test]
fn charted_top_refuses_an_attitude_that_is_not_a_rotation() {
    let w = Vector3::new(0.0, 0.0, 6.0);
    let mut shear = Matrix3::identity();
    shear[(0, 1)] = 0.3;
    let mut nan = Matrix3::identity();
    nan[(2, 2)] = f64::NAN;
    let nearly = Matrix3::identity() * (1.0 + 1e-7);
    let bad = [
        ("zero", Matrix3::zeros()),
        ("scaled", Matrix3::identity() * 2.0),
        ("shear", shear),
        (
            "reflection",
            Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0)),
        ),
        ("NaN entry", nan),
        ("1e-7 off", nearly),
    ];
    for (name, r) in bad {
        let e = charted(&r, &w, ChartConfig::default());
        assert!(
            matches!(e, Err(ChartError::NotARotation { .. })),
            "{name}: {e:?}"
        );
        let message = e.unwrap_err().to_string();
        assert!(message.contains("not a rotation"), "{message}");
    }
    // Rounding of a product of rotations is accepted.
    let r = rz(0.3) * Rotation3::from_axis_angle(&Vector3::x_axis(), 1e-3).matrix() * rz(-2.0);
    assert_eq!(charted(&r, &w, ChartConfig::default()), Ok(()));
}

#[test]
fn charted_top_names_a_non_finite_omega_and_a_bad_switch() {
    let r = Matrix3::identity();
    for w in [
        Vector3::new(f64::NAN, 0.0, 1.0),
        Vector3::new(0.0, f64::INFINITY, 1.0),
    ] {
        let e = charted(&r, &w, ChartConfig::default());
        assert!(matches!(e, Err(ChartError::NonFiniteOmega { .. })), "{e:?}");
        assert!(e.unwrap_err().to_string().contains("angular velocity"));
    }
    for switch_below in [f64::NAN, 0.0, -0.3, f64::INFINITY] {
        let config = ChartConfig {
            switch_below,
            ..ChartConfig::default()
        };
        let e = charted(&r, &Vector3::new(0.0, 0.0, 6.0), config);
        assert!(
            matches!(e, Err(ChartError::InvalidSwitch { .. })),
            "{switch_below}: {e:?}"
        );
    }
}

/// Stop times as the adaptive driver takes them: NaN and ±∞ are non-finite times, a time
/// in the past is refused, and none of them moves the top.
#[test]
fn charted_top_refuses_non_finite_and_past_stop_times() {
    let [zxz, zyx] = TopChart::both(&ReferenceTop);
    let r0 = Rotation3::from_axis_angle(&Vector3::x_axis(), 0.5);
    let w0 = Vector3::new(0.0, 0.0, 6.0);
    let mut top =
        ChartedTop::new([&zxz, &zyx], 0.0, r0.matrix(), &w0, ChartConfig::default()).unwrap();
    top.advance_to(1.0).unwrap();
    let (t, state, steps) = (top.t(), *top.state(), top.stats().steps);
    for stop in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = top.advance_to(stop).unwrap_err();
        assert!(
            matches!(e, TopError::Ode(OdeError::NonFiniteTime { .. })),
            "{stop}: {e:?}"
        );
    }
    assert_eq!(
        top.advance_to(0.5),
        Err(TopError::Ode(OdeError::StopBeforeCurrent {
            stop: 0.5,
            t: 1.0
        }))
    );
    top.advance_to(1.0).unwrap();
    assert_eq!(
        (top.t(), *top.state(), top.stats().steps),
        (t, state, steps)
    );
}

/// The parametric heavy top, interpreted.
fn parametric(a: &mut Arena) -> precess_core::top::TopDerivation {
    let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
    let z = a.zero();
    let mut scene = TopScene::free(a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    scene.derive(a).unwrap()
}

#[test]
fn top_model_names_the_parameter_that_is_missing_unknown_or_not_finite() {
    let mut a = Arena::new();
    let d = parametric(&mut a);
    let all = [
        ("I_1", 2.0),
        ("I_3", 0.5),
        ("M", 3.0),
        ("g", 9.81),
        ("l", 0.1),
    ];
    match TopModel::new(&mut a, &d, &all[..4]) {
        Err(e @ TopError::Binding(BindingError::UnsetParameter { .. })) => {
            assert_eq!(
                e,
                TopError::Binding(BindingError::UnsetParameter {
                    name: "l".into(),
                    known: "I_1, I_3, M, g, l".into()
                })
            );
            assert!(e.to_string().contains("`l` is not set"), "{e}");
        }
        other => panic!("{other:?}"),
    }
    let unknown = TopModel::new(&mut a, &d, &[("h", 1.0)]);
    assert!(
        matches!(unknown, Err(TopError::Binding(BindingError::UnknownParameter { name, .. })) if name == "h")
    );
    let nan = TopModel::new(&mut a, &d, &[("g", f64::NAN)]);
    assert!(
        matches!(nan, Err(TopError::Binding(BindingError::NonFinite { name, .. })) if name == "g")
    );
    // A parameter given twice is refused, not bound to its last value.
    let twice = [all.as_slice(), &[("g", 5.0)]].concat();
    assert_eq!(
        TopModel::new(&mut a, &d, &twice).unwrap_err(),
        TopError::Binding(BindingError::DuplicateParameter {
            name: "g".into(),
            first: 9.81,
            second: 5.0
        })
    );

    // Complete: released at rest, θ̈ = M g l sin θ / I1.
    let mut m = TopModel::new(&mut a, &d, &all).unwrap();
    assert_eq!(
        m.parameters().collect::<Vec<_>>(),
        ["I_1", "I_3", "M", "g", "l"]
    );
    let state = [0.0, 0.5, 0.0, 0.0, 0.0, 0.0];
    let expected = 3.0 * 9.81 * 0.1 * 0.5f64.sin() / 2.0;
    assert_relative_eq!(
        m.accelerations(&state).unwrap()[1],
        expected,
        max_relative = 1e-14
    );
    m.set("l", 0.2).unwrap();
    assert_relative_eq!(
        m.accelerations(&state).unwrap()[1],
        2.0 * expected,
        max_relative = 1e-14
    );
}

#[test]
fn top_model_refuses_a_user_torque_it_cannot_supply() {
    let mut a = Arena::new();
    let (one, z) = (a.one(), a.zero());
    let mut scene = TopScene::free(&mut a, [[one, z, z], [z, one, z], [z, z, one]]);
    scene.user_torque = Some([a.input("u0"), a.input("u1"), a.input("u2")]);
    let d = scene.derive(&mut a).unwrap();
    let e = TopModel::new(&mut a, &d, &[]);
    assert!(
        matches!(e, Err(TopError::Binding(BindingError::RunTimeInput { .. }))),
        "{e:?}"
    );
}

#[test]
fn eulerian_top_names_a_zero_quaternion() {
    type Form<'a> = EulerianTop<'a, ReferenceTop>;
    let zero = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 6.0];
    let e = Form::check_state(&zero).unwrap_err();
    assert_eq!(
        e,
        TopError::ZeroQuaternion {
            quaternion: [0.0; 4]
        }
    );
    assert!(e.to_string().contains("zero"), "{e}");
    assert!(matches!(
        Form::attitude(&zero),
        Err(TopError::ZeroQuaternion { .. })
    ));
    assert!(matches!(
        Form::check_state(&[f64::NAN, 0.0, 0.0, 1.0, 0.0, 0.0, 6.0]),
        Err(TopError::NonFinite {
            quantity: "attitude quaternion",
            ..
        })
    ));
    assert!(matches!(
        Form::check_state(&[1.0, 0.0, 0.0, 0.0, 0.0, f64::NAN, 6.0]),
        Err(TopError::NonFinite {
            quantity: "body angular velocity ω",
            ..
        })
    ));
    // Any non-zero size names an attitude, down to subnormals.
    let tiny = Form::attitude(&[0.0, 0.0, 0.0, 5e-324, 0.0, 0.0, 0.0]).unwrap();
    let half_turn = Rotation3::from_axis_angle(&Vector3::z_axis(), PI);
    assert_relative_eq!(
        *tiny.to_rotation_matrix().matrix(),
        *half_turn.matrix(),
        epsilon = 1e-15
    );
}
