//! Every integrator refuses a derived scene whose fields give it a negative mass before its
//! first step (the `System::check_parameters` hook, called when an integrator is built or
//! restarted), and names the quantity with its value. Before the hook, DOP853, RK4, the
//! Taylor integrator, the fast-top splitting and the mechanisms all integrated such a scene
//! silently: only the checked `accelerations` and the `try_` methods looked at the fields.

use std::cell::Cell;

use precess::free::FreeSystem;
use precess::mechanism::ChartedMechanism;
use precess::ode::{
    AdaptiveConfig, Dop853, FixedStepConfig, OdeError, Rk4, Stepper, System, Vern9,
};
use precess::prelude::*;
use precess::taylor::{Taylor, TaylorConfig, TaylorSystem};
use precess::top::FastTop;

/// The heavy symmetric top of the textbooks, every mass property a field.
#[allow(non_snake_case)]
#[derive(RigidBody)]
#[rigid(
    body(mass = M, at = [0.0, 0.0, l], inertia = diag(I_1, I_1, I_3), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = g, taylor = 12)]
struct FieldTop {
    I_1: f64,
    I_3: f64,
    M: f64,
    g: f64,
    l: f64,
}

/// A top whose mass was typed with a minus sign: its moments stay positive, so only the
/// mass rule catches it (the weight M g would pull it up).
const NEGATIVE: FieldTop = FieldTop {
    I_1: 1.0,
    I_3: 0.5,
    M: -1.0,
    g: 9.81,
    l: 0.1,
};

/// A simple pendulum with the bob's mass a field.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, taylor = 12)]
#[body(bob, parent = ground, joint = revolute(axis = x), q = theta,
       parts(particle(mass = m, at = [0.0, 0.0, -1.0])))]
struct Pendulum {
    m: f64,
}

/// A spherical pendulum with a field mass, for the chart-switching driver.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(bob, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(body(mass = m, at = [0.0, 0.0, -1.0], inertia = diag(0.25, 0.25, 0.5))))]
struct SphericalPendulum {
    m: f64,
}

/// A thrown ball with a field mass.
#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = 0.1))]
#[free(gravity = 9.81, taylor = 12)]
struct Ball {
    m: f64,
}

/// The refusal every integrator must give: the top's body mass, −1.
fn is_negative_mass(e: &OdeError) -> bool {
    matches!(
        e,
        OdeError::InvalidSystemParameter { quantity, value, message }
            if quantity.ends_with("mass") && *value == -1.0 && message.contains("mass must be positive")
    )
}

fn at_60_degrees() -> [f64; 6] {
    [0.0, std::f64::consts::FRAC_PI_3, 0.0, 0.0, 0.0, 20.0]
}

#[test]
fn the_adaptive_pairs_refuse_a_top_with_a_negative_field_mass() {
    let chart = TopChart::declared(&NEGATIVE);
    let cfg = AdaptiveConfig::default();
    let dop = Dop853::new(&chart, 0.0, at_60_degrees(), cfg).map(|_| ());
    assert!(dop.as_ref().is_err_and(is_negative_mass), "{dop:?}");
    let vern = Vern9::new(&chart, 0.0, at_60_degrees(), cfg).map(|_| ());
    assert!(vern.as_ref().is_err_and(is_negative_mass), "{vern:?}");
    // The Eulerian form of the same top, and the one-call driver.
    let euler = EulerianTop(&NEGATIVE);
    let y0 = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 20.0];
    let eul = Dop853::new(&euler, 0.0, y0, cfg).map(|_| ());
    assert!(eul.as_ref().is_err_and(is_negative_mass), "{eul:?}");
    let solved = precess::ode::solve::<precess::ode::Dop853Pair, _, 6>(
        &chart,
        0.0,
        at_60_degrees(),
        1.0,
        &[],
        cfg,
    );
    assert!(solved.as_ref().is_err_and(is_negative_mass), "{solved:?}");
}

#[test]
fn rk4_refuses_a_top_with_a_negative_field_mass() {
    let chart = TopChart::declared(&NEGATIVE);
    let rk4 = Rk4::new(
        &chart,
        0.0,
        at_60_degrees(),
        FixedStepConfig::with_step(1e-3),
    )
    .map(|_| ());
    assert!(rk4.as_ref().is_err_and(is_negative_mass), "{rk4:?}");
}

#[test]
fn the_taylor_integrator_refuses_a_top_with_a_negative_field_mass() {
    let taylor = Taylor::new(&NEGATIVE, 0.0, at_60_degrees(), TaylorConfig::default()).map(|_| ());
    assert!(taylor.as_ref().is_err_and(is_negative_mass), "{taylor:?}");
}

#[test]
fn the_fast_top_splitting_refuses_a_negative_field_mass() {
    let fast = FastTop::new(&NEGATIVE, 9.81);
    assert!(fast.as_ref().is_err_and(is_negative_mass), "{fast:?}");
}

#[test]
fn the_charted_top_refuses_a_negative_field_mass() {
    // ChartedTop checked the top before the hook too; it stays refused.
    let charted = ChartedTop::new(
        TopChart::both(&NEGATIVE),
        0.0,
        &Matrix3::identity(),
        &Vector3::new(0.0, 0.0, 20.0),
        ChartConfig::default(),
    );
    assert!(matches!(
        charted,
        Err(TopError::Body(BodyError::NonPositiveMass {
            value: -1.0,
            ..
        }))
    ));
}

#[test]
fn a_valid_field_top_still_starts() {
    let valid = FieldTop { M: 1.0, ..NEGATIVE };
    let chart = TopChart::declared(&valid);
    assert!(Dop853::new(&chart, 0.0, at_60_degrees(), AdaptiveConfig::default()).is_ok());
    assert!(Taylor::new(&valid, 0.0, at_60_degrees(), TaylorConfig::default()).is_ok());
    assert!(FastTop::new(&valid, 9.81).is_ok());
}

#[test]
fn the_mechanism_integrators_refuse_a_negative_field_mass() {
    let bad = Pendulum { m: -1.0 };
    let y0 = [0.3, 0.0];
    let dop = Dop853::new(&bad, 0.0, y0, AdaptiveConfig::default()).map(|_| ());
    assert!(dop.as_ref().is_err_and(is_negative_mass), "{dop:?}");
    let rk4 = Rk4::new(&bad, 0.0, y0, FixedStepConfig::with_step(1e-3)).map(|_| ());
    assert!(rk4.as_ref().is_err_and(is_negative_mass), "{rk4:?}");
    let taylor = Taylor::new(&bad, 0.0, y0, TaylorConfig::default()).map(|_| ());
    assert!(taylor.as_ref().is_err_and(is_negative_mass), "{taylor:?}");
    // The quantity names the body the mass belongs to.
    let Err(OdeError::InvalidSystemParameter { quantity, .. }) =
        Dop853::new(&bad, 0.0, y0, AdaptiveConfig::default()).map(|_| ())
    else {
        panic!("not refused");
    };
    assert!(quantity.starts_with("body `bob`"), "{quantity}");
}

#[test]
fn the_chart_switching_mechanism_refuses_a_negative_field_mass() {
    let bad = SphericalPendulum { m: -1.0 };
    let y0 = [0.0, 0.5, 0.0, 0.0, 0.0, 1.0];
    let charted = ChartedMechanism::new(&bad, 0.0, y0, ChartSet::DECLARED, ChartConfig::default())
        .map(|_| ());
    assert!(
        matches!(&charted, Err(MechanismError::Ode(e)) if is_negative_mass(e)),
        "{charted:?}"
    );
}

#[test]
fn a_restart_checks_again_after_the_system_changed() {
    let mut ode = Dop853::new(
        Pendulum { m: 1.0 },
        0.0,
        [0.3, 0.0],
        AdaptiveConfig::default(),
    )
    .expect("a valid pendulum starts");
    ode.advance_to(0.1).expect("it swings");
    ode.modify_system(|p| p.m = -1.0);
    let y = *ode.y();
    let restarted = Stepper::restart(&mut ode, 0.1, y);
    assert!(
        restarted.as_ref().is_err_and(is_negative_mass),
        "{restarted:?}"
    );
    let again = ode.reinitialise(0.1, y);
    assert!(again.as_ref().is_err_and(is_negative_mass), "{again:?}");
}

#[test]
fn the_free_body_integrators_refuse_a_negative_field_mass() {
    let bad = Ball { m: -1.0 };
    let y0 = FreeState::at_rest().to_array();
    let dop = Dop853::new(FreeSystem(&bad), 0.0, y0, AdaptiveConfig::default()).map(|_| ());
    assert!(dop.as_ref().is_err_and(is_negative_mass), "{dop:?}");
    let taylor = Taylor::new(&bad, 0.0, y0, TaylorConfig::default()).map(|_| ());
    assert!(taylor.as_ref().is_err_and(is_negative_mass), "{taylor:?}");
}

/// y' = −k y with k shared through a cell, so a test can break it after the start.
struct Decay {
    k: Cell<f64>,
}

impl Decay {
    fn check(&self) -> Result<(), OdeError> {
        let k = self.k.get();
        if k >= 0.0 {
            Ok(())
        } else {
            Err(OdeError::system_parameter(
                "k",
                k,
                "the decay rate k must be ≥ 0",
            ))
        }
    }
}

impl System<1> for Decay {
    fn rhs(&self, _t: f64, y: &[f64; 1], d: &mut [f64; 1]) {
        d[0] = -self.k.get() * y[0];
    }
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.check()
    }
}

impl TaylorSystem<1> for Decay {
    type Workspace = ();
    fn max_order(&self) -> usize {
        30
    }
    fn coefficients_into(
        &self,
        _: &mut (),
        _t: f64,
        y: &[f64; 1],
        order: usize,
        c: &mut [[f64; 1]],
    ) {
        c[0] = *y;
        for j in 1..=order {
            c[j][0] = -self.k.get() * c[j - 1][0] / j as f64;
        }
    }
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.check()
    }
}

fn is_negative_k(e: &OdeError) -> bool {
    matches!(e, OdeError::InvalidSystemParameter { quantity, value, .. } if quantity == "k" && *value == -2.0)
}

#[test]
fn every_stepper_checks_its_system_again_on_restart() {
    let sys = Decay { k: Cell::new(1.0) };
    let mut rk4 = Rk4::new(&sys, 0.0, [1.0], FixedStepConfig::with_step(0.01)).expect("k ≥ 0");
    let mut taylor = Taylor::new(&sys, 0.0, [1.0], TaylorConfig::default()).expect("k ≥ 0");
    let mut dop = Dop853::new(&sys, 0.0, [1.0], AdaptiveConfig::default()).expect("k ≥ 0");
    sys.k.set(-2.0);
    let results = [
        Stepper::restart(&mut rk4, 0.0, [1.0]),
        Stepper::restart(&mut taylor, 0.0, [1.0]),
        Stepper::restart(&mut dop, 0.0, [1.0]),
    ];
    for r in &results {
        assert!(r.as_ref().is_err_and(is_negative_k), "{r:?}");
    }
    let fresh = Rk4::new(&sys, 0.0, [1.0], FixedStepConfig::with_step(0.01)).map(|_| ());
    assert!(fresh.as_ref().is_err_and(is_negative_k), "{fresh:?}");
}
