//! The export of a scene's equations as C99 and Python (`codegen::Exported`, `docs/export.md`).

mod closed;
mod derived;
mod inputs;
mod rolling;
mod runtime;
mod support;
mod system;
