//! precess: rigid-body dynamics derived symbolically at compile time.
//!
//! Describe a body on a struct and derive [`RigidBody`](prelude::RigidBody): the macro
//! computes the body's mass, centre of mass, inertia tensor and principal frame while it
//! expands, and emits Euler's equations specialised to the body.
//!
//! ```
//! use approx::assert_relative_eq;
//! use precess::prelude::*;
//!
//! /// A stem and a disk turning about a pivot at the origin.
//! #[derive(RigidBody)]
//! #[rigid(
//!     cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
//!     disk(mass = m, radius = r, at = [0.0, 0.0, h]),
//!     pivot = [0.0, 0.0, 0.0],
//! )]
//! struct Top { m: f64, r: f64, h: f64 }
//!
//! let top = Top { m: 0.5, r: 0.03, h: 0.05 };
//! // I3 = ½ m_s r_s² + ½ m r².
//! let i3 = 0.5 * 0.2 * 0.004f64.powi(2) + 0.5 * 0.5 * 0.03f64.powi(2);
//! assert_relative_eq!(top.principal().moments[2], i3, max_relative = 1e-15);
//! let w_dot = top.euler_rhs_principal(&Vector3::new(0.0, 0.0, 10.0), &Vector3::zeros());
//! assert_relative_eq!(w_dot.norm(), 0.0);
//! ```
//!
//! The same bodies can be built at run time with [`body::BodyBuilder`]; the macro and the
//! builder share one implementation in `precess-core`, whose modules are re-exported here at
//! the root: the engine ([`sym`], [`codegen`], [`lagrange`], [`ode`], [`exact`], [`taylor`],
//! [`linalg`], and [`ensemble`], many runs at once), the bodies and what the scenes share
//! ([`body`], [`rigid`]: angle sequences, their charts and the chart switch's pieces, the
//! Lie-group and splitting steppers), the scenes ([`top`]: `#[top(...)]`, a body about a
//! fixed pivot; [`free`]: `#[free(...)]`, a body in flight; [`contact`]: `#[contact(...)]`,
//! a body rolling or sliding on a table; [`mechanism`]: `#[derive(Mechanism)]`, trees of
//! bodies and joints), [`variational`] over them (variational equations, Lyapunov exponents,
//! the linearised flow map), and the [`nalgebra`] precess is built on. With the `plot`
//! feature, `plot` draws a run's figures (the `precess-plot` crate). Every scene has the same shape (a description, its
//! derivation, an interpreted model, the trait the derive implements, one error; the same
//! method names for q̈, energy and momenta): `docs/conventions.md` says it.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The derives name what they generate through `::precess::…`; inside this crate that path
// is the crate itself, for the ready scenes of `models`.
extern crate self as precess;

pub use precess_core::*;

#[cfg(feature = "models")]
pub mod models;

/// Figures of runs written as SVG: a trajectory's columns against time, phase portraits,
/// work–precision plots, any series on any axes (the `plot` feature; `docs/plots.md`).
#[cfg(feature = "plot")]
pub use precess_plot as plot;

/// A run as a 3D animation: a binary glTF (`.glb`) of the declared shapes keyframed from a
/// trajectory, and a self-contained HTML page that plays it (the `animate` feature;
/// `docs/animation.md`).
#[cfg(feature = "animate")]
pub use precess_animate as animate;

/// An ODE written as equations, with its right-hand side and its Taylor recurrences
/// generated at compile time (see `docs/taylor.md`).
///
/// # Examples
/// DETEST B5, whose solution from (0, 1, 1) is Jacobi's (sn, cn, dn)(t | 0.51): the
/// coefficient of order 1 is the right-hand side, those of orders 2 and 3 follow from it.
/// ```
/// use approx::assert_relative_eq;
/// use precess::ode::System;
/// use precess::taylor::TaylorSystem;
/// precess::taylor_system! {
///     /// DETEST B5.
///     struct B5;
///     state [y1, y2, y3];
///     taylor = 20;
///     d/dt y1 = y2 * y3;
///     d/dt y2 = -y1 * y3;
///     d/dt y3 = -0.51 * y1 * y2;
/// }
/// let mut c = [[0.0; 3]; 4];
/// B5.coefficients(0.0, &[0.0, 1.0, 1.0], 3, &mut c);
/// let mut f = [0.0; 3];
/// B5.rhs(0.0, &[0.0, 1.0, 1.0], &mut f);
/// for i in 0..3 {
///     assert_relative_eq!(c[1][i], f[i], epsilon = 1e-15);
/// }
/// // sn t = t − (1 + k²) t³/6 + …, cn t = 1 − t²/2 + …, dn t = 1 − k² t²/2 + …
/// assert_relative_eq!(c[2][1], -0.5);
/// assert_relative_eq!(c[2][2], -0.51 / 2.0);
/// assert_relative_eq!(c[3][0], -(1.0 + 0.51) / 6.0);
/// ```
pub use precess_derive::taylor_system;

/// The derive and the types a user of it needs.
pub mod prelude {
    pub use precess_core::body::{
        About, Axis, Body, BodyBuilder, BodyError, Matrix3, Orientation, Principal, RigidBody,
        Rotation3, Shape, Vector3,
    };
    pub use precess_core::codegen::{MethodCost, OpCount, Typeset};
    pub use precess_core::contact::{
        ContactDynamics, ContactError, ContactSystem, LawKind, Phase, Reaction,
    };
    pub use precess_core::free::{FreeDynamics, FreeError, FreeFlight, FreeState, FreeSystem};
    pub use precess_core::mechanism::loops::LoopDynamics;
    pub use precess_core::mechanism::rolling::RollingDynamics;
    pub use precess_core::mechanism::{
        ChartSet, ChartedDynamics, ChartedMechanism, MechanismDynamics, MechanismError,
        MechanismPoses,
    };
    pub use precess_core::nalgebra::UnitQuaternion;
    pub use precess_core::rigid::{AngleSequence, ChartConfig, ChartError};
    pub use precess_core::top::{ChartedTop, EulerianTop, TopChart, TopDynamics, TopError};
    pub use precess_derive::{Mechanism, RigidBody};
}

/// What code generated by the derive names (through `::precess::__private::…`). Not a
/// public API.
#[doc(hidden)]
pub mod __private {
    pub use precess_core::body::{
        About, Axis, BodyError, Description, Matrix3, Orientation, Part, Principal, RigidBody,
        Rotation3, Shape, Vector3, check_part, euler_rhs_diagonal, principal_frame,
    };
    pub use precess_core::codegen::{Export, MethodCost, OpCount, Typeset};
    pub use precess_core::contact::{
        ContactDynamics, ContactError, ContactMomenta, ContactPoint, ContactValues, LawKind, Phase,
        Reaction, SurfaceKind, attitude_of,
    };
    pub use precess_core::exact::Dd;
    pub use precess_core::free::{
        AppliedWrench, FreeDynamics, FreeError, FreeState, STATE_LEN, Wrench,
    };
    pub use precess_core::lagrange::Partition;
    pub use precess_core::mechanism::charts::SphericalJoint;
    pub use precess_core::mechanism::loops::{LoopDynamics, check_loop_sides};
    pub use precess_core::mechanism::rolling::{RollingDynamics, RollingPartials};
    pub use precess_core::mechanism::{
        ChartSet, ChartedDynamics, LinkPose, MechanismDynamics, MechanismError, MechanismPoses,
        check_axis, check_universal_axes, effort_jacobian,
    };
    pub use precess_core::nalgebra::UnitQuaternion;
    pub use precess_core::nalgebra::{SMatrix, SVector};
    pub use precess_core::ode::{OdeError, System};
    pub use precess_core::rigid::AngleSequence;
    pub use precess_core::taylor::EventSeries;
    pub use precess_core::taylor::StateEvent;
    pub use precess_core::taylor::TaylorSystem;
    pub use precess_core::taylor::batch::Lanes;
    pub use precess_core::taylor::batch::TaylorLanes;
    pub use precess_core::taylor::batch::kernels as lane_kernels;
    pub use precess_core::taylor::compact::low_orders;
    pub use precess_core::taylor::kernels;
    pub use precess_core::top::{TopDynamics, TopError, TopParameters};
    pub use precess_core::variational::{Layout, VariationalError};
    pub use std::borrow::Cow;
    pub use std::vec;
}

// The README's and the guides' Rust blocks, compiled and run as doctests (`guides.rs`).
#[cfg(doctest)]
mod guides;
