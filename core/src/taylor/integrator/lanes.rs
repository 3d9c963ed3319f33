//! A [`Taylor`] step cut in pieces for a batch of lanes ([`crate::taylor::batch::BatchTaylor`]):
//! the batch computes the jets of `L` lanes at once, at the lanes' points and then at their
//! steps' ends, sizes and sums the lanes' ordinary steps in lane arithmetic (the
//! `lane_control` module), and each lane does the rest with the scalar step's own code.
//!
//! The pieces follow [`Taylor::step`] with the jet kept by the check: the step takes the jet
//! the last step's check computed at its end (`ahead`), or one the batch writes there
//! ([`Taylor::lane_set_jet`]); the step is sized and summed up to where the check needs the
//! jet at the new point ([`PendingStep`]); the batch computes that jet for every lane, and
//! [`Taylor::lane_finish`] checks the step against it, commits it and keeps the jet as the
//! next step's, as [`Taylor::step`] does. A lane is thus a scalar run with the same jets
//! (the batch's are the scalar ones bit for bit), so it takes the same steps, ends on the
//! same bits and counts the same jets ([`Taylor::jets`], [`Taylor::stats`]). A step the
//! check cuts goes on in scalar, as [`Taylor::step`] would.

use super::{StepRule, Taylor, defect, kahan_add, rows_to_order};
use crate::ode::OdeError;
use crate::taylor::TaylorSystem;

/// A lane's step summed and waiting for the jet at its end, which its check reads and the
/// next step starts from.
#[derive(Clone, Copy)]
pub(crate) struct PendingStep<const N: usize> {
    pub(super) rule: StepRule<N>,
    pub(super) h: f64,
    pub(super) clamped: bool,
    pub(super) t_limit: f64,
    pub(super) comp_new: [f64; N],
    pub(super) slope: defect::Slope<N>,
    /// The step's end: the time, the state and the order of the jet to compute there (the
    /// next step's order).
    pub(crate) t_new: f64,
    pub(crate) y_new: [f64; N],
    pub(crate) order: usize,
}

impl<S: TaylorSystem<N>, const N: usize> Taylor<S, N> {
    /// The rule of the next step towards `t_limit` (`None`: `t_limit` is the current time);
    /// its order is that of the jet the step needs.
    ///
    /// # Errors
    /// As [`Taylor::step`] before its jet; [`OdeError::InvalidParameter`] in the extended
    /// mode, which the lanes do not have.
    pub(crate) fn lane_rule(&self, t_limit: f64) -> Result<Option<StepRule<N>>, OdeError> {
        if let Some(low) = self.cfg.extended {
            return Err(OdeError::InvalidParameter {
                name: "extended (the lanes step in f64 only)",
                value: low as f64,
            });
        }
        self.step_rule(t_limit)
    }

    /// The jet at the current point kept by the last step's check (or written by
    /// [`Taylor::lane_set_jet`]): rows 0 … its order, empty when none is kept.
    pub(crate) fn lane_kept_jet(&self) -> &[[f64; N]] {
        match self.ahead_order {
            0 => &[],
            q => self.ahead.get(..=q).unwrap_or(&[]),
        }
    }

    /// The jet of orders 0 … `order` at the current point, written by `fill` (the rows a
    /// batch computed), kept for the next step and counted as the jet [`Taylor::step`]
    /// would compute there.
    ///
    /// # Errors
    /// [`OdeError::InvalidParameter`] for an order past the rows allocated (never, for a
    /// rule's order).
    pub(crate) fn lane_set_jet(
        &mut self,
        order: usize,
        fill: impl FnOnce(&mut [[f64; N]]),
    ) -> Result<(), OdeError> {
        fill(rows_to_order(&mut self.ahead, order)?);
        self.jets += 1;
        self.stats.rhs_evals += order as u64;
        self.ahead_order = order;
        Ok(())
    }

    /// The step's jet under `rule` taken from the one kept (computed here if none is), as
    /// [`Taylor::step`] takes it.
    ///
    /// # Errors
    /// As [`Taylor::step`]'s jet.
    pub(crate) fn lane_take_jet(&mut self, rule: &StepRule<N>) -> Result<(), OdeError> {
        if self.ahead_order >= rule.order {
            std::mem::swap(&mut self.coeffs, &mut self.ahead);
            self.ahead_order = 0;
            Ok(())
        } else {
            self.ahead_order = 0;
            self.jet(rule.order)
        }
    }

    /// [`Taylor::step`] after its jet ([`Taylor::lane_take_jet`]) up to its check, in scalar:
    /// the step sized and summed. `None` when the step is not checked
    /// ([`super::TaylorConfig::defect_check`] off, a fixed step, a non-finite sum, which the
    /// commit refuses) and was committed.
    ///
    /// # Errors
    /// As [`Taylor::step`].
    pub(crate) fn lane_begin_ruled(
        &mut self,
        rule: StepRule<N>,
        t_limit: f64,
    ) -> Result<Option<PendingStep<N>>, OdeError> {
        let (rule, h, clamped) = self.size_step(rule, t_limit)?;
        let p = rule.order;
        if !self.cfg.defect_check || self.cfg.fixed_step.is_some() {
            self.commit_unchecked(p, h, clamped, t_limit)?;
            return Ok(None);
        }
        let (increment, slope) = defect::increment_and_slope(&self.coeffs[..=p], h);
        let (y_new, comp_new) = kahan_add(self.y, self.y_comp, increment);
        let t_new = self.advanced(h, clamped, t_limit).0;
        if y_new.iter().any(|v| !v.is_finite()) {
            // `Taylor::checked` passes a non-finite sum to the commit, which refuses it.
            self.commit_step(h, p, clamped, t_limit, y_new, comp_new)?;
            return Ok(None);
        }
        Ok(Some(PendingStep {
            rule,
            h,
            clamped,
            t_limit,
            comp_new,
            slope,
            t_new,
            y_new,
            order: self.next_order(&y_new),
        }))
    }

    /// The rest of the step `pending`: `fill` writes the jet at its end to `pending.order`
    /// (the batch's rows), the check reads it, and the step is committed with that jet kept
    /// as the next step's (`true`); or, if the check cuts it, taken again shorter in scalar
    /// until it passes, as [`Taylor::step`] does (`false`: the jet kept is the scalar one at
    /// the shorter step's end).
    ///
    /// # Errors
    /// As [`Taylor::step`].
    pub(crate) fn lane_finish(
        &mut self,
        pending: PendingStep<N>,
        fill: impl FnOnce(&mut [[f64; N]]),
    ) -> Result<bool, OdeError> {
        let PendingStep {
            rule,
            h,
            clamped,
            t_limit,
            comp_new,
            slope,
            y_new,
            order,
            ..
        } = pending;
        fill(rows_to_order(&mut self.ahead, order)?);
        let verdict = self.judge_ahead(order, &slope, &rule);
        match self.cut(verdict)? {
            None => {
                self.commit_step(h, rule.order, clamped, t_limit, y_new, comp_new)?;
                Ok(true)
            }
            Some(shorter) => {
                self.checked_steps(rule, shorter, false, t_limit, true)?;
                Ok(false)
            }
        }
    }
}
