//! The free-floating mechanisms' structs, shared by the `free_floating` example and the
//! mechanism tests (each includes this file with `#[path]`), so the tests check the very
//! mechanisms the example derives.
//!
//! Both fly on a `free` joint: the base body's origin slides by (x, y, z) along the ground's
//! axes and turns by yaw, pitch and roll (ZYX), re-charted to ZXZ by `ChartedMechanism`
//! where pitch nears ±90°.

use precess::prelude::*;

/// A satellite: a bus 1.0 × 1.2 × 0.8 m of 100 kg, centred on its frame's origin, with a
/// panel of 10 kg (0.05 × 2.0 × 1.0 m) hinged about the bus's x axis at its edge
/// y = 0.6 m, the panel's centre 1.0 m further along y; a hinge spring of stiffness `k`
/// [N·m/rad], and gravity `g` [m/s²] along −z (zero in orbit, non-zero for a thrown one).
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = [0.0, 0.0, -g])]
#[body(bus, parent = ground, joint = free(sequence = zyx), q = [x, y, z, yaw, pitch, roll],
       parts(cuboid(mass = 100.0, size = [1.0, 1.2, 0.8])))]
#[body(panel, parent = bus, joint = revolute(name = hinge, axis = x, at = [0.0, 0.6, 0.0]),
       q = beta, spring(k = k, rest = 0.0),
       parts(cuboid(mass = 10.0, size = [0.05, 2.0, 1.0], at = [0.0, 1.0, 0.0])))]
pub struct Satellite {
    /// Gravity along −z [m/s²].
    pub g: f64,
    /// The hinge spring's stiffness [N·m/rad].
    pub k: f64,
}

/// The bus's mass [kg].
pub const BUS_MASS: f64 = 100.0;
/// The bus's size [m].
pub const BUS_SIZE: [f64; 3] = [1.0, 1.2, 0.8];
/// The panel's mass [kg].
pub const PANEL_MASS: f64 = 10.0;
/// The panel's size [m].
pub const PANEL_SIZE: [f64; 3] = [0.05, 2.0, 1.0];
/// The hinge's distance from the bus's centre, along the bus's y [m].
pub const HINGE: f64 = 0.6;
/// The panel's centre's distance from the hinge, along the panel's y [m].
pub const PANEL_ARM: f64 = 1.0;

/// A solid cuboid's principal moments about its centre: m (b² + c²)/12, …
pub fn cuboid_moments(m: f64, [a, b, c]: [f64; 3]) -> [f64; 3] {
    [
        m * (b * b + c * c) / 12.0,
        m * (a * a + c * c) / 12.0,
        m * (a * a + b * b) / 12.0,
    ]
}

/// The bus's roll θ as a function of the hinge angle β when the satellite's angular
/// momentum is zero and it moves in the plane normal to x (the panel released at rest from
/// `beta0`). The two bodies joined at the hinge have, about their common centre,
/// L = I₁ θ̇ + I₂ (θ̇ + β̇) + μ r² (θ̇ + α'(β) β̇) = 0, with I₁, I₂ the moments about x, μ the
/// reduced mass, r = a + Rx(β) d the vector between the centres in bus axes
/// (r² = a² + d² + 2 a d cos β) and α'(β) r² = d (d + a cos β) the turning of r with β. So
/// dθ/dβ = −(I₂ + μ d (d + a cos β)) / (I₁ + I₂ + μ r²), a function of β alone, and θ is its
/// integral from `beta0` (Simpson's rule on 2 000 intervals, exact to rounding here).
pub fn roll_at_zero_momentum(beta0: f64, beta: f64) -> f64 {
    let i1 = cuboid_moments(BUS_MASS, BUS_SIZE)[0];
    let i2 = cuboid_moments(PANEL_MASS, PANEL_SIZE)[0];
    let mu = BUS_MASS * PANEL_MASS / (BUS_MASS + PANEL_MASS);
    let (a, d) = (HINGE, PANEL_ARM);
    let f = |b: f64| {
        let r2 = a * a + d * d + 2.0 * a * d * b.cos();
        (i2 + mu * d * (d + a * b.cos())) / (i1 + i2 + mu * r2)
    };
    let n = 2000;
    let h = (beta - beta0) / f64::from(n);
    let mut sum = f(beta0) + f(beta);
    for k in 1..n {
        let w = if k % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(beta0 + h * f64::from(k));
    }
    -sum * h / 3.0
}

/// The thrown satellite's start, shared by the example and its test: the state (the bus 2 m
/// up, thrown at (1.2, −0.5, 6) m/s with the panel 0.4 rad open and opening at 1.5 rad/s),
/// and the bus's attitude and rates (ZYX angles 0.2, 0.4, −0.3; ω in body axes).
pub fn thrown_start() -> ([f64; 14], Matrix3<f64>, Vector3<f64>) {
    let mut y0 = [0.0; 14];
    y0[Satellite::Z] = 2.0;
    y0[Satellite::BETA] = 0.4;
    y0[7 + Satellite::X] = 1.2;
    y0[7 + Satellite::Y] = -0.5;
    y0[7 + Satellite::Z] = 6.0;
    y0[7 + Satellite::BETA] = 1.5;
    let attitude = *Rotation3::from_euler_angles(0.2, 0.4, -0.3).matrix();
    (y0, attitude, Vector3::new(0.7, -0.4, 1.1))
}
