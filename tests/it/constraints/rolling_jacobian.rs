//! `RollingDynamics::acceleration_jacobian` (the engine's derivatives of M, f, A and Ȧq̇
//! carried through Maggi's projection by the product rule) against central differences of
//! the nonlinear free accelerations u̇(q, u), extrapolated twice by Richardson, at random
//! states of a rolling disk and of the Whipple bicycle. The differences are the less
//! accurate side (truncation O(h⁶), rounding ε|u̇|/h). The interpreted `RollingModel`
//! lowers the same engine derivatives at run time: the disk built here by hand and the
//! bicycle of `bicycle_macro_cross` are checked the same way, and the disk against the
//! derived struct's exact Jacobian.

use precess::codegen::BindingError;
use precess::mechanism::rolling::{
    RollingDynamics, RollingModel, RollingScene, RollingWheel, WheelSurface,
};
use precess::mechanism::{JointKind, MechanismError, MechanismScene, Parent};
use precess::models::Bicycle;
use precess::prelude::*;
use precess::rigid::AngleSequence;
use precess::sym::{Arena, ExprId};
use precess_testkit::rng::Rng;

use super::bicycle_macro_cross::{interpreted, interpreted_values, random_state};
use crate::common::mechanism::examples::bicycle::Bicycle as ExampleBicycle;
use crate::rolling_once::scenes::{GRAVITY, MASS, RADIUS, WheelDisk};

/// u̇ at (q, u), every coordinate free (the heights not re-closed: the Jacobian's meaning).
fn free_accelerations<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
) -> [f64; K] {
    model.derivative(0.0, q, u).expect("derivative").1
}

/// ∂u̇/∂y_j, y = (q, u), by central differences at h, h/2, h/4 extrapolated twice.
fn richardson<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
    j: usize,
    h: f64,
) -> [f64; K] {
    let central = |h: f64| {
        let (mut qp, mut qm, mut up, mut um) = (*q, *q, *u, *u);
        if j < N {
            qp[j] += h;
            qm[j] -= h;
        } else {
            up[j - N] += h;
            um[j - N] -= h;
        }
        let (p, m) = (
            free_accelerations(model, &qp, &up),
            free_accelerations(model, &qm, &um),
        );
        std::array::from_fn::<f64, K, _>(|i| (p[i] - m[i]) / (2.0 * h))
    };
    let d = [central(h), central(h / 2.0), central(h / 4.0)];
    std::array::from_fn(|i| {
        let r1 = (4.0 * d[1][i] - d[0][i]) / 3.0;
        let r2 = (4.0 * d[2][i] - d[1][i]) / 3.0;
        (16.0 * r2 - r1) / 15.0
    })
}

/// The largest difference between the exact Jacobian and the differenced one, relative to
/// the largest entry of the exact one.
fn worst_gap<const N: usize, const M: usize, const K: usize>(
    model: &impl RollingDynamics<N, M, K>,
    q: &[f64; N],
    u: &[f64; K],
    h: f64,
) -> f64 {
    let (by_q, by_u) = model.acceleration_jacobian(0.0, q, u).expect("jacobian");
    let scale = by_q
        .iter()
        .chain(by_u.iter())
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut worst = 0.0_f64;
    for j in 0..N + K {
        let numeric = richardson(model, q, u, j, h);
        for (i, d) in numeric.iter().enumerate() {
            let exact = if j < N {
                by_q[(i, j)]
            } else {
                by_u[(i, j - N)]
            };
            worst = worst.max((exact - d).abs() / scale);
        }
    }
    worst
}

/// A state of the rolling-once tests' disk on the floor: any yaw; the roll near π/2 stands
/// the disk up (its axle z turned horizontal), the pitch turns it about the axle, away from
/// the gimbal's lock at ±π/2; the hub put down by `close_contacts`.
fn disk_state(disk: &impl RollingDynamics<6, 3, 3>, rng: &mut Rng) -> ([f64; 6], [f64; 3]) {
    let mut q = [
        rng.uniform(-1.0, 1.0),
        rng.uniform(-1.0, 1.0),
        0.1,
        rng.uniform(-3.0, 3.0),
        rng.uniform(-1.0, 1.0),
        std::f64::consts::FRAC_PI_2 + rng.uniform(-0.6, 0.6),
    ];
    disk.close_contacts(&mut q).expect("on the floor");
    let u = [
        rng.uniform(-2.0, 2.0),
        rng.uniform(-2.0, 2.0),
        rng.uniform(-15.0, 15.0),
    ];
    (q, u)
}

/// What acts on the disk's roll angle in [`hand_built_disk`].
enum RollEffort {
    /// Nothing: the derived `WheelDisk`.
    None,
    /// −c φ̇ cos θ + s sin ψ (φ the roll, θ the pitch, ψ the yaw), written out as an
    /// expression of the state with parameters c and s.
    Expression,
    /// A constant torque s, a parameter of this value.
    Constant(f64),
    /// The input symbol a user function's value would be.
    UserFunction,
}

/// `WheelDisk` (the rolling-once tests' disk) built by hand at run time: slides along x, y
/// and z carry the hub, a spherical joint (zyx) turns the thin disk (axis z, moments
/// m r²/4, m r²/4, m r²/2), whose rim rolls on the floor z = 0; m, r and g as parameters.
fn hand_built_disk(effort: RollEffort) -> Result<RollingModel<6, 3, 3>, MechanismError> {
    let mut a = Arena::new();
    let (o, z) = (a.one(), a.zero());
    let (m, r, g) = (a.parameter("m"), a.parameter("r"), a.parameter("g"));
    let mut scene = MechanismScene::new();
    let slides: [(&str, [ExprId; 3]); 3] = [("x", [o, z, z]), ("y", [z, o, z]), ("z", [z, z, o])];
    for (i, (name, axis)) in slides.into_iter().enumerate() {
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(i - 1)
        };
        let body = MechanismScene::body(
            &mut a,
            &format!("slide_{name}"),
            parent,
            JointKind::Prismatic { axis },
            &[name],
        );
        scene.bodies.push(body);
    }
    let joint = JointKind::Spherical {
        sequence: AngleSequence::Zyx,
    };
    let mut disk = MechanismScene::body(
        &mut a,
        "disk",
        Parent::Body(2),
        joint,
        &["yaw", "pitch", "roll"],
    );
    disk.mass = m;
    let mr2 = a.product(&[m, r, r]);
    let quarter = a.number("0.25").expect("a literal");
    let half = a.number("0.5").expect("a literal");
    let (thin, axial) = (a.mul(quarter, mr2), a.mul(half, mr2));
    disk.inertia = [[thin, z, z], [z, thin, z], [z, z, axial]];
    let mut values = vec![("m", MASS), ("r", RADIUS), ("g", GRAVITY)];
    match effort {
        RollEffort::None => {}
        RollEffort::Expression => {
            let (c, s) = (a.parameter("c"), a.parameter("s"));
            let (yaw, pitch, roll) = (
                a.coordinate("yaw"),
                a.coordinate("pitch"),
                a.coordinate("roll"),
            );
            let roll_rate = a.rate(roll).expect("a coordinate's rate");
            let (cos_pitch, sin_yaw) = (a.cos(pitch), a.sin(yaw));
            let damping = a.product(&[c, roll_rate, cos_pitch]);
            let push = a.mul(s, sin_yaw);
            disk.joint.loads[2].effort = Some(a.sub(push, damping));
            values.extend([("c", 0.03), ("s", 0.02)]);
        }
        RollEffort::Constant(value) => {
            disk.joint.loads[2].effort = Some(a.parameter("s"));
            values.push(("s", value));
        }
        RollEffort::UserFunction => disk.joint.loads[2].effort = Some(a.input("drive")),
    }
    scene.bodies.push(disk);
    scene.gravity = Some([z, z, a.neg(g)]);
    let rolling = RollingScene {
        up: [z, z, o],
        wheels: vec![RollingWheel {
            body: 3,
            surface: WheelSurface::Disk {
                center: [z; 3],
                axle: [z, z, o],
                radius: r,
            },
        }],
        speeds: ["yaw", "pitch", "roll"].map(str::to_owned).to_vec(),
    };
    RollingModel::from_scene(
        &mut a,
        &scene,
        &rolling,
        ["x", "y", "z", "yaw", "pitch", "roll"],
        &values,
    )
}

#[test]
fn a_rolling_disks_exact_jacobian_matches_richardson_differences() {
    // The rolling-once tests' disk (0.5 kg, radius 0.1 m): slides along x, y and z carry
    // the hub, a spherical joint turns it (6 coordinates, 3 rows, 3 free speeds).
    let coin = WheelDisk;
    let mut rng = Rng::new(39);
    let mut worst = 0.0_f64;
    for _ in 0..10 {
        let (q, u) = disk_state(&coin, &mut rng);
        worst = worst.max(worst_gap(&coin, &q, &u, 1e-3));
    }
    println!("rolling disk: worst relative gap {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
}

#[test]
fn the_bicycles_exact_jacobian_matches_richardson_differences() {
    let bike = Bicycle::benchmark();
    let mut rng = Rng::new(2007);
    let mut worst = 0.0_f64;
    for _ in 0..6 {
        let mut q: [f64; 8] = std::array::from_fn(|_| rng.uniform(-0.5, 0.5));
        q[Bicycle::THETA] = 0.0;
        bike.close_contacts(&mut q).expect("on the floor");
        let u = [
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-20.0, 20.0),
        ];
        worst = worst.max(worst_gap(&bike, &q, &u, 1e-3));
    }
    println!("bicycle: worst relative gap {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// The disk built by hand and interpreted: its exact Jacobian (the engine's derivatives
/// lowered at run time) against the derived struct's, and against Richardson differences.
#[test]
fn the_interpreted_disks_exact_jacobian_is_the_derived_ones_and_matches_differences() {
    let coin = WheelDisk;
    let model = hand_built_disk(RollEffort::None).expect("builds");
    let mut rng = Rng::new(39);
    let (mut against_derived, mut against_differences) = (0.0_f64, 0.0_f64);
    for _ in 0..10 {
        let (q, u) = disk_state(&model, &mut rng);
        let (by_q, by_u) = model
            .acceleration_jacobian(0.0, &q, &u)
            .expect("interpreted");
        let (dq, du) = coin.acceleration_jacobian(0.0, &q, &u).expect("derived");
        let scale = dq
            .iter()
            .chain(du.iter())
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        let gap = (by_q - dq).amax().max((by_u - du).amax()) / scale;
        against_derived = against_derived.max(gap);
        against_differences = against_differences.max(worst_gap(&model, &q, &u, 1e-3));
    }
    println!(
        "interpreted disk: {against_derived:e} from the derived Jacobian, \
         {against_differences:e} from Richardson differences"
    );
    assert!(against_derived < 1e-13, "{against_derived:e}");
    assert!(against_differences < 1e-9, "{against_differences:e}");
}

#[test]
fn the_interpreted_bicycles_exact_jacobian_matches_richardson_differences() {
    let bike = ExampleBicycle::benchmark();
    let model = interpreted(&bike);
    let mut rng = Rng::new(2007);
    let mut worst = 0.0_f64;
    for _ in 0..6 {
        let (q, u) = random_state(&model, &mut rng);
        worst = worst.max(worst_gap(&model, &q, &u, 1e-3));
    }
    println!("interpreted bicycle: worst relative gap {worst:e}");
    assert!(worst < 1e-9, "{worst:e}");
}

/// An effort on the interpreted model is an expression the engine differentiates with the
/// rest (here of q and q̇), so the Jacobian stays exact; a user function's value, whose
/// dependence on the state no derivative can see, cannot be interpreted at all.
#[test]
fn an_interpreted_effort_is_differentiated_and_a_user_function_refused() {
    let model = hand_built_disk(RollEffort::Expression).expect("builds");
    let plain = hand_built_disk(RollEffort::None).expect("builds");
    let mut rng = Rng::new(77);
    let (mut worst, mut moved) = (0.0_f64, 0.0_f64);
    for _ in 0..6 {
        let (q, u) = disk_state(&model, &mut rng);
        worst = worst.max(worst_gap(&model, &q, &u, 1e-3));
        let (by_q, by_u) = model
            .acceleration_jacobian(0.0, &q, &u)
            .expect("with the effort");
        let (pq, pu) = plain.acceleration_jacobian(0.0, &q, &u).expect("without");
        moved = moved.max((by_q - pq).amax().max((by_u - pu).amax()));
    }
    println!(
        "interpreted disk with an effort: worst relative gap {worst:e}; the effort moves the Jacobian by up to {moved:e}"
    );
    assert!(worst < 1e-9, "{worst:e}");
    // The effort's own terms (c cos θ/I and s cos ψ/I, of order 10/s and 10/s²) are in it.
    assert!(moved > 1.0, "{moved:e}");
    let err = hand_built_disk(RollEffort::UserFunction).expect_err("an input to supply");
    assert!(
        matches!(&err, MechanismError::Binding(BindingError::RunTimeInput { name }) if name == "drive"),
        "{err}"
    );
}

/// `WheelDisk` with the torque of [`RollEffort::Expression`] on its roll angle from a user
/// function, which the derive cannot differentiate.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [yaw, pitch, roll])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y,
       parts(particle(mass = 0.0)))]
#[body(slide_z, parent = slide_y, joint = prismatic(axis = z), q = z,
       parts(particle(mass = 0.0)))]
#[body(disk, parent = slide_z, joint = spherical(sequence = zyx), q = [yaw, pitch, roll],
       effort = [0.0, 0.0, roll_torque],
       parts(disk(mass = 0.5, radius = 0.1)), rolls = disk_rim(radius = 0.1, axle = z))]
struct DrivenWheelDisk;

/// −c φ̇ cos θ + s sin ψ with c = 0.03 N m s and s = 0.02 N m, as `hand_built_disk` writes
/// it out.
fn roll_torque(_: &DrivenWheelDisk, _t: f64, q: &[f64; 6], qdot: &[f64; 6]) -> f64 {
    -0.03 * qdot[5] * q[4].cos() + 0.02 * q[3].sin()
}

/// The largest difference between two models' Jacobians at `states` of the disk, relative
/// to the largest entry of the first's.
fn jacobian_gap(
    exact: &impl RollingDynamics<6, 3, 3>,
    other: &impl RollingDynamics<6, 3, 3>,
    t: f64,
    states: &[([f64; 6], [f64; 3])],
) -> f64 {
    let mut worst = 0.0_f64;
    for (q, u) in states {
        let (by_q, by_u) = exact.acceleration_jacobian(t, q, u).expect("exact");
        let (dq, du) = other.acceleration_jacobian(t, q, u).expect("other");
        let scale = by_q
            .iter()
            .chain(by_u.iter())
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        worst = worst.max((by_q - dq).amax().max((by_u - du).amax()) / scale);
    }
    worst
}

/// A derived mechanism with a user-function effort differentiates everything but the
/// function exactly, the effort held at its value, and adds G ∂τ/∂(q, q̇), G = ∂f/∂τ exact
/// and only τ differenced. The interpreted model with the same torque written as an
/// expression differentiates all of it: the two agree to the error of differencing τ alone,
/// well below that of differencing all of u̇ (printed beside it).
#[test]
fn a_derived_user_effort_is_exact_but_for_the_functions_own_derivative() {
    let driven = DrivenWheelDisk;
    let model = hand_built_disk(RollEffort::Expression).expect("builds");
    let mut rng = Rng::new(41);
    let states: Vec<_> = (0..6).map(|_| disk_state(&model, &mut rng)).collect();
    for (q, u) in &states {
        let rates = model.rates(q, u).expect("rates");
        assert!(driven.partials(0.0, q, &rates, &[0.0; 6]).is_some());
    }
    let worst = jacobian_gap(&model, &driven, 0.0, &states);
    println!("derived with a user effort against interpreted (exact): {worst:e}");
    assert!(worst < 1e-13, "{worst:e}");
    // Full differencing of u̇ (the trait's fallback) is about 1e-12 from the exact one.
    let mut differenced = 0.0_f64;
    for (q, u) in &states {
        differenced = differenced.max(worst_gap(&model, q, u, 1e-3));
    }
    println!("full Richardson differences against interpreted (exact): {differenced:e}");
}

/// `WheelDisk` driven by a torque of time alone ([`time_torque`]).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [yaw, pitch, roll])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y,
       parts(particle(mass = 0.0)))]
#[body(slide_z, parent = slide_y, joint = prismatic(axis = z), q = z,
       parts(particle(mass = 0.0)))]
#[body(disk, parent = slide_z, joint = spherical(sequence = zyx), q = [yaw, pitch, roll],
       effort = [0.0, 0.0, time_torque],
       parts(disk(mass = 0.5, radius = 0.1)), rolls = disk_rim(radius = 0.1, axle = z))]
struct TimedWheelDisk;

/// 0.02 (1 + t) N m on the roll angle, whatever the state.
fn time_torque(_: &TimedWheelDisk, t: f64, _q: &[f64; 6], _qdot: &[f64; 6]) -> f64 {
    0.02 * (1.0 + t)
}

/// An effort that does not depend on the state differences to exactly zero, so the derived
/// Jacobian is the exact one to rounding: that of the interpreted disk under the constant
/// torque it has at that time, as close as the effort-free derived and interpreted disks
/// are (`the_interpreted_disks_exact_jacobian_is_the_derived_ones_and_matches_differences`).
#[test]
fn an_effort_free_of_the_state_leaves_the_derived_jacobian_exact() {
    let t = 0.5;
    let timed = TimedWheelDisk;
    let model = hand_built_disk(RollEffort::Constant(0.02 * (1.0 + t))).expect("builds");
    let mut rng = Rng::new(43);
    let states: Vec<_> = (0..6).map(|_| disk_state(&model, &mut rng)).collect();
    let worst = jacobian_gap(&model, &timed, t, &states);
    println!("derived with a torque of time against interpreted (exact): {worst:e}");
    assert!(worst < 1e-14, "{worst:e}");
}

/// Along `height_tangent` the wheel stays on the floor to second order (its height after a
/// step h is O(h²), against O(h) for the angle moved alone); a dependent coordinate has no
/// tangent of its own.
#[test]
fn the_height_tangent_keeps_the_wheel_on_the_floor_to_second_order() {
    use precess::mechanism::MechanismError;
    let disk = WheelDisk;
    let mut q = [0.2, -0.1, 0.1, 0.7, 0.3, std::f64::consts::FRAC_PI_2 - 0.4];
    disk.close_contacts(&mut q).expect("on the floor");
    let h = 1e-3;
    for free in 3..6 {
        let t = disk.height_tangent(&q, free).expect("a free coordinate");
        let along = |s: f64| {
            let moved: [f64; 6] = std::array::from_fn(|k| q[k] + s * t[k]);
            disk.heights(&moved)[2].abs()
        };
        let mut alone = q;
        alone[free] += h;
        let unfollowed = disk.heights(&alone)[2].abs();
        println!(
            "q[{free}]: height {:.1e} at h, {:.1e} at h/2 along the tangent; {unfollowed:.1e} \
             moved alone",
            along(h),
            along(h / 2.0)
        );
        // Second order: at most h² (the rim's curvature is 1/r = 10/m), and a quarter of it
        // at h/2 wherever the angle moves the wheel at all.
        assert!(along(h) <= h * h, "{:e}", along(h));
        if unfollowed > 0.0 {
            assert!(
                along(h) < 1e-2 * unfollowed,
                "{:e} against {unfollowed:e}",
                along(h)
            );
            let ratio = along(h) / along(h / 2.0);
            assert!((3.5..4.5).contains(&ratio), "ratio {ratio}");
        }
    }
    let dependent = disk.partition().dependent;
    assert!(matches!(
        disk.height_tangent(&q, dependent[0]),
        Err(MechanismError::NotFreeCoordinate { .. })
    ));
    assert!(disk.height_tangent(&q, 6).is_err());
}

/// What the exact Jacobian costs the interpreted bicycle, printed (not asserted: speed
/// belongs in benches): `RollingModel::new`, which only extracts M, f, A and Ȧq̇ into an
/// arena of their own, against a whole copy of the arena and the derivatives'
/// differentiation and lowering (timed alone on such a copy: what `new` would add if it
/// lowered them eagerly), the first `acceleration_jacobian` (which lowers them), and a
/// later one against the central differences it replaced (`linalg::jacobian` on
/// `derivative`). Run with `cargo test --test scenes rolling_model_costs -- --ignored
/// --nocapture`.
#[test]
#[ignore = "timing, printed"]
fn rolling_model_costs() {
    use std::time::Instant;

    use precess::codegen::Program;

    fn median(mut v: Vec<f64>) -> f64 {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    }
    let bike = ExampleBicycle::benchmark();
    let mut arena = Arena::new();
    let (scene, rolling) = precess_testkit::bicycle::mechanism_scene(&mut arena);
    let d = scene.derive_rolling(&mut arena, &rolling).expect("derives");
    let names = [
        "x", "y", "psi", "phi", "theta", "theta_r", "delta", "theta_f",
    ];
    let mut times: [Vec<f64>; 5] = Default::default();
    let (mut ops, mut lazy_ops) = (0, 0);
    let mut rng = Rng::new(5);
    let (q, u) = random_state(&interpreted(&bike), &mut rng);
    for _ in 0..7 {
        let start = Instant::now();
        let mut a = arena.clone();
        times[0].push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        let out = d.partials(&mut a);
        times[1].push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        let program = Program::lower(&a, &out);
        times[2].push(start.elapsed().as_secs_f64());
        ops = program.op_count().total();
        let mut a = arena.clone();
        let start = Instant::now();
        let model = RollingModel::<8, 5, 3>::new(&mut a, &d, names, &interpreted_values(&bike))
            .expect("binds");
        times[3].push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        std::hint::black_box(model.acceleration_jacobian(0.0, &q, &u).expect("exact"));
        times[4].push(start.elapsed().as_secs_f64());
        lazy_ops = model.partials_op_count().expect("lowered");
    }
    let [clone, differentiate, lower, new, first] = times.map(median);
    let mut roots: Vec<ExprId> = d.equations.mass.iter().flatten().copied().collect();
    roots.extend(&d.equations.forcing);
    roots.extend(d.constraints.coefficients.iter().flatten());
    roots.extend(&d.rate_terms);
    let extract = median(
        (0..7)
            .map(|_| {
                let start = Instant::now();
                std::hint::black_box(arena.extract(&roots).expect("owned"));
                start.elapsed().as_secs_f64()
            })
            .collect(),
    );
    println!(
        "the arena: {} nodes, copied in {:.1} ms; the {} under M, f, A and Ȧq̇ (and the \
         symbols) extracted in {:.1} ms",
        arena.len(),
        1e3 * clone,
        arena.extract(&roots).expect("owned").0.len(),
        1e3 * extract,
    );
    println!(
        "RollingModel::new {:.1} ms; the derivatives differentiated in {:.1} ms, lowered in \
         {:.1} ms ({ops} operations; {lazy_ops} lowered in the model's own arena); the first \
         acceleration_jacobian {:.1} ms",
        1e3 * new,
        1e3 * differentiate,
        1e3 * lower,
        1e3 * first,
    );
    let model = interpreted(&bike);
    // The first call lowers the derivatives (timed above).
    model.acceleration_jacobian(0.0, &q, &u).expect("exact");
    let reps = 50;
    let start = Instant::now();
    for _ in 0..reps {
        std::hint::black_box(model.acceleration_jacobian(0.0, &q, &u).expect("exact"));
    }
    let exact = start.elapsed().as_secs_f64() / f64::from(reps);
    let start = Instant::now();
    for _ in 0..reps {
        let state: Vec<f64> = q.iter().chain(u.iter()).copied().collect();
        let jac = precess::linalg::jacobian(
            |y, out| {
                let (mut q, mut u) = ([0.0; 8], [0.0; 3]);
                q.copy_from_slice(&y[..8]);
                u.copy_from_slice(&y[8..]);
                let (qd, ud) = model.derivative(0.0, &q, &u).expect("derivative");
                out[..8].copy_from_slice(&qd);
                out[8..].copy_from_slice(&ud);
            },
            &state,
        );
        std::hint::black_box(jac.expect("differences"));
    }
    let differenced = start.elapsed().as_secs_f64() / f64::from(reps);
    let start = Instant::now();
    for _ in 0..reps {
        std::hint::black_box(model.derivative(0.0, &q, &u).expect("derivative"));
    }
    let derivative = start.elapsed().as_secs_f64() / f64::from(reps);
    println!(
        "interpreted bicycle, after the first call: acceleration_jacobian {:.2} ms exact, \
         {:.2} ms by differences; one derivative {:.0} µs",
        1e3 * exact,
        1e3 * differenced,
        1e6 * derivative
    );
}
