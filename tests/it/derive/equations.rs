//! The equations a derived top prints (`TopDynamics::equations`): the heavy symmetric top in
//! its textbook form, every line of general tops read back and evaluated against the
//! generated code, the grouping by parameter, sin² where it is shorter, the operation counts
//! against the programs counted here, and the same strings from the run-time API.

use crate::common;

use std::collections::HashMap;

use common::latex::{evaluate, read_symbols, top_level_symbols, top_level_terms};
use common::rng::Rng;
use precess::codegen::{Op, OpCount, Program, Typeset, latex};
use precess::prelude::*;
use precess::rigid::AngleSequence;
use precess::sym::Arena;
use precess::top::TopScene;

/// The heavy symmetric top with the textbook's names: I₁ = I₂ and I₃ about the pivot, the
/// centre of mass at l on the symmetry axis.
#[allow(non_snake_case)]
#[derive(RigidBody)]
#[rigid(
    body(mass = M, at = [0.0, 0.0, l], inertia = diag(I_1, I_1, I_3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g)]
struct Heavy {
    I_1: f64,
    I_3: f64,
    M: f64,
    g: f64,
    l: f64,
}

/// A general top: the full tensor about the pivot and the centre of mass from fields, damped.
#[allow(non_snake_case)]
#[derive(RigidBody)]
#[rigid(
    body(mass = M, at = [x, y, z], inertia = [[A, F, E], [F, B, D], [E, D, C]], about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, damping = k)]
struct General {
    A: f64,
    B: f64,
    C: f64,
    D: f64,
    E: f64,
    F: f64,
    M: f64,
    x: f64,
    y: f64,
    z: f64,
    g: f64,
    k: f64,
}

/// A brick off its axis under every kind of torque, with literals among its values: its
/// moments are named (`I_{xx} = …`) and printed among the definitions.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = m, size = [a, b, c], at = [0.01, -0.02, h]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(
    gravity = 9.81,
    body_torque = [0.01, 0.0, tau],
    space_torque = [0.0, 0.02, 0.0],
    damping = k,
    torque = push,
)]
struct Lopsided {
    m: f64,
    a: f64,
    b: f64,
    c: f64,
    h: f64,
    tau: f64,
    k: f64,
}

/// The user torque of [`Lopsided`], constant so the test knows τ.
fn push(_: &Lopsided, _t: f64, _r: &Matrix3<f64>, _w: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(0.03, -0.01, 0.05)
}

const HEAVY: Heavy = Heavy {
    I_1: 1.3,
    I_3: 0.45,
    M: 0.8,
    g: 9.81,
    l: 0.35,
};

const GENERAL: General = General {
    A: 2.0,
    B: 2.6,
    C: 1.1,
    D: 0.1,
    E: -0.15,
    F: 0.2,
    M: 1.4,
    x: 0.05,
    y: -0.03,
    z: 0.4,
    g: 9.81,
    k: 0.07,
};

const LOPSIDED: Lopsided = Lopsided {
    m: 0.9,
    a: 0.05,
    b: 0.08,
    c: 0.12,
    h: 0.2,
    tau: 0.004,
    k: 0.02,
};

/// Goldstein's heavy symmetric top (Classical Mechanics, §5.7), written out by hand in the
/// paper form: L = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² − M g l cos θ; each
/// equation `Σⱼ Mᵢⱼ q̈ⱼ = fᵢ` with its terms grouped by parameter (I₁, I₃, then M g l, the
/// parameters of a group in alphabetical order), a group's common factor outside its
/// parentheses and, inside, terms with fewer sines and cosines first. The φ and ψ equations
/// are d/dt p_φ = 0 and I₃ ω̇₃ = 0 differentiated out (ω₃ = ψ̇ + φ̇ cos θ); the θ equation is
/// Goldstein's I₁ θ̈ = I₁ φ̇² sin θ cos θ − I₃ ω₃ φ̇ sin θ + M g l sin θ.
#[test]
fn heavy_top_prints_the_textbook_equations() {
    let eq = HEAVY.equations();
    assert_eq!(
        eq.lagrangian,
        r"L = \frac{1}{2} I_{1} \left(\dot{\theta}^{2} + \dot{\phi}^{2} \sin^{2}\theta\right) + \frac{1}{2} I_{3} \left(\dot{\psi} + \dot{\phi} \cos\theta\right)^{2} - M g l \cos\theta"
    );
    let equations = [
        r"I_{1} \ddot{\phi} \sin^{2}\theta + I_{3} \cos\theta \left(\ddot{\psi} + \ddot{\phi} \cos\theta\right) = -2 I_{1} \dot{\phi} \dot{\theta} \sin\theta \cos\theta + I_{3} \dot{\theta} \sin\theta \left(\dot{\psi} + 2 \dot{\phi} \cos\theta\right)",
        r"I_{1} \ddot{\theta} = I_{1} \dot{\phi}^{2} \sin\theta \cos\theta - I_{3} \dot{\phi} \sin\theta \left(\dot{\psi} + \dot{\phi} \cos\theta\right) + M g l \sin\theta",
        r"I_{3} \left(\ddot{\psi} + \ddot{\phi} \cos\theta\right) = I_{3} \dot{\phi} \dot{\theta} \sin\theta",
    ];
    assert_eq!(eq.equations.len(), 3);
    for (printed, expected) in eq.equations.iter().zip(equations) {
        assert_eq!(printed, expected);
    }
    // p_φ = I₁ φ̇ sin²θ + I₃ ω₃ cos θ and p_ψ = I₃ ω₃, the conserved momenta.
    assert_eq!(
        eq.conserved.as_ref(),
        [
            r"p_{\phi} = I_{1} \dot{\phi} \sin^{2}\theta + I_{3} \cos\theta \left(\dot{\psi} + \dot{\phi} \cos\theta\right)",
            r"p_{\psi} = I_{3} \left(\dot{\psi} + \dot{\phi} \cos\theta\right)",
        ]
    );
    // θ̈ is the θ equation divided by I₁.
    assert_eq!(
        eq.accelerations[1],
        r"\ddot{\theta} = \frac{I_{1} \dot{\phi}^{2} \sin\theta \cos\theta - I_{3} \dot{\phi} \sin\theta \left(\dot{\psi} + \dot{\phi} \cos\theta\right) + M g l \sin\theta}{I_{1}}"
    );
    assert!(eq.definitions.is_empty());
}

/// Every printed line of three tops, read back by the evaluator below and evaluated at
/// random states, agrees with the generated code: Σⱼ Mᵢⱼ q̈ⱼ = fᵢ with q̈ from
/// `accelerations_unchecked`, each q̈ line with `accelerations_unchecked`, L with E − 2V (E from `energy`, V = M g
/// (R c)·ẑ from `rotation_in`), each momentum with `conserved_momenta`.
#[test]
fn every_line_evaluates_to_the_generated_code() {
    let heavy = [
        ("I_{1}", HEAVY.I_1),
        ("I_{3}", HEAVY.I_3),
        ("M", HEAVY.M),
        ("g", HEAVY.g),
        ("l", HEAVY.l),
    ];
    check_lines(&HEAVY, &heavy, [0.0; 3], HEAVY.g, 1);
    let general = [
        ("A", GENERAL.A),
        ("B", GENERAL.B),
        ("C", GENERAL.C),
        ("D", GENERAL.D),
        ("E", GENERAL.E),
        ("F", GENERAL.F),
        ("M", GENERAL.M),
        ("x", GENERAL.x),
        ("y", GENERAL.y),
        ("z", GENERAL.z),
        ("g", GENERAL.g),
        ("k", GENERAL.k),
    ];
    check_lines(&GENERAL, &general, [0.0; 3], GENERAL.g, 2);
    let lopsided = [
        ("m", LOPSIDED.m),
        ("a", LOPSIDED.a),
        ("b", LOPSIDED.b),
        ("c", LOPSIDED.c),
        ("h", LOPSIDED.h),
        ("\\tau", LOPSIDED.tau),
        ("k", LOPSIDED.k),
    ];
    let tau = push(&LOPSIDED, 0.0, &Matrix3::identity(), &Vector3::zeros());
    assert!(!LOPSIDED.equations().definitions.is_empty());
    check_lines(&LOPSIDED, &lopsided, tau.into(), 9.81, 3);
}

fn check_lines<T: TopDynamics + RigidBody>(
    top: &T,
    fields: &[(&str, f64)],
    tau: [f64; 3],
    g: f64,
    seed: u64,
) {
    let eq = top.equations();
    let mut vars: HashMap<String, f64> = fields.iter().map(|&(n, v)| (n.to_owned(), v)).collect();
    for (i, t) in tau.iter().enumerate() {
        vars.insert(format!("\\tau_{{{}}}", i + 1), *t);
    }
    // Named constants read exactly from `values`; their definitions give them to six digits.
    for (symbol, _) in eq.values.iter() {
        let v = eq.value(symbol).expect("a number");
        vars.insert(symbol.to_string(), v);
    }
    // Definitions may name each other: evaluate until every one is known.
    let mut pending: Vec<&str> = eq
        .definitions
        .iter()
        .map(AsRef::as_ref)
        .filter(|line| {
            let (name, value) = line.split_once(" = ").expect("a definition");
            let Some(&exact) = vars.get(name) else {
                return true;
            };
            let read = eval_ok(value, &vars);
            assert!(
                (read - exact).abs() <= 5e-6 * exact.abs(),
                "{line} vs {exact}"
            );
            false
        })
        .collect();
    while !pending.is_empty() {
        let before = pending.len();
        pending.retain(|line| {
            let (name, value) = line.split_once(" = ").expect("a definition");
            match evaluate(value, &vars) {
                Ok(v) => {
                    vars.insert(name.to_owned(), v);
                    false
                }
                Err(_) => true,
            }
        });
        assert!(pending.len() < before, "unresolved definitions {pending:?}");
    }
    let mut rng = Rng::new(seed);
    for _ in 0..20 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(0.3, 2.8),
            rng.uniform(-3.0, 3.0),
        ];
        let q_dot = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        ];
        let q_ddot = top.accelerations_unchecked(0.0, &q, &q_dot);
        for (k, name) in ["\\phi", "\\theta", "\\psi"].iter().enumerate() {
            vars.insert((*name).to_owned(), q[k]);
            vars.insert(format!("\\dot{{{name}}}"), q_dot[k]);
            vars.insert(format!("\\ddot{{{name}}}"), q_ddot[k]);
        }
        for line in eq.equations.iter() {
            let (lhs, rhs) = line.split_once(" = ").expect("an equation");
            let (l, r) = (eval_ok(lhs, &vars), eval_ok(rhs, &vars));
            assert_close(l, r, line);
        }
        for (line, a) in eq.accelerations.iter().zip(q_ddot) {
            let (_, rhs) = line.split_once(" = ").expect("an equation");
            assert_close(eval_ok(rhs, &vars), a, line);
        }
        let r = top.rotation_in(T::SEQUENCE, &q);
        let height = (r * top.center_of_mass()).z;
        let potential = top.mass() * g * height;
        let (_, lagrangian) = eq.lagrangian.split_once(" = ").expect("L = …");
        let expected = top.energy(&q, &q_dot) - 2.0 * potential;
        assert_close(eval_ok(lagrangian, &vars), expected, &eq.lagrangian);
        let momenta: Vec<f64> = top
            .conserved_momenta(&q, &q_dot)
            .into_iter()
            .flatten()
            .collect();
        assert_eq!(momenta.len(), eq.conserved.len());
        for (line, p) in eq.conserved.iter().zip(momenta) {
            let (_, rhs) = line.split_once(" = ").expect("an equation");
            assert_close(eval_ok(rhs, &vars), p, line);
        }
    }
}

fn eval_ok(s: &str, vars: &HashMap<String, f64>) -> f64 {
    evaluate(s, vars).unwrap_or_else(|e| panic!("{e} in {s}"))
}

fn assert_close(a: f64, b: f64, what: &str) {
    let scale = 1.0 + a.abs().max(b.abs());
    assert!(
        (a - b).abs() <= 1e-9 * scale,
        "{a} vs {b} (difference {}) for {what}",
        a - b
    );
}

/// No two terms at the top level of a side of an equation carry the same parameters: the
/// terms of each set of parameters are gathered in one group.
#[test]
fn every_parameter_set_appears_once_per_side() {
    let heavy = ["I_{1}", "I_{3}", "M", "g", "l"];
    let general = ["A", "B", "C", "D", "E", "F", "M", "x", "y", "z", "g", "k"];
    for (eq, params) in [
        (HEAVY.equations(), &heavy[..]),
        (GENERAL.equations(), &general[..]),
    ] {
        let lines = std::iter::once(eq.lagrangian.as_ref())
            .chain(eq.equations.iter().map(AsRef::as_ref))
            .chain(eq.conserved.iter().map(AsRef::as_ref));
        let mut groups_seen = 0;
        for line in lines {
            let (lhs, rhs) = line.split_once(" = ").expect("an equation");
            for side in [lhs, rhs] {
                let mut seen: Vec<Vec<String>> = Vec::new();
                for term in top_level_terms(side) {
                    let mut set: Vec<String> = top_level_symbols(term)
                        .into_iter()
                        .filter(|s| params.contains(&s.as_str()))
                        .collect();
                    set.sort();
                    assert!(!seen.contains(&set), "{set:?} twice in {side}");
                    seen.push(set);
                    groups_seen += usize::from(term.contains("\\left("));
                }
            }
        }
        // The check is not vacuous: parameters do gather terms into groups.
        assert!(groups_seen > 3, "{groups_seen}");
    }
    // Every parameter of the general top is printed somewhere.
    let eq = GENERAL.equations();
    let all: Vec<String> = eq.lines().flat_map(read_symbols).collect();
    for p in general {
        assert!(all.iter().any(|s| s == p), "{p}");
    }
}

/// The engine keeps sin θ to degree one (sin² θ is 1 − cos² θ there); the printed lines use
/// sin² θ where that is shorter, and keep cos² θ where it is not.
#[test]
fn sin_squared_is_printed_where_shorter() {
    let mut a = Arena::new();
    let scene = heavy_scene(&mut a);
    let top = scene.derive(&mut a).expect("derives");
    let l = a.sub(top.kinetic, top.potential);
    let engine = format!("L = {}", latex(&a, l));
    let eq = HEAVY.equations();
    assert!(
        !engine.contains(r"\sin^{2}") && engine.contains(r"\cos^{2}"),
        "{engine}"
    );
    assert!(eq.lagrangian.contains(r"\dot{\phi}^{2} \sin^{2}\theta"));
    assert!(eq.lagrangian.len() < engine.len());
    // I₁ φ̈ (1 − cos² θ) prints as I₁ φ̈ sin² θ.
    assert!(eq.equations[0].starts_with(r"I_{1} \ddot{\phi} \sin^{2}\theta + "));
    // In ψ̈ the numerator's I₁ φ̇ θ̇ (1 + cos² θ) is as long as I₁ φ̇ θ̇ (2 − sin² θ): the
    // engine's form stays.
    assert!(eq.accelerations[2].contains(r"\left(1 + \cos^{2}\theta\right)"));
}

/// A general top's kinetic energy prints as ½ (A ω₁² + B ω₂² + C ω₃²) plus the products of
/// inertia's terms, with Goldstein's body rates (eq. 4.87): ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ,
/// ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ (printed squared as (θ̇ sin ψ − φ̇ sin θ cos ψ)²),
/// ω₃ = φ̇ cos θ + ψ̇; the engine's form holds none of these squares.
#[test]
fn general_kinetic_energy_prints_in_body_rates() {
    let l = &GENERAL.equations().lagrangian;
    let squares = r"L = \frac{1}{2} A \left(\dot{\theta} \cos\psi + \dot{\phi} \sin\theta \sin\psi\right)^{2} + \frac{1}{2} B \left(\dot{\theta} \sin\psi - \dot{\phi} \sin\theta \cos\psi\right)^{2} + \frac{1}{2} C \left(\dot{\psi} + \dot{\phi} \cos\theta\right)^{2} - D ";
    assert!(l.starts_with(squares), "{l}");
    assert!(
        l.ends_with(r"- M g x \sin\theta \sin\psi - M g y \sin\theta \cos\psi - M g z \cos\theta")
    );
}

/// The counts a scene prints are those of the programs lowered here from the same
/// derivation, counted by this test's own loop; a derived struct's are those of the run-time
/// derivation of its scene (the counts of the emitted Rust itself are checked on its tokens
/// in precess-derive's tests).
#[test]
fn op_counts_match_the_programs_counted_here() {
    let mut a = Arena::new();
    let scene = heavy_scene(&mut a);
    let run_time = check_costs(&mut a, &scene);
    assert_eq!(HEAVY.equations().costs, run_time.costs);
    let mut b = Arena::new();
    let scene = general_scene(&mut b);
    let run_time = check_costs(&mut b, &scene);
    // The Eulerian form's count depends on the order its expressions were built in, which
    // differs between the macro's arena (which built the mass properties first) and this
    // one; the angle-form methods agree.
    for c in GENERAL.equations().costs.iter() {
        if c.method != "eulerian_rhs" {
            assert_eq!(run_time.cost(&c.method), Some(c.ops), "{}", c.method);
        }
    }
}

/// Checks the costs `scene` prints against programs counted here, and returns its typeset.
fn check_costs(a: &mut Arena, scene: &TopScene) -> Typeset {
    let r = std::array::from_fn(|i| std::array::from_fn(|j| a.input(&format!("r{i}{j}"))));
    let w = [a.input("w_0"), a.input("w_1"), a.input("w_2")];
    let eq = scene.typeset_reading(a, &r, &w).expect("typesets");
    let top = scene.derive(a).expect("derives");
    let energy = top.energy(a);
    let jacobian = top.jacobian(a);
    let conserved: Vec<_> = top.conserved_momenta.iter().flatten().copied().collect();
    let eulerian = scene.eulerian_rhs(a, &r, &w).expect("invertible");
    let programs = [
        ("accelerations", top.accelerations.accel.clone()),
        ("angle_jacobian", jacobian.as_flattened().to_vec()),
        ("energy", vec![energy]),
        ("conserved_momenta", conserved),
        ("rotation_in", top.rotation.as_flattened().to_vec()),
        ("rate_matrix_in", top.rate_matrix.as_flattened().to_vec()),
        ("eulerian_rhs", eulerian.to_vec()),
    ];
    assert_eq!(eq.costs.len(), programs.len());
    for (name, outputs) in programs {
        let counted = count(&Program::lower(a, &outputs));
        assert_eq!(eq.cost(name), Some(counted), "{name}");
        assert!(
            counted.total() > 0 || (name == "conserved_momenta" && outputs.is_empty()),
            "{name}"
        );
    }
    eq
}

/// The operations a program executes: a sine and a cosine of one argument are one
/// `sin_cos`, as the emitted code computes them.
fn count(p: &Program) -> OpCount {
    let mut c = OpCount::default();
    let (mut sines, mut cosines) = (Vec::new(), Vec::new());
    for op in p.ops() {
        match *op {
            Op::Add(..) | Op::Sub(..) => c.adds += 1,
            Op::Mul(..) => c.muls += 1,
            Op::Div(..) => c.divs += 1,
            Op::Neg(_) => c.negs += 1,
            Op::Sqrt(_) => c.sqrts += 1,
            Op::Powf(..) | Op::Func(..) => c.powfs += 1,
            Op::Sin(x) => sines.push(x),
            Op::Cos(x) => cosines.push(x),
            Op::Const(_) | Op::Input(_) => {}
        }
    }
    for s in &sines {
        if let Some(i) = cosines.iter().position(|c| c == s) {
            cosines.swap_remove(i);
            c.sin_cos += 1;
        } else {
            c.trig += 1;
        }
    }
    c.trig += cosines.len();
    c
}

/// The derived structs' strings equal those of the run-time API for the same scene, built
/// here with parameters named as the fields (and, for the heavy top, the counts too; see
/// `op_counts_match_the_programs_counted_here` for the general top's).
#[test]
fn derived_equations_equal_the_run_time_ones() {
    let mut a = Arena::new();
    let scene = heavy_scene(&mut a);
    let run_time = scene.typeset(&mut a).expect("typesets");
    assert_same_lines(HEAVY.equations(), &run_time);
    assert_eq!(HEAVY.equations(), &run_time);
    let mut b = Arena::new();
    let scene = general_scene(&mut b);
    assert_same_lines(
        GENERAL.equations(),
        &scene.typeset(&mut b).expect("typesets"),
    );
    assert_eq!(Heavy::SEQUENCE, AngleSequence::Zxz);
}

/// Line by line, so a failure names the line.
fn assert_same_lines(derived: &Typeset, run_time: &Typeset) {
    assert_eq!(derived.lines().count(), run_time.lines().count());
    for (d, r) in derived.lines().zip(run_time.lines()) {
        assert_eq!(d, r);
    }
}

fn heavy_scene(a: &mut Arena) -> TopScene {
    let (i1, i3) = (a.parameter("I_1"), a.parameter("I_3"));
    let z = a.zero();
    let mut scene = TopScene::free(a, [[i1, z, z], [z, i1, z], [z, z, i3]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    scene
}

/// [`General`]'s scene, the parameters made in the order the derive meets the fields (mass,
/// centre, then the tensor row by row): generated code's operation counts depend on it.
fn general_scene(a: &mut Arena) -> TopScene {
    let mass = a.parameter("M");
    let center = ["x", "y", "z"].map(|n| a.parameter(n));
    let [ia, i_f, ie, ib, id, ic] = ["A", "F", "E", "B", "D", "C"].map(|n| a.parameter(n));
    let inertia = [[ia, i_f, ie], [i_f, ib, id], [ie, id, ic]];
    let mut scene = TopScene::free(a, inertia);
    scene.mass = mass;
    scene.center = center;
    scene.gravity = Some(a.parameter("g"));
    scene.damping = Some(a.parameter("k"));
    scene
}

/// A wooden top of literal parts in cm, g and kg/m³: a cone of wood on its apex under a
/// brass stem. Its mass properties are exact rationals of twenty digits.
#[derive(RigidBody)]
#[rigid(
    cone(density = 0.7 g/cm^3, radius = 3 cm, height = 4 cm, axis = -z, at = [0, 0, 4 cm]),
    cylinder(mass = 12 g, radius = 5 mm, length = 3 cm, at = [0, 0, 5.5 cm]),
    pivot = [0, 0, 0],
)]
#[top(gravity = 9.81)]
struct Wooden;

/// The same top tilted off its axis: a general tensor and an off-axis centre.
#[derive(RigidBody)]
#[rigid(
    cone(density = 700, radius = 0.03, height = 0.04, axis = -z, at = [0.002, 0, 0.04]),
    cuboid(mass = 12 g, size = [1 cm, 2 cm, 3 cm], at = [0, 0, 5.5 cm], rotate = x(20 deg)),
    pivot = [0, 0, 0],
)]
#[top(gravity = 981 cm/s^2)]
struct Tilted;

/// A pendulum-like top of literal parts hanging below its pivot: its centre of mass is at a
/// negative l, so the potential and the θ equation carry a negative named constant.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.35, radius = 2 cm, length = 6 cm, at = [0, 0, -9 cm]),
    sphere(mass = 0.12, radius = 1.5 cm, at = [0, 0, -14.3 cm]),
    pivot = [0, 0, 0],
)]
#[top(gravity = 9.81)]
struct Hanging;

/// An asymmetric top of literal parts, parts at negative offsets on every axis: negative
/// products of inertia and negative components of the centre of mass.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 0.2, size = [3 cm, 2 cm, 1 cm], at = [-1.7 cm, 0.4 cm, -2.1 cm]),
    sphere(mass = 0.07, radius = 1 cm, at = [0.9 cm, 2.3 cm, 1.3 cm]),
    rod(mass = 0.05, length = 8 cm, axis = x, at = [0, 0.6 cm, 3.3 cm]),
    pivot = [0, 0, 0],
)]
#[top(gravity = 9.81)]
struct Askew;

/// Literal tops with negative values among their mass properties read back line for line:
/// the hanging top (l < 0) against its centre of mass, the askew one (negative products of
/// inertia and centre components) against its tensor; every line agrees with the
/// generated code.
#[test]
fn literal_tops_with_negative_values_read_back() {
    let c = Hanging.center_of_mass();
    assert!(c.z < -0.09, "{c}");
    let eq = Hanging.equations();
    let l = eq.value("l").unwrap_or(f64::NAN);
    assert!((l - c.z).abs() <= 1e-15, "l = {l} vs {}", c.z);
    check_lines(&Hanging, &[], [0.0; 3], 9.81, 6);
    let i = Askew.inertia();
    assert!(i[(0, 2)] < 0.0 && i[(1, 2)] < 0.0, "{i}");
    let eq = Askew.equations();
    for (symbol, value) in [("I_{xz}", i[(0, 2)]), ("I_{yz}", i[(1, 2)])] {
        let exact = eq.value(symbol).unwrap_or(f64::NAN);
        assert!(
            (exact - value).abs() <= 1e-15,
            "{symbol} = {exact} vs {value}"
        );
    }
    check_lines(&Askew, &[], [0.0; 3], 9.81, 7);
}

/// A symmetric top of literal parts prints Goldstein's lines, the very strings of the top
/// whose mass properties are fields, with its values named I₁, I₃, M, l, g; the table gives
/// them to six digits and `values` exactly, both checked against `inertia()`, `principal()`,
/// `mass()` and `center_of_mass()`; no line holds a long number.
#[test]
fn a_literal_top_prints_named_mass_properties() {
    let eq = Wooden.equations();
    let field = HEAVY.equations();
    assert_eq!(eq.lagrangian, field.lagrangian);
    for (l, f) in eq.equations.iter().zip(field.equations.iter()) {
        assert_eq!(l, f);
    }
    assert_eq!(eq.accelerations, field.accelerations);
    assert_eq!(eq.conserved, field.conserved);
    let i = Wooden.inertia();
    let moments = Wooden.principal().moments;
    let expected = [
        ("I_{1}", i[(0, 0)], "6.61714 \\cdot 10^{-5}"),
        ("I_{3}", i[(2, 2)], "7.27513 \\cdot 10^{-6}"),
        ("M", Wooden.mass(), "0.0383894"),
        ("g", 9.81, "9.81"),
        ("l", Wooden.center_of_mass().z, "0.0378147"),
    ];
    assert_eq!(eq.values.len(), expected.len());
    assert_eq!(eq.definitions.len(), expected.len());
    for ((symbol, value, printed), line) in expected.into_iter().zip(eq.definitions.iter()) {
        let exact = eq
            .value(symbol)
            .unwrap_or_else(|| panic!("no value {symbol}"));
        assert!(
            (exact - value).abs() <= 1e-15 * value.abs(),
            "{symbol}: {exact} vs {value}"
        );
        assert_eq!(line, &format!("{symbol} = {printed}"));
        let read = eval_ok(printed, &HashMap::new());
        assert!(
            (read - value).abs() <= 5e-6 * value.abs(),
            "{line} vs {value}"
        );
    }
    // The principal moments are I₁, I₁, I₃ (a cone and a cylinder on one axis).
    let exact = |s| eq.value(s).unwrap_or(f64::NAN);
    assert!(
        (moments.x - exact("I_{1}")).abs() <= 1e-15 && (moments.z - exact("I_{3}")).abs() <= 1e-15
    );
    for line in eq.lines() {
        assert!(
            !line.contains("\\cdot") || eq.definitions.iter().any(|d| d == line),
            "{line}"
        );
        let longest = line
            .split(|c: char| !c.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest <= 7, "a long number in {line}");
    }
}

/// Every printed line of literal tops, read back with the exact values of their names,
/// agrees with the generated code, and its table with the body's mass properties.
#[test]
fn every_line_of_a_literal_top_evaluates_to_the_generated_code() {
    check_lines(&Wooden, &[], [0.0; 3], 9.81, 4);
    check_lines(&Tilted, &[], [0.0; 3], 9.81, 5);
    let eq = Tilted.equations();
    let i = Tilted.inertia();
    let c = Tilted.center_of_mass();
    let mut named = 0;
    for (symbol, value) in [
        ("I_{xx}", i[(0, 0)]),
        ("I_{xy}", i[(0, 1)]),
        ("I_{xz}", i[(0, 2)]),
        ("I_{yy}", i[(1, 1)]),
        ("I_{yz}", i[(1, 2)]),
        ("I_{zz}", i[(2, 2)]),
        ("M", Tilted.mass()),
        ("c_{x}", c.x),
        ("c_{y}", c.y),
        ("c_{z}", c.z),
        ("g", 9.81),
    ] {
        // A zero stays a zero: only nonzero values are named.
        let exact = eq.value(symbol).unwrap_or(0.0);
        named += usize::from(exact != 0.0);
        assert!(
            (exact - value).abs() <= 1e-14 * value.abs(),
            "{symbol}: {exact} vs {value} in {:?}",
            eq.values
        );
    }
    assert_eq!(named, eq.values.len());
    assert!(named >= 8, "{:?}", eq.values);
    // The definitions hold the decimals; no other line holds a number past 7 digits.
    for line in eq
        .lines()
        .filter(|l| !eq.definitions.iter().any(|d| d == l))
    {
        let longest = line
            .split(|c: char| !c.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest <= 7, "a long number in {line}");
    }
}
