//! Variational equations against independent values: the intermediate-axis instability's
//! closed form, central finite differences of the flow in x₀ and in p, the ± pairing of a
//! Hamiltonian spectrum, the Lorenz spectrum's published values and its exact sum, and the
//! covariance of a linear system through the matrix exponential.

use approx::assert_relative_eq;
use nalgebra::{DMatrix, Matrix2, Matrix3, Matrix6};
use precess::mechanism::{MechanismModel, Route};
use precess::ode::{AdaptiveConfig, Dop853, Rk4, System};
use precess::sym::{Arena, ExprId};
use precess::taylor::{Taylor, TaylorConfig};
use precess::top::{TopModel, TopScene};
use precess::variational::{
    BenettinConfig, FlowMap, Layout, VariationalEquations, VariationalError, VariationalSystem,
    benettin,
};

fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// Integrates `sys` from `y0` over [0, t] with DOP853 at tight tolerances.
fn flow<S: System<N>, const N: usize>(sys: S, y0: [f64; N], t: f64) -> [f64; N] {
    let mut ode = Dop853::new(sys, 0.0, y0, tight()).unwrap();
    ode.advance_to(t).unwrap();
    *ode.y()
}

/// Euler's equations of a torque-free body with principal moments I1 < I2 < I3 as
/// parameters, state ω.
fn euler_equations(a: &mut Arena) -> ([ExprId; 3], [ExprId; 3]) {
    let z = a.zero();
    let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
    let scene = TopScene::free(a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    let omega = ["w1", "w2", "w3"].map(|n| a.input(n));
    let rotation = [[z; 3]; 3];
    let rhs = scene.eulerian_rhs(a, &rotation, &omega).unwrap();
    (omega, rhs)
}

/// About the unstable axis 2, ω = (0, w, 0) is an equilibrium of Euler's equations and the
/// linearisation is constant: δω̇₁ = α δω₃, δω̇₃ = β δω₁ with α = (I2 − I3) w / I1,
/// β = (I1 − I2) w / I3, so Φ(t) is exactly cosh λt on the diagonal of that block and
/// (α/λ) sinh λt, (β/λ) sinh λt off it, λ = w √((I2 − I1)(I3 − I2)/(I1 I3)), and Φ₂₂ = 1.
#[test]
fn the_intermediate_axis_transition_matrix_is_the_closed_form() {
    let mut a = Arena::new();
    let (omega, rhs) = euler_equations(&mut a);
    let eq = VariationalEquations::new(&mut a, &omega, &rhs, 3, &[]).unwrap();
    let (i1, i2, i3, w) = (1.0, 2.0, 3.0, 1.5);
    let sys = VariationalSystem::<12>::new(&a, &eq, &[("I1", i1), ("I2", i2), ("I3", i3)]).unwrap();
    let lambda = w * ((i2 - i1) * (i3 - i2) / (i1 * i3)).sqrt();
    let (alpha, beta) = ((i2 - i3) * w / i1, (i1 - i2) * w / i3);
    let t = 6.0;
    let y = flow(&sys, sys.initial_state(&[0.0, w, 0.0]).unwrap(), t);
    let phi = sys.transition(&y);
    let (c, s) = ((lambda * t).cosh(), (lambda * t).sinh());
    let exact = DMatrix::from_row_slice(
        3,
        3,
        &[
            c,
            0.0,
            alpha / lambda * s,
            0.0,
            1.0,
            0.0,
            beta / lambda * s,
            0.0,
            c,
        ],
    );
    let err = (&phi - &exact).amax() / exact.amax();
    eprintln!("intermediate axis: lambda = {lambda}, |Φ − exact|/|Φ| = {err:e}");
    assert!(err < 1e-11, "{err:e}");
    // The growth rate of the largest singular value tends to λ: ln σ₁ / t differs from it by
    // ln(max(|α|,|β|)/λ·…)/t only, which the exact form gives.
    let sigma = phi.singular_values().max();
    let exact_sigma = exact.singular_values().max();
    assert_relative_eq!(sigma.ln() / t, exact_sigma.ln() / t, max_relative = 1e-11);
}

/// The same equilibrium through the Eulerian-top constructor (ω and the attitude, twelve
/// entries): Benettin's largest exponent, after a transient that aligns the tangent vector,
/// is λ; and a fixed-step stepper (RK4) gives it too.
#[test]
fn the_intermediate_axis_exponent_by_benettin() {
    let mut a = Arena::new();
    let z = a.zero();
    let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
    let scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    let eq = VariationalEquations::from_eulerian_top(&mut a, &scene, 1, &[]).unwrap();
    let (i1, i2, i3, w) = (1.0, 2.0, 3.0, 1.5);
    let sys = VariationalSystem::<24>::new(&a, &eq, &[("I1", i1), ("I2", i2), ("I3", i3)]).unwrap();
    let lambda = w * ((i2 - i1) * (i3 - i2) / (i1 * i3)).sqrt();
    let x0 = [0.0, w, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let cfg = BenettinConfig {
        interval: 0.5,
        duration: 40.0,
        transient: 20.0,
    };
    let dop = sys.lyapunov(0.0, &x0, &cfg, tight()).unwrap();
    let mut rk4 = Rk4::new(
        &sys,
        0.0,
        sys.initial_state(&x0).unwrap(),
        precess::ode::FixedStepConfig::with_step(1e-3),
    )
    .unwrap();
    let fixed = benettin(&mut rk4, sys.layout(), &cfg).unwrap();
    eprintln!(
        "intermediate axis by Benettin: λ = {lambda}, DOP853 {:?}, RK4 {:?}",
        dop.exponents, fixed.exponents
    );
    assert_relative_eq!(dop.exponents[0], lambda, max_relative = 1e-8);
    assert_relative_eq!(fixed.exponents[0], lambda, max_relative = 1e-8);
}

/// An asymmetric heavy top in angle form (I = 1, 1.5, 0.7; M g l = 1): Φ(2) from the
/// variational equations against central differences of the flow of the top's own model
/// (step 10⁻⁵ in each initial coordinate, DOP853 at 10⁻¹³).
#[test]
fn the_heavy_top_transition_matrix_matches_finite_differences() {
    let mut a = Arena::new();
    let z = a.zero();
    let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
    let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let derivation = scene.derive(&mut a).unwrap();
    let values = [
        ("I1", 1.0),
        ("I2", 1.5),
        ("I3", 0.7),
        ("M", 1.0),
        ("g", 1.0),
        ("l", 1.0),
    ];
    let eq = VariationalEquations::from_top(&mut a, &derivation, 6, &[]).unwrap();
    let sys = VariationalSystem::<42>::new(&a, &eq, &values).unwrap();
    let model = TopModel::new(&mut a, &derivation, &values).unwrap();
    let x0 = [0.3, 1.0, 0.2, 0.5, 0.3, 2.0];
    let t = 2.0;
    let y = flow(&sys, sys.initial_state(&x0).unwrap(), t);
    let phi = sys.transition(&y);
    let h = 1e-5;
    let mut fd = DMatrix::zeros(6, 6);
    for j in 0..6 {
        let (mut up, mut down) = (x0, x0);
        up[j] += h;
        down[j] -= h;
        let (yu, yd) = (flow(&model, up, t), flow(&model, down, t));
        for i in 0..6 {
            fd[(i, j)] = (yu[i] - yd[i]) / (2.0 * h);
        }
    }
    let err = (&phi - &fd).amax() / phi.amax();
    eprintln!(
        "heavy top Φ(2) against differences: {err:e} of max |Φ| = {}",
        phi.amax()
    );
    assert!(err < 1e-7, "{err:e}");
    // x itself is the model's flow.
    let x = flow(&model, x0, t);
    for k in 0..6 {
        assert_relative_eq!(y[k], x[k], epsilon = 1e-11);
    }
}

/// The double pendulum built as a mechanism: ∂x(t)/∂g and ∂x(t)/∂l1 carried by the
/// sensitivity equations against central differences in the parameters of the mechanism's
/// own model.
#[test]
fn mechanism_sensitivities_match_finite_differences() {
    let mut a = Arena::new();
    let scene = crate::common::mechanism::double_pendulum(&mut a, Some("c"));
    let derivation = scene.derive(&mut a, Route::Auto).unwrap();
    let values = [
        ("m0", 1.3),
        ("m1", 0.7),
        ("l0", 0.9),
        ("l1", 0.6),
        ("g", 9.81),
        ("c", 0.2),
    ];
    let eq = VariationalEquations::from_mechanism(&mut a, &derivation, 0, &["g", "l1"]).unwrap();
    let sys = VariationalSystem::<12>::new(&a, &eq, &values).unwrap();
    let x0 = [0.8, -0.4, 0.0, 0.5];
    let t = 1.5;
    let y = flow(&sys, sys.initial_state(&x0).unwrap(), t);
    let s = sys.sensitivities(&y);
    let mut worst: f64 = 0.0;
    for (j, name) in ["g", "l1"].into_iter().enumerate() {
        let p = values.iter().find(|v| v.0 == name).unwrap().1;
        let h = 1e-5 * p;
        let at = |v: f64| {
            let mut vals = values;
            vals.iter_mut().find(|x| x.0 == name).unwrap().1 = v;
            let model = MechanismModel::from_derivation(&a, &derivation, &vals).unwrap();
            flow(model.system::<4>().unwrap(), x0, t)
        };
        let (up, down) = (at(p + h), at(p - h));
        for i in 0..4 {
            let fd = (up[i] - down[i]) / (2.0 * h);
            worst = worst.max((s[(i, j)] - fd).abs() / s.amax());
        }
    }
    eprintln!(
        "double pendulum ∂x/∂(g, l1) against differences: {worst:e} of max {}",
        s.amax()
    );
    assert!(worst < 1e-7, "{worst:e}");
}

/// Hénon–Heiles, a Hamiltonian system in canonical coordinates at E = 1/6: the spectrum
/// comes in ± pairs and the two exponents of the flow direction and the energy are zero.
/// J has zero trace, so Σλ = 0 holds for every finite time up to the integration error;
/// the pairing and the zeros hold to O(1/T).
#[test]
fn a_hamiltonian_spectrum_comes_in_pairs() {
    let mut a = Arena::new();
    let x = ["x", "y", "px", "py"].map(|n| a.input(n));
    let two = a.integer(2);
    let xy = a.product(&[two, x[0], x[1]]);
    let nx = a.neg(x[0]);
    let fx = a.sub(nx, xy);
    let (xx, yy) = (a.mul(x[0], x[0]), a.mul(x[1], x[1]));
    let ny = a.neg(x[1]);
    let ny_xx = a.sub(ny, xx);
    let fy = a.add(ny_xx, yy);
    let rhs = [x[2], x[3], fx, fy];
    let eq = VariationalEquations::new(&mut a, &x, &rhs, 4, &[]).unwrap();
    let sys = VariationalSystem::<20>::new(&a, &eq, &[]).unwrap();
    let (x0, y0): (f64, f64) = (0.0, 0.3);
    let v = x0 * x0 / 2.0 + y0 * y0 / 2.0 + x0 * x0 * y0 - y0 * y0 * y0 / 3.0;
    let px = (2.0 * (1.0 / 6.0 - v)).sqrt();
    let cfg = BenettinConfig {
        interval: 1.0,
        duration: 2000.0,
        transient: 50.0,
    };
    let l = sys
        .lyapunov(
            0.0,
            &[x0, y0, px, 0.0],
            &cfg,
            AdaptiveConfig::with_tol(1e-11, 1e-11),
        )
        .unwrap()
        .exponents;
    let sum: f64 = l.iter().sum();
    eprintln!("Hénon–Heiles E = 1/6: {l:?}, sum {sum:e}");
    assert!(l[0] > 0.02, "{l:?}");
    assert!(sum.abs() < 1e-9, "{sum:e}");
    assert!((l[0] + l[3]).abs() < 0.01 * l[0], "{l:?}");
    assert!(
        l[1].abs() < 0.05 * l[0] && l[2].abs() < 0.05 * l[0],
        "{l:?}"
    );
}

/// The Lorenz system (σ = 10, ρ = 28, β = 8/3) as arena expressions: the spectrum against
/// the published (0.9056, 0, −14.5723), and its sum against −(σ + 1 + β) = −41/3, exact for
/// any time since the trace of J is constant.
#[test]
fn the_lorenz_spectrum() {
    let mut a = Arena::new();
    let x = ["x", "y", "z"].map(|n| a.input(n));
    let [sigma, rho, beta] = ["sigma", "rho", "beta"].map(|n| a.parameter(n));
    let dx = a.sub(x[1], x[0]);
    let fx = a.mul(sigma, dx);
    let rz = a.sub(rho, x[2]);
    let xrz = a.mul(x[0], rz);
    let fy = a.sub(xrz, x[1]);
    let xy = a.mul(x[0], x[1]);
    let bz = a.mul(beta, x[2]);
    let fz = a.sub(xy, bz);
    let eq = VariationalEquations::new(&mut a, &x, &[fx, fy, fz], 3, &[]).unwrap();
    let sys = VariationalSystem::<12>::new(
        &a,
        &eq,
        &[("sigma", 10.0), ("rho", 28.0), ("beta", 8.0 / 3.0)],
    )
    .unwrap();
    let cfg = BenettinConfig {
        interval: 0.1,
        duration: 1000.0,
        transient: 10.0,
    };
    let run = sys
        .lyapunov(
            0.0,
            &[1.0, 1.0, 20.0],
            &cfg,
            AdaptiveConfig::with_tol(1e-10, 1e-10),
        )
        .unwrap();
    let l = &run.exponents;
    let sum: f64 = l.iter().sum();
    eprintln!("Lorenz: {l:?}, sum {sum}, {:?}", run.stats);
    assert_relative_eq!(sum, -41.0 / 3.0, max_relative = 1e-9);
    assert_relative_eq!(l[0], 0.9056, max_relative = 0.01);
    assert!(l[1].abs() < 0.005, "{l:?}");
    assert_relative_eq!(l[2], -14.5723, max_relative = 0.002);
}

/// A damped oscillator x'' = −k x − c x' is linear, so Φ(t) = exp(A t) exactly and a
/// covariance P₀ becomes exp(A t) P₀ exp(A t)ᵀ; the flow map from the variational equations
/// gives it, and its first-order displacement is exact too.
#[test]
fn the_flow_map_propagates_a_covariance() {
    let mut a = Arena::new();
    let x = ["x", "v"].map(|n| a.input(n));
    let [k, c] = ["k", "c"].map(|n| a.parameter(n));
    let kx = a.mul(k, x[0]);
    let cv = a.mul(c, x[1]);
    let f = a.add(kx, cv);
    let f = a.neg(f);
    let eq = VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[]).unwrap();
    let sys = VariationalSystem::<6>::new(&a, &eq, &[("k", 4.0), ("c", 0.3)]).unwrap();
    let t = 3.0;
    let x0 = [1.0, 0.0];
    let y = flow(&sys, sys.initial_state(&x0).unwrap(), t);
    let map = FlowMap::new(sys.layout(), &y).unwrap();
    let expm = (Matrix2::new(0.0, 1.0, -4.0, -0.3) * t).exp();
    let p0 = DMatrix::from_row_slice(2, 2, &[0.01, 0.002, 0.002, 0.04]);
    let p = map.covariance(&p0).unwrap();
    let e = DMatrix::from_row_slice(2, 2, expm.transpose().as_slice());
    let exact = &e * &p0 * e.transpose();
    let err = (&p - &exact).amax() / exact.amax();
    eprintln!("covariance against exp(At): {err:e}");
    assert!(err < 1e-10, "{err:e}");
    let moved = map.apply(&[0.1, -0.2]).unwrap();
    let exact_moved = expm * nalgebra::Vector2::new(1.1, -0.2);
    assert_relative_eq!(moved[0], exact_moved[0], epsilon = 1e-10);
    assert_relative_eq!(moved[1], exact_moved[1], epsilon = 1e-10);
}

/// Bad sizes and bad settings get typed errors carrying the numbers.
#[test]
fn bad_inputs_are_typed_errors() {
    let mut a = Arena::new();
    let x = ["x", "v"].map(|n| a.input(n));
    let k = a.parameter("k");
    let kx = a.mul(k, x[0]);
    let f = a.neg(kx);
    assert_eq!(
        VariationalEquations::new(&mut a, &x, &[f], 2, &[]),
        Err(VariationalError::RhsLength { state: 2, rhs: 1 })
    );
    assert_eq!(
        VariationalEquations::new(&mut a, &x, &[x[1], f], 3, &[]),
        Err(VariationalError::TooManyTangents {
            tangents: 3,
            state: 2
        })
    );
    assert_eq!(
        VariationalEquations::new(&mut a, &[x[0], k], &[x[1], f], 2, &[]),
        Err(VariationalError::NotAStateSymbol { index: 1 })
    );
    assert_eq!(
        VariationalEquations::new(&mut a, &[x[0], x[0]], &[x[1], f], 2, &[]),
        Err(VariationalError::RepeatedStateSymbol {
            first: 0,
            second: 1
        })
    );
    assert_eq!(
        VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[x[0]]),
        Err(VariationalError::NotAParameter { index: 0 })
    );
    let eq = VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[k]).unwrap();
    assert_eq!(
        VariationalSystem::<6>::new(&a, &eq, &[("k", 1.0)]).err(),
        Some(VariationalError::SizeMismatch {
            expected: 8,
            got: 6
        })
    );
    let sys = VariationalSystem::<8>::new(&a, &eq, &[("k", 1.0)]).unwrap();
    assert_eq!(
        sys.initial_state(&[1.0]),
        Err(VariationalError::InitialStateLength {
            expected: 2,
            got: 1
        })
    );
    let good = BenettinConfig {
        interval: 0.1,
        duration: 1.0,
        transient: 0.0,
    };
    let ode = AdaptiveConfig::with_tol(1e-9, 1e-9);
    let run = |cfg: BenettinConfig, x0: [f64; 2]| sys.lyapunov(0.0, &x0, &cfg, ode).err();
    assert_eq!(
        run(
            BenettinConfig {
                interval: 0.0,
                ..good
            },
            [1.0, 0.0]
        ),
        Some(VariationalError::NonPositiveInterval { interval: 0.0 })
    );
    assert_eq!(
        run(
            BenettinConfig {
                interval: -1.0,
                ..good
            },
            [1.0, 0.0]
        ),
        Some(VariationalError::NonPositiveInterval { interval: -1.0 })
    );
    assert_eq!(
        run(
            BenettinConfig {
                duration: 0.0,
                ..good
            },
            [1.0, 0.0]
        ),
        Some(VariationalError::NonPositiveDuration { duration: 0.0 })
    );
    assert!(matches!(
        run(BenettinConfig { transient: f64::NAN, ..good }, [1.0, 0.0]),
        Some(VariationalError::InvalidTransient { transient }) if transient.is_nan()
    ));
    assert!(matches!(
        run(
            BenettinConfig {
                interval: 1e-300,
                ..good
            },
            [1.0, 0.0]
        ),
        Some(VariationalError::TooManyIntervals {
            max: precess::variational::MAX_INTERVALS,
            ..
        })
    ));
    // A duration lost in rounding beside a late start has no time to average over.
    let late = sys.initial_state(&[1.0, 0.0]).unwrap();
    let mut ode_late = Dop853::new(&sys, 1e20, late, ode).unwrap();
    assert_eq!(
        benettin(
            &mut ode_late,
            sys.layout(),
            &BenettinConfig {
                duration: 1.0,
                interval: 1.0,
                transient: 0.0
            }
        )
        .err(),
        Some(VariationalError::NonPositiveDuration { duration: 0.0 })
    );
    assert!(matches!(
        run(good, [1.0, f64::INFINITY]),
        Some(VariationalError::NonFinite { index: 1, value }) if value == f64::INFINITY
    ));
    // No tangent vectors: nothing to average.
    let eq0 = VariationalEquations::new(&mut a, &x, &[x[1], f], 0, &[k]).unwrap();
    let sys0 = VariationalSystem::<4>::new(&a, &eq0, &[("k", 1.0)]).unwrap();
    assert_eq!(
        sys0.lyapunov(0.0, &[1.0, 0.0], &good, ode).err(),
        Some(VariationalError::NoTangents)
    );
    let y = sys.initial_state(&[1.0, 0.0]).unwrap();
    let map = FlowMap::new(sys.layout(), &y).unwrap();
    assert_eq!(
        map.covariance(&DMatrix::zeros(3, 2)),
        Err(VariationalError::CovarianceShape {
            rows: 3,
            cols: 2,
            n: 2
        })
    );
    let partial = Layout {
        n: 2,
        tangents: 1,
        sensitivities: 0,
    };
    assert_eq!(
        FlowMap::new(partial, &y[..4]),
        Err(VariationalError::NotFullTransition { tangents: 1, n: 2 })
    );
    // A scene's sensitivity to a parameter it does not have.
    let z = a.zero();
    let one = a.one();
    let scene = TopScene::free(&mut a, [[one, z, z], [z, one, z], [z, z, one]]);
    let top = scene.derive(&mut a).unwrap();
    assert_eq!(
        VariationalEquations::from_top(&mut a, &top, 6, &["mass"]),
        Err(VariationalError::UnknownParameter {
            name: "mass".to_owned()
        })
    );
}

/// The augmented system is as shareable as the plain models.
#[test]
fn the_variational_system_is_send_and_sync() {
    fn shareable<T: Send + Sync>() {}
    shareable::<VariationalSystem<12>>();
    shareable::<VariationalEquations>();
}

/// x' = A x with A = (a_ij) parameters: Φ(t) = exp(A t), and the sensitivity to a₀₁ is the
/// upper-right block of exp([[A, E₀₁], [0, A]] t) applied to x₀ (Van Loan's block
/// exponential), both independent of the variational equations. Over random A and x₀.
fn linear_case(
    entries: [f64; 9],
    x0: [f64; 3],
) -> Result<(), proptest::test_runner::TestCaseError> {
    let mut a = Arena::new();
    let x = ["x0", "x1", "x2"].map(|n| a.input(n));
    let p: Vec<ExprId> = (0..9)
        .map(|k| a.parameter(&format!("a{}{}", k / 3, k % 3)))
        .collect();
    let rhs: Vec<ExprId> = (0..3)
        .map(|i| {
            let terms: Vec<ExprId> = (0..3).map(|j| a.mul(p[3 * i + j], x[j])).collect();
            a.sum(&terms)
        })
        .collect();
    let eq = VariationalEquations::new(&mut a, &x, &rhs, 3, &[p[1]]).unwrap();
    let names: Vec<String> = (0..9).map(|k| format!("a{}{}", k / 3, k % 3)).collect();
    let values: Vec<(&str, f64)> = names.iter().map(String::as_str).zip(entries).collect();
    let sys = VariationalSystem::<15>::new(&a, &eq, &values).unwrap();
    let t = 1.0;
    let y = flow(&sys, sys.initial_state(&x0).unwrap(), t);
    let m = Matrix3::from_row_slice(&entries);
    let e = (m * t).exp();
    let phi = sys.transition(&y);
    for i in 0..3 {
        for j in 0..3 {
            proptest::prop_assert!((phi[(i, j)] - e[(i, j)]).abs() < 1e-10 * (1.0 + e.amax()));
        }
    }
    let mut block = Matrix6::zeros();
    block.fixed_view_mut::<3, 3>(0, 0).copy_from(&m);
    block.fixed_view_mut::<3, 3>(3, 3).copy_from(&m);
    block[(0, 4)] = 1.0;
    let d = (block * t).exp();
    let ds = d.fixed_view::<3, 3>(0, 3) * nalgebra::Vector3::from(x0);
    let s = sys.sensitivities(&y);
    for i in 0..3 {
        proptest::prop_assert!(
            (s[(i, 0)] - ds[i]).abs() < 1e-10 * (1.0 + ds.amax()),
            "{} against {}",
            s[(i, 0)],
            ds[i]
        );
    }
    Ok(())
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
    #[test]
    fn linear_systems_have_the_exponential_flow_map(
        entries in proptest::array::uniform9(-1.5f64..1.5),
        x0 in proptest::array::uniform3(-2.0f64..2.0),
    ) {
        linear_case(entries, x0)?;
    }
}

/// The augmented program computes f once, J once, and the products J Φ with J's structural
/// zeros dropped: its operations are at most those of f and J lowered together plus one
/// multiply and one add per nonzero of J per column.
#[test]
fn the_augmented_program_shares_f_and_j() {
    let mut a = Arena::new();
    let z = a.zero();
    let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
    let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let derivation = scene.derive(&mut a).unwrap();
    let cases = [
        (
            "heavy top, angles",
            VariationalEquations::from_top(&mut a, &derivation, 6, &[]).unwrap(),
        ),
        (
            "heavy top, angles, m = 1",
            VariationalEquations::from_top(&mut a, &derivation, 1, &[]).unwrap(),
        ),
        (
            "heavy top, Eulerian",
            VariationalEquations::from_eulerian_top(&mut a, &scene, 12, &[]).unwrap(),
        ),
        (
            "heavy top, Eulerian, m = 1",
            VariationalEquations::from_eulerian_top(&mut a, &scene, 1, &[]).unwrap(),
        ),
    ];
    for (name, eq) in &cases {
        let (plain, augmented) = eq.op_counts(&a);
        let mut fj: Vec<ExprId> = eq.outputs()[..eq.layout().n].to_vec();
        fj.extend(eq.jacobian());
        let together = precess::codegen::Program::lower(&a, &fj).op_count();
        let nonzero = eq.jacobian().iter().filter(|&&e| e != a.zero()).count();
        let bound = together.total() + 2 * nonzero * eq.layout().tangents;
        eprintln!(
            "{name}: f {} ops ({} weighted), f and J {} ops, augmented {} ops ({} weighted), J has {nonzero} nonzeros, bound {bound}",
            plain.total(),
            plain.weighted(),
            together.total(),
            augmented.total(),
            augmented.weighted()
        );
        assert!(
            augmented.total() <= bound,
            "{name}: {} > {bound}",
            augmented.total()
        );
    }
}

precess::taylor_system! {
    /// The Lorenz system with its three tangent vectors written out by hand (J of the
    /// Lorenz field times each): a second formulation of the variational equations, for the
    /// Taylor integrator.
    struct LorenzTangents;
    state [x, y, z, u0, v0, w0, u1, v1, w1, u2, v2, w2];
    taylor = 20;
    d/dt x = 10.0 * (y - x);
    d/dt y = x * (28.0 - z) - y;
    d/dt z = x * y - 8.0 / 3.0 * z;
    d/dt u0 = 10.0 * (v0 - u0);
    d/dt v0 = (28.0 - z) * u0 - v0 - x * w0;
    d/dt w0 = y * u0 + x * v0 - 8.0 / 3.0 * w0;
    d/dt u1 = 10.0 * (v1 - u1);
    d/dt v1 = (28.0 - z) * u1 - v1 - x * w1;
    d/dt w1 = y * u1 + x * v1 - 8.0 / 3.0 * w1;
    d/dt u2 = 10.0 * (v2 - u2);
    d/dt v2 = (28.0 - z) * u2 - v2 - x * w2;
    d/dt w2 = y * u2 + x * v2 - 8.0 / 3.0 * w2;
}

/// Benettin's method over another stepper and another formulation: the hand-written
/// tangent equations of `taylor_system!` on the Taylor integrator give the same published
/// spectrum and the same exact sum.
#[test]
fn the_lorenz_spectrum_through_taylor_system() {
    let layout = Layout {
        n: 3,
        tangents: 3,
        sensitivities: 0,
    };
    let y0 = layout.initial_state::<12>(&[1.0, 1.0, 20.0]).unwrap();
    let mut ode = Taylor::new(
        LorenzTangents,
        0.0,
        y0,
        TaylorConfig::with_tol(1e-12, 1e-12),
    )
    .unwrap();
    let cfg = BenettinConfig {
        interval: 0.1,
        duration: 1000.0,
        transient: 10.0,
    };
    let run = benettin(&mut ode, layout, &cfg).unwrap();
    let l = &run.exponents;
    let sum: f64 = l.iter().sum();
    eprintln!("Lorenz by Taylor: {l:?}, sum {sum}, {:?}", run.stats);
    assert_relative_eq!(sum, -41.0 / 3.0, max_relative = 1e-9);
    assert_relative_eq!(l[0], 0.9056, max_relative = 0.01);
    assert!(l[1].abs() < 0.005, "{l:?}");
    assert_relative_eq!(l[2], -14.5723, max_relative = 0.002);
}

/// A heavy top with unequal moments (1, 1.5, 0.7) and its centre on the third axis is not
/// integrable; in Eulerian form (ω and R, twelve entries, no chart) J has zero trace in
/// principal axes, so Σλ = 0 for every finite time, and the spectrum pairs: λ₁ ≈ −λ₁₂ with
/// ten exponents near zero (energy, the vertical momentum, the flow direction, and the six
/// orthonormality conditions of R with their partners).
#[test]
fn the_heavy_top_spectrum_comes_in_pairs() {
    let mut a = Arena::new();
    let z = a.zero();
    let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
    let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
    scene.mass = a.parameter("M");
    scene.center = [z, z, a.parameter("l")];
    scene.gravity = Some(a.parameter("g"));
    let eq = VariationalEquations::from_eulerian_top(&mut a, &scene, 12, &[]).unwrap();
    let values = [
        ("I1", 1.0),
        ("I2", 1.5),
        ("I3", 0.7),
        ("M", 1.0),
        ("g", 1.0),
        ("l", 1.0),
    ];
    let sys = VariationalSystem::<156>::new(&a, &eq, &values).unwrap();
    // Tilted 1.5 rad about the first axis, turning slowly: kinetic and potential energy
    // of one size, the chaotic regime (λ₁ ≈ 0.24; a fast spin is nearly the free body and
    // regular).
    let (c, s) = (1.5f64.cos(), 1.5f64.sin());
    let x0 = [0.5, 0.3, 0.2, 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c];
    let cfg = BenettinConfig {
        interval: 1.0,
        duration: 400.0,
        transient: 20.0,
    };
    let run = sys
        .lyapunov(0.0, &x0, &cfg, AdaptiveConfig::with_tol(1e-11, 1e-11))
        .unwrap();
    let l = &run.exponents;
    let sum: f64 = l.iter().sum();
    eprintln!("heavy top, Eulerian: {l:?}, sum {sum:e}, {:?}", run.stats);
    assert!(l[0] > 0.1, "{l:?}");
    assert!(sum.abs() < 1e-9, "{sum:e}");
    assert!((l[0] + l[11]).abs() < 0.01 * l[0], "{l:?}");
    for k in 1..11 {
        assert!(l[k].abs() < 0.05 * l[0], "{l:?}");
    }
}
