//! The README and every guide in `docs/` but `contact.md`, each the documentation of a
//! hidden item, so that `cargo test --doc` compiles and runs every Rust block in them and no
//! guide's example can go stale. A block that is a fragment has hidden `# ` lines (the scene
//! it runs on, an assertion of what it shows); what is not Rust is fenced as `text`, `sh`,
//! `toml`. `tests/it/guides.rs` checks that every guide is listed here. Only doctest builds
//! see this module.

/// The README.
#[doc = include_str!("../README.md")]
pub struct Readme;

/// docs/animation.md (the `animate` feature, which the tests' build turns on).
#[doc = include_str!("../docs/animation.md")]
#[cfg(feature = "animate")]
pub struct Animation;

/// docs/attributes.md.
#[doc = include_str!("../docs/attributes.md")]
pub struct Attributes;

/// docs/bicycle.md.
#[doc = include_str!("../docs/bicycle.md")]
pub struct Bicycle;

/// docs/linearisation.md.
#[doc = include_str!("../docs/linearisation.md")]
pub struct Linearisation;

/// docs/bodies.md.
#[doc = include_str!("../docs/bodies.md")]
pub struct Bodies;

/// docs/constraints.md.
#[doc = include_str!("../docs/constraints.md")]
pub struct Constraints;

/// docs/contact.md (its tippe top draws a figure: the `plot` feature, which the tests'
/// build turns on).
#[doc = include_str!("../docs/contact.md")]
#[cfg(feature = "plot")]
pub struct Contact;

/// docs/conventions.md.
#[doc = include_str!("../docs/conventions.md")]
pub struct Conventions;

/// docs/ensembles.md.
#[doc = include_str!("../docs/ensembles.md")]
pub struct Ensembles;

/// docs/equations.md.
#[doc = include_str!("../docs/equations.md")]
pub struct Equations;

/// docs/export.md.
#[doc = include_str!("../docs/export.md")]
pub struct Export;

/// docs/exact.md.
#[doc = include_str!("../docs/exact.md")]
pub struct Exact;

/// docs/free-bodies.md.
#[doc = include_str!("../docs/free-bodies.md")]
pub struct FreeBodies;

/// docs/gallery.md.
#[doc = include_str!("../docs/gallery.md")]
pub struct Gallery;

/// docs/hard-cases.md.
#[doc = include_str!("../docs/hard-cases.md")]
pub struct HardCases;

/// docs/integrators.md.
#[doc = include_str!("../docs/integrators.md")]
pub struct Integrators;

/// docs/lanes.md.
#[doc = include_str!("../docs/lanes.md")]
pub struct Lanes;

/// docs/mechanisms.md.
#[doc = include_str!("../docs/mechanisms.md")]
pub struct Mechanisms;

/// docs/performance.md.
#[doc = include_str!("../docs/performance.md")]
pub struct Performance;

/// docs/plots.md (its figures need the `plot` feature, which the tests' build turns on).
#[doc = include_str!("../docs/plots.md")]
#[cfg(feature = "plot")]
pub struct Plots;

/// docs/symbolic.md.
#[doc = include_str!("../docs/symbolic.md")]
pub struct Symbolic;

/// docs/taylor.md.
#[doc = include_str!("../docs/taylor.md")]
pub struct Taylor;

/// docs/taylor-integrator.md.
#[doc = include_str!("../docs/taylor-integrator.md")]
pub struct TaylorIntegrator;

/// docs/theory.md.
#[doc = include_str!("../docs/theory.md")]
pub struct Theory;

/// docs/tops.md.
#[doc = include_str!("../docs/tops.md")]
pub struct Tops;

/// docs/trajectories.md.
#[doc = include_str!("../docs/trajectories.md")]
pub struct Trajectories;

/// docs/variational.md.
#[doc = include_str!("../docs/variational.md")]
pub struct Variational;
