//! Ready scenes a user can depend on, each declared with the derives as a user would, with
//! its parameters from the literature (heyoka keeps such systems in its `model/` folder):
//!
//! - [`Bicycle`]: the benchmark bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007),
//!   a rolling mechanism, with its linearisation in their canonical form M, C₁, K₀, K₂
//!   ([`bicycle::Canonical`]), the eigenvalues against speed and the weave and capsize
//!   speeds;
//! - [`TippeTop`]: an eccentric sphere gliding with viscous friction, which turns over;
//! - [`Rattleback`]: the rolling ellipsoid of Kane & Levinson (1982), which reverses its
//!   spin;
//! - [`HeavyTop`]: a disk on a stem about a fixed pivot (a symmetric heavy top);
//! - [`FourBar`]: a crank-rocker four-bar linkage, a closed loop, with Freudenstein's
//!   position analysis;
//! - [`SliderCrank`]: a crank, a connecting rod and a slider, a closed loop through a
//!   prismatic joint, with the slider's position in closed form.
//!
//! The examples `bicycle`, `tippe_top`, `rattleback`, `heavy_top`, `four_bar` and
//! `slider_crank` run them. The module is
//! behind the `models` feature (`precess = { version = "..", features = ["models"] }`): the
//! scenes are derived where precess is compiled, and a crate that does not use them should
//! not pay for the bicycle's derive.

pub mod bicycle;
pub mod four_bar;
pub mod heavy_top;
pub mod rattleback;
pub mod slider_crank;
pub mod tippe_top;

pub use bicycle::Bicycle;
pub use four_bar::FourBar;
pub use heavy_top::HeavyTop;
pub use rattleback::Rattleback;
pub use slider_crank::SliderCrank;
pub use tippe_top::TippeTop;
