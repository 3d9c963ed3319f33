//! Symbol hygiene: a struct field may take any name the engine itself uses (time, the
//! coordinates' rates, the Euler-equation inputs) without changing the physics. Each scene
//! below is the same body twice, once with a plain field name and once with a reserved-looking
//! one; the generated equations must agree exactly.

use precess::prelude::*;

macro_rules! cylinder_top {
    ($name:ident, $len:ident) => {
        /// A cylinder standing on its end, its length a field.
        #[derive(RigidBody)]
        #[rigid(
                    cylinder(mass = mass, radius = 0.02, length = $len, at = [0.0, 0.0, 0.05]),
                    pivot = [0.0, 0.0, 0.0],
                )]
        #[top(gravity = 9.81, damping = 0.001)]
        #[allow(non_snake_case)]
        struct $name {
            mass: f64,
            $len: f64,
        }
    };
}

cylinder_top!(Plain, h);
cylinder_top!(FieldNamedT, t);
cylinder_top!(FieldNamedThetaDot, theta_dot);
cylinder_top!(FieldNamedPsiDdot, psi_ddot);
cylinder_top!(FieldNamedOmega, omega);
cylinder_top!(FieldNamedTorque, torque);
cylinder_top!(FieldNamedOmega1, omega_1);
cylinder_top!(FieldNamedG1, G_1);

fn check<T: RigidBody + precess::prelude::Top>(other: &T, plain: &Plain) {
    assert_eq!(other.mass(), plain.mass());
    assert_eq!(other.inertia(), plain.inertia());
    assert!(other.mass().is_finite() && other.inertia().iter().all(|x| x.is_finite()));
    let (q, qd) = ([0.3, 0.4, -0.2], [0.5, -1.0, 30.0]);
    for t in [0.0, 1.0, 17.0] {
        assert_eq!(
            other.angle_accel(t, &q, &qd),
            plain.angle_accel(0.0, &q, &qd)
        );
    }
    assert_eq!(other.energy(&q, &qd), plain.energy(&q, &qd));
}

#[test]
fn reserved_looking_field_names_change_nothing() {
    let plain = Plain { mass: 0.3, h: 0.1 };
    check(&FieldNamedT { mass: 0.3, t: 0.1 }, &plain);
    check(
        &FieldNamedThetaDot {
            mass: 0.3,
            theta_dot: 0.1,
        },
        &plain,
    );
    check(
        &FieldNamedPsiDdot {
            mass: 0.3,
            psi_ddot: 0.1,
        },
        &plain,
    );
    check(
        &FieldNamedOmega {
            mass: 0.3,
            omega: 0.1,
        },
        &plain,
    );
    check(
        &FieldNamedTorque {
            mass: 0.3,
            torque: 0.1,
        },
        &plain,
    );
    check(
        &FieldNamedOmega1 {
            mass: 0.3,
            omega_1: 0.1,
        },
        &plain,
    );
    check(
        &FieldNamedG1 {
            mass: 0.3,
            G_1: 0.1,
        },
        &plain,
    );
}
