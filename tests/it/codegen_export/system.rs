//! `taylor_system!`'s `impl Export`: its right-hand side and the Jacobian of it, in C and
//! Python, against `System::rhs` and the Jacobian written by hand.

use super::derived::{cases, compare};
use precess::codegen::Export;
use precess::ode::System;

precess::taylor_system! {
    /// A forced Duffing oscillator with a sine of a square root in its spring:
    /// x'' = −δ v − α x − β x³ + γ cos(ω t) + sin √(x² + 1).
    struct Duffing { delta: f64, alpha: f64, beta: f64, gamma: f64, w: f64 }
    state [x, v];
    taylor = 12;
    d/dt x = v;
    d/dt v = -delta * v - alpha * x - beta * x.powi(3) + gamma * (w * t).cos() + (x * x + 1.0).sqrt().sin();
}

#[test]
fn a_taylor_system_exports_its_right_hand_side_and_jacobian_bit_for_bit() {
    let e = Duffing::exported().expect("exported");
    assert_eq!(e.name(), "duffing");
    assert_eq!(e.state(), ["x", "v"]);
    let mut fields = e.parameters().to_vec();
    fields.sort();
    assert_eq!(fields, ["alpha", "beta", "delta", "gamma", "w"]);
    let cases = cases(&e, 1000, 9, |_, _| {});
    let (mut rhs, mut jac) = (vec![], vec![]);
    for c in &cases {
        let v = |n: &str| c.param(&e, n);
        let s = Duffing {
            delta: v("delta"),
            alpha: v("alpha"),
            beta: v("beta"),
            gamma: v("gamma"),
            w: v("w"),
        };
        let mut d = [0.0; 2];
        System::<2>::rhs(&s, c.t, &[c.y[0], c.y[1]], &mut d);
        rhs.push(d.to_vec());
        // ∂v'/∂x = −α − 3βx² + cos √(x² + 1) · x/√(x² + 1), ∂v'/∂v = −δ.
        let j = e.eval("jacobian", c.t, &c.y, &c.p).expect("eval");
        let x = c.y[0];
        let root = (x * x + 1.0).sqrt();
        let want = [
            0.0,
            1.0,
            -s.alpha - 3.0 * s.beta * x * x + root.cos() * x / root,
            -s.delta,
        ];
        for (got, want) in j.iter().zip(want) {
            assert!(
                (got - want).abs() <= 1e-14 * (1.0 + want.abs()),
                "{got} vs {want}"
            );
        }
        jac.push(j);
    }
    compare("system", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}
