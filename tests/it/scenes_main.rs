//! The integration tests of the scenes over the engine: the top, the free body, mechanisms,
//! constraints, bodies on a table, and what every scene offers alike. The second test crate
//! over this tree (`main.rs` is the first and says why there are two); it shares `common`
//! with it.

// Each of the two crates uses part of the shared helpers (and re-exports).
#[allow(dead_code, unused_imports)]
mod common;

/// Closed forms for bodies on a table against an independent Newton–Euler formulation.
mod contact_theory {
    mod disk;
    mod scene;
    mod sphere;
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
    mod rolling_jacobian;
    mod rolling_macro;
    mod shared_rows;
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
    mod motor_nan;
    mod reference;
    mod steppers;
    mod thrust;
    mod top;
    mod wrench;
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
    mod loops;
    mod loops_slider;
    mod parameters;
    mod pendulum;
    mod poses;
    mod recursive;
    mod rolling;
    mod timing;
    mod top;
    mod variational_derive;
}
/// The models and generated types shared between threads are `Send + Sync`.
mod send_sync;
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
    mod motor_nan;
    mod theory;
    mod torque_free;
    mod validate;
}
/// The contact scene: a body on a table.
mod contact {
    mod coin;
    mod derived_laws;
    mod errors;
    mod events;
    mod invariants;
    mod laws;
    mod newton_euler;
    mod pivot_held;
    mod properties;
    pub mod reference;
    mod rolling_disk;
    mod routh;
    mod run_loop;
    mod stick_slip;
    mod support;
    mod system_checks;
    mod tippe_laws;
    mod tippe_top;
}
/// The rolling disk declared once on a table and once as a mechanism's wheel: one geometry.
mod rolling_once {
    mod accelerations;
    mod poses;
    mod run;
    pub(crate) mod scenes;
    mod support;
    mod theory;
}
/// What every scene offers alike: parameters checked by every integrator before its first
/// step, the closed-form theory from a derived top, the quantities of a run.
mod scenes {
    mod accessors;
    mod checks;
    mod models_bicycle;
    mod models_state_space;
    mod quantities;
    mod theory;
}
