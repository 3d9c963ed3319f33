//! Symbol hygiene: a struct field may take any name the engine itself uses (time, the
//! angles and their rates, the Euler-equation and Eulerian-form inputs, the user torque,
//! the generated code's locals, the words of the attribute language, and the names free
//! bodies and mechanisms will add) without changing the physics.
//!
//! Each scene is the same top twice, once with the plain field `h` and once with a
//! reserved-looking name: the field sets the mass, the length, the centre of mass, the
//! damping and a body torque, so it reaches every generated method. Everything generated
//! must agree exactly with the plain scene, be finite, and not depend on time.

use precess::prelude::*;

/// The field's value in every scene.
const VALUE: f64 = 0.1;

macro_rules! scenes {
    ($($name:ident: $field:ident),* $(,)?) => {
        $(
            /// A cylinder standing on its end, its size a field.
            #[derive(RigidBody)]
            #[rigid(
                cylinder(mass = 2.0 * $field, radius = 0.02, length = $field, at = [0.0, 0.0, $field / 2.0]),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = 9.81, damping = 0.01 * $field, body_torque = [0.0, 0.0, 0.1 * $field])]
            #[allow(non_snake_case)]
            struct $name {
                $field: f64,
            }
        )*

        /// Every scene against the plain one.
        #[test]
        fn reserved_looking_field_names_change_nothing() {
            let plain = Plain { h: VALUE };
            $( same_physics(stringify!($field), &$name { $field: VALUE }, &plain); )*
        }
    };
}

scenes! {
    Plain: h,
    // Time.
    T: t, Time: time,
    // The ZXZ angles' rates and accelerations (the angles themselves, the coordinates of
    // this top, are refused: its printed equations would show two quantities as one letter;
    // see the ui case `top_field_named_like_a_coordinate`).
    PhiDot: phi_dot, ThetaDot: theta_dot, PsiDot: psi_dot,
    PhiDdot: phi_ddot, ThetaDdot: theta_ddot, PsiDdot: psi_ddot,
    // The ZYX angles, their rates and accelerations.
    Yaw: yaw, Pitch: pitch, Roll: roll,
    YawDot: yaw_dot, PitchDot: pitch_dot, RollDot: roll_dot,
    YawDdot: yaw_ddot, PitchDdot: pitch_ddot, RollDdot: roll_ddot,
    // Euler's equations' inputs.
    Omega: omega, Omega1: omega_1, Omega2: omega_2, Omega3: omega_3,
    Omega0: omega0, OmegaOne: omega1, OmegaTwo: omega2,
    Torque: torque, G1: G_1, G2: G_2, G3: G_3,
    // Generalised coordinates and the user torque.
    Q: q, QDot: q_dot, U: u, U0: u0, U1: u1, U2: u2,
    // The Eulerian form's rotation entries and rates.
    R00: R00, R01: R01, R02: R02, R10: R10, R11: R11, R12: R12, R20: R20, R21: R21, R22: R22,
    W0: w0, W1: w1, W2: w2,
    // The generated code's parameters and locals.
    State: state, Attitude: attitude, Seq: seq,
    Locals: __u, LocalR: __r, LocalQ: __q, LocalW: __w, Slot0: __p0, Slot1: __p1,
    // Words of the attribute language.
    X: x, Y: y, Z: z, Center: center, Pivot: pivot, Diag: diag, Mass: mass,
    Gravity: gravity, Damping: damping,
    // Names free bodies and mechanisms will add.
    Position: position, Velocity: velocity, Quaternion: quaternion, V: v, Force: force,
    Momentum: momentum, AngularMomentum: angular_momentum, Lambda: lambda, Joint: joint,
    // A raw identifier.
    Raw: r#type,
}

fn same_physics<B: RigidBody + precess::prelude::TopDynamics>(
    name: &str,
    other: &B,
    plain: &Plain,
) {
    // The rigid body.
    assert_eq!(other.mass(), plain.mass(), "{name}");
    assert_eq!(other.center_of_mass(), plain.center_of_mass(), "{name}");
    assert_eq!(other.inertia(), plain.inertia(), "{name}");
    assert_eq!(other.inertia_cm(), plain.inertia_cm(), "{name}");
    assert_eq!(
        other.principal().moments,
        plain.principal().moments,
        "{name}"
    );
    assert_eq!(other.description(), plain.description(), "{name}");
    assert!(other.validate().is_ok(), "{name}");
    let finite = |m: &Matrix3<f64>| m.iter().all(|x| x.is_finite());
    assert!(
        other.mass().is_finite() && finite(&other.inertia()),
        "{name}"
    );
    let (w, g) = (
        Vector3::new(0.3, -1.2, 7.0),
        Vector3::new(0.01, 0.02, -0.03),
    );
    assert_eq!(
        other.euler_rhs_principal(&w, &g),
        plain.euler_rhs_principal(&w, &g),
        "{name}"
    );

    // The top, in both charts, at several times against the plain top at t = 0.
    let (q, q_dot) = ([0.3, 0.4, -0.2], [0.5, -1.0, 30.0]);
    let state = [q[0], q[1], q[2], q_dot[0], q_dot[1], q_dot[2]];
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.7, -0.3);
    for seq in [AngleSequence::Zxz, AngleSequence::Zyx] {
        assert_eq!(
            other.rotation_in(seq, &q),
            plain.rotation_in(seq, &q),
            "{name}"
        );
        assert_eq!(
            other.rate_matrix_in(seq, &q),
            plain.rate_matrix_in(seq, &q),
            "{name}"
        );
        assert_eq!(
            other.energy_in(seq, &state),
            plain.energy_in(seq, &state),
            "{name}"
        );
        let accel = plain.accelerations_unchecked_in(seq, 0.0, &state);
        assert!(accel.iter().all(|x| x.is_finite()), "{name}");
        for t in [0.0, 1.0, 17.0] {
            assert_eq!(
                other.accelerations_unchecked_in(seq, t, &state),
                accel,
                "{name} at t = {t}"
            );
        }
    }
    for t in [0.0, 1.0, 17.0] {
        assert_eq!(
            other.angle_jacobian(t, &q, &q_dot),
            plain.angle_jacobian(0.0, &q, &q_dot),
            "{name} at t = {t}"
        );
        assert_eq!(
            other.eulerian_rhs(t, &attitude, &w),
            plain.eulerian_rhs(0.0, &attitude, &w),
            "{name} at t = {t}"
        );
    }
    assert_eq!(
        other.conserved_momenta(&q, &q_dot),
        plain.conserved_momenta(&q, &q_dot),
        "{name}"
    );
}
