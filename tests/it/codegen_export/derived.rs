//! Every derive's `impl Export` against the struct's own Rust methods: the exported C
//! (compiled by `cc -std=c99 -O2 -ffp-contract=off`) and Python (NumPy, all states in one
//! vectorised call) give the bits the derived methods give, on 1000 random states and
//! parameters. These scenes use only + − × ÷, √, sin and cos, which the C library's libm,
//! Rust's std (which calls it) and NumPy on this machine compute alike.

use super::support::{Case, run_c, run_python, worst};
use crate::common::rng::Rng;
use nalgebra::{DMatrix, DVector};
use precess::codegen::{Export, ExportError, Exported};
use precess::contact::{ContactDynamics, Phase};
use precess::free::FreeDynamics;
use precess::mechanism::MechanismDynamics;
use precess::mechanism::rolling::RollingDynamics;
use precess::ode::System;
use precess::prelude::*;
use precess::top::TopDynamics;

/// States and parameters drawn by `draw` (the export's order), `count` of them.
fn cases(e: &Exported, count: usize, seed: u64, draw: impl Fn(&mut Rng, &mut Case)) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let mut c = Case {
                t: rng.uniform(0.0, 10.0),
                y: (0..e.state().len())
                    .map(|_| rng.uniform(-2.0, 2.0))
                    .collect(),
                u: (0..e.inputs().len())
                    .map(|_| rng.uniform(-2.0, 2.0))
                    .collect(),
                p: (0..e.parameters().len())
                    .map(|_| rng.uniform(0.05, 1.0))
                    .collect(),
            };
            draw(&mut rng, &mut c);
            c
        })
        .collect()
}

/// Compares each of `functions` (export name, the Rust outputs per case) in C and Python,
/// printing the worst distance, and asserts it is at most `max_ulps`.
fn compare(
    test: &str,
    e: &Exported,
    cases: &[Case],
    functions: &[(&str, Vec<Vec<f64>>)],
    max_ulps: u64,
) {
    for (lang, got) in [
        ("C", run_c(test, e, cases)),
        ("Python", run_python(test, e, cases)),
    ] {
        let Some(got) = got else { continue };
        for (name, want) in functions {
            let (w, n) = worst(e, &got, name, want);
            println!("{test}: {lang} {name}: {n} values, worst {w} ulp");
            assert!(w <= max_ulps, "{test}: {lang} {name} differs by {w} ulp");
        }
    }
}

/// A heavy top of fields with damping and a body-fixed torque.
#[derive(RigidBody)]
#[rigid(cuboid(mass = mass, size = [wide, deep, tall], at = [0.01, -0.02, lift]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, body_torque = [0.01, 0.0, spin_up], damping = drag, angles = zxz)]
struct ExportedBrick {
    mass: f64,
    wide: f64,
    deep: f64,
    tall: f64,
    lift: f64,
    spin_up: f64,
    drag: f64,
}

#[test]
fn a_top_exports_its_state_derivative_and_jacobian_bit_for_bit() {
    let e = ExportedBrick::exported().expect("exported");
    assert_eq!(e.name(), "exported_brick");
    assert_eq!(
        e.state(),
        ["phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot"]
    );
    let mut fields = e.parameters().to_vec();
    fields.sort();
    assert_eq!(
        fields,
        ["deep", "drag", "lift", "mass", "spin_up", "tall", "wide"]
    );
    let cases = cases(&e, 1000, 1, |_, _| {});
    let mut rhs: Vec<Vec<f64>> = Vec::new();
    let mut jac = Vec::new();
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let top = ExportedBrick {
            mass: v("mass"),
            wide: v("wide"),
            deep: v("deep"),
            tall: v("tall"),
            lift: v("lift"),
            spin_up: v("spin_up"),
            drag: v("drag"),
        };
        let (q, qd) = ([c.y[0], c.y[1], c.y[2]], [c.y[3], c.y[4], c.y[5]]);
        let acc = top.accelerations_unchecked(c.t, &q, &qd);
        rhs.push(qd.iter().chain(&acc).copied().collect());
        let j = top.angle_jacobian(c.t, &q, &qd);
        // dq/dt = q̇: the first three rows are (0 | I).
        let mut full: Vec<f64> = (0..3)
            .flat_map(|i| (0..6).map(move |k| if k == i + 3 { 1.0 } else { 0.0 }))
            .collect();
        full.extend(j.iter().flatten());
        jac.push(full);
    }
    // The interpreter of the exported programs is the Rust evaluation too.
    for (c, want) in cases.iter().zip(&rhs) {
        let got = e.eval("rhs", c.t, &c.y, &c.p).expect("eval");
        assert_eq!(
            got.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            want.iter().map(|x: &f64| x.to_bits()).collect::<Vec<_>>()
        );
    }
    compare("top", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}

/// A tippe top whose every value is a field: a sphere of radius r centred 0.3 r above the
/// centre of mass, gliding with viscous friction c.
#[derive(RigidBody)]
#[rigid(body(mass = m, inertia = diag(i1, i1, i3)))]
#[contact(surface = sphere(radius = r, center = [0.0, 0.0, 0.3 * r]), law = sliding(viscous = c), gravity = 9.81)]
struct Tippe {
    m: f64,
    i1: f64,
    i3: f64,
    r: f64,
    c: f64,
}

#[test]
fn a_body_on_a_table_exports_its_phase_reaction_energy_and_jellett_bit_for_bit() {
    let e = Tippe::exported().expect("exported");
    let mut fields = e.parameters().to_vec();
    fields.sort();
    assert_eq!(fields, ["c", "i1", "i3", "m", "r"]);
    let names: Vec<&str> = e.functions().iter().map(|f| f.name()).collect();
    assert_eq!(
        names,
        [
            "rhs_sliding",
            "reaction_sliding",
            "energy_sliding",
            "jellett"
        ]
    );
    let cases = cases(&e, 1000, 2, |rng, c| {
        // A unit quaternion, ω up to 200 rad/s.
        let q: Vec<f64> = (0..4).map(|_| rng.uniform(-1.0, 1.0)).collect();
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        for (y, q) in c.y[4..8].iter_mut().zip(&q) {
            *y = q / n;
        }
        for w in &mut c.y[8..11] {
            *w = rng.uniform(-200.0, 200.0);
        }
    });
    let (mut rhs, mut reaction, mut energy, mut jellett) = (vec![], vec![], vec![], vec![]);
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let top = Tippe {
            m: v("m"),
            i1: v("i1"),
            i3: v("i3"),
            r: v("r"),
            c: v("c"),
        };
        let y: [f64; 11] = c.y.clone().try_into().expect("11 states");
        let mut d = [0.0; 11];
        top.phase_rhs(Phase::Sliding, c.t, &y, &mut d);
        rhs.push(d.to_vec());
        let r = top.reaction(Phase::Sliding, &y);
        reaction.push(vec![r.normal, r.friction.x, r.friction.y, r.friction.z]);
        energy.push(vec![top.energy(Phase::Sliding, &y)]);
        jellett.push(vec![top.jellett(&y)]);
    }
    compare(
        "tippe",
        &e,
        &cases,
        &[
            ("rhs_sliding", rhs),
            ("reaction_sliding", reaction),
            ("energy_sliding", energy),
            ("jellett", jellett),
        ],
        0,
    );
}

/// A gyroscope on a pivot: a wheel spun at a constant rate, and two wheels turned by motors
/// whose torques are the fields `torque_a`, `torque_b` (read by the motors, not by the
/// equations: the export takes them as its inputs u, so both sides see the same torques).
#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.01, 0.0, -h], inertia = diag(a, a, c), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, angles = zyx, damping = drag,
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
}

impl Gimbal {
    fn spin_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_a
    }

    fn tilt_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_b
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
    assert_eq!(e.inputs(), ["u_rotor_1", "u_rotor_2"]);
    assert_eq!(Gimbal::input_names().expect("inputs"), e.inputs());
    let mut fields = e.parameters().to_vec();
    fields.sort();
    // The motors' fields are the inputs' values, no parameters.
    assert_eq!(
        fields,
        ["a", "c", "drag", "h", "j_spin", "j_tilt", "m", "spin"]
    );
    let header = e.c_header();
    assert!(header.contains("#define GIMBAL_INPUT_LEN 2\n#define GIMBAL_U_U_ROTOR_1 0"));
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

/// A ball in flight under gravity and linear drag.
#[derive(RigidBody)]
#[rigid(cuboid(mass = m, size = [0.1, 0.2, 0.3]))]
#[free(gravity = 9.81, drag = c)]
struct Flying {
    m: f64,
    c: f64,
}

#[test]
fn a_free_body_exports_its_state_derivative_and_energy_bit_for_bit() {
    let e = Flying::exported().expect("exported");
    let cases = cases(&e, 1000, 3, |_, _| {});
    let (mut rhs, mut energy) = (vec![], vec![]);
    for c in &cases {
        let body = Flying {
            m: c.param(&e, "m"),
            c: c.param(&e, "c"),
        };
        let y: [f64; 13] = c.y.clone().try_into().expect("13 states");
        let mut d = [0.0; 13];
        body.free_rhs(c.t, &y, &mut d);
        rhs.push(d.to_vec());
        energy.push(vec![FreeDynamics::energy(&body, &y)]);
    }
    compare("free", &e, &cases, &[("rhs", rhs), ("energy", energy)], 0);
}

/// Two point masses on rods of field lengths, swinging about y.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = y), q = theta1, parts(particle(mass = m1, at = [0.0, 0.0, -l1])))]
#[body(lower, parent = upper, joint = revolute(axis = y, at = [0.0, 0.0, -l1]), q = theta2, parts(particle(mass = m2, at = [0.0, 0.0, -l2])))]
struct Swing {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
}

#[test]
fn a_mechanism_exports_its_state_derivative_bit_for_bit() {
    let e = Swing::exported().expect("exported");
    assert_eq!(e.state(), ["theta1", "theta2", "theta1_dot", "theta2_dot"]);
    let cases = cases(&e, 1000, 4, |_, _| {});
    let mut rhs = vec![];
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let s = Swing {
            m1: v("m1"),
            l1: v("l1"),
            m2: v("m2"),
            l2: v("l2"),
        };
        let a = s.accelerations_unchecked(c.t, &[c.y[0], c.y[1]], &[c.y[2], c.y[3]]);
        rhs.push(vec![c.y[2], c.y[3], a[0], a[1]]);
    }
    compare("mechanism", &e, &cases, &[("rhs", rhs)], 0);
}

/// A disk of fields rolling on its rim: slides along x, y and z carry the hub, a spherical
/// joint turns the disk (n = 6 coordinates, 3 rows: no slip along x and y, the height; 3
/// free speeds).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [yaw, pitch, roll])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y, parts(particle(mass = 0.0)))]
#[body(slide_z, parent = slide_y, joint = prismatic(axis = z), q = z, parts(particle(mass = 0.0)))]
#[body(disk, parent = slide_z, joint = spherical(sequence = zyx), q = [yaw, pitch, roll],
       parts(disk(mass = m, radius = r)), rolls = disk_rim(radius = r, axle = z))]
struct RollingCoin {
    m: f64,
    r: f64,
}

#[test]
fn a_rolling_mechanism_exports_the_pieces_of_maggis_equations_bit_for_bit() {
    let e = RollingCoin::exported().expect("exported");
    // `y` is the emitted code's state array: the coordinate gets a trailing `_`.
    assert_eq!(e.state()[..6], ["x", "y_", "z", "yaw", "pitch", "roll"]);
    let dots = ["x", "y", "z", "yaw", "pitch", "roll"].map(|q| format!("{q}_dot"));
    assert_eq!(e.state()[6..], dots);
    let fns: Vec<&str> = e.functions().iter().map(|f| f.name()).collect();
    assert_eq!(
        fns,
        [
            "mass",
            "forcing",
            "constraints",
            "rate_terms",
            "heights",
            "energy"
        ]
    );
    // Leans up to a radian, so the disk stands (the projection below needs it).
    let cases = cases(&e, 1000, 8, |rng, c| {
        c.y[4] = rng.uniform(-1.0, 1.0);
        c.y[5] = rng.uniform(-1.0, 1.0);
    });
    let coin = |c: &Case| RollingCoin {
        m: c.param(&e, "m"),
        r: c.param(&e, "r"),
    };
    let split = |c: &Case| -> ([f64; 6], [f64; 6]) {
        (
            c.y[..6].try_into().expect("q"),
            c.y[6..].try_into().expect("q̇"),
        )
    };
    let (mut mass, mut forcing, mut rows, mut rate_terms, mut heights, mut energy) =
        (vec![], vec![], vec![], vec![], vec![], vec![]);
    for c in &cases {
        let (w, (q, qd)) = (coin(c), split(c));
        let (mm, f) = RollingDynamics::<6, 3, 3>::mass_forcing(&w, c.t, &q, &qd);
        // nalgebra is column-major; the export writes a matrix row by row.
        mass.push(mm.transpose().as_slice().to_vec());
        forcing.push(f.as_slice().to_vec());
        let (a, b) = RollingDynamics::<6, 3, 3>::constraint_rows(&w, &q, &qd);
        rows.push(a.transpose().as_slice().to_vec());
        rate_terms.push(b.as_slice().to_vec());
        heights.push(RollingDynamics::<6, 3, 3>::heights(&w, &q).to_vec());
        energy.push(vec![RollingDynamics::<6, 3, 3>::energy(&w, &q, &qd)]);
    }
    // Maggi's projection as docs/export.md writes it, over the exported pieces, against the
    // Rust rolling rhs (`derivative`), from (q, u): u the free speeds (yaw, pitch, roll).
    let mut worst_projection = 0.0_f64;
    for c in cases.iter().take(200) {
        let w = coin(c);
        let (q, _) = split(c);
        let u = [c.y[9], c.y[10], c.y[11]];
        let (ind, dep) = ([3, 4, 5], [0, 1, 2]);
        let ev = |name: &str, qd: &[f64]| {
            let y: Vec<f64> = q.iter().chain(qd).copied().collect();
            e.eval(name, c.t, &y, &c.p).expect("eval")
        };
        let a = DMatrix::from_row_slice(3, 6, &ev("constraints", &[0.0; 6]));
        let block = |cols: [usize; 3]| DMatrix::from_fn(3, 3, |i, j| a[(i, cols[j])]);
        let a_d = block(dep).lu();
        // S: q̇ = S u, S_I = 1, S_D = −A_D⁻¹ A_I.
        let s_d = -a_d.solve(&block(ind)).expect("A_D regular");
        let mut s = DMatrix::zeros(6, 3);
        for j in 0..3 {
            s[(ind[j], j)] = 1.0;
            for i in 0..3 {
                s[(dep[i], j)] = s_d[(i, j)];
            }
        }
        let qd = &s * DVector::from_column_slice(&u);
        let mm = DMatrix::from_row_slice(6, 6, &ev("mass", qd.as_slice()));
        let f = DVector::from_vec(ev("forcing", qd.as_slice()));
        let b = DVector::from_vec(ev("rate_terms", qd.as_slice()));
        // s₀: the accelerations at u̇ = 0, s₀_I = 0, s₀_D = −A_D⁻¹ Ȧq̇.
        let s0_d = -a_d.solve(&b).expect("A_D regular");
        let mut s0 = DVector::zeros(6);
        for i in 0..3 {
            s0[dep[i]] = s0_d[i];
        }
        let k = s.transpose() * &mm * &s;
        let rhs = s.transpose() * (f - &mm * s0);
        let ud = k.lu().solve(&rhs).expect("K regular");
        let (want_qd, want_ud) = w.derivative(c.t, &q, &u).expect("the coin stands");
        for (got, want) in qd
            .iter()
            .chain(ud.iter())
            .zip(want_qd.iter().chain(&want_ud))
        {
            let d = (got - want).abs() / (1.0 + want.abs());
            assert!(d <= 1e-12, "{got} vs {want}");
            worst_projection = worst_projection.max(d);
        }
    }
    println!(
        "rolling: the projection over the exported pieces against derivative: {worst_projection:e}"
    );
    compare(
        "rolling",
        &e,
        &cases,
        &[
            ("mass", mass),
            ("forcing", forcing),
            ("constraints", rows),
            ("rate_terms", rate_terms),
            ("heights", heights),
            ("energy", energy),
        ],
        0,
    );
}

/// A box of fields, with the Taylor system of its torque-free Euler equations.
#[derive(RigidBody)]
#[rigid(cuboid(mass = m, size = [a, b, c]), taylor = 20)]
struct Brick3 {
    m: f64,
    a: f64,
    b: f64,
    c: f64,
}

#[test]
fn a_body_exports_its_euler_equations_bit_for_bit() {
    let e = Brick3::exported().expect("exported");
    assert_eq!(e.state(), ["omega_1", "omega_2", "omega_3"]);
    let cases = cases(&e, 1000, 5, |_, _| {});
    let mut rhs = vec![];
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let b = Brick3 {
            m: v("m"),
            a: v("a"),
            b: v("b"),
            c: v("c"),
        };
        let mut d = [0.0; 3];
        System::<3>::rhs(&b, c.t, &[c.y[0], c.y[1], c.y[2]], &mut d);
        rhs.push(d.to_vec());
    }
    compare("euler", &e, &cases, &[("rhs", rhs)], 0);
}

/// A top whose torque is a Rust function: its value cannot be exported.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.3]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, torque = twist)]
struct Twisted;

fn twist(_: &Twisted, _t: f64, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(0.0, 0.0, 0.1)
}

#[test]
fn a_user_function_is_a_typed_refusal_not_a_wrong_export() {
    let err = Twisted::c_source().expect_err("a user torque cannot be exported");
    let ExportError::NotExportable { reason } = &err else {
        panic!("{err:?}");
    };
    assert!(reason.contains("u0"), "{reason}");
    assert!(Twisted::state_names().is_err());
}
