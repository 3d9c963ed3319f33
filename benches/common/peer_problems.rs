//! The two problems the ensemble and lanes benches share with `scripts/heyoka_ensemble.py`,
//! as `taylor_system!` equations (included by path by `ensemble.rs` and `lanes.rs`).

precess::taylor_system! {
    /// The heavy top of (a) in Euler–Poisson form, as heyoka integrates it: ω and the upward
    /// vertical γ in body axes, r = (I1 − I3)/I1 and s = M g l / I1 of `SpinningTop` written
    /// out (`scripts/heyoka_ensemble.py` computes the same doubles), γ3 = cos θ.
    #[derive(Clone, Copy, Debug)]
    pub struct EulerPoisson;
    state [w1, w2, w3, g1, g2, g3];
    taylor = 24;
    d/dt w1 = 0.7338597364012156 * w2 * w3 + 169.65662315850153 * g2;
    d/dt w2 = -0.7338597364012156 * w3 * w1 - 169.65662315850153 * g1;
    d/dt w3 = 0.0 * w3;
    d/dt g1 = g2 * w3 - g3 * w2;
    d/dt g2 = g3 * w1 - g1 * w3;
    d/dt g3 = g1 * w2 - g2 * w1;
}

precess::taylor_system! {
    /// The torque-free body of (b) as equations, ṁ = m × I⁻¹m for I = (3, 5, 9), its
    /// constants 1/I3 − 1/I2, 1/I1 − 1/I3, 1/I2 − 1/I1 written out.
    #[derive(Clone, Copy, Debug)]
    pub struct FreeEquations;
    state [m1, m2, m3];
    taylor = 24;
    d/dt m1 = -0.0888888888888889 * m2 * m3;
    d/dt m2 = 0.2222222222222222 * m3 * m1;
    d/dt m3 = -0.1333333333333333 * m1 * m2;
}
