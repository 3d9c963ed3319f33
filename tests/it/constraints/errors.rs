//! Bad input to the constraint engine: typed errors naming the quantity and its value.

use precess::lagrange::{ConstrainedModel, Constraints, Coordinates, EquationsOfMotion};
use precess::lagrange::{LagrangeError, MAX_NEWTON, START_RESIDUAL};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;

use super::four_bar::{four_bar, start, values};

/// A point mass on the circle x² + y² = ℓ² in Cartesian coordinates, under gravity.
fn circle(a: &mut Arena) -> (EquationsOfMotion, Constraints, Coordinates) {
    let c = Coordinates::new(a, &["x", "y"]);
    let (m, g, l) = (a.parameter("m"), a.parameter("g"), a.parameter("l"));
    let half = a.number("0.5").expect("a decimal");
    let v2 = {
        let x = a.mul(c.rates[0], c.rates[0]);
        let y = a.mul(c.rates[1], c.rates[1]);
        a.add(x, y)
    };
    let t = a.product(&[half, m, v2]);
    let v = a.product(&[m, g, c.q[1]]);
    let lag = a.sub(t, v);
    let zero = a.zero();
    let eom = EquationsOfMotion::derive(a, lag, c.clone(), &[zero, zero]).expect("derives");
    let r2 = {
        let x = a.mul(c.q[0], c.q[0]);
        let y = a.mul(c.q[1], c.q[1]);
        a.add(x, y)
    };
    let l2 = a.mul(l, l);
    let phi = a.sub(r2, l2);
    let mut k = Constraints::new();
    k.holonomic(a, &c, phi).expect("no rates");
    (eom, k, c)
}

#[test]
fn the_pendulum_on_a_circle_has_tension_m_v2_over_l_plus_gravity() {
    // Independent value: at the bottom (0, −ℓ) moving at speed v, the rod pulls up with
    // T = m g + m v²/ℓ; φ = x² + y² − ℓ² has ∂φ/∂y = −2ℓ there, so λ = −T/(2ℓ).
    let mut a = Arena::new();
    let (eom, k, _) = circle(&mut a);
    let eqs = eom
        .constrain(&mut a, &k, Some(&[1]))
        .expect("y is dependent");
    let (m, g, l, v) = (1.5, 9.81, 0.8, 2.5);
    let model =
        ConstrainedModel::new(&mut a, &eqs, &[], &[("m", m), ("g", g), ("l", l)]).expect("binds");
    let state = [0.0, -l, v];
    let lambda = model.multipliers(0.0, &state).expect("regular");
    let tension = m * g + m * v * v / l;
    assert!((lambda[0] + tension / (2.0 * l)).abs() < 1e-13 * tension);
    // On the horizontal diameter (ℓ, 0) the block ∂φ/∂y = 2y vanishes: a typed error.
    let err = model.rates(0.0, &[l, 0.0, 0.0]).unwrap_err();
    assert!(
        matches!(err, LagrangeError::SingularAtState { determinant, .. } if determinant == 0.0)
    );
}

#[test]
fn a_loop_that_cannot_close_is_named_with_its_residual() {
    let mut a = Arena::new();
    let (eom, k, _) = circle(&mut a);
    let eqs = eom
        .constrain(&mut a, &k, Some(&[1]))
        .expect("y is dependent");
    let model = ConstrainedModel::new(&mut a, &eqs, &[], &[("m", 1.0), ("g", 9.81), ("l", 1.0)])
        .expect("binds");
    // x = 2 > ℓ: no y closes x² + y² = 1.
    let mut state = [2.0, -0.5, 0.0];
    let err = model.close_loop(0.0, &mut state, 1e-14).unwrap_err();
    match err {
        LagrangeError::LoopNotClosed {
            residual,
            iterations,
            ..
        } => {
            assert!(
                residual > 1.0 && iterations <= MAX_NEWTON,
                "{residual} after {iterations}"
            );
            assert!(err.to_string().contains("does not close"), "{err}");
        }
        other => panic!("expected LoopNotClosed, got {other:?}"),
    }
    assert_eq!(state, [2.0, -0.5, 0.0], "the state is left unchanged");
    // A reachable x closes from a rough guess to rounding.
    let mut state = [0.6, -0.7, 0.0];
    let n = model.close_loop(0.0, &mut state, 1e-15).expect("closes");
    assert!(
        n >= 1 && (state[1] + 0.8).abs() < 1e-15,
        "y = {} after {n}",
        state[1]
    );
}

#[test]
fn a_partitioned_run_refuses_a_start_off_the_loop() {
    let mut a = Arena::new();
    let (eqs, out) = four_bar(&mut a).expect("the four-bar derives");
    let model = ConstrainedModel::new(&mut a, &eqs, &out, &values()).expect("binds");
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    // The rocker 1e-3 rad off Freudenstein's angle: Newton would close the loop by moving it,
    // so the run would start from a state the user did not give.
    let mut off = start(6.0);
    off[2] += 1e-3;
    let mut ode =
        Dop853::new(model.system::<4>().expect("n + k = 4"), 0.0, off, cfg).expect("starts");
    let err = model.advance_partitioned(&mut ode, 0.1, 1e-15).unwrap_err();
    match err {
        LagrangeError::StartOffLoop { residual, allowed } => {
            // The rocker (c = 2.5) moved by 1e-3 rad moves its end by about 2.5e-3.
            assert!(residual > 1e-4 && residual < 1e-2, "{residual}");
            assert_eq!(allowed, START_RESIDUAL);
            assert!(err.to_string().contains("off the loop"), "{err}");
        }
        other => panic!("expected StartOffLoop, got {other:?}"),
    }
    assert_eq!(*ode.y(), off, "nothing was integrated");
    // The state as set up from Freudenstein's closed form (closed to rounding) runs.
    let on = start(6.0);
    let mut ode =
        Dop853::new(model.system::<4>().expect("n + k = 4"), 0.0, on, cfg).expect("starts");
    model
        .advance_partitioned(&mut ode, 0.1, 1e-15)
        .expect("a closed start runs");
    assert!(ode.t() >= 0.1);
}

#[test]
fn bad_choices_of_dependent_coordinates_are_refused() {
    let mut a = Arena::new();
    let (eom, k, c) = circle(&mut a);
    let err = eom.constrain(&mut a, &k, Some(&[0, 1])).unwrap_err();
    assert!(
        matches!(err, LagrangeError::DependentChoice { .. }),
        "{err:?}"
    );
    let err = eom.constrain(&mut a, &k, Some(&[2])).unwrap_err();
    assert!(
        matches!(err, LagrangeError::DependentChoice { .. }),
        "{err:?}"
    );
    // Two copies of the same loop: no pair of coordinates solves them.
    let mut twice = k.clone();
    let phi = k.positions[0].expect("holonomic");
    twice.holonomic(&mut a, &c, phi).expect("no rates");
    let err = eom.constrain(&mut a, &twice, None).unwrap_err();
    assert!(
        matches!(err, LagrangeError::TooManyConstraints { .. }),
        "{err:?}"
    );
    // A row on x alone cannot make y dependent.
    let mut only_x = Constraints::new();
    let zero = a.zero();
    only_x
        .nonholonomic(&mut a, &c, &[c.q[1], zero], zero)
        .expect("linear");
    let err = eom.constrain(&mut a, &only_x, Some(&[1])).unwrap_err();
    assert!(
        matches!(err, LagrangeError::SingularConstraintBlock { ref dependent } if dependent == &[1]),
        "{err:?}"
    );
    // A coefficient holding a rate is not a velocity constraint.
    let err = Constraints::new()
        .nonholonomic(&mut a, &c, &[c.rates[0], zero], zero)
        .unwrap_err();
    assert!(
        matches!(err, LagrangeError::ConstraintNotLinear { row: 0, .. }),
        "{err:?}"
    );
    let err = Constraints::new()
        .nonholonomic(&mut a, &c, &[zero], zero)
        .unwrap_err();
    assert!(matches!(
        err,
        LagrangeError::ConstraintLength {
            got: 1,
            expected: 2,
            ..
        }
    ));
}

#[test]
fn run_time_states_are_checked() {
    let mut a = Arena::new();
    let (eqs, out) = four_bar(&mut a).expect("derives");
    let model = ConstrainedModel::new(&mut a, &eqs, &out, &values()).expect("binds");
    let err = model.rates(0.0, &[0.1, 0.2, 0.3]).unwrap_err();
    assert!(matches!(
        err,
        LagrangeError::StateLength {
            got: 3,
            expected: 4
        }
    ));
    let mut y = start(1.0);
    y[3] = f64::NAN;
    let err = model.rates(0.0, &y).unwrap_err();
    assert!(matches!(
        err,
        LagrangeError::NonFiniteState { index: 3, .. }
    ));
    assert!(model.system::<5>().is_err());
    let unset = ConstrainedModel::new(&mut a, &eqs, &out, &values()[1..]);
    assert!(matches!(unset, Err(LagrangeError::Binding(_))));
}

#[test]
fn no_constraints_reduce_to_the_free_equations() {
    // The pendulum in its angle, with an empty constraint set: u̇ is the free θ̈.
    let mut a = Arena::new();
    let c = Coordinates::new(&mut a, &["theta"]);
    let (g, l) = (a.parameter("g"), a.parameter("l"));
    let half = a.number("0.5").expect("a decimal");
    let t = a.product(&[half, l, l, c.rates[0], c.rates[0]]);
    let cos = a.cos(c.q[0]);
    let v = a.product(&[g, l, cos]);
    let lag = a.add(t, v);
    let zero = a.zero();
    let eom = EquationsOfMotion::derive(&mut a, lag, c, &[zero]).expect("derives");
    let eqs = eom
        .constrain(&mut a, &Constraints::new(), None)
        .expect("nothing to eliminate");
    assert!(eqs.dependent.is_empty() && eqs.multipliers.is_empty());
    let model =
        ConstrainedModel::new(&mut a, &eqs, &[], &[("g", 9.81), ("l", 2.0)]).expect("binds");
    let acc = model.accelerations(0.0, &[0.7, 1.0]).expect("regular");
    assert!((acc[0] + 9.81 / 2.0 * 0.7_f64.sin()).abs() < 1e-15);
    assert_eq!(model.position_residuals(0.0, &[0.7, 1.0]), Ok(None));
}
