//! Free bodies shared by the `free` tests and `derive::taylor`.

use precess::prelude::*;

/// A T-handle: a bar along x (the handle) on top of a stem along z. Its moments about the
/// centre of mass are all different, the intermediate one about x (the bar), so a throw
/// spinning about the bar flips (the Dzhanibekov effect).
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x, at = [0.0, 0.0, 0.1]),
    cylinder(mass = 0.2, radius = 0.01, length = 0.2, axis = z, at = [0.0, 0.0, 0.0]),
)]
#[free(gravity = 9.81)]
pub struct THandle;

/// The T-handle's moments about its centre of mass, summed by hand from the parts
/// (cylinder: ½ m r² about its axis, m (3r² + L²)/12 across) and the parallel-axis theorem
/// with the centre of mass at z = 0.06.
pub const T_HANDLE_MOMENTS: [f64; 3] = [
    // x: stem across + 0.2·0.06², bar along + 0.3·0.04².
    0.2 * (3e-4 + 0.04) / 12.0 + 0.2 * 0.0036 + 0.5 * 0.3 * 1e-4 + 0.3 * 0.0016,
    // y: both across.
    0.2 * (3e-4 + 0.04) / 12.0 + 0.2 * 0.0036 + 0.3 * (3e-4 + 0.04) / 12.0 + 0.3 * 0.0016,
    // z: stem along, bar across.
    0.5 * 0.2 * 1e-4 + 0.3 * (3e-4 + 0.04) / 12.0,
];

/// The T-handle's throw near its intermediate axis (it flips every few seconds), used by
/// the tests that follow it against the exact flight.
pub fn throw() -> precess::free::FreeState {
    precess::free::FreeState {
        position: Vector3::new(0.0, 0.0, 1.5),
        velocity: Vector3::new(0.5, 0.0, 4.0),
        attitude: UnitQuaternion::from_euler_angles(0.1, -0.2, 0.3),
        omega_principal: Vector3::new(20.0, 0.5, 0.75),
    }
}
