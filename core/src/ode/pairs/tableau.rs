//! A pair as data: its published tableau, and which of the published error estimates and
//! dense outputs it takes. The three pairs differ in nothing else, so one skeleton (the
//! provided methods of [`EmbeddedPair`](super::EmbeddedPair)) steps all of them, and a pair's
//! file is its coefficients alone.

use super::ControllerGains;

/// How a pair estimates its local error from the stages, per unit step (the skeleton scales
/// by h and by the tolerances).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ErrorEstimate {
    /// e = Σⱼ Eⱼ kⱼ with the published differences Eⱼ = bⱼ − b̂ⱼ, measured in Hairer's RMS
    /// norm √(mean((h eᵢ / skᵢ)²)), skᵢ = atol + rtol·max(|yᵢ|, |y_newᵢ|) (DOPRI5).
    Weights(&'static [f64]),
    /// e = Σⱼ bⱼ kⱼ − Σⱼ b̂ⱼ kⱼ, the two solutions' increments apart, in the same norm: the
    /// field is b̂ (Verner publishes the weights, not their differences).
    Difference(&'static [f64]),
    /// DOP853's combination err = |h| E₅ / √(N (E₅ + 0.01 E₃)) of the squared scaled norms
    /// E₅ = Σᵢ (e₅ᵢ/skᵢ)² of e₅ = Σⱼ E5ⱼ kⱼ and E₃ of e₃ = Σⱼ bⱼ kⱼ − Σⱼ b̂₃ⱼ kⱼ: a
    /// pessimistic 5th-order estimate then does not drive the 8th-order step sizes.
    Combined {
        /// The 5th-order estimate's weights E5.
        e5: &'static [f64],
        /// The 3rd-order solution's non-zero weights b̂₃ as (stage, weight), subtracted
        /// from b.
        b3: &'static [(usize, f64)],
    },
}

/// How a pair builds its dense output u(θ), θ = (t − t₀)/h ∈ [0, 1], from the stages of an
/// accepted step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DenseOutput {
    /// Hairer's form (DOPRI5, DOP853): d₀ = y, d₁ = Δy, d₂ = h f₀ − Δy,
    /// d₃ = Δy − h f₁ − d₂, and d₄₊ᵣ = h Σⱼ Dᵣⱼ kⱼ for each published row Dᵣ, read as
    /// u(θ) = d₀ + θ(d₁ + θ′(d₂ + θ(d₃ + θ′(d₄ + θ(d₅ + …))))) with θ′ = 1 − θ.
    Hermite(&'static [&'static [f64]]),
    /// A polynomial in θ (Verner): d₀ = y, dₚ = h Σⱼ Pⱼ,ₚ₋₁ kⱼ (p = 1…8), and
    /// u(θ) = Σₚ dₚ θᵖ.
    Polynomial(&'static [[f64; 8]]),
}

/// An explicit embedded Runge–Kutta pair as its published data: everything the skeleton
/// needs to make a trial step, its error, the stage at the new point and the dense output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tableau {
    /// Human-readable name, e.g. `"DOP853"`.
    pub name: &'static str,
    /// Order of the propagated solution.
    pub order: u32,
    /// Exponent of the error in the step-size controller, 1/(q + 1) for an estimate of
    /// order q.
    pub err_exponent: f64,
    /// The step-size controller's defaults.
    pub gains: ControllerGains,
    /// Nodes cₛ of every stage: the trial step's, f at the new point, the dense output's.
    pub c: &'static [f64],
    /// Rows of A, each the non-zero prefix of the strictly lower triangle (missing entries
    /// are zero); at most 21 (the length of [`Stages`](super::Stages)).
    pub a: &'static [&'static [f64]],
    /// Weights b of the propagated solution: y_new = y + h Σⱼ bⱼ kⱼ.
    pub b: &'static [f64],
    /// A trial step makes stages 1 … `trial` − 1 (stage 0 is f(t, y), carried over).
    pub trial: usize,
    /// The stage that holds f(t + h, y_new); stages after it serve the dense output alone.
    pub fsal: usize,
    /// Whether the trial step makes f(t + h, y_new) itself, because the error estimate
    /// reads it (DOPRI5), or it is made once the step is accepted.
    pub fsal_in_trial: bool,
    /// The error estimate.
    pub error: ErrorEstimate,
    /// The dense output.
    pub dense: DenseOutput,
}
