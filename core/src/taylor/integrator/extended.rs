//! The extended mode of [`Taylor`]: steps whose low orders are computed and summed in
//! double-double ([`TaylorConfig::extended`](super::TaylorConfig::extended)).
//!
//! In the plain mode the state is carried compensated (y plus its Kahan term), but the jet
//! is computed from the rounded y and c₁ = f(y) is itself rounded: each step adds an error
//! of about 2⁻⁵³‖h f‖ that no compensation recovers, and on a problem that amplifies
//! perturbations (a body next to its unstable axis) these errors decide the last digits.
//! Here the state is the unevaluated sum y = y_hi + y_lo, with y_lo = −(Kahan term) so that
//! the fields and the dense output of the plain mode keep their meaning, and a step
//! 1. asks the system for c_k in `f64` for all k ≤ p and in double-double for k ≤ L
//!    ([`TaylorSystem::coefficients_extended_into`]), computed from (y_hi, y_lo);
//! 2. sums the increment Δ = Σₖ₌₁ᵖ c_k hᵏ by Horner's rule, orders p … L + 1 in `f64` and
//!    then L … 1 in double-double (compensated Horner):
//!    s = Σₖ₌ₗ₊₁ᵖ c_k hᵏ⁻ᴸ⁻¹ (f64), S = (…((s·h + c_L)·h + c_{L−1})·h … + c₁), Δ = S·h;
//! 3. adds Δ to (y_hi, y_lo) in double-double: the new state is rounded at 2⁻¹⁰⁶, not 2⁻⁵³.
//!
//! The f64 orders k > L enter multiplied by hᵏ ≈ (e⁻²ρ)ᵏ, so their rounding is ≈ 2⁻⁵³e⁻²ᵏ
//! relative to ‖y‖. Order, step and time follow the plain mode's rules exactly: the two
//! modes share the start (`Taylor::step_rule`), the step size (`Taylor::step_size`) and the
//! end (`Taylor::commit_step`).

use super::{Taylor, rows_to_order};
use crate::exact::Dd;
use crate::ode::OdeError;
use crate::taylor::TaylorSystem;

/// The double-double coefficient table of the extended mode (`low + 1` rows, orders
/// 0 … low), after checking once, at (t0, y0), that the system computes them.
///
/// # Errors
/// [`OdeError::NoExtendedCoefficients`] when the system's
/// [`TaylorSystem::coefficients_extended_into`] returns `false`.
pub(super) fn low_table<S: TaylorSystem<N>, const N: usize>(
    sys: &S,
    ws: &mut S::Workspace,
    low: usize,
    t0: f64,
    y0: &[f64; N],
) -> Result<Vec<[Dd; N]>, OdeError> {
    let mut table = vec![[Dd::default(); N]; low + 1];
    let mut probe = [[0.0; N]; 2];
    let y = y0.map(Dd::from);
    if !sys.coefficients_extended_into(ws, Dd::from(t0), &y, 1, &mut probe, &mut table) {
        return Err(OdeError::NoExtendedCoefficients { low });
    }
    Ok(table)
}

impl<S: TaylorSystem<N>, const N: usize> Taylor<S, N> {
    /// [`Taylor::step`] in the extended mode (see the module's docs); same contract, same
    /// errors.
    pub(super) fn step_extended(&mut self, t_limit: f64) -> Result<(), OdeError> {
        let Some(rule) = self.step_rule(t_limit)? else {
            return Ok(());
        };
        let p = rule.order;
        let c = rows_to_order(&mut self.coeffs, p)?;
        let low_len = self.low.len().min(p + 1);
        let low = &mut self.low[..low_len];
        let mut y = [Dd::default(); N];
        for (yi, (&hi, &comp)) in y.iter_mut().zip(self.y.iter().zip(&self.y_comp)) {
            *yi = Dd { hi, lo: -comp };
        }
        let t = Dd {
            hi: self.t,
            lo: self.t_lo,
        };
        if !self
            .sys
            .coefficients_extended_into(&mut self.ws, t, &y, p, c, low)
        {
            // low_table checked the system at construction; one that changes its mind is
            // refused the same way.
            return Err(OdeError::NoExtendedCoefficients { low: low_len - 1 });
        }
        self.jets += 1;
        self.stats.rhs_evals += p as u64;
        // As in the plain step, no scan for finiteness: a NaN or ∞ in the coefficients, f64
        // or double-double, reaches the new state through the sums and is caught there.
        let (mut h, mut clamped) = self.step_size(&self.coeffs[..=p], rule, t_limit)?;
        loop {
            let (y_new, comp_new) = self.extended_sum(p, low_len, &y, h);
            // The defect check of the plain mode, on the f64 rows: it looks for what the
            // rows past p would have added, far above the double-double rounding.
            let (_, slope) = super::defect::increment_and_slope(&self.coeffs[..=p], h);
            let t_new = self.advanced(h, clamped, t_limit).0;
            match self.checked(t_new, &y_new, &slope, &rule, false)? {
                Some(shorter) => (h, clamped) = (shorter, false),
                None => return self.commit_step(h, p, clamped, t_limit, y_new, comp_new),
            }
        }
    }

    /// The new state y + Σₖ₌₁ᵖ c_k hᵏ from the state `y` in double-double, with the rows
    /// past the table's last (`low_len − 1`) in f64: the sum of the module's docs, as
    /// (y_hi, its Kahan term).
    fn extended_sum(&self, p: usize, low_len: usize, y: &[Dd; N], h: f64) -> ([f64; N], [f64; N]) {
        let c = &self.coeffs[..=p];
        let low = &self.low[..low_len];
        // L, the highest double-double order (low_len ≥ 1 since the table has row 0).
        let last = low_len - 1;
        // Horner with the order outside and the components inside, so that the N chains
        // overlap in the processor: s = Σ_{k>L} c_k h^(k−L−1) in f64, then the
        // double-double orders L … 1.
        let hd = Dd::from(h);
        let mut s = [0.0; N];
        for ck in c[last + 1..].iter().rev() {
            for (si, cki) in s.iter_mut().zip(ck) {
                *si = *si * h + cki;
            }
        }
        let mut acc = s.map(Dd::from);
        for ck in low[1..].iter().rev() {
            for (a, cki) in acc.iter_mut().zip(ck) {
                *a = *a * hd + *cki;
            }
        }
        let mut y_new = [0.0; N];
        let mut comp_new = [0.0; N];
        for i in 0..N {
            let sum = y[i] + acc[i] * hd;
            y_new[i] = sum.hi;
            comp_new[i] = -sum.lo;
        }
        (y_new, comp_new)
    }
}
