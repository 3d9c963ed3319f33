//! Scenes whose equations read user functions' values (a motor's torque, a user torque):
//! the values are the export's inputs u, which the caller supplies; with the same u the
//! exported functions give the bits of the Rust methods, and `jacobian` is ∂rhs/∂y at fixed
//! u (checked against central differences of `rhs_in` where no Rust Jacobian exists).

use super::derived::{cases, compare};
use super::support::Case;
use precess::codegen::Export;
use precess::contact::{ContactDynamics, Phase};
use precess::free::{AppliedWrench, FreeDynamics, FreeState};
use precess::mechanism::MechanismDynamics;
use precess::prelude::*;
use precess::top::TopDynamics;

/// A gyroscope on a pivot: a wheel spun at a constant rate, two wheels turned by motors
/// whose torques are the fields `torque_a`, `torque_b`, and a user torque of the fields
/// `push` (read by the functions, not by the equations: the export takes them as its inputs
/// u, so both sides see the same values).
#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.01, 0.0, -h], inertia = diag(a, a, c), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, angles = zyx, damping = drag, torque = Gimbal::push,
      rotor(axis = [0, 1, 0], inertia = 0.01, rate = spin),
      rotor(axis = [0, 0, 1], inertia = j_spin, torque = Gimbal::spin_motor),
      rotor(axis = [1, 0, 1], inertia = j_tilt, torque = Gimbal::tilt_motor))]
struct Gimbal {
    m: f64,
    h: f64,
    a: f64,
    c: f64,
    drag: f64,
    spin: f64,
    j_spin: f64,
    j_tilt: f64,
    torque_a: f64,
    torque_b: f64,
    push: [f64; 3],
}

impl Gimbal {
    fn spin_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_a
    }

    fn tilt_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_b
    }

    fn push(&self, _t: f64, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from(self.push)
    }
}

#[test]
fn a_top_with_motors_exports_its_state_derivative_with_the_motor_torques_as_inputs() {
    let e = Gimbal::exported().expect("exported");
    assert_eq!(
        e.state(),
        [
            "yaw",
            "pitch",
            "roll",
            "yaw_dot",
            "pitch_dot",
            "roll_dot",
            "rotor_1",
            "rotor_2"
        ]
    );
    assert_eq!(
        e.inputs(),
        ["u_rotor_1", "u_rotor_2", "torque_x", "torque_y", "torque_z"]
    );
    assert_eq!(Gimbal::input_names().expect("inputs"), e.inputs());
    let mut fields = e.parameters().to_vec();
    fields.sort();
    // The motors' fields are the inputs' values, no parameters.
    assert_eq!(
        fields,
        ["a", "c", "drag", "h", "j_spin", "j_tilt", "m", "spin"]
    );
    let header = e.c_header();
    assert!(header.contains("#define GIMBAL_INPUT_LEN 5\n#define GIMBAL_U_U_ROTOR_1 0"));
    assert!(header.contains(
        "void gimbal_rhs(double t, const double *y, const double *u, const gimbal_params *p, double *out);"
    ));
    assert!(e.python().contains("def rhs(t, y, u, *, "));
    // Wheels light enough that I − Σ J â âᵀ stays positive definite, the pitch away from
    // the chart's gimbal lock at ±π/2 (where the finite differences below lose their digits).
    let cases = cases(&e, 1000, 6, |rng, c| {
        c.y[1] = rng.uniform(-1.2, 1.2);
        for (name, lo, hi) in [
            ("a", 0.5, 1.0),
            ("c", 0.5, 1.0),
            ("j_spin", 0.01, 0.2),
            ("j_tilt", 0.01, 0.2),
        ] {
            let k = e
                .parameters()
                .iter()
                .position(|p| p == name)
                .expect("a parameter");
            c.p[k] = rng.uniform(lo, hi);
        }
    });
    let top = |c: &Case| {
        let v = |n: &str| c.param(&e, n);
        Gimbal {
            m: v("m"),
            h: v("h"),
            a: v("a"),
            c: v("c"),
            drag: v("drag"),
            spin: v("spin"),
            j_spin: v("j_spin"),
            j_tilt: v("j_tilt"),
            torque_a: c.u[0],
            torque_b: c.u[1],
            push: [c.u[2], c.u[3], c.u[4]],
        }
    };
    let rhs_in = |c: &Case, y: &[f64; 8]| {
        let mut d = [0.0; 8];
        TopDynamics::<8>::rhs_in(&top(c), AngleSequence::Zyx, c.t, y, &mut d);
        d
    };
    let mut rhs: Vec<Vec<f64>> = Vec::new();
    let mut jac = Vec::new();
    for c in &cases {
        let y: [f64; 8] = c.y.clone().try_into().expect("8 states");
        let want = rhs_in(c, &y);
        let got = e
            .eval_with_inputs("rhs", c.t, &c.y, &c.u, &c.p)
            .expect("eval");
        assert_eq!(
            got.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            want.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        rhs.push(want.to_vec());
        // The Jacobian at fixed u against central differences of the Rust rhs_in.
        let j = e
            .eval_with_inputs("jacobian", c.t, &c.y, &c.u, &c.p)
            .expect("eval");
        for k in 0..8 {
            let step = 1e-6 * (1.0 + y[k].abs());
            let (mut up, mut down) = (y, y);
            up[k] += step;
            down[k] -= step;
            let (fu, fd) = (rhs_in(c, &up), rhs_in(c, &down));
            for i in 0..8 {
                let fd_ik = (fu[i] - fd[i]) / (2.0 * step);
                let scale = 1.0 + j[i * 8 + k].abs() + want[i].abs();
                assert!(
                    (j[i * 8 + k] - fd_ik).abs() <= 1e-6 * scale,
                    "d rhs_{i}/d y_{k}: {} vs {fd_ik}",
                    j[i * 8 + k]
                );
            }
        }
        jac.push(j);
    }
    compare("driven", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}

/// A heavy top of fields whose user torque is the field `tau` (body axes).
#[derive(RigidBody)]
#[rigid(cuboid(mass = mass, size = [0.1, 0.2, tall], at = [0.01, -0.02, lift]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, torque = Pushed::torque, damping = drag, angles = zxz)]
struct Pushed {
    mass: f64,
    tall: f64,
    lift: f64,
    drag: f64,
    tau: [f64; 3],
}

impl Pushed {
    fn torque(&self, _t: f64, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from(self.tau)
    }
}

#[test]
fn a_top_with_a_user_torque_exports_it_as_three_inputs() {
    let e = Pushed::exported().expect("exported");
    assert_eq!(e.inputs(), ["torque_x", "torque_y", "torque_z"]);
    let cases = cases(&e, 1000, 11, |_, _| {});
    let (mut rhs, mut jac) = (vec![], vec![]);
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let top = Pushed {
            mass: v("mass"),
            tall: v("tall"),
            lift: v("lift"),
            drag: v("drag"),
            tau: [c.u[0], c.u[1], c.u[2]],
        };
        let (q, qd) = ([c.y[0], c.y[1], c.y[2]], [c.y[3], c.y[4], c.y[5]]);
        let acc = top.accelerations_unchecked(c.t, &q, &qd);
        rhs.push(qd.iter().chain(&acc).copied().collect());
        // dq/dt = q̇: the first three rows are (0 | I); `angle_jacobian` holds the torque.
        let mut full: Vec<f64> = (0..3)
            .flat_map(|i| (0..6).map(move |k| if k == i + 3 { 1.0 } else { 0.0 }))
            .collect();
        full.extend(top.angle_jacobian(c.t, &q, &qd).iter().flatten());
        jac.push(full);
    }
    compare("pushed", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}

/// A satellite with every user function a free body takes, each returning fields: a motor,
/// a force (space axes), a torque (description axes) and a wrench of a space and a body part.
#[derive(RigidBody)]
#[rigid(cuboid(mass = m, size = [0.3, 0.2, 0.1]))]
#[free(gravity = 9.81, drag = k, force = Sat::force, torque = Sat::torque, wrench = Sat::wrench,
       rotor(axis = [0, 0, 1], inertia = 0.001, torque = Sat::motor))]
struct Sat {
    m: f64,
    k: f64,
    u: [f64; 16],
}

impl Sat {
    fn part(&self, k: usize) -> Vector3<f64> {
        Vector3::new(self.u[k], self.u[k + 1], self.u[k + 2])
    }

    fn motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.u[0]
    }

    fn force(&self, _t: f64, _s: &FreeState) -> Vector3<f64> {
        self.part(1)
    }

    fn torque(&self, _t: f64, _s: &FreeState) -> Vector3<f64> {
        self.part(4)
    }

    fn wrench(&self, _t: f64, _s: &FreeState) -> AppliedWrench {
        AppliedWrench::space(self.part(7), self.part(10))
            + AppliedWrench::body(self.part(13), Vector3::zeros())
    }
}

#[test]
fn a_free_body_exports_its_motor_force_torque_and_wrench_as_inputs() {
    let e = Sat::exported().expect("exported");
    let parts = |p: &str| ["x", "y", "z"].map(|a| format!("{p}_{a}"));
    let want: Vec<String> = std::iter::once("u_rotor_0".to_owned())
        .chain(parts("force"))
        .chain(parts("torque"))
        .chain(parts("wrench_force_space"))
        .chain(parts("wrench_torque_space"))
        .chain(parts("wrench_force_description"))
        .chain(parts("wrench_torque_description"))
        .collect();
    assert_eq!(e.inputs(), want);
    // The wrench's torque in description axes (the last three inputs) is zero: the test's
    // function gives none.
    let cases = cases(&e, 1000, 12, |_, c| c.u[16..].fill(0.0));
    let mut rhs = vec![];
    for c in &cases {
        let mut u = [0.0; 16];
        u.copy_from_slice(&c.u[..16]);
        let body = Sat {
            m: c.param(&e, "m"),
            k: c.param(&e, "k"),
            u,
        };
        let y: [f64; 14] = c.y.clone().try_into().expect("14 states");
        let mut d = [0.0; 14];
        body.free_rhs(c.t, &y, &mut d);
        rhs.push(d.to_vec());
    }
    compare("sat", &e, &cases, &[("rhs", rhs)], 0);
}

/// A coin rolling on a table under a user couple of fields.
#[derive(RigidBody)]
#[rigid(disk(mass = m, radius = r))]
#[contact(surface = disk_rim(radius = r), law = rolling, gravity = 9.81, torque = Spun::couple)]
struct Spun {
    m: f64,
    r: f64,
    tau: [f64; 3],
}

impl Spun {
    fn couple(&self, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from(self.tau)
    }
}

#[test]
fn a_body_on_a_table_exports_its_user_couple_as_inputs() {
    let e = Spun::exported().expect("exported");
    assert_eq!(e.inputs(), ["couple_x", "couple_y", "couple_z"]);
    let cases = cases(&e, 1000, 13, |rng, c| {
        // A unit quaternion.
        let q: Vec<f64> = (0..4).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        for (y, q) in c.y[4..8].iter_mut().zip(&q) {
            *y = q / n;
        }
    });
    let (mut rhs, mut reaction) = (vec![], vec![]);
    for c in &cases {
        let coin = Spun {
            m: c.param(&e, "m"),
            r: c.param(&e, "r"),
            tau: [c.u[0], c.u[1], c.u[2]],
        };
        let y: [f64; 11] = c.y.clone().try_into().expect("11 states");
        let mut d = [0.0; 11];
        coin.phase_rhs(Phase::Rolling, c.t, &y, &mut d);
        rhs.push(d.to_vec());
        let f = coin.reaction(Phase::Rolling, &y);
        reaction.push(vec![f.normal, f.friction.x, f.friction.y, f.friction.z]);
    }
    compare(
        "spun",
        &e,
        &cases,
        &[("rhs_rolling", rhs), ("reaction_rolling", reaction)],
        0,
    );
}

/// A double pendulum whose lower hinge is driven by a user effort of a field.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = y), q = a1, parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = y, at = [0.0, 0.0, -l1]), q = a2,
       effort = Driven2::drive, parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct Driven2 {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
    tau: f64,
}

impl Driven2 {
    fn drive(&self, _t: f64, _q: &[f64; 2], _qd: &[f64; 2]) -> f64 {
        self.tau
    }
}

#[test]
fn a_mechanism_exports_its_user_efforts_as_inputs() {
    let e = Driven2::exported().expect("exported");
    assert_eq!(e.inputs(), ["effort_0"]);
    let cases = cases(&e, 1000, 14, |_, _| {});
    let mut rhs = vec![];
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let s = Driven2 {
            m1: v("m1"),
            l1: v("l1"),
            m2: v("m2"),
            l2: v("l2"),
            tau: c.u[0],
        };
        let a = s.accelerations_unchecked(c.t, &[c.y[0], c.y[1]], &[c.y[2], c.y[3]]);
        rhs.push(vec![c.y[2], c.y[3], a[0], a[1]]);
    }
    compare("effort", &e, &cases, &[("rhs", rhs)], 0);
}
