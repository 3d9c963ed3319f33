//! The mechanism scene's one error: a malformed tree, a derivation that cannot be solved,
//! run-time values the model refuses, and what the chart switch of its spherical joints
//! refuses.

use thiserror::Error;

use crate::body::BodyError;
use crate::codegen::BindingError;
use crate::lagrange::LagrangeError;
use crate::ode::{OdeError, binding_quantity, body_quantity, refused};
use crate::rigid::{ChartError, SurfaceError};
use crate::sym::SymError;

/// What can go wrong describing, deriving or evaluating a mechanism.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MechanismError {
    /// A mechanism needs at least one joint with a coordinate.
    #[error("the mechanism has no moving joint (declare at least one body with its joint)")]
    NoMovingJoint,
    /// A joint names a parent body that does not exist.
    #[error("body `{body}` hangs from body number {parent}, but there are only {count} bodies")]
    UnknownParent {
        /// The child body.
        body: String,
        /// The parent index given.
        parent: usize,
        /// How many bodies the mechanism has.
        count: usize,
    },
    /// The joints do not form a tree: following parents from these bodies returns to them.
    #[error("the joints form a cycle through the bodies {}", bodies.join(" → "))]
    Cycle {
        /// The bodies on the cycle, in parent order.
        bodies: Vec<String>,
    },
    /// Two bodies, joints or coordinates share a name.
    #[error("two {kind}s are both named `{name}`")]
    DuplicateName {
        /// `"body"`, `"joint"` or `"coordinate"`.
        kind: &'static str,
        /// The repeated name.
        name: String,
    },
    /// A joint axis with no direction: the zero vector (identically, or for the values
    /// given), or one whose |axis|² underflows or overflows f64.
    #[error("joint `{joint}`: {}", detail(*squared_length))]
    ZeroAxis {
        /// The joint.
        joint: String,
        /// |axis|² at the values given, when known (`None`: identically zero).
        squared_length: Option<f64>,
    },
    /// A universal joint whose two axes are parallel (or opposite): its two coordinates
    /// would turn about one line and the mass matrix is singular.
    #[error(
        "joint `{joint}`: the universal joint's axes are parallel (the sine of the angle between them is {sine:e}, below √ε ≈ {minimum:.1e}), so its two coordinates turn about one line: give axes at an angle, such as [x, y]"
    )]
    ParallelAxes {
        /// The joint.
        joint: String,
        /// |a × b| / (|a| |b|) for the values given.
        sine: f64,
        /// The smallest sine accepted, [`super::PARALLEL_SINE`].
        minimum: f64,
    },
    /// A parameter given twice to [`super::MechanismModel::new`] or
    /// [`super::MechanismModel::from_derivation`].
    #[error("parameter `{name}` is given twice ({first}, then {second}): give each parameter once")]
    DuplicateParameter {
        /// The parameter.
        name: String,
        /// Its first value.
        first: f64,
        /// Its second value.
        second: f64,
    },
    /// A free joint hanging from a body rather than the ground: a free joint attaches a
    /// mechanism's base body to the ground.
    #[error(
        "free joint `{joint}` hangs from body `{parent}`: a free joint attaches the base body to the ground (use a spherical or other joint between bodies)"
    )]
    FreeJointNotOnGround {
        /// The joint.
        joint: String,
        /// The body it hangs from (its index when there is no such body).
        parent: String,
    },
    /// A second free joint: a mechanism has one base body flying free.
    #[error("free joints `{first}` and `{second}`: a mechanism has at most one, on its base body")]
    SecondFreeJoint {
        /// The first free joint, in body order.
        first: String,
        /// The second.
        second: String,
    },
    /// A joint with the wrong number of coordinate names.
    #[error("joint `{joint}` ({kind}) has {got} coordinate names, expected {expected}")]
    WrongCoordinateCount {
        /// The joint.
        joint: String,
        /// Its kind.
        kind: &'static str,
        /// Its degrees of freedom.
        expected: usize,
        /// The names given.
        got: usize,
    },
    /// A joint with the wrong number of coordinate loads.
    #[error("joint `{joint}` ({kind}) has {got} coordinate loads, expected {expected}")]
    WrongLoadCount {
        /// The joint.
        joint: String,
        /// Its kind.
        kind: &'static str,
        /// Its degrees of freedom.
        expected: usize,
        /// The loads given.
        got: usize,
    },
    /// The mass matrix is singular: a pivot of its factorisation (a block determinant on the
    /// symbolic route) is not positive. Massless links cause this.
    #[error(
        "the mass matrix is singular: pivot {pivot} is {value:e} (a massless or inertia-free link?)"
    )]
    SingularMassMatrix {
        /// Which pivot (0-based).
        pivot: usize,
        /// Its value (`0` when identically zero).
        value: f64,
    },
    /// NaN or ±∞ in a state, a time or a result.
    #[error("non-finite {quantity}: {values:?}")]
    NonFinite {
        /// What held the value.
        quantity: &'static str,
        /// The values.
        values: Vec<f64>,
    },
    /// A coordinate index that is not one of the free (independent) coordinates.
    #[error(
        "coordinate {index} is not a free coordinate of the {coordinates} (dependent: {dependent:?})"
    )]
    NotFreeCoordinate {
        /// The index given.
        index: usize,
        /// The coordinate count.
        coordinates: usize,
        /// The dependent coordinates' indices.
        dependent: Vec<usize>,
    },
    /// A state of the wrong length.
    #[error("{quantity} has {got} entries, the mechanism has {expected} coordinates")]
    StateLength {
        /// What was given.
        quantity: &'static str,
        /// The coordinate count.
        expected: usize,
        /// The entries given.
        got: usize,
    },
    /// A route that this build cannot take.
    #[error("the {route} route is not available: {reason}")]
    RouteUnavailable {
        /// The route.
        route: &'static str,
        /// Why.
        reason: &'static str,
    },
    /// A value the struct's fields give a quantity is NaN or infinite.
    #[error("{owner}: {quantity} is {value} from the struct's fields; it must be finite")]
    NonFiniteParameter {
        /// The body or joint holding the quantity (`` body `arm` ``, `` joint `elbow` ``), or
        /// `the mechanism` for gravity.
        owner: String,
        /// The quantity and component (`at[2]`, `stiffness of theta`, …).
        quantity: String,
        /// Its value.
        value: f64,
    },
    /// A spring stiffness or a damper coefficient the struct's fields make negative (it would
    /// feed energy in); literals are refused by the derive.
    #[error("{owner}: {quantity} must not be negative, got {value:e} from the struct's fields")]
    NegativeParameter {
        /// The joint.
        owner: String,
        /// The coefficient and its coordinate (`damper of theta`).
        quantity: String,
        /// Its value.
        value: f64,
    },
    /// A rolling body's radius, or its disk axle's squared length, that the struct's fields
    /// make zero or negative (or NaN); literals are refused by the derive.
    #[error("{owner}: {quantity} must be positive, got {value:e} from the struct's fields")]
    NonPositiveParameter {
        /// The rolling body (`` body `rear_wheel` ``).
        owner: String,
        /// The quantity (`rolling radius`, `|axle|²`).
        quantity: String,
        /// Its value.
        value: f64,
    },
    /// A part of a body breaks, for the values of the struct's fields, a rule of the body
    /// language that literal parts meet at compile time (a zero mass is allowed: a massless
    /// link is the singular mass matrix's concern).
    #[error("body `{body}`: {error}")]
    Part {
        /// The body.
        body: String,
        /// The rule broken, numbering the part within the body.
        error: BodyError,
    },
    /// The floor's `up` is not a signed ground axis.
    #[error("the floor's `up` must be a signed ground axis (x, -x, y, -y, z or -z)")]
    FloorNotAxis,
    /// A rolling wheel names a body that does not exist.
    #[error("a rolling wheel names body number {body}, but there are {count} bodies")]
    UnknownWheelBody {
        /// The index given.
        body: usize,
        /// The number of bodies.
        count: usize,
    },
    /// A free speed names no coordinate, or one named already.
    #[error("free speed `{speed}` is {}", if *repeated { "named twice".to_owned() } else { format!("not a coordinate (coordinates: {})", coordinates.join(", ")) })]
    UnknownSpeed {
        /// The name given.
        speed: String,
        /// Whether it is a repeat (else it names no coordinate).
        repeated: bool,
        /// The coordinates there are.
        coordinates: Vec<String>,
    },
    /// The free speeds are not as many as the coordinates less the constraint rows.
    #[error(
        "{got} free speeds named for {coordinates} coordinates under {rows} rolling \
         constraint rows: name {}", coordinates.saturating_sub(*rows)
    )]
    SpeedCount {
        /// Speeds named.
        got: usize,
        /// Coordinates.
        coordinates: usize,
        /// Constraint rows of the wheels.
        rows: usize,
    },
    /// A rolling disk lies flat (or past it): the cosine of its lean from the vertical,
    /// |d| = √(1 − (up·n)²), is at most `rolling::MIN_TILT`, and its contact point is
    /// undefined.
    #[error(
        "rolling wheel {wheel} lies flat: the cosine of its lean is {tilt:e}, it must exceed \
         {minimum:e}",
        minimum = crate::rigid::MIN_TILT
    )]
    WheelFlat {
        /// The wheel, in declaration order.
        wheel: usize,
        /// Its |d|.
        tilt: f64,
    },
    /// A run would start with a wheel off the floor (or into it): a run keeps the heights
    /// where they start.
    #[error(
        "constraint row {row}: a wheel's height above the floor is {height:e} at the start (at \
         most {allowed:e}); put the wheels down first with close_contacts"
    )]
    WheelOffFloor {
        /// The height row.
        row: usize,
        /// Its height.
        height: f64,
        /// `lagrange::START_RESIDUAL`.
        allowed: f64,
    },
    /// A rolling model built for other sizes than its derivation's.
    #[error(
        "the rolling derivation has {coordinates} coordinates, {rows} constraint rows and \
         {speeds} free speeds; the model was asked for {asked:?}"
    )]
    RollingSizes {
        /// n.
        coordinates: usize,
        /// m.
        rows: usize,
        /// k.
        speeds: usize,
        /// [N, M, K] of the model's type.
        asked: [usize; 3],
    },
    /// A planar loop whose longest side is not shorter than the sum of the others: it
    /// cannot close, or closes only folded flat ([`super::loops::check_loop_sides`]).
    #[error(
        "the loop closed by `{closure}` cannot close: the side of `{body}` is {longest}, not shorter than the sum of the others, {others}"
    )]
    LoopCannotClose {
        /// The closing body.
        closure: String,
        /// The body (or `"ground"`) with the longest side.
        body: String,
        /// That side's length.
        longest: f64,
        /// The sum of the other sides.
        others: f64,
    },
    /// The closures give as many independent-looking rows as there are coordinates, or
    /// more: nothing would be left to move.
    #[error(
        "the loop closures give {rows} constraint rows on {coordinates} coordinates, leaving no free coordinate"
    )]
    TooManyClosureRows {
        /// The closure rows (identically zero components left out).
        rows: usize,
        /// The coordinates.
        coordinates: usize,
    },
    /// A closure names a body index past the mechanism's bodies.
    #[error("a loop closure names body number {body}, but there are only {count} bodies")]
    UnknownClosureBody {
        /// The index given.
        body: usize,
        /// How many bodies there are.
        count: usize,
    },
    /// A parameter could not be bound.
    #[error(transparent)]
    Binding(#[from] BindingError),
    /// The Euler–Lagrange engine failed.
    #[error(transparent)]
    Lagrange(#[from] LagrangeError),
    /// The chart switch cannot start: a `switch_below` that is not finite and positive
    /// ([`crate::rigid::ChartConfig::check`]).
    #[error(transparent)]
    Chart(#[from] ChartError),
    /// The ODE state of the chart switch is not twice the coordinate count.
    #[error("the ODE state has {got} entries, the mechanism needs 2n = {expected}")]
    OdeStateLength {
        /// 2n.
        expected: usize,
        /// S.
        got: usize,
    },
    /// More spherical joints than a [`super::charts::ChartSet`] can name.
    #[error("{count} spherical joints; a chart set names at most {max}")]
    TooManyJoints {
        /// The spherical joints.
        count: usize,
        /// [`super::charts::MAX_SPHERICAL_JOINTS`].
        max: usize,
    },
    /// A chart set the mechanism does not provide ([`super::charts::chart_variants`]).
    #[error("the mechanism provides no equations for the chart set {charts:#b}")]
    UnavailableCharts {
        /// The chart set's bits.
        charts: u32,
    },
    /// One attitude and angular velocity per spherical joint is needed.
    #[error("{got} joint attitudes given for {expected} spherical joints")]
    AttitudeCount {
        /// The spherical joints.
        expected: usize,
        /// The attitudes given.
        got: usize,
    },
    /// A joint's attitude is not a rotation matrix, or its ω is not finite.
    #[error("spherical joint `{joint}`: {source}")]
    Attitude {
        /// The joint.
        joint: String,
        /// What is wrong with it.
        source: ChartError,
    },
    /// A joint's state cannot be represented in any chart available to it (its rate map is
    /// singular in its chart and it cannot switch), or its angles or rates are not finite.
    #[error("spherical joint `{joint}` in its chart: {source}")]
    Joint {
        /// The joint.
        joint: String,
        /// The rate map's complaint.
        source: ChartError,
    },
    /// The stepper of the chart switch failed, or a stop time is not finite or lies in the
    /// past.
    #[error(transparent)]
    Ode(#[from] OdeError),
    /// A constructor of the symbolic engine failed.
    #[error(transparent)]
    Sym(#[from] SymError),
    /// A wheel's surface the shared support map cannot turn onto an axle.
    #[error(transparent)]
    Surface(#[from] SurfaceError),
}

impl MechanismError {
    /// This refusal as the integrators report it, from
    /// [`System::check_parameters`](crate::ode::System::check_parameters) (the derive's
    /// `impl System` calls it): [`OdeError::InvalidSystemParameter`] naming the owner and
    /// quantity with its value and this error's message ([`MechanismError::Ode`] is passed
    /// on as it is).
    ///
    /// ```
    /// use precess::mechanism::MechanismError;
    /// use precess::ode::OdeError;
    /// let e = MechanismError::NegativeParameter {
    ///     owner: "joint `hinge`".into(),
    ///     quantity: "damper of theta".into(),
    ///     value: -0.3,
    /// };
    /// assert!(matches!(
    ///     e.into_ode_error(),
    ///     OdeError::InvalidSystemParameter { ref quantity, value, .. }
    ///         if quantity == "joint `hinge`: damper of theta" && value == -0.3
    /// ));
    /// ```
    pub fn into_ode_error(self) -> OdeError {
        let named = match &self {
            MechanismError::Ode(e) => return e.clone(),
            MechanismError::NonFiniteParameter {
                owner,
                quantity,
                value,
            }
            | MechanismError::NegativeParameter {
                owner,
                quantity,
                value,
            }
            | MechanismError::NonPositiveParameter {
                owner,
                quantity,
                value,
            } => (format!("{owner}: {quantity}"), *value),
            MechanismError::Part { body, error } => {
                let (quantity, value) = body_quantity(error);
                (format!("body `{body}`: {quantity}"), value)
            }
            MechanismError::LoopCannotClose {
                closure,
                body,
                longest,
                ..
            } => (
                format!("loop closed by `{closure}`: side of `{body}`"),
                *longest,
            ),
            MechanismError::Binding(b) => binding_quantity(b),
            _ => ("parameters".to_owned(), f64::NAN),
        };
        refused(named, &self)
    }
}

/// Why an axis has no direction.
fn detail(squared_length: Option<f64>) -> String {
    match squared_length {
        None => "the axis is zero, so it has no direction".to_owned(),
        Some(0.0) => {
            "the axis is zero at the values given (|axis|² = 0), so it has no direction".to_owned()
        }
        Some(f64::INFINITY) => {
            "|axis|² overflows f64 at the values given: scale the axis down".to_owned()
        }
        Some(v) if v > 0.0 => format!(
            "|axis|² = {v:e} at the values given underflows f64's normal numbers: scale the axis up"
        ),
        Some(v) => format!("|axis|² is {v} at the values given: the axis has no direction"),
    }
}
