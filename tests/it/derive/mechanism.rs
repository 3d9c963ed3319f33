//! `#[derive(Mechanism)]` against independent formulations: the double pendulum's
//! hand-derived closed form, a loaded single pendulum's, the heavy top of `#[top]` for one
//! spherical joint, the run-time `MechanismModel` of the same scene, and field values against
//! literals; and the typed errors of the checked accelerations.

use crate::common;

use approx::assert_relative_eq;
use common::rng::Rng;
use precess::mechanism::{
    JointKind, MechanismError, MechanismModel, MechanismScene, Parent, Route,
};
use precess::prelude::*;
use precess::sym::Arena;

const G: f64 = 9.81;

/// Two point masses on massless rods, swinging about x; θ2 is the lower rod's angle
/// relative to the upper's.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -l1]), q = theta2,
       parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct DoublePendulum {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
}

/// The same pendulum in literals.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = 1.5, at = [0.0, 0.0, -0.7])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.7]), q = theta2,
       parts(particle(mass = 0.25, at = [0.0, 0.0, -1.1])))]
struct LiteralPendulum;

/// q̈ of the double pendulum from the textbook equations in absolute angles φ1 = θ1,
/// φ2 = θ1 + θ2 (Lagrange's equations solved by hand), converted to the relative θ2.
fn closed_form(p: &DoublePendulum, q: [f64; 2], qd: [f64; 2]) -> [f64; 2] {
    let (m1, m2, l1, l2) = (p.m1, p.m2, p.l1, p.l2);
    let (f1, f2) = (q[0], q[0] + q[1]);
    let (w1, w2) = (qd[0], qd[0] + qd[1]);
    let den = 2.0 * m1 + m2 - m2 * (2.0 * f1 - 2.0 * f2).cos();
    let a1 = (-G * (2.0 * m1 + m2) * f1.sin()
        - m2 * G * (f1 - 2.0 * f2).sin()
        - 2.0 * (f1 - f2).sin() * m2 * (w2 * w2 * l2 + w1 * w1 * l1 * (f1 - f2).cos()))
        / (l1 * den);
    let a2 = 2.0
        * (f1 - f2).sin()
        * (w1 * w1 * l1 * (m1 + m2)
            + G * (m1 + m2) * f1.cos()
            + w2 * w2 * l2 * m2 * (f1 - f2).cos())
        / (l2 * den);
    [a1, a2 - a1]
}

#[test]
fn the_double_pendulum_matches_its_closed_form() {
    let mut rng = Rng::new(14);
    for _ in 0..1000 {
        let p = DoublePendulum {
            m1: rng.uniform(0.1, 3.0),
            l1: rng.uniform(0.2, 2.0),
            m2: rng.uniform(0.1, 3.0),
            l2: rng.uniform(0.2, 2.0),
        };
        let q = [rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)];
        let qd = [rng.uniform(-4.0, 4.0), rng.uniform(-4.0, 4.0)];
        let got = p.accelerations(0.0, &q, &qd).expect("a regular state");
        let want = closed_form(&p, q, qd);
        let scale = want[0].abs().max(want[1].abs()).max(1.0);
        for k in 0..2 {
            assert!(
                (got[k] - want[k]).abs() <= 1e-12 * scale,
                "q̈[{k}] = {} against {} at q = {q:?}, q̇ = {qd:?}",
                got[k],
                want[k]
            );
        }
        assert_eq!(p.accelerations_unchecked(0.0, &q, &qd), got);
    }
}

#[test]
fn energy_is_the_closed_form_and_the_coordinates_are_named() {
    let p = DoublePendulum {
        m1: 1.5,
        l1: 0.7,
        m2: 0.25,
        l2: 1.1,
    };
    let (q, qd): ([f64; 2], [f64; 2]) = ([0.4, -1.2], [0.8, 2.5]);
    let (f1, f2, w1, w2) = (q[0], q[0] + q[1], qd[0], qd[0] + qd[1]);
    let t = 0.5 * (p.m1 + p.m2) * (p.l1 * w1).powi(2)
        + 0.5 * p.m2 * (p.l2 * w2).powi(2)
        + p.m2 * p.l1 * p.l2 * w1 * w2 * (f1 - f2).cos();
    let v = -(p.m1 + p.m2) * G * p.l1 * f1.cos() - p.m2 * G * p.l2 * f2.cos();
    assert_relative_eq!(p.kinetic(&q, &qd), t, max_relative = 1e-14);
    // V is measured from q = 0, where both masses hang straight down.
    let v0 = -(p.m1 + p.m2) * G * p.l1 - p.m2 * G * p.l2;
    assert_relative_eq!(
        p.potential(&q) - p.potential(&[0.0, 0.0]),
        v - v0,
        max_relative = 1e-13
    );
    assert_relative_eq!(p.energy(&q, &qd), p.kinetic(&q, &qd) + p.potential(&q));
    assert_eq!(p.power(0.0, &q, &qd), 0.0);
    assert_eq!(DoublePendulum::COORDINATES, ["theta1", "theta2"]);
    assert_eq!((DoublePendulum::THETA1, DoublePendulum::THETA2), (0, 1));
    assert_eq!(DoublePendulum::coordinate("theta2"), Some(1));
    assert_eq!(DoublePendulum::coordinate("phi"), None);
    // Gravity couples both angles: neither is cyclic.
    assert_eq!(p.conserved_momenta(&q, &qd), [None, None]);
}

#[test]
fn field_values_give_what_literals_give() {
    let fields = DoublePendulum {
        m1: 1.5,
        l1: 0.7,
        m2: 0.25,
        l2: 1.1,
    };
    let mut rng = Rng::new(7);
    for _ in 0..200 {
        let q = [rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)];
        let qd = [rng.uniform(-4.0, 4.0), rng.uniform(-4.0, 4.0)];
        let a = fields.accelerations_unchecked(0.0, &q, &qd);
        let b = LiteralPendulum.accelerations_unchecked(0.0, &q, &qd);
        for k in 0..2 {
            assert_relative_eq!(a[k], b[k], max_relative = 1e-13, epsilon = 1e-13);
        }
        assert_relative_eq!(
            fields.energy(&q, &qd),
            LiteralPendulum.energy(&q, &qd),
            // E = T + V cancels: its terms are ~10 J.
            epsilon = 1e-13
        );
    }
}

#[test]
fn massless_links_are_a_singular_mass_matrix_and_bad_states_are_refused() {
    let p = DoublePendulum {
        m1: 0.0,
        l1: 1.0,
        m2: 0.0,
        l2: 1.0,
    };
    let e = p.accelerations(0.0, &[0.1, 0.2], &[0.0, 0.0]);
    assert!(
        matches!(e, Err(MechanismError::SingularMassMatrix { .. })),
        "{e:?}"
    );
    let p = DoublePendulum {
        m1: 1.0,
        l1: 1.0,
        m2: 1.0,
        l2: 1.0,
    };
    let e = p.accelerations(0.0, &[f64::NAN, 0.2], &[0.0, 0.0]);
    assert!(matches!(e, Err(MechanismError::NonFinite { .. })), "{e:?}");
    let e = p.accelerations(f64::INFINITY, &[0.1, 0.2], &[0.0, 0.0]);
    assert!(matches!(e, Err(MechanismError::NonFinite { .. })), "{e:?}");
}

/// A uniform rod on a hinge with a spring, a damper and a driving torque from a function.
#[derive(Mechanism)]
#[mechanism(gravity = g)]
#[body(rod, joint = revolute(axis = -y), q = theta, spring(k = k, rest = 0.2), damper = c,
       effort = drive, parts(rod(mass = m, length = l, at = [0.0, 0.0, -0.5 * l])))]
struct Driven {
    g: f64,
    k: f64,
    c: f64,
    m: f64,
    l: f64,
    amplitude: f64,
}

fn drive(d: &Driven, t: f64, _q: &[f64; 1], _qdot: &[f64; 1]) -> f64 {
    d.amplitude * (3.0 * t).sin()
}

#[test]
fn a_loaded_pendulum_matches_its_closed_form() {
    let d = Driven {
        g: 9.81,
        k: 2.0,
        c: 0.3,
        m: 0.8,
        l: 1.3,
        amplitude: 0.7,
    };
    let mut rng = Rng::new(3);
    for _ in 0..200 {
        let (t, th, w) = (
            rng.uniform(0.0, 5.0),
            rng.uniform(-3.0, 3.0),
            rng.uniform(-5.0, 5.0),
        );
        // I θ̈ = −m g (l/2) sin θ − k (θ − rest) − c θ̇ + τ(t), I = m l²/3 about the end.
        let i = d.m * d.l * d.l / 3.0;
        let tau = drive(&d, t, &[th], &[w]);
        let want = (-d.m * d.g * 0.5 * d.l * th.sin() - d.k * (th - 0.2) - d.c * w + tau) / i;
        let got = d.accelerations(t, &[th], &[w]).expect("regular")[Driven::THETA];
        assert_relative_eq!(got, want, max_relative = 1e-12, epsilon = 1e-12);
        // Only the damper and the drive do work: dE/dt = (τ − c θ̇) θ̇.
        assert_relative_eq!(
            d.power(t, &[th], &[w]),
            (tau - d.c * w) * w,
            max_relative = 1e-12,
            epsilon = 1e-12
        );
    }
}

/// A heavy symmetric top as one spherical joint: a disk on a stem.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(top, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
             disk(mass = 0.5, radius = 0.03, at = [0.0, 0.0, 0.05])))]
struct SphericalTop;

/// The same body by `#[rigid]` and `#[top]`.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
    disk(mass = 0.5, radius = 0.03, at = [0.0, 0.0, 0.05]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, angles = zxz)]
struct DerivedTop;

#[test]
fn one_spherical_joint_is_the_derived_top() {
    let mut rng = Rng::new(11);
    for _ in 0..1000 {
        // Away from the chart's singularity θ = 0, π.
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.3, 2.8),
            rng.uniform(-3.0, 3.0),
        ];
        let qd = [
            rng.uniform(-5.0, 5.0),
            rng.uniform(-5.0, 5.0),
            rng.uniform(-50.0, 50.0),
        ];
        let state = [q[0], q[1], q[2], qd[0], qd[1], qd[2]];
        let want = DerivedTop.accelerations_unchecked_in(AngleSequence::Zxz, 0.0, &state);
        let got = SphericalTop.accelerations(0.0, &q, &qd).expect("regular");
        let scale = want.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        for k in 0..3 {
            assert!(
                (got[k] - want[k]).abs() <= 1e-13 * scale,
                "q̈[{k}] = {} against the top's {} at q = {q:?}, q̇ = {qd:?}",
                got[k],
                want[k]
            );
        }
        assert_relative_eq!(
            SphericalTop.energy(&q, &qd) - SphericalTop.energy(&[0.0; 3], &[0.0; 3]),
            DerivedTop.energy_in(AngleSequence::Zxz, &state)
                - DerivedTop.energy_in(AngleSequence::Zxz, &[0.0; 6]),
            max_relative = 1e-12
        );
    }
    // φ and ψ are cyclic for the symmetric top, as for #[top].
    let m = SphericalTop.conserved_momenta(&[0.1, 0.7, 0.2], &[1.0, 0.5, 30.0]);
    let t = DerivedTop.conserved_momenta(&[0.1, 0.7, 0.2], &[1.0, 0.5, 30.0]);
    for k in 0..3 {
        match (m[k], t[k]) {
            (Some(a), Some(b)) => assert_relative_eq!(a, b, max_relative = 1e-13),
            (a, b) => assert_eq!(a.is_some(), b.is_some(), "momentum {k}"),
        }
    }
}

/// A gimbal on a slider: every joint kind but the spherical, parts off their axes.
#[derive(Mechanism)]
#[mechanism(gravity = [0.0, -2.0, -9.81])]
#[body(cart, joint = prismatic(axis = [1.0, 1.0, 0.0]), q = s, spring(k = 3.0),
       parts(cuboid(mass = 2.0, size = [0.4, 0.2, 0.1])))]
#[body(outer, parent = cart, joint = revolute(axis = z, at = [0.1, 0.0, 0.05]), q = alpha,
       damper = 0.05, parts(ring(mass = 0.3, radius = 0.2, axis = x, at = [0.0, 0.01, 0.0])))]
#[body(rotor, parent = outer, joint = universal(axes = [x, y], at = [0.0, 0.0, 0.02]),
       q = [beta, gamma], parts(disk(mass = 0.5, radius = 0.1, at = [0.0, 0.02, -0.1])))]
struct GimbalCart;

/// The scene of [`GimbalCart`], built by hand for the run-time model.
fn gimbal_cart_scene(a: &mut Arena) -> MechanismScene {
    let n = |a: &mut Arena, x: f64| a.float(x).expect("finite");
    let v = |a: &mut Arena, x: [f64; 3]| x.map(|c| a.float(c).expect("finite"));
    let diag = |a: &mut Arena, d: [f64; 3]| {
        let z = a.zero();
        let d = d.map(|c| a.float(c).expect("finite"));
        [[d[0], z, z], [z, d[1], z], [z, z, d[2]]]
    };
    let mut scene = MechanismScene::new();
    scene.gravity = Some(v(a, [0.0, -2.0, -9.81]));
    let axis = v(a, [1.0, 1.0, 0.0]);
    let mut cart = MechanismScene::body(
        a,
        "cart",
        Parent::Ground,
        JointKind::Prismatic { axis },
        &["s"],
    );
    cart.mass = n(a, 2.0);
    // A box's moments m (b² + c²)/12, …
    cart.inertia = diag(
        a,
        [
            2.0 * (0.04 + 0.01) / 12.0,
            2.0 * (0.16 + 0.01) / 12.0,
            2.0 * (0.16 + 0.04) / 12.0,
        ],
    );
    let (k, zero) = (n(a, 3.0), a.zero());
    cart.joint.loads[0].spring = Some(precess::mechanism::Spring {
        stiffness: k,
        rest: zero,
    });
    let z = v(a, [0.0, 0.0, 1.0]);
    let mut outer = MechanismScene::body(
        a,
        "outer",
        Parent::Body(0),
        JointKind::Revolute { axis: z },
        &["alpha"],
    );
    outer.joint.at = v(a, [0.1, 0.0, 0.05]);
    outer.mass = n(a, 0.3);
    outer.center = v(a, [0.0, 0.01, 0.0]);
    // A ring about x: m r² on its axis, m r²/2 across.
    outer.inertia = diag(a, [0.3 * 0.04, 0.3 * 0.04 / 2.0, 0.3 * 0.04 / 2.0]);
    outer.joint.loads[0].damper = Some(n(a, 0.05));
    let (x, y) = (v(a, [1.0, 0.0, 0.0]), v(a, [0.0, 1.0, 0.0]));
    let mut rotor = MechanismScene::body(
        a,
        "rotor",
        Parent::Body(1),
        JointKind::Universal { axes: [x, y] },
        &["beta", "gamma"],
    );
    rotor.joint.at = v(a, [0.0, 0.0, 0.02]);
    rotor.mass = n(a, 0.5);
    rotor.center = v(a, [0.0, 0.02, -0.1]);
    // A disk about z: m r²/2 on its axis, m r²/4 across.
    rotor.inertia = diag(a, [0.5 * 0.01 / 4.0, 0.5 * 0.01 / 4.0, 0.5 * 0.01 / 2.0]);
    scene.bodies = vec![cart, outer, rotor];
    scene
}

#[test]
fn the_derived_code_is_the_run_time_model() {
    let mut a = Arena::new();
    let scene = gimbal_cart_scene(&mut a);
    let model = MechanismModel::new(&mut a, &scene, Route::Auto, &[]).expect("derives");
    let mut rng = Rng::new(5);
    for _ in 0..1000 {
        let q: [f64; 4] = std::array::from_fn(|_| rng.uniform(-3.0, 3.0));
        let qd: [f64; 4] = std::array::from_fn(|_| rng.uniform(-4.0, 4.0));
        let got = GimbalCart.accelerations(0.0, &q, &qd).expect("regular");
        let want = model.accelerations(0.0, &q, &qd).expect("regular");
        let scale = want.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        for k in 0..4 {
            assert!(
                (got[k] - want[k]).abs() <= 1e-12 * scale,
                "q̈[{k}] = {} against the model's {}",
                got[k],
                want[k]
            );
        }
        assert_relative_eq!(
            GimbalCart.energy(&q, &qd),
            model.energy(0.0, &q, &qd).expect("finite"),
            max_relative = 1e-12,
            epsilon = 1e-12
        );
    }
}

/// A rod on a hinge about x under a body-fixed and a space-fixed torque.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(rod, joint = revolute(axis = x), q = theta, body_torque = [0.3, 0.2, 0.1],
       space_torque = [0.5, 0.0, 0.7], parts(rod(mass = 2.0, length = 1.0, at = [0.0, 0.0, -0.5])))]
struct Torqued;

#[test]
fn torques_act_through_the_joint_axis() {
    // Only the components along the hinge (x in both frames) turn it.
    let i = 2.0 / 3.0;
    for (th, w) in [(0.3, 1.0), (-2.0, 0.5), (1.4, -3.0)] {
        let want = (-2.0 * G * 0.5 * f64::sin(th) + 0.3 + 0.5) / i;
        let got = Torqued.accelerations(0.0, &[th], &[w]).expect("regular")[0];
        assert_relative_eq!(got, want, max_relative = 1e-13);
        assert_relative_eq!(
            Torqued.power(0.0, &[th], &[w]),
            0.8 * w,
            max_relative = 1e-13
        );
    }
}

/// A ball on a universal joint at its centre, loads on each coordinate.
#[derive(Mechanism)]
#[body(ball, joint = universal(axes = [x, y]), q = [a, b],
       spring(k = [2.0, 3.0], rest = [0.1, -0.2]), damper = [0.5, c], effort = [push, 0.25],
       parts(sphere(mass = 1.0, radius = 0.1)))]
struct LoadedGimbal {
    c: f64,
}

fn push(_: &LoadedGimbal, t: f64, q: &[f64; 2], _qdot: &[f64; 2]) -> f64 {
    t * q[1]
}

#[test]
fn each_coordinate_of_a_gimbal_has_its_own_loads() {
    // A ball about its centre: I = 2/5 m r² on every axis, so T = ½ I (ȧ² + ḃ²) (x and the
    // turned y are perpendicular) and the coordinates decouple.
    let g = LoadedGimbal { c: 0.7 };
    let i = 0.4 * 0.01;
    let mut rng = Rng::new(21);
    for _ in 0..100 {
        let t = rng.uniform(0.0, 3.0);
        let q = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)];
        let qd = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)];
        let got = g.accelerations(t, &q, &qd).expect("regular");
        let a = (-2.0 * (q[0] - 0.1) - 0.5 * qd[0] + t * q[1]) / i;
        let b = (-3.0 * (q[1] + 0.2) - 0.7 * qd[1] + 0.25) / i;
        assert_relative_eq!(
            got[LoadedGimbal::A],
            a,
            max_relative = 1e-12,
            epsilon = 1e-9
        );
        assert_relative_eq!(
            got[LoadedGimbal::B],
            b,
            max_relative = 1e-12,
            epsilon = 1e-9
        );
        let v = 0.5 * 2.0 * (q[0] - 0.1).powi(2) + 0.5 * 3.0 * (q[1] + 0.2).powi(2);
        assert_relative_eq!(
            g.potential(&q) - g.potential(&[0.0, 0.0]),
            v - 0.5 * 2.0 * 0.01 - 0.5 * 3.0 * 0.04,
            max_relative = 1e-12,
            epsilon = 1e-12
        );
    }
}

/// A double pendulum (two point masses) with a spring, a damper and a constant torque on each
/// hinge, all written in the description: its Jacobian is the engine's, exact.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       spring(k = 2.0, rest = 0.1), damper = 0.5, effort = 0.3,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.9]), q = theta2,
       spring(k = 3.0, rest = -0.2), damper = 0.7, effort = 0.25,
       parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct SprungDouble;

/// [`SprungDouble`] with the same loads from user functions ([`upper_load`],
/// [`lower_load`]), on the symbolic route.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1, effort = upper_load,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.9]), q = theta2,
       effort = lower_load, parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct DrivenDouble;

/// [`DrivenDouble`] on the factored route (q̈ through abbreviations).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, route = factored)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1, effort = upper_load,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.9]), q = theta2,
       effort = lower_load, parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct DrivenDoubleFactored;

/// −2 (θ₁ − 0.1) − 0.5 θ̇₁ + 0.3: [`SprungDouble`]'s loads on the shoulder.
fn upper_load<T>(_: &T, _t: f64, q: &[f64; 2], qdot: &[f64; 2]) -> f64 {
    -2.0 * (q[0] - 0.1) - 0.5 * qdot[0] + 0.3
}

/// −3 (θ₂ + 0.2) − 0.7 θ̇₂ + 0.25: [`SprungDouble`]'s loads on the elbow.
fn lower_load<T>(_: &T, _t: f64, q: &[f64; 2], qdot: &[f64; 2]) -> f64 {
    -3.0 * (q[1] + 0.2) - 0.7 * qdot[1] + 0.25
}

/// [`SprungDouble`] without springs or dampers, its constant torques from user functions of
/// time ([`timed_torque`]).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1, effort = timed_torque,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.9]), q = theta2,
       effort = 0.25, parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct TimedDouble;

/// 0.3 (1 + t), whatever the state.
fn timed_torque(_: &TimedDouble, t: f64, _q: &[f64; 2], _qdot: &[f64; 2]) -> f64 {
    0.3 * (1.0 + t)
}

/// [`TimedDouble`] at t = 0, its torques written in the description.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1, effort = 0.3,
       parts(particle(mass = 1.3, at = [0.0, 0.0, -0.9])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.9]), q = theta2,
       effort = 0.25, parts(particle(mass = 0.7, at = [0.0, 0.0, -0.6])))]
struct ConstantDouble;

/// The largest difference between two mechanisms' (∂q̈/∂q, ∂q̈/∂q̇) at random states at
/// time t, relative to the largest entry of the first's.
fn double_jacobian_gap(
    exact: &impl MechanismDynamics<2>,
    other: &impl MechanismDynamics<2>,
    t: f64,
    seed: u64,
) -> f64 {
    let mut rng = Rng::new(seed);
    let mut worst = 0.0_f64;
    for _ in 0..50 {
        let q = [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)];
        let qd = [rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)];
        let (eq, ed) = exact.acceleration_jacobian(t, &q, &qd).expect("exact");
        let (oq, od) = other.acceleration_jacobian(t, &q, &qd).expect("other");
        let scale = eq
            .iter()
            .chain(&ed)
            .flatten()
            .fold(0.0_f64, |m, v| m.max(v.abs()));
        for i in 0..2 {
            for j in 0..2 {
                let gap = (eq[i][j] - oq[i][j]).abs().max((ed[i][j] - od[i][j]).abs());
                worst = worst.max(gap / scale);
            }
        }
    }
    worst
}

/// A tree mechanism with user-function efforts differentiates q̈ exactly with the efforts
/// held and adds (∂q̈/∂τ)(∂τ/∂(q, q̇)), only τ differenced: the same loads written as a
/// spring, a damper and a torque give the engine's exact Jacobian, which it matches to the
/// error of differencing τ alone (on both routes that have exact derivatives), which is
/// printed beside that of the trait's full differencing of q̈.
#[test]
fn a_tree_with_user_efforts_is_exact_but_for_the_functions_own_derivative() {
    let symbolic = double_jacobian_gap(&SprungDouble, &DrivenDouble, 0.0, 17);
    let factored = double_jacobian_gap(&SprungDouble, &DrivenDoubleFactored, 0.0, 17);
    println!("user loads against the described ones: symbolic {symbolic:e}, factored {factored:e}");
    // What differencing all of q̈ (the trait's default) gives on the same states.
    struct Differenced;
    impl MechanismDynamics<2> for Differenced {
        const COORDINATES: [&'static str; 2] = ["theta1", "theta2"];
        const ROUTE: &'static str = "differenced";
        fn accelerations(
            &self,
            t: f64,
            q: &[f64; 2],
            qdot: &[f64; 2],
        ) -> Result<[f64; 2], MechanismError> {
            DrivenDouble.accelerations(t, q, qdot)
        }
        fn accelerations_unchecked(&self, t: f64, q: &[f64; 2], qdot: &[f64; 2]) -> [f64; 2] {
            DrivenDouble.accelerations_unchecked(t, q, qdot)
        }
        fn kinetic(&self, q: &[f64; 2], qdot: &[f64; 2]) -> f64 {
            DrivenDouble.kinetic(q, qdot)
        }
        fn potential(&self, q: &[f64; 2]) -> f64 {
            DrivenDouble.potential(q)
        }
        fn power(&self, t: f64, q: &[f64; 2], qdot: &[f64; 2]) -> f64 {
            DrivenDouble.power(t, q, qdot)
        }
        fn conserved_momenta(&self, q: &[f64; 2], qdot: &[f64; 2]) -> [Option<f64>; 2] {
            DrivenDouble.conserved_momenta(q, qdot)
        }
    }
    let differenced = double_jacobian_gap(&SprungDouble, &Differenced, 0.0, 17);
    println!("full differences of q̈ against the described loads: {differenced:e}");
    // Differencing τ alone leaves its rounding, ε |τ| / h (|τ| up to about 10 here).
    assert!(symbolic < 1e-12, "{symbolic:e}");
    assert!(factored < 1e-12, "{factored:e}");
}

/// Efforts that do not depend on the state difference to exactly zero: the Jacobian is the
/// exact one of the same torques written in the description, to rounding.
#[test]
fn a_tree_effort_free_of_the_state_leaves_the_jacobian_exact() {
    let worst = double_jacobian_gap(&ConstantDouble, &TimedDouble, 0.0, 19);
    println!("torque of time against the described constant: {worst:e}");
    assert!(worst < 1e-14, "{worst:e}");
}
