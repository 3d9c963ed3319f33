//! A field named like a coordinate of its scene is refused at compile time (see the ui
//! cases `top_field_named_like_a_coordinate` and `mechanism_field_named_like_a_coordinate`);
//! a field named like a coordinate of another sequence is only a name, and harmless.

use approx::assert_relative_eq;
use precess::prelude::*;

/// A top in zyx angles (yaw, pitch, roll) whose fields take the names of the zxz angles.
#[derive(RigidBody)]
#[rigid(cone(mass = phi, radius = theta, height = psi, axis = -z, at = [0, 0, psi]),
        pivot = [0, 0, 0])]
#[top(gravity = 9.81, angles = zyx)]
struct Named {
    phi: f64,
    theta: f64,
    psi: f64,
}

/// The same top with plain field names.
#[derive(RigidBody)]
#[rigid(cone(mass = m, radius = r, height = h, axis = -z, at = [0, 0, h]), pivot = [0, 0, 0])]
#[top(gravity = 9.81, angles = zyx)]
struct Plain {
    m: f64,
    r: f64,
    h: f64,
}

#[test]
fn fields_named_like_another_sequences_angles_are_only_names() {
    let named = Named {
        phi: 0.3,
        theta: 0.04,
        psi: 0.05,
    };
    let plain = Plain {
        m: 0.3,
        r: 0.04,
        h: 0.05,
    };
    for (q, qd) in [
        ([0.1, 0.4, -0.2], [0.3, -0.5, 2.0]),
        ([1.2, -0.3, 0.7], [-1.0, 0.2, 40.0]),
    ] {
        let (a, b) = (
            named.accelerations_unchecked(0.0, &q, &qd),
            plain.accelerations_unchecked(0.0, &q, &qd),
        );
        for k in 0..3 {
            assert_relative_eq!(a[k], b[k], max_relative = 1e-15);
        }
    }
}
