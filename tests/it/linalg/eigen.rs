//! The eigenvalue routine against matrices whose spectra are known by construction:
//! companion matrices of polynomials with chosen roots, rotations, Jordan blocks, and
//! random orthogonal similarity transforms of block-diagonal matrices; and the stability
//! verdict on systems with closed-form spectra.

use crate::common;

use common::rng::Rng;
use nalgebra::{Complex, DMatrix, Matrix2, Rotation3, Vector3};
use precess_core::linalg::{LinalgError, LinearSystem, Stability, eigenvalues};
use precess_core::ode::FnSystem;

/// The largest distance from each expected eigenvalue to the computed one matched to it
/// (greedy nearest match, each computed value used once).
fn worst_match(computed: &[Complex<f64>], expected: &[Complex<f64>]) -> f64 {
    assert_eq!(computed.len(), expected.len(), "{computed:?}");
    let mut free: Vec<Complex<f64>> = computed.to_vec();
    let mut worst: f64 = 0.0;
    for e in expected {
        let (k, d) = free
            .iter()
            .enumerate()
            .map(|(k, c)| (k, (c - e).norm()))
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .unwrap();
        worst = worst.max(d);
        free.remove(k);
    }
    worst
}

/// The companion matrix of the monic polynomial with the given roots (conjugate pairs
/// included), its coefficients expanded in complex arithmetic.
fn companion(roots: &[Complex<f64>]) -> DMatrix<f64> {
    let mut coef = vec![Complex::new(1.0, 0.0)];
    for r in roots {
        let mut next = vec![Complex::new(0.0, 0.0); coef.len() + 1];
        for (k, c) in coef.iter().enumerate() {
            next[k + 1] += c;
            next[k] -= c * r;
        }
        coef = next;
    }
    let n = roots.len();
    // Last column −c₀ … −c_{n−1}, ones on the subdiagonal.
    DMatrix::from_fn(n, n, |i, j| {
        if j == n - 1 {
            -coef[i].re
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    })
}

fn c(re: f64, im: f64) -> Complex<f64> {
    Complex::new(re, im)
}

#[test]
fn companion_matrices_give_their_roots() {
    let cases: Vec<Vec<Complex<f64>>> = vec![
        (1..=5).map(|k| c(k as f64, 0.0)).collect(),
        vec![c(-1.0, 0.0), c(0.5, 2.0), c(0.5, -2.0), c(3.0, 0.0)],
        vec![
            c(-2.0, 0.1),
            c(-2.0, -0.1),
            c(0.0, 1.0),
            c(0.0, -1.0),
            c(0.25, 0.0),
            c(4.0, 3.0),
            c(4.0, -3.0),
        ],
    ];
    for roots in cases {
        let eig = eigenvalues(&companion(&roots)).unwrap();
        let err = worst_match(&eig, &roots);
        // Companion matrices are badly scaled; balancing brings the error to ~1e-13 here.
        assert!(err < 1e-10, "roots {roots:?}: error {err:e}");
    }
}

#[test]
fn rotations_have_unit_eigenvalues() {
    for alpha in [0.3, 1.0, 2.5, std::f64::consts::PI - 1e-3] {
        let r2 = Matrix2::new(alpha.cos(), -alpha.sin(), alpha.sin(), alpha.cos());
        let expected = [c(alpha.cos(), alpha.sin()), c(alpha.cos(), -alpha.sin())];
        assert!(worst_match(&eigenvalues(&r2).unwrap(), &expected) < 1e-15);
        let axis = Vector3::new(0.3, -0.5, 0.8).normalize();
        let r3 = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), alpha);
        let eig = eigenvalues(r3.matrix()).unwrap();
        let expected = [c(1.0, 0.0), expected[0], expected[1]];
        assert!(worst_match(&eig, &expected) < 1e-14, "{eig:?}");
    }
}

/// A cyclic permutation has the n-th roots of unity as eigenvalues and defeats the standard
/// shifts (they are all zero); the exceptional shifts must break the cycle.
#[test]
fn cyclic_permutations_converge() {
    for n in [3, 4, 7, 12] {
        let p = DMatrix::from_fn(n, n, |i, j| if i == (j + 1) % n { 1.0 } else { 0.0 });
        let expected: Vec<Complex<f64>> = (0..n)
            .map(|k| Complex::from_polar(1.0, 2.0 * std::f64::consts::PI * k as f64 / n as f64))
            .collect();
        let err = worst_match(&eigenvalues(&p).unwrap(), &expected);
        assert!(err < 1e-13, "n = {n}: {err:e}");
    }
}

/// A k×k Jordan block is perturbed to eigenvalues ε^{1/k} away, but their mean stays exact
/// (the trace).
#[test]
fn jordan_blocks_and_their_mean() {
    let mut rng = Rng::new(17);
    for (k, lambda) in [(2, 1.5), (3, -0.5), (4, 2.0)] {
        let j = DMatrix::from_fn(k, k, |r, s| {
            if r == s {
                lambda
            } else if s == r + 1 {
                1.0
            } else {
                0.0
            }
        });
        for a in [j.clone(), similar(&j, &mut rng)] {
            let eig = eigenvalues(&a).unwrap();
            let bound = 10.0 * (f64::EPSILON * a.norm()).powf(1.0 / k as f64);
            for e in &eig {
                assert!((e - c(lambda, 0.0)).norm() < bound, "k = {k}: {eig:?}");
            }
            let mean: Complex<f64> = eig.iter().sum::<Complex<f64>>() / k as f64;
            assert!((mean - c(lambda, 0.0)).norm() < 1e-14 * a.norm(), "{mean}");
        }
    }
}

/// A random orthogonal matrix: the Q factor of a matrix of uniform entries.
fn orthogonal(n: usize, rng: &mut Rng) -> DMatrix<f64> {
    DMatrix::from_fn(n, n, |_, _| rng.uniform(-1.0, 1.0))
        .qr()
        .q()
}

fn similar(a: &DMatrix<f64>, rng: &mut Rng) -> DMatrix<f64> {
    let q = orthogonal(a.nrows(), rng);
    &q * a * q.transpose()
}

/// Q D Qᵀ with D block diagonal: real eigenvalues on the diagonal and 2×2 blocks
/// [[a, b], [−b, a]] for a ± i b.
#[test]
fn random_orthogonal_similarity_with_chosen_spectra() {
    let mut rng = Rng::new(3);
    for trial in 0..40 {
        let n_real = 1 + trial % 5;
        let n_pairs = 1 + (trial / 5) % 6;
        let n = n_real + 2 * n_pairs;
        let mut d = DMatrix::zeros(n, n);
        let mut expected = Vec::new();
        for i in 0..n_real {
            let v = rng.uniform(-5.0, 5.0);
            d[(i, i)] = v;
            expected.push(c(v, 0.0));
        }
        for p in 0..n_pairs {
            let i = n_real + 2 * p;
            let (a, b) = (rng.uniform(-3.0, 3.0), rng.uniform(0.1, 4.0));
            d[(i, i)] = a;
            d[(i + 1, i + 1)] = a;
            d[(i, i + 1)] = b;
            d[(i + 1, i)] = -b;
            expected.extend([c(a, b), c(a, -b)]);
        }
        // An upper-triangular coupling keeps the spectrum and makes A non-normal.
        for i in 0..n {
            for j in i + 2..n {
                d[(i, j)] = rng.uniform(-1.0, 1.0);
            }
        }
        let a = similar(&d, &mut rng);
        let err = worst_match(&eigenvalues(&a).unwrap(), &expected);
        assert!(err < 1e-10 * a.norm(), "trial {trial} (n = {n}): {err:e}");
    }
}

#[test]
fn badly_scaled_and_special_matrices() {
    // Diagonal similarity by 1e±100 leaves the spectrum {1, 2, 3}.
    let base = DMatrix::from_row_slice(3, 3, &[1.0, 1.0, 0.0, 0.0, 2.0, 1.0, 0.5, 0.0, 3.0]);
    let expected_base = eigenvalues(&base).unwrap();
    let s = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![1e-100, 1.0, 1e100]));
    let s_inv = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![1e100, 1.0, 1e-100]));
    let scaled = &s * &base * &s_inv;
    let err = worst_match(&eigenvalues(&scaled).unwrap(), &expected_base);
    assert!(err < 1e-13, "{err:e}");
    // The base's characteristic polynomial x³ − 6x² + 11x − 6.5 (direct expansion) at them.
    for e in &expected_base {
        let p = e * e * e - 6.0 * e * e + 11.0 * e - 6.5;
        assert!(p.norm() < 1e-13, "{e}: {p}");
    }
    assert!(
        eigenvalues(&DMatrix::<f64>::zeros(0, 0))
            .unwrap()
            .is_empty()
    );
    assert_eq!(
        eigenvalues(&DMatrix::<f64>::zeros(4, 4)).unwrap(),
        vec![c(0.0, 0.0); 4]
    );
}

#[test]
fn bad_input_is_refused() {
    assert_eq!(
        eigenvalues(&DMatrix::<f64>::zeros(2, 3)),
        Err(LinalgError::NotSquare { rows: 2, cols: 3 })
    );
    let mut a = DMatrix::<f64>::identity(3, 3);
    a[(1, 2)] = f64::NAN;
    assert!(matches!(
        eigenvalues(&a),
        Err(LinalgError::NonFinite { row: 1, col: 2, .. })
    ));
    let lin = LinearSystem::new(DMatrix::identity(2, 2)).unwrap();
    assert!(matches!(
        lin.stability_with(-1.0),
        Err(LinalgError::InvalidParameter { .. })
    ));
}

/// Damped oscillator ẍ + 2ζω ẋ + ω² x = 0: eigenvalues −ζω ± iω√(1 − ζ²), so asymptotically
/// stable with decay rate ζω; undamped, linearly stable; with negative damping, unstable.
#[test]
fn stability_verdicts_of_oscillators() {
    let omega: f64 = 3.0;
    for (zeta, verdict) in [
        (
            0.1,
            Stability::AsymptoticallyStable {
                decay_rate: 0.1 * omega,
            },
        ),
        (0.0, Stability::LinearlyStable { max_abs_real: 0.0 }),
        (
            -0.2,
            Stability::Unstable {
                growth_rate: 0.2 * omega,
            },
        ),
    ] {
        let sys = FnSystem(move |_t: f64, y: &[f64; 2], d: &mut [f64; 2]| {
            d[0] = y[1];
            d[1] = -omega * omega * y[0] - 2.0 * zeta * omega * y[1];
        });
        let got = LinearSystem::from_system(&sys, 0.0, &[0.1, -0.2])
            .unwrap()
            .stability()
            .unwrap();
        match (got, verdict) {
            (
                Stability::AsymptoticallyStable { decay_rate: a },
                Stability::AsymptoticallyStable { decay_rate: b },
            )
            | (Stability::Unstable { growth_rate: a }, Stability::Unstable { growth_rate: b }) => {
                assert!((a - b).abs() < 1e-10, "{a} vs {b}")
            }
            (Stability::LinearlyStable { max_abs_real }, Stability::LinearlyStable { .. }) => {
                assert!(max_abs_real < 1e-12)
            }
            _ => panic!("ζ = {zeta}: {got:?}, expected {verdict:?}"),
        }
    }
}
