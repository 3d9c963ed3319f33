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
