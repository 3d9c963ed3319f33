//! Dormand–Prince 5(4) (DOPRI5): the published tableau (Dormand & Prince 1980, with
//! Shampine's dense output as in Hairer's DOPRI5) and the pair built on it.
//!
//! Rows of `A` hold the non-zero prefix of the strictly lower triangle; missing entries are
//! zero. The order conditions are checked numerically in the tests (convergence order).

use super::tableau::{DenseOutput, ErrorEstimate, Tableau};
use super::{ControllerGains, EmbeddedPair};

/// Nodes `c` of Dormand–Prince 5(4).
const DOPRI5_C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];

/// Stage coefficients of Dormand–Prince 5(4); row 6 equals the weights (FSAL).
const DOPRI5_A: [&[f64]; 7] = [
    &[],
    &[0.2],
    &[3.0 / 40.0, 9.0 / 40.0],
    &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
    &[
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
    ],
    &[
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ],
    &[
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// Error weights `b − b̂` of Dormand–Prince 5(4) over the 7 stages.
const DOPRI5_E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Dense-output coefficients `d` of Dormand–Prince 5(4) (Shampine 1986).
const DOPRI5_D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// Dormand–Prince 5(4) (DOPRI5): 6 evaluations per step, 4th-order dense output for free.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dopri5Pair;

impl EmbeddedPair for Dopri5Pair {
    const TABLEAU: Tableau = Tableau {
        name: "DOPRI5",
        order: 5,
        err_exponent: 0.2,
        gains: ControllerGains {
            beta: 0.04,
            beta_weight: 0.75,
            fac_min: 0.2,
            fac_max: 10.0,
        },
        c: &DOPRI5_C,
        a: &DOPRI5_A,
        b: DOPRI5_A[6],
        // Stages 1…5, then f at the new point (stage 6), which the error estimate reads.
        trial: 6,
        fsal: 6,
        fsal_in_trial: true,
        error: ErrorEstimate::Weights(&DOPRI5_E),
        dense: DenseOutput::Hermite(&[&DOPRI5_D]),
    };
}
