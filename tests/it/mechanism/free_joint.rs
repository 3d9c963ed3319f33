//! The `free` joint: a base body flying free of the ground (three translations of its origin
//! in ground axes, three Euler angles charted as a spherical joint's), against independent
//! values — a lone brick against the Jacobi-elliptic solution of Euler's torque-free
//! equations (`FreeBodyExact`) and its centre of mass against the exact parabola, through
//! the derive and through the run-time model; a satellite with a hinged panel thrown under
//! gravity against the conservation laws, evaluated by hand from the bodies' Newton–Euler
//! kinematics; the same satellite at zero angular momentum, whose bus turns as the panel
//! swings, against the closed form of its attitude as a function of the hinge angle.

use crate::common;

use common::mechanism::examples::free_floating::{
    BUS_MASS, BUS_SIZE, HINGE, PANEL_ARM, PANEL_MASS, PANEL_SIZE, Satellite, cuboid_moments,
    roll_at_zero_momentum, thrown_start,
};
use precess::exact::FreeBodyExact;
use std::cell::RefCell;

use precess::mechanism::charts::{
    ChartSet, ChartedDynamics, ChartedMechanism, MechanismCharts, SphericalJoint, chart_variants,
    scene_in_charts,
};
use precess::mechanism::{
    JointKind, MechanismAba, MechanismDynamics, MechanismError, MechanismScene, Parent, Route,
};
use precess::ode::AdaptiveConfig;
use precess::prelude::*;
use precess::sym::{Arena, Rational};
use precess::taylor::{TaylorConfig, TaylorSystem};

const G: f64 = 9.81;

fn tight() -> ChartConfig {
    ChartConfig {
        switch_below: 0.3,
        stepper: AdaptiveConfig::with_tol(1e-13, 1e-13),
    }
}

fn rx(angle: f64) -> Matrix3<f64> {
    *Rotation3::from_axis_angle(&Vector3::x_axis(), angle).matrix()
}

/// A brick 0.3 × 0.2 × 0.1 m of 2 kg whose centre sits off its frame's origin, so the
/// origin the free joint moves is not the centre of mass.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(brick, joint = free(sequence = zxz), q = [x, y, z, phi, theta, psi],
       parts(cuboid(mass = 2.0, size = [0.3, 0.2, 0.1], at = [0.05, -0.02, 0.03])))]
struct Brick;

const BRICK_MASS: f64 = 2.0;
const BRICK_SIZE: [f64; 3] = [0.3, 0.2, 0.1];
const BRICK_CENTER: [f64; 3] = [0.05, -0.02, 0.03];

/// The brick built at run time, for the interpreted model.
fn brick_scene(arena: &mut Arena) -> MechanismScene {
    let exact = |arena: &mut Arena, v: f64| {
        let r = Rational::from_f64(v).unwrap();
        arena.constant(r)
    };
    let kind = JointKind::Free {
        sequence: AngleSequence::Zxz,
    };
    let names = ["x", "y", "z", "phi", "theta", "psi"];
    let mut brick = MechanismScene::body(arena, "brick", Parent::Ground, kind, &names);
    brick.mass = exact(arena, BRICK_MASS);
    brick.center = BRICK_CENTER.map(|c| exact(arena, c));
    let moments = cuboid_moments(BRICK_MASS, BRICK_SIZE);
    let z = arena.zero();
    let mut inertia = [[z; 3]; 3];
    for k in 0..3 {
        inertia[k][k] = exact(arena, moments[k]);
    }
    brick.inertia = inertia;
    let mut scene = MechanismScene::new();
    scene.bodies.push(brick);
    let down = exact(arena, -G);
    scene.gravity = Some([z, z, down]);
    scene
}

/// The brick's translations at the throw, attitude `r0` and body rate `omega0`: its
/// reference point at (0.1, 0.2, 1.0) and its centre moving at V₀ = (1.5, −0.4, 4.0), so the
/// reference point's velocity is v_o = V₀ − R (ω × c). Returns the 12-slot state with zero
/// angles and rates (the charts set them from the attitude), C₀ and V₀.
fn thrown(r0: Matrix3<f64>, omega0: Vector3<f64>) -> ([f64; 12], Vector3<f64>, Vector3<f64>) {
    let c = Vector3::from(BRICK_CENTER);
    let v_center0 = Vector3::new(1.5, -0.4, 4.0);
    let origin0 = Vector3::new(0.1, 0.2, 1.0);
    let v_origin0 = v_center0 - r0 * omega0.cross(&c);
    let mut y0 = [0.0; 12];
    y0[..3].copy_from_slice(origin0.as_slice());
    y0[6..9].copy_from_slice(v_origin0.as_slice());
    (y0, origin0 + r0 * c, v_center0)
}

/// Throws the brick tumbling and compares, at samples to t = 6 s: I ω against m(t) of
/// `FreeBodyExact` (gravity exerts no torque about the centre), and the centre against
/// C₀ + V₀ t − ½ g t² ẑ. Returns the worst relative errors (momentum, centre).
fn throw_brick<D: ChartedDynamics<12>>(dynamics: D) -> (f64, f64) {
    let moments = cuboid_moments(BRICK_MASS, BRICK_SIZE);
    let inertia = Matrix3::from_diagonal(&Vector3::from(moments));
    let c = Vector3::from(BRICK_CENTER);
    // Near the intermediate axis, so the tumble is far from steady.
    let omega0 = Vector3::new(0.4, 6.0, -0.8);
    let r0 = *Rotation3::from_euler_angles(0.3, -0.5, 1.1).matrix();
    let (y0, center0, v_center0) = thrown(r0, omega0);
    let exact = FreeBodyExact::new(moments, inertia * omega0).unwrap();
    let mut run =
        ChartedMechanism::from_attitudes(dynamics, 0.0, y0, &[(r0, omega0)], tight()).unwrap();
    let (mut momentum, mut centre) = (0.0f64, 0.0f64);
    let m0 = (inertia * omega0).norm();
    for step in 1..=24 {
        let t = 0.25 * f64::from(step);
        run.advance_to(t).unwrap();
        let (r, omega) = (run.joint_rotation(0).unwrap(), run.joint_omega(0).unwrap());
        let m = inertia * omega;
        momentum = momentum.max((m - exact.m_at(t).unwrap()).norm() / m0);
        let y = run.state();
        let at = Vector3::new(y[0], y[1], y[2]) + r * c;
        let expected = center0 + v_center0 * t - Vector3::new(0.0, 0.0, 0.5 * G * t * t);
        centre = centre.max((at - expected).norm() / expected.norm());
    }
    // A tumble about the intermediate axis turns far from the start: the run went through
    // the charts' trouble, not around it.
    assert!(run.switches() > 0, "the run never left ZXZ");
    eprintln!(
        "brick: I ω {momentum:.1e}, centre {centre:.1e}, {} chart switches",
        run.switches()
    );
    (momentum, centre)
}

#[test]
fn a_derived_free_brick_tumbles_as_eulers_equations_and_falls_on_the_parabola() {
    let (momentum, centre) = throw_brick(&Brick);
    assert!(momentum < 1e-10, "I ω against FreeBodyExact: {momentum:e}");
    assert!(
        centre < 1e-10,
        "the centre against the parabola: {centre:e}"
    );
}

#[test]
fn a_run_time_free_brick_tumbles_as_eulers_equations_and_falls_on_the_parabola() {
    let mut arena = Arena::new();
    let scene = brick_scene(&mut arena);
    let charts = MechanismCharts::new(&mut arena, &scene, Route::Auto, &[]).unwrap();
    let (momentum, centre) = throw_brick(&charts);
    assert!(momentum < 1e-10, "I ω against FreeBodyExact: {momentum:e}");
    assert!(
        centre < 1e-10,
        "the centre against the parabola: {centre:e}"
    );
}

/// The run-time articulated-body algorithm ([`MechanismAba`]) of each chart of a scene as
/// [`ChartedDynamics`]: q̈ from the O(n) recursion, the charts' joints and energy from the
/// interpreted model of the same scene (the energy only reports).
struct AbaCharts {
    charts: MechanismCharts,
    aba: Vec<(ChartSet, RefCell<MechanismAba>)>,
}

impl AbaCharts {
    fn new(arena: &mut Arena, scene: &MechanismScene) -> AbaCharts {
        let charts = MechanismCharts::new(arena, scene, Route::Auto, &[]).unwrap();
        let env = vec![f64::NAN; arena.symbol_count()];
        let aba = chart_variants(&[true])
            .into_iter()
            .map(|set| {
                let in_chart = scene_in_charts(scene, set);
                let aba = MechanismAba::new(arena, &in_chart, &env).unwrap();
                (set, RefCell::new(aba))
            })
            .collect();
        AbaCharts { charts, aba }
    }
}

impl ChartedDynamics<12> for AbaCharts {
    fn dof(&self) -> usize {
        6
    }
    fn spherical_joints(&self) -> Vec<SphericalJoint> {
        ChartedDynamics::<12>::spherical_joints(&self.charts)
    }
    fn has_charts(&self, charts: ChartSet) -> bool {
        self.aba.iter().any(|(set, _)| *set == charts)
    }
    fn rhs_in(&self, charts: ChartSet, _t: f64, y: &[f64; 12], dydt: &mut [f64; 12]) {
        let Some((_, aba)) = self.aba.iter().find(|(set, _)| *set == charts) else {
            dydt.fill(f64::NAN);
            return;
        };
        let (q, qd) = y.split_at(6);
        let (rates, qdd) = dydt.split_at_mut(6);
        rates.copy_from_slice(qd);
        if aba.borrow_mut().accelerations(q, qd, qdd).is_err() {
            qdd.fill(f64::NAN);
        }
    }
    fn energy_in(&self, charts: ChartSet, t: f64, y: &[f64; 12]) -> f64 {
        ChartedDynamics::<12>::energy_in(&self.charts, charts, t, y)
    }
}

/// The same brick through the run-time articulated-body algorithm of each chart.
#[test]
fn an_articulated_body_free_brick_tumbles_as_eulers_equations_and_falls_on_the_parabola() {
    let mut arena = Arena::new();
    let scene = brick_scene(&mut arena);
    let dynamics = AbaCharts::new(&mut arena, &scene);
    let (momentum, centre) = throw_brick(&dynamics);
    assert!(momentum < 1e-10, "I ω against FreeBodyExact: {momentum:e}");
    assert!(
        centre < 1e-10,
        "the centre against the parabola: {centre:e}"
    );
}

/// The brick with Taylor recurrences (`taylor = 24`): one chart, so thrown spinning near its
/// axis of largest moment, tilted 1.4 rad, which keeps ZXZ's θ away from its gimbal lock.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 24)]
#[body(brick, joint = free(sequence = zxz), q = [x, y, z, phi, theta, psi],
       parts(cuboid(mass = 2.0, size = [0.3, 0.2, 0.1], at = [0.05, -0.02, 0.03])))]
struct TaylorBrick;

/// The Taylor integrator on a free-floating mechanism: at samples to 3 s, I ω against
/// `FreeBodyExact` and the centre against the parabola, the states read through the
/// charts' converters (the derived struct's joint rotation and ω).
#[test]
fn a_taylor_free_brick_tumbles_as_eulers_equations_and_falls_on_the_parabola() {
    assert_eq!(TaylorSystem::<12>::max_order(&TaylorBrick), 24);
    let moments = cuboid_moments(BRICK_MASS, BRICK_SIZE);
    let inertia = Matrix3::from_diagonal(&Vector3::from(moments));
    let c = Vector3::from(BRICK_CENTER);
    let omega0 = Vector3::new(0.5, -0.7, 7.0);
    // θ = 1.4 in ZXZ (sin θ = 0.99), while ZYX's pitch is near its lock (cos = 0.31), so the
    // declared chart is the better one and stays so: the spin keeps the body's z axis near
    // its angular momentum.
    let rz = |a: f64| *Rotation3::from_axis_angle(&Vector3::z_axis(), a).matrix();
    let r0 = rz(0.3) * rx(1.4) * rz(1.3);
    let (y0, center0, v_center0) = thrown(r0, omega0);
    let start =
        ChartedMechanism::from_attitudes(&TaylorBrick, 0.0, y0, &[(r0, omega0)], tight()).unwrap();
    assert_eq!(
        start.charts(),
        ChartSet::DECLARED,
        "the start is not in ZXZ"
    );
    let y0 = *start.state();
    let exact = FreeBodyExact::new(moments, inertia * omega0).unwrap();
    let m0 = (inertia * omega0).norm();
    let (mut momentum, mut centre) = (0.0f64, 0.0f64);
    for step in 1..=6 {
        let t = 0.5 * f64::from(step);
        let cfg = TaylorConfig::with_tol(1e-14, 1e-14);
        let end = precess::taylor::solve(&TaylorBrick, 0.0, y0, t, &[], cfg).unwrap();
        let at_t =
            ChartedMechanism::new(&TaylorBrick, t, end.y, ChartSet::DECLARED, tight()).unwrap();
        let (r, omega) = (
            at_t.joint_rotation(0).unwrap(),
            at_t.joint_omega(0).unwrap(),
        );
        let m = inertia * omega;
        momentum = momentum.max((m - exact.m_at(t).unwrap()).norm() / m0);
        let y = end.y;
        let at = Vector3::new(y[0], y[1], y[2]) + r * c;
        let expected = center0 + v_center0 * t - Vector3::new(0.0, 0.0, 0.5 * G * t * t);
        centre = centre.max((at - expected).norm() / expected.norm());
    }
    eprintln!("taylor brick: I ω {momentum:.1e}, centre {centre:.1e}");
    assert!(momentum < 1e-10, "I ω against FreeBodyExact: {momentum:e}");
    assert!(
        centre < 1e-10,
        "the centre against the parabola: {centre:e}"
    );
}

#[test]
fn the_free_joints_coordinates_are_named_and_its_translations_are_cyclic() {
    assert_eq!(
        Satellite::COORDINATES,
        ["x", "y", "z", "yaw", "pitch", "roll", "beta"]
    );
    assert_eq!((Satellite::X, Satellite::ROLL, Satellite::BETA), (0, 5, 6));
    // x and y are absent from L under gravity along z: their momenta, the horizontal
    // linear momentum M V, are conserved; z is not.
    let sat = Satellite { g: G, k: 0.0 };
    let q = [0.3, -0.2, 5.0, 0.1, 0.2, 0.3, 0.4];
    let qd = [1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0];
    let p = sat.conserved_momenta(&q, &qd);
    assert!(p[0].is_some() && p[1].is_some() && p[2].is_none());
    // A pure translation: p_x = (M_bus + M_panel) ẋ.
    let total = BUS_MASS + PANEL_MASS;
    for i in 0..2 {
        let value = p[i].unwrap_or(f64::NAN);
        assert!(
            (value - total * qd[i]).abs() < 1e-12 * total,
            "p_{i} = {value}"
        );
    }
}

/// The satellite's bodies as Newton–Euler sees them, from the bus's attitude R, angular
/// velocity ω (bus axes), origin o and its velocity, and the hinge angle and rate.
struct Bodies {
    /// Centres of mass (bus, panel), ground axes.
    centers: [Vector3<f64>; 2],
    /// Their velocities.
    velocities: [Vector3<f64>; 2],
    /// Angular momentum of each body about its own centre, ground axes.
    spins: [Vector3<f64>; 2],
    /// ½ ωᵀ I ω of each.
    rotational: [f64; 2],
}

fn bodies(run: &ChartedMechanism<&Satellite, 14>) -> Bodies {
    let (r, omega) = (run.joint_rotation(0).unwrap(), run.joint_omega(0).unwrap());
    let y = run.state();
    let (o, v_o) = (
        Vector3::new(y[0], y[1], y[2]),
        Vector3::new(y[7], y[8], y[9]),
    );
    let (beta, beta_dot) = (y[6], y[13]);
    let hinge = Vector3::new(0.0, HINGE, 0.0);
    let arm = Vector3::new(0.0, PANEL_ARM, 0.0);
    let turn = rx(beta);
    let lever = hinge + turn * arm;
    let panel_center = o + r * lever;
    // d/dt R x = R (ω × x + ẋ), with ẋ of Rx(β) d = Rx(β) (β̇ x̂ × d).
    let panel_velocity =
        v_o + r * (omega.cross(&lever) + turn * (Vector3::x() * beta_dot).cross(&arm));
    let panel_omega = turn.transpose() * omega + Vector3::x() * beta_dot;
    let i_bus = Matrix3::from_diagonal(&Vector3::from(cuboid_moments(BUS_MASS, BUS_SIZE)));
    let i_panel = Matrix3::from_diagonal(&Vector3::from(cuboid_moments(PANEL_MASS, PANEL_SIZE)));
    Bodies {
        centers: [o, panel_center],
        velocities: [v_o, panel_velocity],
        spins: [r * i_bus * omega, r * turn * i_panel * panel_omega],
        rotational: [
            0.5 * omega.dot(&(i_bus * omega)),
            0.5 * panel_omega.dot(&(i_panel * panel_omega)),
        ],
    }
}

/// The totals of a state: centre of mass, its velocity, angular momentum about it, and
/// T + V with V = Σ m g z + ½ k β².
struct Totals {
    center: Vector3<f64>,
    velocity: Vector3<f64>,
    angular: Vector3<f64>,
    energy: f64,
}

fn totals(b: &Bodies, g: f64, k: f64, beta: f64) -> Totals {
    let masses = [BUS_MASS, PANEL_MASS];
    let total = BUS_MASS + PANEL_MASS;
    let center = (b.centers[0] * masses[0] + b.centers[1] * masses[1]) / total;
    let velocity = (b.velocities[0] * masses[0] + b.velocities[1] * masses[1]) / total;
    let mut angular = b.spins[0] + b.spins[1];
    let mut energy = b.rotational[0] + b.rotational[1] + 0.5 * k * beta * beta;
    for ((&m, c), v) in masses.iter().zip(&b.centers).zip(&b.velocities) {
        angular += m * (c - center).cross(&(v - velocity));
        energy += 0.5 * m * v.norm_squared() + m * g * c.z;
    }
    Totals {
        center,
        velocity,
        angular,
        energy,
    }
}

#[test]
fn a_thrown_satellite_keeps_its_momenta_and_its_centre_falls_on_the_parabola() {
    let sat = Satellite { g: G, k: 40.0 };
    // The example's throw.
    let (y0, r0, omega0) = thrown_start();
    let mut run =
        ChartedMechanism::from_attitudes(&sat, 0.0, y0, &[(r0, omega0)], tight()).unwrap();
    let beta = |run: &ChartedMechanism<&Satellite, 14>| run.state()[Satellite::BETA];
    let start = totals(&bodies(&run), G, sat.k, beta(&run));
    // The hand-computed energy is the derived one: T and V agree at the start.
    assert!((start.energy - run.energy()).abs() < 1e-12 * start.energy.abs());
    let (mut centre, mut horizontal, mut angular, mut energy) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut swing = 0.0f64;
    for step in 1..=20 {
        let t = 0.1 * f64::from(step);
        run.advance_to(t).unwrap();
        let now = totals(&bodies(&run), G, sat.k, beta(&run));
        let parabola = start.center + start.velocity * t - Vector3::new(0.0, 0.0, 0.5 * G * t * t);
        centre = centre.max((now.center - parabola).norm() / parabola.norm());
        let (h0, h) = (start.velocity.xy(), now.velocity.xy());
        horizontal = horizontal.max((h - h0).norm() / h0.norm());
        angular = angular.max((now.angular - start.angular).norm() / start.angular.norm());
        energy = energy.max((now.energy - start.energy).abs() / start.energy.abs());
        swing = swing.max((beta(&run) - 0.4).abs());
    }
    eprintln!(
        "thrown satellite: centre {centre:.1e}, horizontal {horizontal:.1e}, L {angular:.1e}, E {energy:.1e}, swing {swing:.2}, {} switches",
        run.switches()
    );
    assert!(swing > 0.3, "the panel hardly swung: {swing}");
    assert!(centre < 1e-10, "centre against the parabola: {centre:e}");
    assert!(horizontal < 1e-10, "horizontal momentum: {horizontal:e}");
    assert!(
        angular < 1e-10,
        "angular momentum about the centre: {angular:e}"
    );
    assert!(energy < 1e-10, "energy: {energy:e}");
}

#[test]
fn a_satellite_at_zero_angular_momentum_turns_its_bus_as_its_panel_swings() {
    // In orbit (no gravity), released at rest with the panel sprung 1 rad open: L = 0
    // throughout, and the bus turns back and forth about the hinge axis as the panel swings.
    let sat = Satellite { g: 0.0, k: 200.0 };
    let beta0 = 1.0;
    let mut y0 = [0.0; 14];
    y0[Satellite::BETA] = beta0;
    let attitudes = [(Matrix3::identity(), Vector3::zeros())];
    let mut run = ChartedMechanism::from_attitudes(&sat, 0.0, y0, &attitudes, tight()).unwrap();
    // The scale of L: the panel's own spin at its fastest, ω ~ √(k/I) β₀.
    let i2 = cuboid_moments(PANEL_MASS, PANEL_SIZE)[0] + PANEL_MASS * PANEL_ARM * PANEL_ARM;
    let scale = i2 * (sat.k / i2).sqrt() * beta0;
    let (mut worst_l, mut worst_roll, mut turned) = (0.0f64, 0.0f64, 0.0f64);
    for step in 1..=40 {
        let t = 0.05 * f64::from(step);
        run.advance_to(t).unwrap();
        let l = totals(&bodies(&run), 0.0, sat.k, run.state()[Satellite::BETA]).angular;
        worst_l = worst_l.max(l.norm() / scale);
        let r = run.joint_rotation(0).unwrap();
        let roll = r[(2, 1)].atan2(r[(1, 1)]);
        let expected = roll_at_zero_momentum(beta0, run.state()[Satellite::BETA]);
        worst_roll = worst_roll.max((roll - expected).abs());
        turned = turned.max(roll.abs());
        // Planar: the bus turns about x alone.
        assert!((r[(0, 0)] - 1.0).abs() < 1e-12);
    }
    eprintln!("zero L: L {worst_l:.1e}, roll {worst_roll:.1e}, turned {turned:.3}");
    assert!(turned > 0.1, "the bus hardly turned: {turned}");
    assert!(
        worst_l < 1e-10,
        "L about the centre, relative to the panel's: {worst_l:e}"
    );
    assert!(
        worst_roll < 1e-10,
        "the bus's roll against the closed form: {worst_roll:e}"
    );
}

#[test]
fn a_free_joint_hangs_from_the_ground_and_there_is_one() {
    let mut arena = Arena::new();
    let free = || JointKind::Free {
        sequence: AngleSequence::Zyx,
    };
    let names = ["x", "y", "z", "a", "b", "c"];
    let other = ["u", "v", "w", "d", "e", "f"];
    let mut scene = MechanismScene::new();
    scene.bodies.push(MechanismScene::body(
        &mut arena,
        "base",
        Parent::Ground,
        free(),
        &names,
    ));
    scene.bodies.push(MechanismScene::body(
        &mut arena,
        "limb",
        Parent::Body(0),
        free(),
        &other,
    ));
    assert_eq!(
        scene.validate(&arena),
        Err(MechanismError::FreeJointNotOnGround {
            joint: "limb".into(),
            parent: "base".into()
        })
    );
    scene.bodies[1].joint.parent = Parent::Ground;
    assert_eq!(
        scene.validate(&arena),
        Err(MechanismError::SecondFreeJoint {
            first: "base".into(),
            second: "limb".into()
        })
    );
    scene.bodies.pop();
    assert_eq!(scene.validate(&arena), Ok(vec![0]));
}
