//! The integration tests of the engine, the bodies and the derive: one of two test crates
//! over this tree (the other, `scenes_main.rs`, holds the scenes: the top, the free body,
//! mechanisms, constraints, contact). A module per area, each file a module of its own, both
//! crates sharing the helpers in `common` (generators, the Newton–Euler reference, shared
//! scenes, the LaTeX reader). Two crates, not one, because rustc's front end (the derives'
//! expansion, type checking) runs on one thread: the two compile side by side, and each area
//! sits in the crate that keeps their build times close.

// Each of the two crates uses part of the shared helpers (the mechanism references are the
// other crate's, the body sums this one's).
#[allow(dead_code, unused_imports)]
mod common;

/// Mass properties, shapes and their validation.
mod body {
    mod euler;
    mod magnitudes;
    mod near_rotation;
    mod parallel;
    mod principal;
    mod properties;
    mod rotated;
    mod rotation_forms;
    mod shapes;
    mod validate;
}
/// The derive macro end to end.
/// The export of a scene's equations as C99 and Python.
mod codegen_export;
mod derive {
    mod contact;
    mod equations;
    mod fields;
    mod hygiene;
    mod literal;
    mod mechanism;
    mod parametric;
    mod rotated;
    mod signs;
    mod taylor;
    mod top;
}
/// The physics of the `chaos_map` example: Lyapunov exponents of integrable and chaotic
/// tops, against ln T / T, a closed form and two nearby trajectories.
mod chaos_map;
/// Ensembles: determinism over threads, per-run errors, a sweep against the closed form.
mod ensemble;
/// An ensemble's edges: the last indices of usize, a panicking progress callback.
mod ensemble_edges;
/// Sharding: the sleeping-top sweep whole and as shards merged from CSV, to the bit.
mod ensemble_shards;
/// Batch lanes: L Taylor trajectories stepped at once.
mod lanes;
/// Closed-form solutions.
mod exact {
    mod attitude;
    mod elliptic;
    mod extremes;
    mod free_body;
    mod tiny_inertia;
}
/// The symmetric eigensolver.
mod linalg {
    mod crossing;
    mod eigen;
    mod state_space;
}
/// The physics of the `monte_carlo_top` example: a Gaussian cloud's moments against the
/// linearised flow map Φ P₀ Φᵀ.
mod monte_carlo_top;
/// The figures of `precess::plot`: what the SVG holds, the axes' ranges, each error.
mod plot;
/// The integrators, events and sampling.
mod ode {
    mod attitude;
    mod compensated;
    mod event_roots;
    mod events;
    mod methods;
    mod reference;
    mod sampling;
    mod splitting;
    mod trajectory;
}
/// Rigid-body Taylor kernels.
mod rigid {
    mod taylor;
}
/// The symbolic engine.
mod sym {
    mod extract;
    mod identities;
    mod limits;
    mod properties;
    mod scaling;
}
/// The Taylor integrator.
mod taylor {
    mod coefficients;
    mod compiled_events;
    mod config;
    mod defect;
    mod events;
    mod events_guarantee;
    mod exp;
    mod extended;
    mod extended_functions;
    mod extended_generated;
    mod integrator;
    /// The minimum-work order against Jorba and Zou's, on closed forms and invariants.
    mod order_rule;
    mod powers;
    mod scenes;
    mod step_rule;
    mod time;
}
/// The guides' Rust blocks are all doctests.
mod guides;
mod variational;
mod variational_derive;
/// Variational equations refusing what would give a made-up answer: a hand-built layout
/// with too many tangents, an unread or repeated sensitivity, an overflowing flow map; and
/// Lyapunov exponents of a tangent vector that shrinks towards atol.
mod variational_refusals;
mod work_precision;
/// Values as measured: units, density, constant arithmetic, names.
mod values {
    mod constants;
    mod density;
    mod mechanism_units;
    mod names;
    mod units;
}
