//! A run of precess as a 3D animation: a binary glTF 2.0 file (`.glb`) of the bodies drawn
//! from their declared shapes and keyframed from a [`Trajectory`](precess_core::ode::Trajectory),
//! and a self-contained HTML page that plays it (the facade's `animate` feature, used as
//! `precess::animate`; `docs/animation.md`).
//!
//! - [`top`], [`contact`], [`free`] and [`mechanism`] turn a scene's run into an [`Animation`] in one call;
//!   [`Animation`] with [`part_groups`] builds any other by hand from [`Pose`]s.
//! - [`Animation::to_glb`] writes the `.glb` that Blender, three.js and any glTF viewer play:
//!   each part a mesh in its colour (its two halves in the colour and its complement, so a
//!   turn about a symmetry axis shows), space z up (glTF's y up is one turn at the root).
//! - [`page`] writes one HTML file holding the `.glb` and a small WebGL viewer: play/pause, a
//!   time slider, an orbiting camera, and the run's table beside it.
//!
//! ```
//! use precess::animate::{Options, top};
//! use precess::nalgebra::{UnitQuaternion, Vector3};
//! use precess::ode::Trajectory;
//! use precess::prelude::*;
//!
//! #[derive(RigidBody)]
//! #[rigid(
//!     disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]),
//!     cylinder(mass = 0.01, radius = 0.003, length = 0.08, at = [0.0, 0.0, 0.04]),
//!     pivot = [0.0, 0.0, 0.0],
//! )]
//! struct Spinner;
//!
//! // A steady precession written down directly: φ = 2 t at θ = 0.3, spinning ψ = 50 t.
//! let mut run = Trajectory::new(vec![]);
//! for k in 0..=100 {
//!     let t = 0.01 * k as f64;
//!     run.push(t, [2.0 * t, 0.3, 50.0 * t], &[])?;
//! }
//! let zxz = |q: &[f64; 3]| {
//!     UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q[0])
//!         * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), q[1])
//!         * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), q[2])
//! };
//! let options = Options { time_scale: 4.0, ..Options::default() };
//! let animation = top(&Spinner, &run, zxz, options)?;
//! assert_eq!(animation.duration(), 4.0);
//! let glb = animation.to_glb()?;
//! assert!(glb.len() > 1000);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod animation;
mod base64;
mod error;
mod free;
mod geometry;
pub mod glb;
mod gltf;
mod mechanism;
mod page;
mod parts;
mod scenes;

pub use animation::{Animation, PIVOT, Pose, TABLE};
pub use error::AnimateError;
pub use free::{FreeSample, free};
pub use gltf::{Keyframes, Z_UP_TO_Y_UP};
pub use mechanism::{BAR, MechanismSample, link_node, mechanism};
pub use page::{BACKGROUND, Camera, PageTable, page, write_page};
pub use parts::{Group, PALETTE, Rgb, body_size, complement, part_groups};
pub use scenes::{Options, TRACE, TableState, contact, surface_groups, top};

impl Animation {
    /// The keyframes written for body `index` (in the order the bodies were added), `None`
    /// past the last: what the `.glb`'s animation samplers hold.
    pub fn keyframes(&self, index: usize) -> Option<Keyframes> {
        let track = self.tracks.get(index)?;
        Some(gltf::keyframes(track, self.start(), self.time_scale))
    }
}
