//! The work-precision report: every method over its ladder on every problem it applies to,
//! errors against independent references, median times, tables and log-log figures written
//! into `docs/performance.md` (between its work-precision markers) and `docs/img/perf/`.
//!
//! Used by `examples/work_precision.rs` (the full report) and by the integration test
//! `work_precision` (one cheap rung per problem, written into a temporary directory).

pub mod methods;
pub mod problems;
pub mod report;
pub mod taylor;

use std::sync::atomic::{AtomicBool, Ordering};

static QUICK: AtomicBool = AtomicBool::new(false);

/// Whether the report runs its cheap rungs only (`--quick`).
pub fn quick_mode() -> bool {
    QUICK.load(Ordering::Relaxed)
}

/// Switches `--quick` on or off.
pub fn set_quick(on: bool) {
    QUICK.store(on, Ordering::Relaxed);
}
