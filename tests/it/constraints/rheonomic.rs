//! A constraint with explicit time: a bead on a frictionless rod spun at constant rate ω
//! about the vertical, in Cartesian coordinates with φ = −x sin ωt + y cos ωt = 0. Its
//! closed form r(t) = r₀ cosh ωt (from rest on the rod) and the rod's push on the bead
//! N = 2 m ω ṙ check the ∂φ/∂t and ḃ terms that time-free constraints never reach.

use precess::lagrange::{ConstrainedModel, Constraints, Coordinates, EquationsOfMotion};
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;

#[test]
fn a_bead_on_a_spinning_rod_follows_cosh() {
    let (m, omega, r0) = (0.7, 1.3, 0.4);
    let mut a = Arena::new();
    let c = Coordinates::new(&mut a, &["x", "y"]);
    let (pm, pw) = (a.parameter("m"), a.parameter("w"));
    let t = a.time();
    let half = a.number("0.5").expect("a decimal");
    let v2 = {
        let (x, y) = (a.mul(c.rates[0], c.rates[0]), a.mul(c.rates[1], c.rates[1]));
        a.add(x, y)
    };
    let lagrangian = a.product(&[half, pm, v2]);
    let zero = a.zero();
    let eom =
        EquationsOfMotion::derive(&mut a, lagrangian, c.clone(), &[zero, zero]).expect("derives");
    let wt = a.mul(pw, t);
    let (s, co) = (a.sin(wt), a.cos(wt));
    let phi = {
        let xs = a.mul(c.q[0], s);
        let yc = a.mul(c.q[1], co);
        a.sub(yc, xs)
    };
    let mut k = Constraints::new();
    k.holonomic(&mut a, &c, phi).expect("no rates");
    // y dependent: the block ∂φ/∂y = cos ωt, regular for ωt < π/2.
    let eqs = eom.constrain(&mut a, &k, Some(&[1])).expect("reduces");
    let model = ConstrainedModel::new(&mut a, &eqs, &[], &[("m", m), ("w", omega)]).expect("binds");
    // From rest on the rod at r₀ along x: ẋ(0) = 0 (the rod carries it round, ẏ = ω r₀).
    let y0 = [r0, 0.0, 0.0];
    let cfg = AdaptiveConfig::with_tol(1e-13, 1e-13);
    let mut ode =
        Dop853::new(model.system::<3>().expect("n + k = 3"), 0.0, y0, cfg).expect("starts");
    for step in 1..=10 {
        let time = 0.1 * f64::from(step);
        model
            .advance_partitioned(&mut ode, time, 1e-15)
            .expect("closes");
        let y = *ode.y();
        let r = r0 * (omega * time).cosh();
        let want = [r * (omega * time).cos(), r * (omega * time).sin()];
        for i in 0..2 {
            assert!(
                (y[i] - want[i]).abs() < 1e-12 * r,
                "t = {time}: q = {:?} against {want:?}",
                &y[..2]
            );
        }
        let lambda = model.multipliers(time, &y).expect("regular");
        let push = 2.0 * m * omega * omega * r0 * (omega * time).sinh();
        assert!(
            (lambda[0] - push).abs() < 1e-11 * push.max(1.0),
            "t = {time}: λ = {} against 2 m ω ṙ = {push}",
            lambda[0]
        );
    }
}
