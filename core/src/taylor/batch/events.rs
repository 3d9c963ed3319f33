//! A batch lane's terminal event: g at the ends of the lane's steps, and the root of a sign
//! change refined in scalar on the lane's step polynomial.

use super::TaylorLanes;
use super::integrator::LaneEnd;
use crate::ode::OdeError;
use crate::taylor::Taylor;

/// g at a lane's point, checked finite.
pub(super) fn event_value<const N: usize>(
    g: &mut impl FnMut(usize, f64, &[f64; N]) -> f64,
    l: usize,
    t: f64,
    y: &[f64; N],
) -> Result<f64, OdeError> {
    let v = g(l, t, y);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(OdeError::NonFiniteEvent {
            index: 0,
            t,
            value: v,
        })
    }
}

/// After a lane's step: the lane's end if its event changed sign in the step (the lane put
/// at the root), else `None`; `g_last` follows the step.
pub(super) fn event_step<S: TaylorLanes<N, L>, const N: usize, const L: usize>(
    ode: &mut Taylor<S, N>,
    l: usize,
    g: &mut impl FnMut(usize, f64, &[f64; N]) -> f64,
    g_last: &mut f64,
) -> Result<Option<LaneEnd<N>>, OdeError> {
    let (t_a, t_b) = (ode.last_step_start(), ode.t());
    let g_b = event_value(g, l, t_b, ode.y())?;
    let g_a = *g_last;
    *g_last = g_b;
    if g_a == 0.0 {
        // A start on g = 0: the sign to leave from is the first one g takes.
        return Ok(None);
    }
    if (g_a < 0.0) == (g_b < 0.0) && g_b != 0.0 {
        return Ok(None);
    }
    // Bisection with the secant (Illinois), on the step polynomial: [lo, hi] brackets the
    // root, g(lo) has g_a's sign.
    let (mut lo, mut hi, mut g_lo, mut g_hi) = (t_a, t_b, g_a, g_b);
    let mut side = 0i8;
    for _ in 0..200 {
        if g_hi == 0.0 {
            break;
        }
        let secant = hi - g_hi * (hi - lo) / (g_hi - g_lo);
        let mid = 0.5 * (lo + hi);
        let t = if secant > lo && secant < hi {
            secant
        } else {
            mid
        };
        if t <= lo || t >= hi {
            break;
        }
        let v = event_value(g, l, t, &ode.dense_at(t)?)?;
        if (v < 0.0) == (g_lo < 0.0) && v != 0.0 {
            (lo, g_lo) = (t, v);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, g_hi) = (t, v);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
    }
    let y = ode.dense_at(hi)?;
    ode.reset_state(hi, y);
    Ok(Some(LaneEnd {
        t: hi,
        y,
        event: true,
    }))
}
