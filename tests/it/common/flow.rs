//! A tight reference flow and a reproducible uniform generator, shared by the tests of the
//! derived variational equations (tops and mechanisms), which difference flows and draw
//! random states the same way.

use precess::ode::{AdaptiveConfig, Dop853, System};

/// DOP853 at rtol = atol = 1e-13.
pub fn tight() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-13, 1e-13)
}

/// Integrates `sys` from `y0` over [0, t] with DOP853 at tight tolerances.
pub fn flow<S: System<N>, const N: usize>(sys: S, y0: [f64; N], t: f64) -> [f64; N] {
    let mut ode = Dop853::new(sys, 0.0, y0, tight()).unwrap();
    ode.advance_to(t).unwrap();
    *ode.y()
}

/// SplitMix64, uniform in [lo, hi): reproducible states without a generator crate.
pub struct Uniform(pub u64);

impl Uniform {
    /// The next value in [lo, hi).
    pub fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        lo + (hi - lo) * (z >> 11) as f64 / (1u64 << 53) as f64
    }
}
