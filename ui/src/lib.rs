//! Compile-fail cases of `#[derive(RigidBody)]`, one per error, under `tests/ui`; the test
//! `tests/ui.rs` checks each case's spanned message against its `.stderr` file. This
//! library is empty: Cargo wants a target besides the tests.
#![forbid(unsafe_code)]
