//! The thin rolling disk against the closed form of its accelerations quoted in SymPy issue
//! 27631 (the Lagrange example that gets them wrong): with yaw q₁ about the vertical, lean q₂
//! about the yawed x axis and spin q₃ about the leaned y axis (the disk's axis), radius r,
//!
//! q₁'' = −2 q₂' q₃'/cos q₂,
//! q₂'' = 4 g sin q₂/(5 r) + sin(2 q₂) q₁'²/2 + 6 cos q₂ q₁' q₃'/5,
//! q₃'' = −(10 cos q₂ q₁' − 12 tan q₂ q₃') q₂'/6.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, Phase, STATE_LEN};
use proptest::prelude::*;

use super::reference::{ROLLING, model, thin_disk};

/// The SymPy frame of the disk (axis along y) in the description axes of the contact
/// scene's disk rim (axis along z): description (a, b, c) is R-frame (b, c, a).
fn description_to_sympy() -> Matrix3<f64> {
    Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)
}

/// The model's ω̇ (description axes) against the closed form's q̈ mapped to ω̇.
fn mismatch(q: [f64; 3], qd: [f64; 3]) -> f64 {
    let (g, r) = (9.81, 0.1);
    let m = model(&thin_disk(), ROLLING);
    let [_, q2, q3] = q;
    let [q1d, q2d, q3d] = qd;
    let (s, c) = q2.sin_cos();
    let q1dd = -2.0 * q2d * q3d / c;
    let q2dd =
        4.0 * g * s / (5.0 * r) + (2.0 * q2).sin() * q1d * q1d / 2.0 + 6.0 * c * q1d * q3d / 5.0;
    let q3dd = -(10.0 * c * q1d - 12.0 * q2.tan() * q3d) * q2d / 6.0;
    // ω and its inertial derivative in the lean frame L (the disk frame before the spin).
    let w_l = Vector3::new(q2d, q1d * s + q3d, q1d * c);
    let frame = Vector3::new(q2d, q1d * s, q1d * c);
    let rate = Vector3::new(
        q2dd,
        q1dd * s + q1d * q2d * c + q3dd,
        q1dd * c - q1d * q2d * s,
    );
    let alpha_l = rate + frame.cross(&w_l);
    let spin = Rotation3::from_axis_angle(&Vector3::y_axis(), q3);
    let to_desc = description_to_sympy().transpose();
    let w_desc = to_desc * (spin.inverse() * w_l);
    let alpha_desc = to_desc * (spin.inverse() * alpha_l);
    let attitude = Rotation3::from_axis_angle(&Vector3::z_axis(), q[0])
        * Rotation3::from_axis_angle(&Vector3::x_axis(), q2)
        * spin
        * Rotation3::from_matrix_unchecked(description_to_sympy());
    let y = m
        .rolling_state(
            [0.0, 0.0],
            &UnitQuaternion::from_rotation_matrix(&attitude),
            &w_desc,
        )
        .unwrap();
    let mut d = [0.0; STATE_LEN];
    m.phase_rhs(Phase::Rolling, 0.0, &y, &mut d);
    let got = Vector3::new(d[8], d[9], d[10]);
    (got - alpha_desc).norm() / (alpha_desc.norm() + w_desc.norm_squared() + g / r)
}

#[test]
fn the_rolling_disk_matches_the_closed_form_at_a_state() {
    let e = mismatch([0.3, 0.4, 1.1], [1.5, -0.7, 6.0]);
    println!("rolling disk against SymPy 27631's closed form: relative error {e:e}");
    assert!(e < 1e-13, "{e:e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_rolling_disk_matches_the_closed_form(
        q1 in -3.0f64..3.0, q2 in -1.3f64..1.3, q3 in -3.0f64..3.0,
        qd in prop::array::uniform3(-10.0f64..10.0),
    ) {
        let e = mismatch([q1, q2, q3], qd);
        prop_assert!(e < 1e-12, "{e:e}");
    }
}
