//! Mechanisms: trees of rigid bodies joined by revolute, prismatic, universal and spherical
//! joints, derived to `M(q) q̈ = f(q, q̇, t)` and solved by the cheapest exact route.
//!
//! - [`MechanismScene`] describes the tree and its loads (see `scene.rs` for the frames).

mod scene;

pub use scene::{CoordinateLoad, Joint, JointKind, MechanismBody, MechanismScene, Parent, Spring};
