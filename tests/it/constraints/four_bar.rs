//! The crank-rocker four-bar as a closed loop: three link angles, two holonomic closure
//! constraints. Positions against Freudenstein's closed form, energy over a long run, the
//! loop's residual with and without coordinate partitioning, and the joint reaction against
//! Newton–Euler for each link written out here.

use nalgebra::{Matrix4, Vector4};
use precess::lagrange::{ConstrainedEquations, ConstrainedModel, Constraints, Coordinates};
use precess::lagrange::{EquationsOfMotion, LagrangeError};
use precess::sym::{Arena, ExprId};

/// Ground d, crank a, coupler b, rocker c: s + l = 1 + 3 < p + q = 3 + 2.5 (Grashof), the
/// crank the shortest and next to the ground, so it turns fully.
pub const LINKS: [f64; 4] = [1.0, 3.0, 2.5, 3.0];
/// Masses of the crank, coupler and rocker (uniform rods) and g.
pub const MASSES: [f64; 3] = [0.5, 1.5, 1.2];
/// Gravity.
pub const G: f64 = 9.81;

/// The parameter values by name.
pub fn values() -> Vec<(&'static str, f64)> {
    let [a, b, c, d] = LINKS;
    let [m1, m2, m3] = MASSES;
    vec![
        ("a", a),
        ("b", b),
        ("c", c),
        ("d", d),
        ("m1", m1),
        ("m2", m2),
        ("m3", m3),
        ("g", G),
    ]
}

/// The four-bar's reduced equations (crank angle θ₁ independent, coupler θ₂ and rocker θ₃
/// dependent) and its energy as the one extra output. Angles are measured from the ground
/// line, the crank pivoted at the origin, the rocker at (d, 0), gravity along −y.
pub fn four_bar(a: &mut Arena) -> Result<(ConstrainedEquations, Vec<ExprId>), LagrangeError> {
    let c = Coordinates::new(a, &["th1", "th2", "th3"]);
    let [la, lb, lc, ld] = ["a", "b", "c", "d"].map(|n| a.parameter(n));
    let [m1, m2, m3] = ["m1", "m2", "m3"].map(|n| a.parameter(n));
    let g = a.parameter("g");
    let cs: Vec<(ExprId, ExprId)> = c.q.iter().map(|&q| (a.cos(q), a.sin(q))).collect();
    let half = a.number("0.5").map_err(LagrangeError::Sym)?;
    let third = {
        let k = a.integer(3);
        a.recip(k)?
    };
    let twelfth = {
        let k = a.integer(12);
        a.recip(k)?
    };
    // Coupler centre: A + (b/2) e₂ with A = a e₁.
    let gx = {
        let t1 = a.mul(la, cs[0].0);
        let t2 = a.product(&[half, lb, cs[1].0]);
        a.add(t1, t2)
    };
    let gy = {
        let t1 = a.mul(la, cs[0].1);
        let t2 = a.product(&[half, lb, cs[1].1]);
        a.add(t1, t2)
    };
    let (vx, vy) = (a.dt(gx), a.dt(gy));
    let [w1, w2, w3] = [c.rates[0], c.rates[1], c.rates[2]];
    let kinetic = {
        let t1 = a.product(&[half, third, m1, la, la, w1, w1]);
        let v2 = {
            let x = a.mul(vx, vx);
            let y = a.mul(vy, vy);
            a.add(x, y)
        };
        let t2 = a.product(&[half, m2, v2]);
        let t3 = a.product(&[half, twelfth, m2, lb, lb, w2, w2]);
        let t4 = a.product(&[half, third, m3, lc, lc, w3, w3]);
        a.sum(&[t1, t2, t3, t4])
    };
    let potential = {
        let v1 = a.product(&[m1, g, half, la, cs[0].1]);
        let v2 = a.product(&[m2, g, gy]);
        let v3 = a.product(&[m3, g, half, lc, cs[2].1]);
        a.sum(&[v1, v2, v3])
    };
    let lagrangian = a.sub(kinetic, potential);
    let energy = a.add(kinetic, potential);
    let zero = a.zero();
    let eom = EquationsOfMotion::derive(a, lagrangian, c.clone(), &[zero; 3])?;
    // φ = (a e₁ + b e₂) − (d x̂ + c e₃): the coupler's end against the rocker's.
    let phi_x = {
        let t = [a.mul(la, cs[0].0), a.mul(lb, cs[1].0), a.neg(ld), {
            let p = a.mul(lc, cs[2].0);
            a.neg(p)
        }];
        a.sum(&t)
    };
    let phi_y = {
        let t = [a.mul(la, cs[0].1), a.mul(lb, cs[1].1), {
            let p = a.mul(lc, cs[2].1);
            a.neg(p)
        }];
        a.sum(&t)
    };
    let mut k = Constraints::new();
    k.holonomic(a, &c, phi_x)?;
    k.holonomic(a, &c, phi_y)?;
    let eqs = eom.constrain(a, &k, None)?;
    Ok((eqs, vec![energy]))
}

/// Freudenstein: K₁ cos θ₃ − K₂ cos θ₁ + K₃ = cos(θ₁ − θ₃), K₁ = d/a, K₂ = d/c,
/// K₃ = (a² − b² + c² + d²)/(2ac), solved as A cos θ₃ + B sin θ₃ + C = 0 by the half-angle
/// tangent; `branch` ±1 picks the assembly. The coupler angle follows from
/// b e₂ = d x̂ + c e₃ − a e₁.
pub fn freudenstein(theta1: f64, branch: f64) -> (f64, f64) {
    let [a, b, c, d] = LINKS;
    let (k1, k2, k3) = (
        d / a,
        d / c,
        (a * a - b * b + c * c + d * d) / (2.0 * a * c),
    );
    let (big_a, big_b, big_c) = (k1 - theta1.cos(), -theta1.sin(), k3 - k2 * theta1.cos());
    let root = (big_a * big_a + big_b * big_b - big_c * big_c).sqrt();
    let t = (-big_b + branch * root) / (big_c - big_a);
    let theta3 = 2.0 * t.atan();
    let bx = d + c * theta3.cos() - a * theta1.cos();
    let by = c * theta3.sin() - a * theta1.sin();
    (by.atan2(bx), theta3)
}

/// The difference of two angles, wrapped into (−π, π].
pub fn angle_diff(x: f64, y: f64) -> f64 {
    let d = (x - y).rem_euclid(std::f64::consts::TAU);
    if d > std::f64::consts::PI {
        d - std::f64::consts::TAU
    } else {
        d
    }
}

/// The initial state: crank at θ₁ = 0.3 on the `branch = +1` assembly, crank rate `w`.
pub fn start(w: f64) -> [f64; 4] {
    let (t2, t3) = freudenstein(0.3, 1.0);
    [0.3, t2, t3, w]
}

fn model() -> ConstrainedModel {
    let mut a = Arena::new();
    let (eqs, out) = four_bar(&mut a).expect("the four-bar derives");
    assert_eq!(eqs.independent, [0], "the crank is the free coordinate");
    ConstrainedModel::new(&mut a, &eqs, &out, &values()).expect("binds")
}

#[test]
fn the_start_closes_the_loop_and_grashof_holds() {
    let [a, b, c, d] = LINKS;
    let mut l = LINKS;
    l.sort_by(f64::total_cmp);
    assert!(
        l[0] + l[3] < l[1] + l[2] && a == l[0],
        "crank-rocker: s + l < p + q"
    );
    let _ = (b, c, d);
    let m = model();
    let phi = m.position_residuals(0.0, &start(4.0)).expect("finite");
    let phi = phi.expect("every row is holonomic");
    assert!(
        phi.iter().all(|v| v.abs() < 1e-14),
        "Freudenstein closes: {phi:?}"
    );
}

/// Runs `turns`-ish crank turns; returns (max |φ|, max |θ₃ − Freudenstein|, max relative
/// energy error, crank turns made).
fn run(model: &ConstrainedModel, t_end: f64, partition: bool) -> (f64, f64, f64, f64) {
    let y0 = start(6.0);
    let e0 = model.outputs(0.0, &y0).expect("finite")[0];
    let samples = 200;
    let times: Vec<f64> = (1..=samples)
        .map(|k| t_end * k as f64 / samples as f64)
        .collect();
    let states = precess_testkit::constrained::dop853_states(
        model,
        y0,
        &times,
        1e-12,
        partition.then_some(1e-15),
    )
    .expect("integrates, and the loop closes");
    let (mut residual, mut position, mut energy) = (0.0_f64, 0.0_f64, 0.0_f64);
    for (&t, y) in times.iter().zip(&states) {
        let phi = model
            .position_residuals(t, y)
            .expect("finite")
            .expect("holonomic");
        residual = residual.max(phi[0].abs().max(phi[1].abs()));
        let (t2, t3) = freudenstein(y[0], 1.0);
        position = position.max(angle_diff(y[1], t2).abs().max(angle_diff(y[2], t3).abs()));
        let e = model.outputs(t, y).expect("finite")[0];
        energy = energy.max(((e - e0) / e0).abs());
    }
    let last = states.last().expect("samples");
    let turns = (last[0] - y0[0]) / std::f64::consts::TAU;
    (residual, position, energy, turns)
}

#[test]
fn partitioning_keeps_the_loop_closed_where_plain_integration_drifts() {
    let m = model();
    let t_end = 1000.0;
    let (r_on, p_on, e_on, turns) = run(&m, t_end, true);
    let (r_off, p_off, e_off, _) = run(&m, t_end, false);
    eprintln!(
        "{turns:.0} turns: partitioned |φ| {r_on:.1e}, position {p_on:.1e}, energy {e_on:.1e}; \
         plain |φ| {r_off:.1e}, position {p_off:.1e}, energy {e_off:.1e}"
    );
    assert!(turns > 500.0, "the crank turns fully ({turns} turns)");
    assert!(r_on < 1e-14, "partitioned residual {r_on:e}");
    assert!(
        p_on < 1e-13,
        "partitioned positions off Freudenstein by {p_on:e}"
    );
    assert!(
        r_off > 10.0 * r_on.max(1e-16),
        "plain integration drifts only to {r_off:e}"
    );
    // Measured over 1353 turns at rtol = atol = 1e-12 with DOP853: |φ| 8.9e-16 partitioned
    // against 1.5e-10 plain; energy 1.4e-9 and 8.9e-10 (the integrator's truncation error,
    // which wanders as it grows; a wrong force drifts at order one).
    assert!(
        e_on < 1e-8 && e_off < 1e-8,
        "energy drifts by {e_on:e} / {e_off:e}"
    );
}

/// Newton–Euler for each link with the contact forces written out: F_A on the coupler at
/// A from the crank, F_B on the coupler at B from the rocker (the multipliers λ, which the
/// constraint φ = (coupler end) − (rocker end) makes the force on the coupler's end).
/// Coupler (3 equations) and rocker (moment about D) give F_A and F_B; the crank's moment
/// about O is then a check on the accelerations.
#[test]
fn joint_reactions_match_newton_euler() {
    let m = model();
    let [a, b, c, _] = LINKS;
    let [m1, m2, m3] = MASSES;
    for (theta1, w) in [(0.3, 4.0), (2.0, -3.0), (4.5, 7.0)] {
        let (t2, t3) = freudenstein(theta1, 1.0);
        let y = [theta1, t2, t3, w];
        let rates = m.rates(0.0, &y).expect("regular");
        let acc = m.accelerations(0.0, &y).expect("regular");
        let lambda = m.multipliers(0.0, &y).expect("regular");
        let [w1, w2, w3] = [rates[0], rates[1], rates[2]];
        let [a1, a2, a3] = [acc[0], acc[1], acc[2]];
        let e = |t: f64| [t.cos(), t.sin()];
        let n = |t: f64| [-t.sin(), t.cos()];
        let (e1, e2, e3) = (e(theta1), e(t2), e(t3));
        let (n1, n2) = (n(theta1), n(t2));
        // Acceleration of the coupler's centre: a(θ̈₁ n₁ − θ̇₁² e₁) + b/2 (θ̈₂ n₂ − θ̇₂² e₂).
        let ag: [f64; 2] = std::array::from_fn(|i| {
            a * (a1 * n1[i] - w1 * w1 * e1[i]) + 0.5 * b * (a2 * n2[i] - w2 * w2 * e2[i])
        });
        let crs = |p: [f64; 2], f: [f64; 2]| p[0] * f[1] - p[1] * f[0];
        // Unknowns (F_Ax, F_Ay, F_Bx, F_By).
        let half_b = [0.5 * b * e2[0], 0.5 * b * e2[1]];
        let rows = Matrix4::new(
            1.0,
            0.0,
            1.0,
            0.0, //
            0.0,
            1.0,
            0.0,
            1.0, //
            // Coupler about its centre: (A − G)×F_A + (B − G)×F_B = I₂ θ̈₂.
            half_b[1],
            -half_b[0],
            -half_b[1],
            half_b[0], //
            // Rocker about D: c e₃ × (−F_B) + (c/2) e₃ × (−m₃ g ŷ) = I_D θ̈₃.
            0.0,
            0.0,
            c * e3[1],
            -c * e3[0],
        );
        let rhs = Vector4::new(
            m2 * ag[0],
            m2 * ag[1] + m2 * G,
            m2 * b * b / 12.0 * a2,
            m3 * c * c / 3.0 * a3 + 0.5 * c * e3[0] * m3 * G,
        );
        let f = rows.lu().solve(&rhs).expect("regular");
        let tol = 1e-12 * f.amax();
        assert!(
            (f[2] - lambda[0]).abs() < tol && (f[3] - lambda[1]).abs() < tol,
            "λ = {lambda:?} against F_B = ({}, {})",
            f[2],
            f[3]
        );
        // Crank about O: a e₁ × (−F_A) + (a/2) e₁ × (−m₁ g ŷ) = I_O θ̈₁.
        let moment = crs([a * e1[0], a * e1[1]], [-f[0], -f[1]]) - 0.5 * a * e1[0] * m1 * G;
        let inertia = m1 * a * a / 3.0 * a1;
        assert!(
            (moment - inertia).abs() < 1e-12 * f.amax(),
            "crank: moment {moment} against I θ̈ {inertia}"
        );
        let _ = w3;
    }
}

/// The reduced equations against the augmented system of Lagrange multipliers, a second
/// formulation: the same q̈ and λ at random states on the loop, and the cost of each.
#[test]
fn the_reduced_equations_agree_with_the_augmented_system() {
    let mut a = Arena::new();
    let (eqs, out) = four_bar(&mut a).expect("derives");
    let aug = eqs
        .equations
        .augmented(&mut a, &eqs.constraints)
        .expect("the 5 × 5 augmented system solves");
    let model = ConstrainedModel::new(&mut a, &eqs, &out, &values()).expect("binds");
    let program = precess::codegen::Program::lower(&a, &aug);
    let reduced = precess::lagrange::op_count(&a, &eqs.rhs_outputs());
    let mut multipliers = eqs.multipliers.clone();
    multipliers.extend(eqs.rhs_outputs());
    let with_lambda = precess::lagrange::op_count(&a, &multipliers);
    eprintln!(
        "four-bar ops: reduced rhs {} ({} weighted), with λ {} ({}), augmented {} ({})",
        reduced.total(),
        reduced.weighted(),
        with_lambda.total(),
        with_lambda.weighted(),
        program.op_count().total(),
        program.op_count().weighted()
    );
    let mut env = vec![f64::NAN; a.symbol_count()];
    for (name, v) in values() {
        let s = a.find_parameter(name).expect("a parameter");
        env[s.index()] = v;
    }
    let c = &eqs.equations.coords;
    let sym = |e| a.as_symbol(e).expect("a symbol");
    let mut rng = crate::common::rng::Rng::new(4);
    for _ in 0..50 {
        let theta1 = rng.uniform(-3.1, 3.1);
        let (t2, t3) = freudenstein(theta1, 1.0);
        let y = [theta1, t2, t3, rng.uniform(-8.0, 8.0)];
        let rates = model.rates(0.0, &y).expect("regular");
        for i in 0..3 {
            env[sym(c.q[i]).index()] = y[i];
            env[sym(c.rates[i]).index()] = rates[i];
        }
        let want = program.eval(&env);
        let acc = model.accelerations(0.0, &y).expect("regular");
        let lambda = model.multipliers(0.0, &y).expect("regular");
        let got: Vec<f64> = acc.iter().chain(&lambda).copied().collect();
        let scale = want.iter().fold(1.0_f64, |s, v| s.max(v.abs()));
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() < 1e-11 * scale, "{got:?} against {want:?}");
        }
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(128))]

    /// From any crank angle and a guess up to 0.1 rad off, Newton closes the loop onto
    /// Freudenstein's assembly to rounding.
    #[test]
    fn newton_closes_onto_freudenstein_from_a_rough_guess(
        theta1 in -3.2..3.2_f64, d2 in -0.1..0.1_f64, d3 in -0.1..0.1_f64, w in -9.0..9.0_f64,
    ) {
        let m = MODEL.with(|m| m.take()).unwrap_or_else(model);
        let (t2, t3) = freudenstein(theta1, 1.0);
        let mut y = [theta1, t2 + d2, t3 + d3, w];
        let n = m.close_loop(0.0, &mut y, 1e-15).expect("closes");
        proptest::prop_assert!(n <= 8, "{n} Newton iterations");
        proptest::prop_assert!(angle_diff(y[1], t2).abs() < 1e-14, "θ₂ {} against {t2}", y[1]);
        proptest::prop_assert!(angle_diff(y[2], t3).abs() < 1e-14, "θ₃ {} against {t3}", y[2]);
        proptest::prop_assert_eq!(y[0], theta1);
        MODEL.with(|cell| cell.set(Some(m)));
    }
}

thread_local! {
    static MODEL: std::cell::Cell<Option<ConstrainedModel>> = const { std::cell::Cell::new(None) };
}
