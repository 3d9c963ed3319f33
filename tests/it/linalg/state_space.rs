//! `linalg::StateSpace` against closed forms: the sleeping heavy top (`models::HeavyTop`)
//! in the Euler–Poisson equations with a motor torque about its axis, linearised by the
//! differencing fallback (`from_fn`), whose tilt grows at √(4 M g l I₁ − I₃² ω₃²) / (2 I₁)
//! below the Maxwell–Klein spin ω₃² = 4 M g l I₁ / I₃² and not at all above it; and the
//! typed errors.

use precess::linalg::{
    LinalgError, OPERATING_POINT_TOLERANCE, SecondOrder, StateSpace, StateSpaceError,
};
use precess::models::HeavyTop;
use precess::nalgebra::{DMatrix, Vector3};
use precess::prelude::RigidBody;

/// The top's moments about the pivot and M g l.
fn top() -> (Vector3<f64>, f64) {
    let moments = HeavyTop.principal().moments;
    let mgl = HeavyTop.mass() * 9.81 * HeavyTop.center_of_mass().z;
    (moments, mgl)
}

/// The Euler–Poisson equations in body axes, x = (γ, ω) with γ the upward vertical:
/// I ω̇ = (I ω) × ω + M g l γ × e₃ + τ, γ̇ = γ × ω; the input τ a body-fixed couple.
fn euler_poisson(x: &[f64], tau: &[f64], out: &mut [f64]) {
    let (i, mgl) = top();
    let gamma = Vector3::new(x[0], x[1], x[2]);
    let w = Vector3::new(x[3], x[4], x[5]);
    let l = i.component_mul(&w);
    let torque = l.cross(&w) + mgl * gamma.cross(&Vector3::z()) + Vector3::from_column_slice(tau);
    let gamma_dot = gamma.cross(&w);
    out[..3].copy_from_slice(gamma_dot.as_slice());
    out[3..].copy_from_slice(torque.component_div(&i).as_slice());
}

fn sleeping(w3: f64) -> StateSpace {
    StateSpace::from_fn(
        euler_poisson,
        &[0.0, 0.0, 1.0, 0.0, 0.0, w3],
        &[0.0; 3],
        OPERATING_POINT_TOLERANCE,
    )
    .expect("the sleeping top is a steady motion")
}

fn max_re(lin: &StateSpace) -> f64 {
    lin.eigenvalues()
        .expect("eigenvalues")
        .iter()
        .map(|z| z.re)
        .fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn sleeping_top_grows_below_the_maxwell_klein_spin_and_not_above() {
    let (i, mgl) = top();
    let (i1, i3) = (i.x, i.z);
    let threshold = (4.0 * mgl * i1).sqrt() / i3;
    for factor in [0.3, 0.7, 0.95] {
        let w3 = factor * threshold;
        let want = (4.0 * mgl * i1 - i3 * i3 * w3 * w3).sqrt() / (2.0 * i1);
        let got = max_re(&sleeping(w3));
        println!("ω₃ = {factor} × threshold: growth {got} against {want}");
        assert!(((got - want) / want).abs() < 1e-9, "{got} vs {want}");
    }
    for factor in [1.05, 2.0, 10.0] {
        let got = max_re(&sleeping(factor * threshold));
        assert!(got.abs() < 1e-9 * threshold, "{factor}: {got:e}");
    }
}

#[test]
fn motor_torque_enters_through_the_inverse_inertia() {
    let (i, _) = top();
    let lin = sleeping(100.0);
    assert_eq!((lin.states(), lin.inputs()), (6, 3));
    let want = DMatrix::from_fn(6, 3, |r, c| if r == c + 3 { 1.0 / i[c] } else { 0.0 });
    let err = (&lin.b - &want).amax() / want.amax();
    assert!(err < 1e-11, "B off by {err:e}:\n{}", lin.b);
}

#[test]
fn a_tilted_top_at_rest_is_not_an_operating_point() {
    let (_, mgl) = top();
    let tilt = 0.1_f64;
    let x0 = [tilt.sin(), 0.0, tilt.cos(), 0.0, 0.0, 0.0];
    match StateSpace::from_fn(euler_poisson, &x0, &[0.0; 3], OPERATING_POINT_TOLERANCE) {
        Err(StateSpaceError::NotOperatingPoint {
            quantity,
            component,
            residual,
            ..
        }) => {
            // Gravity's torque about body y: ω̇₂ = −M g l sin θ / I₂ (γ × e₃ = (0, −sin θ, 0)).
            let i2 = HeavyTop.principal().moments.y;
            assert_eq!((quantity, component), ("ẋ", 4));
            assert!((residual + mgl * tilt.sin() / i2).abs() < 1e-12 * residual.abs());
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn non_finite_and_misshapen_inputs_are_typed_errors() {
    // A NaN state, an infinite input, a zero tolerance.
    let spinning = [0.0, 0.0, 1.0, 0.0, 0.0, 1.0];
    let nan_state = [0.0, 0.0, 1.0, 0.0, 0.0, f64::NAN];
    for (x0, u0, tol) in [
        (&nan_state, [0.0; 3], 1e-9),
        (&spinning, [f64::INFINITY, 0.0, 0.0], 1e-9),
        (&spinning, [0.0; 3], 0.0),
    ] {
        let refused = StateSpace::from_fn(euler_poisson, x0, &u0, tol);
        let typed = match &refused {
            Err(StateSpaceError::Linalg(LinalgError::NonFinite { .. })) => tol > 0.0,
            Err(StateSpaceError::Linalg(LinalgError::InvalidParameter { .. })) => tol == 0.0,
            _ => false,
        };
        assert!(typed, "{refused:?}");
    }
    // One coordinate: a Jacobian block of the wrong size, then a singular mass.
    let (one, two, zero) = (
        DMatrix::from_element(1, 1, 1.0),
        DMatrix::zeros(2, 2),
        DMatrix::zeros(1, 1),
    );
    for (by_q, mass) in [(&two, &one), (&one, &zero)] {
        let refused = StateSpace::second_order(&SecondOrder {
            accelerations: &[0.0],
            by_q,
            by_qdot: &one,
            mass,
            inputs: &one,
        });
        let expected = match refused {
            Err(StateSpaceError::Shape { quantity, rows, .. }) => quantity == "∂q̈/∂q" && rows == 2,
            Err(StateSpaceError::Linalg(LinalgError::InvalidParameter { name, .. })) => {
                name == "mass matrix determinant"
            }
            _ => false,
        };
        assert!(expected, "{refused:?}");
    }
}
