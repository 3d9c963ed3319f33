//! The torque-free rigid body and the published GNI values (Hairer, Lubich, Wanner) shared by
//! the integrator and exact-solution tests.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use precess_core::ode::System;

/// Free rigid body in angular momentum: ṁ = m × (I⁻¹ m).
pub struct FreeBody(pub [f64; 3]);

impl System<3> for FreeBody {
    fn rhs(&self, _t: f64, m: &[f64; 3], d: &mut [f64; 3]) {
        let w = [m[0] / self.0[0], m[1] / self.0[1], m[2] / self.0[2]];
        d[0] = m[1] * w[2] - m[2] * w[1];
        d[1] = m[2] * w[0] - m[0] * w[2];
        d[2] = m[0] * w[1] - m[1] * w[0];
    }
}

/// GNI body: I = (2, 1, 2/3), m(0) = (cos 1.1, 0, sin 1.1).
pub const GNI_I: [f64; 3] = [2.0, 1.0, 2.0 / 3.0];
/// m(1) to 30 digits (rounded to f64).
pub const GNI_M1: [f64; 3] = [
    0.369_110_080_850_460_6,
    -0.372_846_321_121_433_4,
    0.851_318_606_069_889_3,
];
/// m(10).
pub const GNI_M10: [f64; 3] = [
    0.407_066_136_588_040_8,
    0.283_007_426_812_843_7,
    0.868_449_167_661_561_7,
];
