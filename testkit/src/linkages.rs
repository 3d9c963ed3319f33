//! Closed-form position analysis of planar linkages, independent of the derive: what the
//! loop tests compare a closed-loop mechanism's run with.

use std::f64::consts::{PI, TAU};

/// Freudenstein's equation K₁ cos θ₃ − K₂ cos θ₁ + K₃ = cos(θ₁ − θ₃), K₁ = d/a, K₂ = d/c,
/// K₃ = (a² − b² + c² + d²)/(2ac), solved for the rocker θ₃ by the half-angle substitution
/// on the assembly `branch` = ±1; with the coupler's absolute angle from the closing
/// triangle. `[a, b, c, d]` = crank, coupler, rocker, ground; returns (coupler, rocker).
pub fn freudenstein([a, b, c, d]: [f64; 4], theta1: f64, branch: f64) -> (f64, f64) {
    let (k1, k2, k3) = (
        d / a,
        d / c,
        (a * a - b * b + c * c + d * d) / (2.0 * a * c),
    );
    // A cos θ₃ + B sin θ₃ = C with A = K₁ − cos θ₁, B = −sin θ₁, C = K₂ cos θ₁ − K₃.
    let (ca, cb, cc) = (k1 - theta1.cos(), -theta1.sin(), k2 * theta1.cos() - k3);
    let t = (-cb + branch * (ca * ca + cb * cb - cc * cc).sqrt()) / (-cc - ca);
    let theta3 = 2.0 * t.atan();
    let bx = d + c * theta3.cos() - a * theta1.cos();
    let by = c * theta3.sin() - a * theta1.sin();
    (by.atan2(bx), theta3)
}

/// `x − y` wrapped into (−π, π].
pub fn wrap(x: f64, y: f64) -> f64 {
    let d = (x - y).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}
