//! The integration tests, one crate so that the whole graph links once: a module per area,
//! each file a module of its own, all sharing the helpers in `common` (generators, the
//! Newton–Euler reference, shared scenes, the LaTeX reader).

mod common;

/// Closed forms for bodies on a table against an independent Newton–Euler formulation.
mod contact_theory {
    mod disk;
    mod newton_euler;
    mod scene;
    mod sphere;
}
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
/// Constraints: nonholonomic rolling and closed loops.
mod constraints {
    mod bicycle;
    mod bicycle_macro;
    mod bicycle_macro_cross;
    mod dead_point;
    pub mod disk;
    mod errors;
    mod four_bar;
    mod rheonomic;
    mod rolling_macro;
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
/// The free-body scene.
mod free {
    mod balance;
    mod driven_rules;
    mod errors;
    mod exact;
    mod gyrostat;
    mod gyrostat_driven;
    mod gyrostat_example;
    mod reference;
    mod steppers;
    mod thrust;
    mod top;
    mod wrench;
}
/// The symmetric eigensolver.
mod linalg {
    mod eigen;
}
/// The mechanism scene.
mod mechanism {
    mod charts;
    mod checks;
    mod engine;
    mod errors;
    mod examples;
    mod free_joint;
    mod jacobian;
    mod kane;
    mod parameters;
    mod pendulum;
    mod poses;
    mod recursive;
    mod rolling;
    mod timing;
    mod top;
    mod variational_derive;
}
/// The physics of the `monte_carlo_top` example: a Gaussian cloud's moments against the
/// linearised flow map Φ P₀ Φᵀ.
mod monte_carlo_top;
/// The figures of `precess::plot`: what the SVG holds, the axes' ranges, each error.
mod plot;
/// The models and generated types shared between threads are `Send + Sync`.
mod send_sync;
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
    mod identities;
    mod limits;
    mod properties;
    mod scaling;
}
/// The Taylor integrator.
mod taylor {
    mod coefficients;
    mod config;
    mod defect;
    mod events;
    mod events_guarantee;
    mod exp;
    mod extended;
    mod extended_functions;
    mod extended_generated;
    mod integrator;
    mod powers;
    mod scenes;
    mod step_rule;
    mod time;
}
/// The top scene.
mod top {
    mod check_all;
    mod checks;
    mod cross_check;
    mod gimbal;
    mod gyrostat;
    mod gyrostat_driven;
    mod linear;
    mod motion;
    mod theory;
    mod torque_free;
    mod validate;
}
mod work_precision;
/// The contact scene: a body on a table.
mod contact {
    mod errors;
    mod events;
    mod invariants;
    mod newton_euler;
    mod properties;
    pub mod reference;
    mod rolling_disk;
    mod routh;
    mod run_loop;
    mod stick_slip;
    mod support;
    mod system_checks;
    mod tippe_top;
}
/// The rolling disk declared once on a table and once as a mechanism's wheel: one geometry.
mod rolling_once {
    mod accelerations;
    mod run;
    mod scenes;
    mod support;
    mod theory;
}
/// The guides' Rust blocks are all doctests.
mod guides;
mod variational;
mod variational_derive;
/// Variational equations refusing what would give a made-up answer: a hand-built layout
/// with too many tangents, an unread or repeated sensitivity, an overflowing flow map; and
/// Lyapunov exponents of a tangent vector that shrinks towards atol.
mod variational_refusals;
/// Values as measured: units, density, constant arithmetic, names.
mod values {
    mod constants;
    mod density;
    mod mechanism_units;
    mod names;
    mod units;
}

/// What every scene offers alike: parameters checked by every integrator before its first
/// step, the closed-form theory from a derived top, the quantities of a run.
mod scenes {
    mod accessors;
    mod checks;
    mod quantities;
    mod theory;
}
