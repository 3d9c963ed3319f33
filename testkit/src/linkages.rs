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

/// Newton–Euler's pin force (λ_x, λ_y) at the cut of a slider-crank (crank `r` from the
/// origin, rod `l` to the slider on the x axis; uniform rods of masses m₁, m₂, a slider of
/// m₃; gravity g along −y) at (q, q̇, q̈) = ((θ, ψ − θ, x), …): λ_x from the slider's
/// equation, λ_y from the moments of the crank and the rod about the origin.
pub fn slider_crank_pin_force(
    [r, l]: [f64; 2],
    [m1, m2, m3]: [f64; 3],
    g: f64,
    (q, qd, qdd): (&[f64; 3], &[f64; 3], &[f64; 3]),
) -> (f64, f64) {
    let (t1, w1, a1) = (q[0], qd[0], qdd[0]);
    let (psi, wp, ap) = (q[0] + q[1], qd[0] + qd[1], qdd[0] + qdd[1]);
    let r_g = [
        r * t1.cos() + l / 2.0 * psi.cos(),
        r * t1.sin() + l / 2.0 * psi.sin(),
    ];
    let acc_g = [
        r * (-a1 * t1.sin() - w1 * w1 * t1.cos())
            + l / 2.0 * (-ap * psi.sin() - wp * wp * psi.cos()),
        r * (a1 * t1.cos() - w1 * w1 * t1.sin()) + l / 2.0 * (ap * psi.cos() - wp * wp * psi.sin()),
    ];
    let dl = m1 * r * r / 3.0 * a1
        + m2 * (r_g[0] * acc_g[1] - r_g[1] * acc_g[0])
        + m2 * l * l / 12.0 * ap;
    let weights = -m1 * g * r / 2.0 * t1.cos() - m2 * g * r_g[0];
    (-m3 * qdd[2], (dl - weights) / q[2])
}
