//! Every derive's `impl Export` against the struct's own Rust methods: the exported C
//! (compiled by `cc -std=c99 -O2 -ffp-contract=off`) and Python (NumPy, all states in one
//! vectorised call) give the bits the derived methods give, on 1000 random states and
//! parameters. These scenes use only + − × ÷, √, sin and cos, which the C library's libm,
//! Rust's std (which calls it) and NumPy on this machine compute alike.

use super::support::{Case, run_c, run_python, worst};
use crate::common::mechanism::{random_inertia, relative_difference};
use crate::common::rng::Rng;
use precess::codegen::{Export, ExportError, Exported};
use precess::contact::{ContactDynamics, Phase};
use precess::free::FreeDynamics;
use precess::mechanism::MechanismDynamics;
use precess::ode::System;
use precess::prelude::*;
use precess::top::TopDynamics;

/// States and parameters drawn by `draw` (the export's order), `count` of them.
pub(super) fn cases(
    e: &Exported,
    count: usize,
    seed: u64,
    draw: impl Fn(&mut Rng, &mut Case),
) -> Vec<Case> {
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
pub(super) fn compare(
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

/// A body whose every product of inertia is a field: its principal frame is found at run
/// time, so its export is Euler's equations in the description axes.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]))]
struct Skewed {
    ixx: f64,
    iyy: f64,
    izz: f64,
    ixy: f64,
    ixz: f64,
    iyz: f64,
}

impl Skewed {
    /// The body of the case's parameters.
    fn of(e: &Exported, c: &Case) -> Skewed {
        let v = |n: &str| c.param(e, n);
        Skewed {
            ixx: v("ixx"),
            iyy: v("iyy"),
            izz: v("izz"),
            ixy: v("ixy"),
            ixz: v("ixz"),
            iyz: v("iyz"),
        }
    }

    /// ω̇ in description axes from the run-time principal frame: R f(Rᵀ ω), f the derived
    /// `euler_rhs_principal` over the moments `principal` found, R its rotation.
    fn reference(&self, w: &Vector3<f64>) -> Vector3<f64> {
        let p = self.principal();
        let r = p.rotation;
        r * self.euler_rhs_principal(&(r.inverse() * w), &Vector3::zeros())
    }
}

/// Cases of `Skewed`: a random positive definite tensor whose principal moments obey the
/// triangle inequality, turned by a random rotation; ω in [−2, 2]³.
fn skewed_cases(e: &Exported, count: usize, seed: u64) -> Vec<Case> {
    cases(e, count, seed, |rng, c| {
        let i = random_inertia(rng);
        for (name, (row, col)) in [
            ("ixx", (0, 0)),
            ("iyy", (1, 1)),
            ("izz", (2, 2)),
            ("ixy", (0, 1)),
            ("ixz", (0, 2)),
            ("iyz", (1, 2)),
        ] {
            let k = e.parameters().iter().position(|p| p == name).expect(name);
            c.p[k] = i[(row, col)];
        }
    })
}

#[test]
fn a_body_of_field_products_of_inertia_exports_euler_in_description_axes_bit_for_bit() {
    let e = Skewed::exported().expect("exported without a principal frame");
    assert_eq!(e.state(), ["omega_1", "omega_2", "omega_3"]);
    let mut fields = e.parameters().to_vec();
    fields.sort();
    assert_eq!(fields, ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]);
    let rhs = e.get("rhs").expect("rhs");
    assert!(rhs.doc().contains("description axes"), "{}", rhs.doc());
    assert_eq!(e.get("jacobian").expect("jacobian").shape(), (3, 3));
    let cases = skewed_cases(&e, 1000, 6);
    let eval = |name: &str| -> Vec<Vec<f64>> {
        cases
            .iter()
            .map(|c| e.eval(name, c.t, &c.y, &c.p).expect("eval"))
            .collect()
    };
    let (rhs, jac) = (eval("rhs"), eval("jacobian"));
    compare("skewed", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}

#[test]
fn a_body_of_field_products_of_inertia_exports_the_principal_frame_equations_rotated() {
    let e = Skewed::exported().expect("exported");
    let cases = skewed_cases(&e, 1000, 7);
    let (mut worst_rhs, mut worst_scaled, mut worst_jac) = (0.0f64, 0.0f64, 0.0f64);
    for c in &cases {
        let s = Skewed::of(&e, c);
        s.validate().expect("a valid body");
        let w = Vector3::new(c.y[0], c.y[1], c.y[2]);
        // ω̇ against the run-time principal frame's, relative to max|ω̇ᵢ| (and to the larger
        // of it and |ω|², ω̇'s scale when the moments are of order one).
        let got = e.eval("rhs", c.t, &c.y, &c.p).expect("rhs");
        let want = s.reference(&w);
        worst_rhs = worst_rhs.max(relative_difference(&got, want.as_slice(), 0.0));
        worst_scaled =
            worst_scaled.max(relative_difference(&got, want.as_slice(), w.norm_squared()));
        // The Jacobian against central differences of the same: ω̇ is quadratic in ω, so
        // the differences are exact but for rounding.
        let jac = e.eval("jacobian", c.t, &c.y, &c.p).expect("jacobian");
        let h = 1e-2;
        for j in 0..3 {
            let step = Vector3::from_fn(|i, _| if i == j { h } else { 0.0 });
            let d = (s.reference(&(w + step)) - s.reference(&(w - step))) / (2.0 * h);
            for i in 0..3 {
                worst_jac = worst_jac.max((jac[3 * i + j] - d[i]).abs() / w.norm());
            }
        }
    }
    println!(
        "skewed: rhs worst {worst_rhs:e} relative ({worst_scaled:e} of max(|ω̇|, |ω|²)), jacobian worst {worst_jac:e} of |ω|"
    );
    assert!(worst_rhs < 1e-13, "{worst_rhs:e}");
    assert!(worst_scaled < 1e-14, "{worst_scaled:e}");
    assert!(worst_jac < 1e-11, "{worst_jac:e}");
}

/// A scene whose export failed: the reason the derive would record.
struct Refused;

impl Export for Refused {
    const EXPORTED: Result<&'static str, &'static str> = Err("a symbol that is not bound");
}

#[test]
fn a_scene_that_could_not_be_exported_is_a_typed_refusal() {
    let err = Refused::c_source().expect_err("no text");
    assert_eq!(
        err,
        ExportError::NotExportable {
            reason: "a symbol that is not bound".to_owned()
        }
    );
    assert!(Refused::state_names().is_err() && Refused::python_module().is_err());
}
