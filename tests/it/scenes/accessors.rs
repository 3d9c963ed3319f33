//! State accessors by name for every derived scene: a top's angle consts and
//! `coordinate(name)`, a free body's slot consts and `coordinate(name)`, a mechanism's
//! coordinate consts, each against the documented layout — the names `state_names()` heads
//! the CSV with, the slots `FreeState::to_array` fills, and a state read back from a run.

use approx::assert_relative_eq;
use precess::free::{FreeDynamics, FreeQuantities, FreeState, layout};
use precess::mechanism::{MechanismDynamics, MechanismQuantities};
use precess::ode::{AdaptiveConfig, Dop853, Run};
use precess::prelude::*;
use precess::top::{TopDynamics, TopQuantities};

/// A heavy symmetric top in the default ZXZ chart.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
struct Zxz;

/// The same top in Tait–Bryan angles.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0, angles = zyx)]
struct Zyx;

/// A free box.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
#[free(gravity = 9.81)]
struct Brick;

/// A unit mass on a hinge about x, on a massless turntable about the vertical.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(table, parent = ground, joint = revolute(axis = z), q = phi,
       parts(particle(mass = 0.0, at = [0.0, 0.0, 0.0])))]
#[body(bob, parent = table, joint = revolute(axis = x), q = theta,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
struct Conical;

#[test]
fn a_tops_angle_consts_and_lookup_name_the_slots_of_its_state_columns() {
    let zxz = TopQuantities::<Zxz>::state_names();
    assert_eq!((Zxz::PHI, Zxz::THETA, Zxz::PSI), (0, 1, 2));
    for (name, k) in [("phi", Zxz::PHI), ("theta", Zxz::THETA), ("psi", Zxz::PSI)] {
        assert_eq!(Zxz::coordinate(name), Some(k));
        assert_eq!(zxz[k], name);
        assert_eq!(zxz[k + 3], format!("{name}_dot"));
    }
    let zyx = TopQuantities::<Zyx>::state_names();
    assert_eq!((Zyx::YAW, Zyx::PITCH, Zyx::ROLL), (0, 1, 2));
    for (name, k) in [
        ("yaw", Zyx::YAW),
        ("pitch", Zyx::PITCH),
        ("roll", Zyx::ROLL),
    ] {
        assert_eq!(Zyx::coordinate(name), Some(k));
        assert_eq!(zyx[k], name);
    }
    assert_eq!(Zxz::coordinate("roll"), None);
    assert_eq!(Zyx::coordinate("theta"), None);
}

#[test]
fn a_tops_theta_slot_holds_the_nutation_angle_of_a_run() {
    // Released at rest from θ0 = 60° spinning at ω3 = 20: θ stays within a narrow band
    // above θ0 (a fast top nutates by about 2 M g l I1 sin θ0 / (I3 ω3)² ≈ 0.017 rad), while
    // ψ grows at about ω3 t and φ slowly: reading a wrong slot fails one of these.
    let chart = TopChart::declared(&Zxz);
    let theta0 = std::f64::consts::FRAC_PI_3;
    let y0 = [0.0, theta0, 0.0, 0.0, 0.0, 20.0];
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(&chart, 0.0, y0, tight).expect("a valid top");
    let out = Run::new(&mut ode, 1.0)
        .sample_every(0.25)
        .integrate()
        .expect("a regular run");
    let last = out.trajectory.states().last().expect("samples");
    let theta = last[Zxz::THETA];
    assert!((theta0..theta0 + 0.02).contains(&theta), "θ = {theta}");
    assert_relative_eq!(last[Zxz::PSI], 20.0, epsilon = 0.5);
    assert!(last[Zxz::PHI].abs() < 0.5, "φ = {}", last[Zxz::PHI]);
    assert!(last[3 + Zxz::PSI] > 19.0, "ψ̇ = {}", last[3 + Zxz::PSI]);
}

#[test]
fn a_free_bodys_slot_consts_and_lookup_read_what_the_state_array_holds() {
    let names = FreeQuantities::<Brick>::state_names();
    let consts = [
        Brick::X,
        Brick::Y,
        Brick::Z,
        Brick::VX,
        Brick::VY,
        Brick::VZ,
        Brick::QW,
        Brick::QX,
        Brick::QY,
        Brick::QZ,
        Brick::OMEGA_1,
        Brick::OMEGA_2,
        Brick::OMEGA_3,
    ];
    for (k, name) in names.iter().enumerate() {
        assert_eq!(Brick::coordinate(name), Some(k), "{name}");
        assert_eq!(consts[k], k, "{name}");
    }
    assert_eq!(Brick::coordinate("theta"), None);
    // Every slot a distinct value: each const reads the field the layout documents.
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3);
    let s = FreeState {
        position: Vector3::new(1.0, 2.0, 3.0),
        velocity: Vector3::new(4.0, 5.0, 6.0),
        attitude,
        omega_principal: Vector3::new(7.0, 8.0, 9.0),
    };
    let y = s.to_array();
    assert_eq!([y[Brick::X], y[Brick::Y], y[Brick::Z]], [1.0, 2.0, 3.0]);
    assert_eq!([y[Brick::VX], y[Brick::VY], y[Brick::VZ]], [4.0, 5.0, 6.0]);
    let q = attitude.quaternion();
    assert_eq!(
        [y[Brick::QW], y[Brick::QX], y[Brick::QY], y[Brick::QZ]],
        [q.w, q.i, q.j, q.k]
    );
    assert_eq!(
        [y[Brick::OMEGA_1], y[Brick::OMEGA_2], y[Brick::OMEGA_3]],
        [7.0, 8.0, 9.0]
    );
    assert_eq!(
        (Brick::VX, Brick::QW, Brick::OMEGA_1),
        (layout::VELOCITY, layout::QUATERNION, layout::OMEGA)
    );
}

#[test]
fn a_mechanisms_coordinate_consts_name_the_slots_of_its_state_columns() {
    const N: usize = 2;
    let names = MechanismQuantities::<Conical, N>::state_names();
    for (name, k) in [("phi", Conical::PHI), ("theta", Conical::THETA)] {
        assert_eq!(Conical::coordinate(name), Some(k));
        assert_eq!(names[k], name);
        assert_eq!(names[N + k], format!("{name}_dot"));
    }
    // Spinning the table at φ̇ = 2 with the bob at θ = 0.5: after a short run φ has grown
    // and θ has not left (0, π), so the consts read the right slots.
    let mut y0 = [0.0; 2 * N];
    y0[Conical::THETA] = 0.5;
    y0[N + Conical::PHI] = 2.0;
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(&Conical, 0.0, y0, tight).expect("a valid mechanism");
    let out = Run::new(&mut ode, 0.1)
        .sample_every(0.1)
        .integrate()
        .expect("a regular run");
    let last = out.trajectory.states().last().expect("samples");
    assert!(last[Conical::PHI] > 0.15, "φ = {}", last[Conical::PHI]);
    assert!(
        (0.4..0.7).contains(&last[Conical::THETA]),
        "θ = {}",
        last[Conical::THETA]
    );
}
