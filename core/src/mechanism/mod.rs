//! Mechanisms: trees of rigid bodies joined by revolute, prismatic, universal and spherical
//! joints, derived to `M(q) q̈ = f(q, q̇, t)` and solved by the cheapest exact route.
//!
//! - [`MechanismScene`] describes the tree and its loads (see `scene.rs` for the frames).
//! - [`recursive_accelerations`] is the recursive route (the articulated-body algorithm,
//!   symbolic), [`MechanismAba`] the same algorithm numerically, the generic O(n) reference.

mod aba;
mod error;
pub mod recursive;
mod scene;

pub use aba::MechanismAba;
pub use error::MechanismError;
pub use recursive::{RecursiveForm, coordinate_forces, derive_recursive, recursive_accelerations};
pub use scene::{CoordinateLoad, Joint, JointKind, MechanismBody, MechanismScene, Parent, Spring};
