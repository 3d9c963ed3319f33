//! Typed errors of the time-stepping layer.

use thiserror::Error;

use crate::exact::ExactError;

/// Why an integration could not start or could not finish.
///
/// Every variant carries the numbers that explain it, so a caller can report
/// `t` and `h` without re-running anything.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum OdeError {
    /// The controller asked for a step too small to change `t` in floating point.
    #[error("step size underflow at t = {t}: h = {h:e} is below the resolution of t")]
    StepSizeUnderflow {
        /// Time at which the step failed.
        t: f64,
        /// The rejected step size.
        h: f64,
    },
    /// A stage or the new state contained NaN or ±∞ (the state before that step is kept).
    #[error("non-finite state in the step from t = {t}")]
    NonFiniteState {
        /// Start of the step that produced the non-finite value (for the splittings, which
        /// carry no clock, the time since the start of the call).
        t: f64,
    },
    /// An input the system reads from a user function (a driven rotor's motor, say) returned
    /// NaN or ±∞ during a step: the cause of a non-finite f, named by the system's
    /// [`System::explain_non_finite`](super::System::explain_non_finite) (the state before
    /// that step is kept).
    #[error("{input} returned {value} at t = {t}: it must return a finite number")]
    NonFiniteInput {
        /// The input, as its scene names it (``the motor `spin_up` of rotor_0``, …).
        input: String,
        /// Time of the evaluation (a stage's time, inside the failed step).
        t: f64,
        /// The value returned.
        value: f64,
    },
    /// The initial state holds NaN or ±∞ (component `index`).
    #[error("non-finite initial state: component {index} is {value}")]
    NonFiniteInitialState {
        /// Index of the first offending component.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A stop or output time lies before the current time.
    #[error("stop time {stop} is before the current time {t}")]
    StopBeforeCurrent {
        /// The requested stop time.
        stop: f64,
        /// The integrator's current time.
        t: f64,
    },
    /// `t_end` is before `t_start` (only forward integration is supported).
    #[error("t_end = {t_end} is before t_start = {t_start}")]
    EndBeforeStart {
        /// Start time.
        t_start: f64,
        /// Requested end time.
        t_end: f64,
    },
    /// A start, stop or output time is NaN or infinite.
    #[error("time {t} is not finite: start, stop and output times must be finite numbers")]
    NonFiniteTime {
        /// The offending time.
        t: f64,
    },
    /// Tolerances must be finite and positive.
    #[error("tolerances must be finite and > 0: rtol = {rtol:e}, atol = {atol:e}")]
    InvalidTolerance {
        /// Relative tolerance given.
        rtol: f64,
        /// Absolute tolerance given.
        atol: f64,
    },
    /// A step size (fixed step, initial step or maximum step) must be finite and positive.
    #[error("step size must be finite and > 0, got {h}")]
    InvalidStep {
        /// The offending step size.
        h: f64,
    },
    /// A controller parameter is out of its documented range.
    #[error("controller parameter `{name}` = {value} is out of range")]
    InvalidParameter {
        /// Name of the configuration field.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A fixed Taylor order above the highest the run may compute.
    #[error("Taylor order {order} is above {cap}, the highest that {limit} allows")]
    TaylorOrderTooHigh {
        /// The order asked for ([`TaylorConfig::order`](crate::taylor::TaylorConfig::order)).
        order: usize,
        /// The highest order allowed.
        cap: usize,
        /// Which setting caps it: `TaylorConfig::max_order` or the system's
        /// `TaylorSystem::max_order`.
        limit: &'static str,
    },
    /// The configured maximum number of steps was reached before the end time.
    #[error("maximum of {max_steps} steps reached at t = {t}")]
    MaxStepsExceeded {
        /// Time reached.
        t: f64,
        /// The configured limit.
        max_steps: u64,
    },
    /// A fixed-step advance would take more steps than its configured limit (checked before
    /// any work).
    #[error(
        "advancing from t = {t} to {t_stop} in steps of at most h = {h} takes {steps:e} steps, \
         more than max_steps = {max_steps}"
    )]
    TooManySteps {
        /// Current time.
        t: f64,
        /// The requested stop time.
        t_stop: f64,
        /// The configured largest step.
        h: f64,
        /// The steps the advance would take.
        steps: f64,
        /// The configured limit.
        max_steps: u64,
    },
    /// Dense output was asked for a time outside the last accepted step.
    #[error("dense output at t = {t} is outside the last step [{t_prev}, {t_now}]")]
    OutsideLastStep {
        /// Requested time.
        t: f64,
        /// Start of the last step.
        t_prev: f64,
        /// End of the last step (the current time).
        t_now: f64,
    },
    /// An event function g(t, y) returned NaN or ±∞.
    #[error("event {index}: g = {value} at t = {t} is not finite")]
    NonFiniteEvent {
        /// Index of the event, in the order the events were added.
        index: usize,
        /// Time of the evaluation.
        t: f64,
        /// The value returned.
        value: f64,
    },
    /// A witness of a hybrid run (a scene's event function: a normal force, a slip speed)
    /// returned NaN or ±∞.
    #[error("witness `{witness}`: {value} at t = {t} is not finite")]
    NonFiniteWitness {
        /// The witness's name, as its scene gives it.
        witness: &'static str,
        /// Time of the evaluation.
        t: f64,
        /// The value returned.
        value: f64,
    },
    /// A step was asked of a hybrid run that its scene has halted (read the outcome from
    /// the run; restart it to go on).
    #[error("the run was halted by its scene at t = {t}: it takes no more steps")]
    Halted {
        /// When the run halted.
        t: f64,
    },
    /// A hybrid run switched mode more times at one instant than it allows: the scene's
    /// modes send it back and forth without time passing (a Zeno point).
    #[error(
        "{switches} switches of mode at t = {t} without time passing: the scene's modes \
         send the run back and forth (a Zeno point)"
    )]
    Zeno {
        /// The instant.
        t: f64,
        /// The switches taken there.
        switches: usize,
    },
    /// An event expanded with the Taylor steps (`Run::taylor_event`) whose Taylor polynomial
    /// on a step is not g there: at the step's end it is further from g than
    /// `taylor::EVENT_MISMATCH` times the tolerance (relative to the polynomial's terms). g
    /// varies faster than the step resolves (it reads the time at a frequency the system
    /// does not have, or amplifies the state's variation), so the polynomial's roots would
    /// not be g's. Bound the step (`TaylorConfig::h_max`) or scan g (`Run::event`).
    #[error(
        "event {index}: its Taylor polynomial on the step ending at t = {t} is {mismatch:e} from g there, above {limit:e}: g varies faster than the step resolves (bound the step or scan g)"
    )]
    EventNotResolved {
        /// Index of the event, in the order the events were added.
        index: usize,
        /// End of the step.
        t: f64,
        /// |q(h) − g(t, y)| at the step's end.
        mismatch: f64,
        /// The largest mismatch accepted there.
        limit: f64,
    },
    /// A derived quantity of a trajectory came out NaN or ±∞.
    #[error("trajectory quantity {column}: {value} at t = {t} is not finite")]
    NonFiniteQuantity {
        /// Index of the quantity among the trajectory's derived columns.
        column: usize,
        /// Time of the sample.
        t: f64,
        /// The value computed.
        value: f64,
    },
    /// A sample time lies after the end of the run (it would never be reached).
    #[error("sample time {t} is after the end of the run, t_end = {t_end}")]
    SampleAfterEnd {
        /// The sample time.
        t: f64,
        /// The end of the run.
        t_end: f64,
    },
    /// A list of column names does not match the columns it names.
    #[error("{got} column names given for {expected} columns")]
    ColumnCount {
        /// Columns there are.
        expected: usize,
        /// Names given.
        got: usize,
    },
    /// An exact sub-flow (the free-body flow of a splitting) failed.
    #[error("exact flow: {0}")]
    Exact(#[from] ExactError),
    /// An attitude quaternion is not of unit norm (|q| − 1 beyond 1e-6): it is no rotation.
    #[error("attitude quaternion has norm {norm}, not 1: it is no rotation")]
    NotUnitQuaternion {
        /// Its norm.
        norm: f64,
    },
    /// Mass or a principal moment of inertia is not finite and positive.
    #[error("mass and inertia must be finite and > 0: mass = {mass}, inertia = {inertia:?}")]
    InvalidInertia {
        /// Mass given (1 where only inertia matters).
        mass: f64,
        /// Principal moments given.
        inertia: [f64; 3],
    },
    /// A run or a trajectory would hold more samples than [`super::MAX_SAMPLES`] (or a
    /// number of samples that does not even fit in `usize`): checked before any work for
    /// `sample_every` and `sample_at`, and when a sample is pushed for `sample_steps`.
    #[error(
        "{samples:e} samples asked for, more than the cap of {max}: sample less often \
         (sample_every with a larger dt) or watch the steps with an observer"
    )]
    TooManySamples {
        /// The samples the request takes (∞ when it does not fit in f64).
        samples: f64,
        /// The cap, [`super::MAX_SAMPLES`].
        max: usize,
    },
    /// A sample interval too fine for the doubles near the run's times: t0 + k·dt would
    /// round onto the same time for several k. dt must be at least
    /// [`super::MIN_SAMPLE_SPACINGS`] times the spacing of doubles at the larger of |t0|,
    /// |t_end|.
    #[error(
        "sample interval dt = {dt:e} is below the resolution of t near {t:e}: doubles there \
         are {spacing:e} apart, and dt must be at least {min} times that so that no sample \
         time repeats",
        min = super::MIN_SAMPLE_SPACINGS
    )]
    SampleIntervalBelowResolution {
        /// The interval given.
        dt: f64,
        /// The run's time of largest magnitude (t0 or t_end).
        t: f64,
        /// The spacing of doubles there (one ulp).
        spacing: f64,
    },
    /// A sample pushed onto a trajectory before its last time: the times of a trajectory
    /// never decrease.
    #[error("time {t} comes before the last sample's time {previous}: times must not decrease")]
    DecreasingTime {
        /// The offending time.
        t: f64,
        /// The last sample's time.
        previous: f64,
    },
    /// The Taylor integrator's extended mode was asked of a system whose
    /// `TaylorSystem::coefficients_extended_into` returns `false`: a hand-written system that
    /// does not implement it (every generated system and every `TaylorTape` does).
    #[error(
        "the extended mode (orders 0..={low} in double-double) needs a system that computes \
         double-double coefficients, and this one's TaylorSystem::coefficients_extended_into \
         returns false: implement it, or leave TaylorConfig::extended at None"
    )]
    NoExtendedCoefficients {
        /// The highest order asked in double-double (`TaylorConfig::extended`).
        low: usize,
    },
    /// A value of the system's parameters breaks a rule of its scene (a negative mass, a
    /// negative gravity, a NaN stiffness, …), found by
    /// [`System::check_parameters`](super::System::check_parameters) when the integrator was
    /// built or restarted, before any step.
    #[error("the system's parameters are refused before the first step: {message}")]
    InvalidSystemParameter {
        /// The quantity, as the scene names it (`mass`, `gravity`, `stiffness of theta`, …).
        quantity: String,
        /// Its value.
        value: f64,
        /// The scene's own explanation (the display of its error), naming the part or joint.
        message: String,
    },
}

impl OdeError {
    /// The error of a system whose `quantity` has the unphysical `value`, explained by the
    /// scene's own error: what a [`System::check_parameters`](super::System::check_parameters)
    /// returns.
    ///
    /// ```
    /// use precess_core::ode::OdeError;
    /// let e = OdeError::system_parameter("gravity", -9.81, "gravity must be ≥ 0");
    /// assert!(matches!(e, OdeError::InvalidSystemParameter { value, .. } if value == -9.81));
    /// ```
    pub fn system_parameter(
        quantity: impl Into<String>,
        value: f64,
        message: impl core::fmt::Display,
    ) -> OdeError {
        OdeError::InvalidSystemParameter {
            quantity: quantity.into(),
            value,
            message: message.to_string(),
        }
    }
}

/// Checks that every component of `y` is finite.
///
/// # Errors
/// [`OdeError::NonFiniteInitialState`] naming the first NaN or infinite component.
pub(crate) fn check_finite(y: &[f64]) -> Result<(), OdeError> {
    match y.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(OdeError::NonFiniteInitialState {
            index,
            value: y[index],
        }),
        None => Ok(()),
    }
}

/// Checks that `t_start ≤ t_end` and both are finite.
///
/// # Errors
/// [`OdeError::NonFiniteTime`] or [`OdeError::EndBeforeStart`].
pub(crate) fn check_span(t_start: f64, t_end: f64) -> Result<(), OdeError> {
    for t in [t_start, t_end] {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
    }
    if t_end < t_start {
        return Err(OdeError::EndBeforeStart { t_start, t_end });
    }
    Ok(())
}

/// Checks that a stepper at time `t` may be sent to `stop`: finite and not before `t`.
///
/// # Errors
/// [`OdeError::NonFiniteTime`] or [`OdeError::StopBeforeCurrent`].
pub(crate) fn check_stop(t: f64, stop: f64) -> Result<(), OdeError> {
    if !stop.is_finite() {
        return Err(OdeError::NonFiniteTime { t: stop });
    }
    if stop < t {
        return Err(OdeError::StopBeforeCurrent { stop, t });
    }
    Ok(())
}

/// Checks that mass and principal moments are finite and positive.
///
/// # Errors
/// [`OdeError::InvalidInertia`].
pub(crate) fn check_inertia(mass: f64, inertia: [f64; 3]) -> Result<(), OdeError> {
    let ok = |v: f64| v.is_finite() && v > 0.0;
    if ok(mass) && inertia.iter().all(|&v| ok(v)) {
        Ok(())
    } else {
        Err(OdeError::InvalidInertia { mass, inertia })
    }
}
