//! The same thin rolling disk declared twice — as a body on a table (`#[contact(surface =
//! disk_rim(..), law = rolling)]`) and as a wheel of a mechanism (`rolls = disk_rim(..)` on a
//! body hung from three slides by a spherical joint) — and the maps between their states,
//! written by hand from the two declarations' conventions (not from either scene's code).
//!
//! The disk's axis is description z in both. The mechanism's spherical joint turns the disk
//! by R = Rz(ψ) Ry(θ) Rx(φ) (sequence zyx): its one singular attitude has body x vertical,
//! a disk standing on its rim at a point of the x axis, so the disk lying flat (body z
//! vertical) is a regular point of the chart and the flatness limit can be measured there.

use precess::contact::{ContactDynamics, STATE_LEN, attitude_of, layout};
use precess::mechanism::rolling::RollingDynamics;
use precess::nalgebra::{Matrix3, Rotation3, Vector3};
use precess::prelude::*;

/// The disk's radius r (m).
pub const RADIUS: f64 = 0.1;
/// Its mass m (kg).
pub const MASS: f64 = 0.5;
/// Gravity g (m/s²).
pub const GRAVITY: f64 = 9.81;

/// The disk on a table.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.5, radius = 0.1))]
#[contact(surface = disk_rim(radius = 0.1), law = rolling, gravity = 9.81)]
pub struct TableDisk;

/// The disk as a mechanism's wheel: slides along x, y and z carry the hub, a spherical joint
/// turns the disk, whose rim rolls on the floor z = 0.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [yaw, pitch, roll])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y,
       parts(particle(mass = 0.0)))]
#[body(slide_z, parent = slide_y, joint = prismatic(axis = z), q = z,
       parts(particle(mass = 0.0)))]
#[body(disk, parent = slide_z, joint = spherical(sequence = zyx), q = [yaw, pitch, roll],
       parts(disk(mass = 0.5, radius = 0.1)), rolls = disk_rim(radius = 0.1, axle = z))]
pub struct WheelDisk;

/// The mechanism's coordinates (x, y, z of the hub, then ψ, θ, φ).
pub type Q = [f64; 6];
/// Its free speeds (ψ̇, θ̇, φ̇).
pub type U = [f64; 3];

/// R = Rz(ψ) Ry(θ) Rx(φ).
pub fn rotation(yaw: f64, pitch: f64, roll: f64) -> Matrix3<f64> {
    let r = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), pitch)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), roll);
    *r.matrix()
}

/// The joint's axes in space: ẑ, Rz ŷ and Rz Ry x̂, so ω = ψ̇ ẑ + θ̇ e₂ + φ̇ e₃ (space axes).
pub fn joint_axes(yaw: f64, pitch: f64) -> [Vector3<f64>; 3] {
    let rz = Rotation3::from_axis_angle(&Vector3::z_axis(), yaw);
    let ry = Rotation3::from_axis_angle(&Vector3::y_axis(), pitch);
    [Vector3::z(), rz * Vector3::y(), rz * (ry * Vector3::x())]
}

/// The angles (ψ, θ, φ) of an attitude: θ = −asin R₃₁, ψ = atan2(R₂₁, R₁₁),
/// φ = atan2(R₃₂, R₃₃) (|θ| < π/2).
pub fn angles(r: &Matrix3<f64>) -> [f64; 3] {
    [
        r[(1, 0)].atan2(r[(0, 0)]),
        (-r[(2, 0)]).clamp(-1.0, 1.0).asin(),
        r[(2, 1)].atan2(r[(2, 2)]),
    ]
}

/// The angles' rates of a space angular velocity ω: the 3×3 solve of ω = Σ q̇ₖ eₖ.
pub fn angle_rates(q: &[f64; 3], omega: &Vector3<f64>) -> [f64; 3] {
    let [e1, e2, e3] = joint_axes(q[0], q[1]);
    let j = Matrix3::from_columns(&[e1, e2, e3]);
    let rates = j
        .lu()
        .solve(omega)
        .expect("the zyx chart is regular away from θ = ±π/2");
    [rates.x, rates.y, rates.z]
}

/// The table's state of the wheel's disk at (q, q̇): its centre of mass (the hub) and its
/// velocity, the attitude and ω in body axes.
pub fn table_state(q: &Q, rates: &Q) -> [f64; STATE_LEN] {
    let r = rotation(q[3], q[4], q[5]);
    let omega = space_omega(q, rates);
    let attitude = precess_testkit::rotations::quaternion_of(&r);
    let mut y = [0.0; STATE_LEN];
    y[layout::POSITION] = q[0];
    y[layout::POSITION + 1] = q[1];
    y[layout::VELOCITY] = rates[0];
    y[layout::VELOCITY + 1] = rates[1];
    let qq = attitude.quaternion();
    y[layout::QUATERNION..layout::QUATERNION + 4].copy_from_slice(&[qq.w, qq.i, qq.j, qq.k]);
    let body = r.transpose() * omega;
    y[layout::OMEGA..layout::OMEGA + 3].copy_from_slice(body.as_slice());
    y
}

/// ω in space axes from the mechanism's rates.
pub fn space_omega(q: &Q, rates: &Q) -> Vector3<f64> {
    let [e1, e2, e3] = joint_axes(q[3], q[4]);
    e1 * rates[3] + e2 * rates[4] + e3 * rates[5]
}

/// ω̇ in space axes from the mechanism's rates and accelerations: the derivative of
/// ψ̇ ẑ + θ̇ e₂ + φ̇ e₃ with ė₂ = ψ̇ ẑ × e₂ and ė₃ = (ψ̇ ẑ + θ̇ e₂) × e₃.
pub fn space_omega_rate(q: &Q, rates: &Q, accel: &Q) -> Vector3<f64> {
    let [e1, e2, e3] = joint_axes(q[3], q[4]);
    let carrier = e1 * rates[3] + e2 * rates[4];
    e1 * accel[3]
        + e2 * accel[4]
        + e1.cross(&e2) * (rates[3] * rates[4])
        + e3 * accel[5]
        + carrier.cross(&e3) * rates[5]
}

/// ω̇ in space axes from the table's state derivative (ω̇ in body axes: Rω̇_b, the body's
/// turning adds ω × ω = 0).
pub fn table_omega_rate(y: &[f64; STATE_LEN], dy: &[f64; STATE_LEN]) -> Vector3<f64> {
    let at = layout::OMEGA;
    attitude_of(y) * Vector3::new(dy[at], dy[at + 1], dy[at + 2])
}

/// The mechanism's rates and full accelerations q̈ at (q, u).
pub fn wheel_accelerations(w: &WheelDisk, q: &Q, u: &U) -> (Q, Q) {
    let (rates, ud) = w.derivative(0.0, q, u).expect("the wheel's derivative");
    let partition = w.partition();
    let (a, rate_terms) = w.constraint_rows(q, &rates);
    let projected = partition.rates(&a, u).expect("projects");
    let accel = partition
        .full_accelerations(&a, &rate_terms, &projected, &ud)
        .expect("accelerations");
    (rates, accel.into())
}

/// The table's state derivative at y (rolling).
pub fn table_derivative(d: &TableDisk, y: &[f64; STATE_LEN]) -> [f64; STATE_LEN] {
    d.accelerations(precess::contact::Phase::Rolling, 0.0, y)
        .expect("the table's accelerations")
}
