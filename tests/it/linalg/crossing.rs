//! `linalg::stability_crossing` and `find_crossing` against closed forms: the Routh–Hurwitz
//! boundary of a cubic (a complex pair crossing the axis, a Hopf point), a real eigenvalue
//! crossing at a known parameter, and the typed errors.

use std::convert::Infallible;

use precess::linalg::{
    CROSSING_TOLERANCE, CrossingError, LinalgError, find_crossing, spectral_abscissa,
    stability_crossing,
};
use precess::nalgebra::{Complex, DMatrix};

/// The companion matrix of s³ + a s² + b s + c.
fn companion(a: f64, b: f64, c: f64) -> DMatrix<f64> {
    DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -c, -b, -a])
}

#[test]
fn hopf_point_of_a_cubic_is_the_routh_hurwitz_boundary() {
    // s³ + p s² + b s + c is stable iff p > 0, c > 0 and p b > c: the boundary p = c / b,
    // where a complex pair ±i√b crosses the axis.
    let (b, c) = (2.0_f64.sqrt(), std::f64::consts::PI);
    let found = stability_crossing(
        |p| Ok::<_, Infallible>(companion(p, b, c)),
        0.5,
        5.0,
        CROSSING_TOLERANCE,
    )
    .expect("crossing");
    let want = c / b;
    println!("{found:?} against {want}");
    assert!((found.parameter - want).abs() < 1e-12 * want);
    assert!(found.bracket_width <= 2e-13 * want);
    // Brent's method, not bisection: far fewer than the ~45 halvings of the bracket.
    assert!(found.evaluations < 40, "{} evaluations", found.evaluations);
    let eig = precess::linalg::eigenvalues(&companion(want, b, c)).expect("eigenvalues");
    let pair = eig.iter().find(|z| z.im > 0.0).expect("a complex pair");
    assert!((pair.im - b.sqrt()).abs() < 1e-12, "{pair}");
}

#[test]
fn real_eigenvalue_crossing_at_a_known_parameter() {
    // diag(p² − 2, −1) with a coupling that leaves the eigenvalues alone: crosses at √2.
    let a = |p: f64| {
        Ok::<_, Infallible>(DMatrix::from_row_slice(
            2,
            2,
            &[p * p - 2.0, 5.0, 0.0, -1.0],
        ))
    };
    let found = stability_crossing(a, 0.0, 3.0, 1e-15).expect("crossing");
    assert!(
        (found.parameter - 2.0_f64.sqrt()).abs() < 4e-16 * 3.0,
        "{found:?}"
    );
}

#[test]
fn spectral_abscissa_is_the_largest_real_part() {
    let eig = [
        Complex::new(-1.0, 2.0),
        Complex::new(0.5, 0.0),
        Complex::new(-3.0, 0.0),
    ];
    assert_eq!(spectral_abscissa(&eig), 0.5);
    assert_eq!(spectral_abscissa(&[]), f64::NEG_INFINITY);
}

#[test]
fn no_sign_change_names_both_ends() {
    let stable = |_p: f64| Ok::<_, Infallible>(companion(3.0, 2.0, 1.0));
    match stability_crossing(stable, 0.0, 1.0, CROSSING_TOLERANCE) {
        Err(CrossingError::NoCrossing {
            lo,
            hi,
            at_lo,
            at_hi,
        }) => {
            assert_eq!((lo, hi), (0.0, 1.0));
            assert!(at_lo < 0.0 && at_hi < 0.0);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_brackets_tolerances_and_values_are_typed_errors() {
    let g = |p: f64| Ok::<_, CrossingError>(p - 1.0);
    for (lo, hi) in [
        (2.0, 1.0),
        (1.0, 1.0),
        (f64::NAN, 1.0),
        (0.0, f64::INFINITY),
    ] {
        assert!(
            matches!(
                find_crossing(g, lo, hi, 1e-12),
                Err(CrossingError::InvalidBracket { .. })
            ),
            "[{lo}, {hi}]"
        );
    }
    for tol in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            find_crossing(g, 0.0, 2.0, tol),
            Err(CrossingError::InvalidTolerance { .. })
        ));
    }
    // NaN inside the bracket: reported with where it happened.
    let nan_inside = |p: f64| {
        Ok::<_, CrossingError>(if p > 0.5 && p < 1.5 {
            f64::NAN
        } else {
            p - 1.0
        })
    };
    match find_crossing(nan_inside, 0.0, 2.0, 1e-12) {
        Err(CrossingError::NonFinite { parameter, value }) => {
            assert!(parameter > 0.5 && parameter < 1.5 && value.is_nan());
        }
        other => panic!("{other:?}"),
    }
    // A matrix with a NaN entry: the eigenvalue routine's error, with the parameter.
    let nan_matrix = |_p: f64| Ok::<_, Infallible>(DMatrix::from_element(2, 2, f64::NAN));
    assert!(matches!(
        stability_crossing(nan_matrix, 0.0, 1.0, 1e-12),
        Err(CrossingError::Linalg {
            parameter: 0.0,
            source: LinalgError::NonFinite { .. }
        })
    ));
    // The model's own error, passed on.
    let failing = |p: f64| -> Result<DMatrix<f64>, LinalgError> {
        Err(LinalgError::InvalidParameter {
            name: "p",
            value: p,
        })
    };
    assert!(matches!(
        stability_crossing(failing, 0.0, 1.0, 1e-12),
        Err(CrossingError::Model { parameter: 0.0, .. })
    ));
}
