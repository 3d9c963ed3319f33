//! `precess::models::Bicycle` linearised by the library (`Bicycle::canonical`) against the
//! values Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463, 2007) print for the
//! benchmark (eq. 5.3–5.6, Table 2), and against their closed-form expressions of
//! appendix A, evaluated here from the parameters, at a bicycle far from the benchmark.

use precess::linalg::CrossingError;
use precess::models::Bicycle;
use precess::models::bicycle::{BicycleLinearisationError, Canonical};
use precess::nalgebra::Matrix2;

/// Largest entrywise error, relative where the reference entry is nonzero and absolute
/// where it is 0.
fn worst(got: &Matrix2<f64>, want: &Matrix2<f64>) -> f64 {
    got.zip_map(want, |g, w| {
        ((g - w) / if w == 0.0 { 1.0 } else { w }).abs()
    })
    .max()
}

/// The four matrices' worst errors against `reference` (M, C₁, K₀, K₂), printed, each
/// below `limit`.
fn assert_close(lin: &Canonical, reference: &[Matrix2<f64>; 4], limit: f64, against: &str) {
    let got = [&lin.m, &lin.c1, &lin.k0, &lin.k2];
    let errors: Vec<(&str, f64)> = ["M", "C1", "K0", "K2"]
        .into_iter()
        .zip(got.iter().zip(reference).map(|(g, w)| worst(g, w)))
        .collect();
    println!("against {against}: {errors:?}");
    for (name, e) in errors {
        assert!(e < limit, "{name} off {against} by {e:e}");
    }
}

/// Meijaard et al. (2007), eq. 5.3–5.6, as printed.
fn published() -> [Matrix2<f64>; 4] {
    [
        Matrix2::new(
            80.81722,
            2.31941332208709,
            2.31941332208709,
            0.29784188199686,
        ),
        Matrix2::new(0.0, 33.86641391492494, -0.85035641456978, 1.68540397397560),
        Matrix2::new(
            -80.95,
            -2.59951685249872,
            -2.59951685249872,
            -0.80329488458618,
        ),
        Matrix2::new(0.0, 76.59734589573222, 0.0, 2.65431523794604),
    ]
}

/// The weave and capsize speeds of Table 2 [m/s].
const WEAVE_SPEED: f64 = 4.29238253634111;
const CAPSIZE_SPEED: f64 = 6.02426201538837;

#[test]
fn canonical_matrices_of_the_benchmark_match_the_paper() {
    let lin = Bicycle::benchmark().canonical().expect("linearises");
    // The paper prints 15 significant digits.
    assert_close(&lin, &published(), 1e-13, "the paper");
    assert_eq!(lin.g, 9.81);
}

#[test]
fn weave_and_capsize_speeds_of_the_benchmark_match_table_2() {
    let lin = Bicycle::benchmark().canonical().expect("linearises");
    let weave = lin.stability_crossing(4.0, 5.0).expect("weave in [4, 5]");
    let capsize = lin
        .stability_crossing(5.5, 7.0)
        .expect("capsize in [5.5, 7]");
    let ew = ((weave.parameter - WEAVE_SPEED) / WEAVE_SPEED).abs();
    let ec = ((capsize.parameter - CAPSIZE_SPEED) / CAPSIZE_SPEED).abs();
    println!(
        "weave {:.15} ({ew:.1e}, {} evaluations), capsize {:.15} ({ec:.1e}, {})",
        weave.parameter, weave.evaluations, capsize.parameter, capsize.evaluations
    );
    assert!(ew < 1e-12 && ec < 1e-12, "weave {ew:e}, capsize {ec:e}");
    assert!(weave.bracket_width < 1e-12 * WEAVE_SPEED);
    // The same from the printed matrices alone: the root finder, not the model.
    let [m, c1, k0, k2] = published();
    let paper = Canonical::new(m, c1, k0, k2, 9.81).expect("valid");
    let w = paper.stability_crossing(4.0, 5.0).expect("weave").parameter;
    let c = paper
        .stability_crossing(5.5, 7.0)
        .expect("capsize")
        .parameter;
    assert!(((w - WEAVE_SPEED) / WEAVE_SPEED).abs() < 1e-12, "{w}");
    assert!(((c - CAPSIZE_SPEED) / CAPSIZE_SPEED).abs() < 1e-12, "{c}");
    // Stable between them, unstable on either side.
    let max_re = |v: f64| {
        lin.eigenvalues(v)
            .expect("eigenvalues")
            .iter()
            .map(|z| z.re)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    assert!(max_re(4.0) > 0.0 && max_re(5.0) < 0.0 && max_re(7.0) > 0.0);
}

#[test]
fn a_range_without_a_crossing_is_a_typed_error() {
    let lin = Bicycle::benchmark().canonical().expect("linearises");
    // Stable throughout [4.5, 5.5] m/s.
    let refused = lin.stability_crossing(4.5, 5.5);
    let Err(CrossingError::NoCrossing { at_lo, at_hi, .. }) = refused else {
        panic!("{refused:?}");
    };
    assert!(at_lo < 0.0 && at_hi < 0.0, "{at_lo} {at_hi}");
    assert!(matches!(
        lin.stability_crossing(5.0, f64::NAN),
        Err(CrossingError::InvalidBracket { .. })
    ));
    assert!(matches!(
        lin.stability_crossing(5.0, 4.0),
        Err(CrossingError::InvalidBracket { .. })
    ));
}

#[test]
fn non_finite_input_is_refused() {
    let bike = Bicycle {
        m_b: f64::NAN,
        ..Bicycle::benchmark()
    };
    assert!(matches!(
        bike.canonical(),
        Err(BicycleLinearisationError::Mechanism(_))
    ));
    let [m, c1, k0, k2] = published();
    let mut bad = k0;
    bad[(1, 0)] = f64::INFINITY;
    assert!(Canonical::new(m, c1, bad, k2, 9.81).is_err());
    assert!(Canonical::new(Matrix2::zeros(), c1, k0, k2, 9.81).is_err());
    let lin = Canonical::new(m, c1, k0, k2, 9.81).expect("valid");
    assert!(lin.eigenvalues(f64::NAN).is_err());
    assert!(
        Bicycle::benchmark()
            .lateral_jacobian(f64::INFINITY)
            .is_err()
    );
}

/// A bicycle far from the benchmark: every length, mass and inertia changed, the front
/// wheel smaller than the rear.
fn other_bicycle() -> Bicycle {
    Bicycle {
        w: 1.15,
        c: 0.06,
        lambda: 0.35,
        g: 9.78,
        r_r: 0.34,
        m_r: 2.6,
        i_rxx: 0.075,
        i_ryy: 0.145,
        x_b: 0.42,
        z_b: -1.05,
        m_b: 72.0,
        i_bxx: 7.9,
        i_byy: 9.5,
        i_bzz: 3.1,
        i_bxz: 1.7,
        x_h: 0.95,
        z_h: -0.82,
        m_h: 5.5,
        i_hxx: 0.071,
        i_hyy: 0.07,
        i_hzz: 0.012,
        i_hxz: -0.011,
        r_f: 0.31,
        m_f: 2.2,
        i_fxx: 0.09,
        i_fyy: 0.17,
    }
}

/// M, C₁, K₀, K₂ from the parameters by the closed forms of Meijaard et al. (2007),
/// appendix A: the total and front-assembly mass properties, then the matrices.
fn appendix_a(b: &Bicycle) -> [Matrix2<f64>; 4] {
    let (sl, cl) = b.lambda.sin_cos();
    let m_t = b.m_r + b.m_b + b.m_h + b.m_f;
    let x_t = (b.x_b * b.m_b + b.x_h * b.m_h + b.w * b.m_f) / m_t;
    let z_t = (-b.r_r * b.m_r + b.z_b * b.m_b + b.z_h * b.m_h - b.r_f * b.m_f) / m_t;
    // The totals about the rear contact; the wheels' I_zz equal their I_xx.
    let i_txx = [b.i_rxx, b.i_bxx, b.i_hxx, b.i_fxx].iter().sum::<f64>()
        + [
            (b.m_r, b.r_r),
            (b.m_b, b.z_b),
            (b.m_h, b.z_h),
            (b.m_f, b.r_f),
        ]
        .iter()
        .map(|(m, z)| m * z * z)
        .sum::<f64>();
    let i_txz =
        b.i_bxz + b.i_hxz - b.m_b * b.x_b * b.z_b - b.m_h * b.x_h * b.z_h + b.m_f * b.w * b.r_f;
    let i_tzz = [b.i_rxx, b.i_bzz, b.i_hzz, b.i_fxx].iter().sum::<f64>()
        + [(b.m_b, b.x_b), (b.m_h, b.x_h), (b.m_f, b.w)]
            .iter()
            .map(|(m, x)| m * x * x)
            .sum::<f64>();
    let m_a = b.m_h + b.m_f;
    let x_a = (b.x_h * b.m_h + b.w * b.m_f) / m_a;
    let z_a = (b.z_h * b.m_h - b.r_f * b.m_f) / m_a;
    let i_axx = b.i_hxx + b.i_fxx + b.m_h * (b.z_h - z_a).powi(2) + b.m_f * (b.r_f + z_a).powi(2);
    let i_axz =
        b.i_hxz - b.m_h * (b.x_h - x_a) * (b.z_h - z_a) + b.m_f * (b.w - x_a) * (b.r_f + z_a);
    let i_azz = b.i_hzz + b.i_fxx + b.m_h * (b.x_h - x_a).powi(2) + b.m_f * (b.w - x_a).powi(2);
    let u_a = (x_a - b.w - b.c) * cl - z_a * sl;
    let i_all = m_a * u_a * u_a + i_axx * sl * sl + 2.0 * i_axz * sl * cl + i_azz * cl * cl;
    let i_alx = -m_a * u_a * z_a + i_axx * sl + i_axz * cl;
    let i_alz = m_a * u_a * x_a + i_axz * sl + i_azz * cl;
    let mu = b.c / b.w * cl;
    let (s_r, s_f) = (b.i_ryy / b.r_r, b.i_fyy / b.r_f);
    let s_t = s_r + s_f;
    let s_a = m_a * u_a + mu * m_t * x_t;
    let m_pd = i_alx + mu * i_txz;
    let m = Matrix2::new(
        i_txx,
        m_pd,
        m_pd,
        i_all + 2.0 * mu * i_alz + mu * mu * i_tzz,
    );
    let k0 = Matrix2::new(m_t * z_t, -s_a, -s_a, -s_a * sl);
    let k2 = Matrix2::new(
        0.0,
        (s_t - m_t * z_t) / b.w * cl,
        0.0,
        (s_a + s_f * sl) / b.w * cl,
    );
    let c1 = Matrix2::new(
        0.0,
        mu * s_t + s_f * cl + i_txz / b.w * cl - mu * m_t * z_t,
        -(mu * s_t + s_f * cl),
        i_alz / b.w * cl + mu * (s_a + i_tzz / b.w * cl),
    );
    [m, c1, k0, k2]
}

#[test]
fn appendix_a_closed_forms_reproduce_the_published_benchmark() {
    // The test's own closed forms, checked first where the paper prints their values.
    let [m, c1, k0, k2] = appendix_a(&Bicycle::benchmark());
    let [pm, pc1, pk0, pk2] = published();
    for (name, got, want) in [
        ("M", m, pm),
        ("C1", c1, pc1),
        ("K0", k0, pk0),
        ("K2", k2, pk2),
    ] {
        let e = worst(&got, &want);
        assert!(e < 1e-13, "appendix A's {name} off the paper by {e:e}");
    }
}

#[test]
fn canonical_matrices_match_appendix_a_at_other_parameters() {
    let bike = other_bicycle();
    let lin = bike.canonical().expect("linearises");
    let closed = appendix_a(&bike);
    assert_close(&lin, &closed, 1e-11, "appendix A");
    let [_, _, k0, k2] = closed;
    // And the capsize speed against det(g K₀ + v² K₂) = 0, linear in v² since K₂'s first
    // column is zero: v_c² = −det K₀ g² / (g (K₀₀ K₂₁₁ − K₀₁₀ K₂₀₁)).
    let g = bike.g;
    let det_k0 = k0.determinant() * g * g;
    let b = g * (k0[(0, 0)] * k2[(1, 1)] - k0[(1, 0)] * k2[(0, 1)]);
    let v_c = (-det_k0 / b).sqrt();
    let zero = lin
        .eigenvalues(v_c)
        .expect("eigenvalues")
        .iter()
        .map(|z| z.norm())
        .fold(f64::INFINITY, f64::min);
    assert!(zero < 1e-9, "no zero eigenvalue at v_c = {v_c}: {zero:e}");
    let found = lin
        .stability_crossing(0.9 * v_c, 1.1 * v_c)
        .expect("one crossing");
    println!("capsize {v_c} (closed form) vs {}", found.parameter);
    assert!(((found.parameter - v_c) / v_c).abs() < 1e-10);
}

/// The rolling input matrix K⁻¹ Sᵀ G of a lean torque on φ and a steer torque on δ, at the
/// upright run: the lateral response is M⁻¹ of the paper's M (eq. 5.3), and the rear
/// wheel's speed, which the mirror symmetry decouples, takes none of it.
#[test]
fn lean_and_steer_torques_accelerate_by_the_inverse_of_the_published_mass_matrix() {
    use precess::mechanism::rolling::RollingDynamics;
    use precess::nalgebra::SMatrix;
    let b = Bicycle::benchmark();
    let mut q = [0.0; 8];
    b.close_contacts(&mut q).expect("on the floor");
    let mut g = SMatrix::<f64, 8, 2>::zeros();
    g[(Bicycle::PHI, 0)] = 1.0;
    g[(Bicycle::DELTA, 1)] = 1.0;
    let v = 5.0;
    let inputs = b
        .input_matrix(0.0, &q, &[0.0, 0.0, -v / b.r_r], &g)
        .expect("regular");
    let lateral = Matrix2::new(
        inputs[(0, 0)],
        inputs[(0, 1)],
        inputs[(1, 0)],
        inputs[(1, 1)],
    );
    let identity = published()[0] * lateral;
    let off = (identity - Matrix2::identity()).amax();
    let rear: Vec<f64> = inputs.row(2).iter().copied().collect();
    println!("M·B_lateral − I: {off:e}; rear wheel: {rear:?}");
    assert!(off < 1e-12, "{off:e}");
    assert!(inputs.row(2).amax() < 1e-12, "{:?}", inputs.row(2));
    let bad = g.map(|x| x * f64::NAN);
    assert!(
        b.input_matrix(0.0, &q, &[0.0, 0.0, -v / b.r_r], &bad)
            .is_err()
    );
}
