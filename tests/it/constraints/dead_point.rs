//! A four-bar whose free coordinate reaches a dead point: the triple rocker a = 2 (crank),
//! b = 1.5 (coupler), c = 2 (rocker), d = 3 (ground) — s + l = 4.5 > p + q = 4, not Grashof —
//! whose crank swings at most to cos θ₁ = (a² + d² − (b + c)²)/(2ad) = 1/16, where the
//! coupler and the rocker line up and det A_D = 0. A partitioned run with the crank free
//! stepped through it (energy error 6·10⁻³ J); it now stops with a typed error there.

use precess::lagrange::{ConstrainedModel, LagrangeError};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;

use super::four_bar::four_bar;

/// The triple rocker's parameters by name.
fn values() -> Vec<(&'static str, f64)> {
    vec![
        ("a", 2.0),
        ("b", 1.5),
        ("c", 2.0),
        ("d", 3.0),
        ("m1", 0.5),
        ("m2", 1.5),
        ("m3", 1.2),
        ("g", 9.81),
    ]
}

#[test]
fn a_partitioned_run_stops_at_the_crank_s_dead_point() {
    let mut a = Arena::new();
    let (eqs, out) = four_bar(&mut a).expect("the four-bar derives");
    assert_eq!(eqs.independent, [0], "the crank is the free coordinate");
    let model = ConstrainedModel::new(&mut a, &eqs, &out, &values()).expect("binds");
    // Crank at 60° swinging up at 4 rad/s; the coupler and rocker closed by Newton from a
    // rough guess (θ₃ ≈ 105°, θ₂ ≈ 8°, read off a sketch).
    let mut y0 = [60f64.to_radians(), 0.13, 1.83, 4.0];
    model.close_loop(0.0, &mut y0, 1e-15).expect("closes");
    let limit = (1.0f64 / 16.0).acos();
    let cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let mut ode = Dop853::new(model.system::<4>().expect("n + k = 4"), 0.0, y0, cfg).unwrap();
    let e0 = model.outputs(0.0, &y0).expect("finite")[0];
    let result = model.advance_partitioned(&mut ode, 5.0, 1e-15);
    let y = *ode.y();
    let e = model.outputs(ode.t(), &y).expect("finite")[0];
    eprintln!(
        "stopped at t = {}, θ₁ = {} (limit {limit}), energy error {:e}: {result:?}",
        ode.t(),
        y[0],
        e - e0
    );
    assert!(
        matches!(result, Err(LagrangeError::DeadPoint { before, after, .. }) if before * after < 0.0),
        "{result:?}"
    );
    // Stopped at the start of the step that crossed it, just short of the limit, with the
    // energy still kept.
    assert!(y[0] < limit && limit - y[0] < 0.05, "θ₁ = {}", y[0]);
    assert!(
        (e - e0).abs() < 1e-8 * e0.abs().max(1.0),
        "{e} against {e0}"
    );
}
