//! Angle charts and getting through their gimbal lock, for every scene that has Euler
//! angles (a top's attitude, a mechanism's spherical joints).
//!
//! - [`check_chart`] and [`rates_from_omega`] are the one rule for when a chart is singular
//!   (`|det B(q)|` below [`SINGULAR_DET`]) and for solving `B(q) q̇ = ω` there.
//! - [`joint_rotation`], [`joint_rate_matrix`] and [`map_to_partner`] give R(q) and B(q)
//!   numerically and move angles and rates to the partner chart (ZXZ ↔ ZYX) exactly,
//!   through the attitude and ω both charts share.
//! - [`ChartConfig`] says when a switching driver changes chart; [`check_rotation`] checks
//!   the attitude it starts from; [`ChartError`] is what all of these refuse.
//!
//! The drivers themselves are the scenes': `ChartedTop` and
//! `ChartedMechanism`.

mod config;
mod error;
mod partner;
mod singular;

pub use config::{ChartConfig, ROTATION_TOLERANCE, check_rotation};
pub use error::ChartError;
pub(crate) use partner::state_in_chart;
pub use partner::{joint_rate_matrix, joint_rotation, map_to_partner};
pub use singular::{SINGULAR_DET, check_chart, rates_from_omega};
