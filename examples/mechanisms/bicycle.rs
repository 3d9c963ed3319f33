//! The Whipple bicycle derived by `#[derive(Mechanism)]`: the library's ready model
//! ([`precess::models::Bicycle`], the benchmark of Meijaard, Papadopoulos, Ruina & Schwab,
//! Proc. R. Soc. A 463, 2007), named here so that the `bicycle` example and
//! tests/it/constraints (each includes this file with `#[path]`) run the very mechanism a
//! user depends on.

// The test crate that includes every example mechanism does not use this one.
#[allow(unused_imports)]
pub use precess::models::Bicycle;
