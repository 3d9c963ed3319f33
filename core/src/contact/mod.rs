//! A body on a table: rolling and sliding contact with a horizontal plane.
//!
//! A scene over the engine, in one place:
//! - [`ContactScene`] holds the body's mass properties, the convex [`Surface`] it touches the
//!   table with and the [`ContactLaw`] (rolling, sliding under a [`Friction`], stick–slip).
//! - [`Surface::support`] gives the contact point as a closed-form function of the attitude.
//! - [`STATE_LEN`] and [`layout`] place the state in the array the steppers integrate, one
//!   layout for every law.

mod scene;
mod state;
mod surface;
pub mod theory;

pub use scene::{ContactLaw, ContactScene, Friction};
pub use state::{STATE_LEN, layout};
pub use surface::Surface;
