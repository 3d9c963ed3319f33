//! Every model and generated type a user would share between threads is `Send + Sync`,
//! checked at compile time: the list below stops compiling if one of them gains a `RefCell`
//! or an `Rc` again (the interpreted models kept their scratch space in `RefCell`s, so an
//! ensemble could not share one model between its threads).

use precess::codegen::{Bindings, EvalWorkspace, Program};
use precess::contact::{ContactModel, ContactRun, ContactSystem};
use precess::ensemble::{Ensemble, EnsembleError, EnsembleResults};
use precess::free::{FreeFlight, FreeModel};
use precess::lagrange::{ConstrainedModel, ConstrainedSystem};
use precess::mechanism::{
    ChartedMechanism, MechanismAba, MechanismCharts, MechanismModel, MechanismSystem,
};
use precess::ode::{Dop853, OdeError, Rk4, Trajectory};
use precess::prelude::*;
use precess::sym::{Arena, SymbolId};
use precess::taylor::{Taylor, TaylorSystem, TaylorTape};
use precess::top::{TopDerivation, TopModel};
use proptest::prelude::*;

fn assert_send_sync<T: Send + Sync>() {}

/// A derived heavy top with its Taylor recurrences.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, taylor = 12)]
struct DerivedTop;

/// A derived free body.
#[derive(RigidBody)]
#[rigid(cylinder(mass = 0.3, radius = 0.01, length = 0.2, axis = x))]
#[free(gravity = 9.81)]
struct DerivedFree;

/// A derived body on a table.
#[derive(RigidBody)]
#[rigid(sphere(mass = 0.015, radius = 0.02), particle(mass = 0.001, at = [0.0, 0.0, 0.015]))]
#[contact(surface = sphere(radius = 0.02), law = sliding(viscous = 0.3), gravity = 9.81)]
struct DerivedContact;

/// A derived mechanism: a top on a spherical joint.
#[derive(Mechanism)]
#[mechanism(gravity = 1.0)]
#[body(top, joint = spherical(sequence = zxz), q = [phi, theta, psi],
       parts(body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(0.25, 0.25, 0.5))))]
struct DerivedMechanism;

precess::taylor_system! {
    /// The Lorenz system.
    struct Lorenz;
    state [x, y, z];
    taylor = 16;
    d/dt x = 10.0 * (y - x);
    d/dt y = x * (28.0 - z) - y;
    d/dt z = x * y - 8.0 / 3.0 * z;
}

#[test]
fn models_and_generated_types_are_send_and_sync() {
    // The interpreted models and what they evaluate through.
    assert_send_sync::<Bindings>();
    assert_send_sync::<EvalWorkspace>();
    assert_send_sync::<Program>();
    assert_send_sync::<Arena>();
    assert_send_sync::<TopDerivation>();
    assert_send_sync::<TopModel>();
    assert_send_sync::<FreeModel>();
    assert_send_sync::<MechanismModel>();
    assert_send_sync::<MechanismCharts>();
    assert_send_sync::<MechanismAba>();
    assert_send_sync::<ContactModel>();
    assert_send_sync::<ConstrainedModel>();
    assert_send_sync::<precess::mechanism::rolling::RollingModel<5, 2, 3>>();
    assert_send_sync::<
        precess::mechanism::rolling::RollingSystem<
            'static,
            precess::mechanism::rolling::RollingModel<5, 2, 3>,
            5,
            2,
            3,
            8,
        >,
    >();
    assert_send_sync::<TaylorTape<6>>();
    // The systems that borrow them, and integrators over those.
    assert_send_sync::<MechanismSystem<'static, 6>>();
    assert_send_sync::<ConstrainedSystem<'static, 4>>();
    assert_send_sync::<ContactSystem<'static, ContactModel>>();
    assert_send_sync::<Dop853<MechanismSystem<'static, 6>, 6>>();
    assert_send_sync::<Rk4<&'static TopModel, 6>>();
    assert_send_sync::<Dop853<&'static FreeModel, 13>>();
    assert_send_sync::<ChartedTop<&'static TopModel>>();
    assert_send_sync::<ChartedMechanism<MechanismCharts, 6>>();
    assert_send_sync::<ContactRun<'static, ContactModel>>();
    assert_send_sync::<Taylor<TaylorTape<6>, 6>>();
    assert_send_sync::<Trajectory<[f64; 6]>>();
    // The types of the derives and `taylor_system!`, their systems and workspaces.
    assert_send_sync::<DerivedTop>();
    assert_send_sync::<Taylor<DerivedTop, 6>>();
    assert_send_sync::<<DerivedTop as TaylorSystem<6>>::Workspace>();
    assert_send_sync::<DerivedFree>();
    assert_send_sync::<FreeFlight<FreeSystem<'static, DerivedFree>>>();
    assert_send_sync::<DerivedContact>();
    assert_send_sync::<ContactRun<'static, DerivedContact>>();
    assert_send_sync::<DerivedMechanism>();
    assert_send_sync::<ChartedMechanism<DerivedMechanism, 6>>();
    assert_send_sync::<Lorenz>();
    assert_send_sync::<Taylor<Lorenz, 3>>();
    assert_send_sync::<<Lorenz as TaylorSystem<3>>::Workspace>();
    // The ensemble's own types.
    assert_send_sync::<Ensemble<'static>>();
    assert_send_sync::<EnsembleResults<[f64; 6], OdeError>>();
    assert_send_sync::<EnsembleError<OdeError>>();
}

fn bits<const N: usize>(y: &[f64; N]) -> [u64; N] {
    y.map(f64::to_bits)
}

/// One evaluation: which bindings, x, t, whether t is given (`Some`), a new k set first.
type Call = (usize, f64, f64, Option<f64>, Option<f64>);

/// An evaluation in the shared per-thread workspace, after any sequence of others (two
/// bindings of one program, parameters changed between calls, the time input sometimes left
/// out), gives the same bits as the same call on bindings made fresh for it: nothing of an
/// earlier call or of another model leaks into a result, which is what makes an ensemble's
/// results independent of how its runs fall on threads.
fn shared_matches_fresh(calls: &[Call]) {
    let mut a = Arena::new();
    let (x, t, k) = (a.input("x"), a.input("t"), a.parameter("k"));
    let kx = a.mul(k, x);
    let s = a.sin(t);
    let e = a.add(kx, s);
    let p = Program::lower(&a, &[e, kx]);
    let sym = |e| a.as_symbol(e).unwrap();
    let supplied: [SymbolId; 2] = [sym(x), sym(t)];
    // The references first, each call on bindings of its own, so that the shared pass
    // below meets no other evaluation between its calls.
    let mut ks = [0.5, -2.0];
    let mut want = Vec::new();
    for &(which, xv, tv, with_time, new_k) in calls {
        ks[which] = new_k.unwrap_or(ks[which]);
        let fresh =
            Bindings::new(&a, std::slice::from_ref(&p), &supplied, &[("k", ks[which])]).unwrap();
        let mut out = [0.0; 2];
        let time = with_time.map(|_| (supplied[1], tv));
        fresh.eval(&p, std::iter::once((supplied[0], xv)).chain(time), &mut out);
        want.push(bits(&out));
    }
    let mut shared = [0.5, -2.0]
        .map(|k| Bindings::new(&a, std::slice::from_ref(&p), &supplied, &[("k", k)]).unwrap());
    for (n, &(which, xv, tv, with_time, new_k)) in calls.iter().enumerate() {
        if let Some(k) = new_k {
            shared[which].set("k", k).unwrap();
        }
        let mut got = [0.0; 2];
        let time = with_time.map(|_| (supplied[1], tv));
        shared[which].eval(&p, std::iter::once((supplied[0], xv)).chain(time), &mut got);
        assert_eq!(
            bits(&got),
            want[n],
            "call {n}: bindings {which}, x = {xv}, t = {tv:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn an_evaluation_sees_only_its_own_inputs_and_parameters(
        calls in proptest::collection::vec(
            (0usize..2, -10.0..10.0f64, -10.0..10.0f64,
             proptest::option::of(Just(0.0)), proptest::option::weighted(0.2, -5.0..5.0f64)),
            1..40,
        )
    ) {
        shared_matches_fresh(&calls);
    }
}
