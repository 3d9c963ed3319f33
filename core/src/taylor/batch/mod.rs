//! Batch lanes: `L` trajectories of one Taylor system stepped at once, their jets computed in
//! SIMD lanes.
//!
//! # How: plain arrays the compiler vectorises
//! A value of the recurrences is a [`Lanes<L>`], a newtype over `[f64; L]` whose every
//! operation is a loop over the `L` lanes; `taylor_system!` emits the same straight-line
//! recurrences as for one trajectory with `Lanes<L>` in place of `f64`
//! ([`crate::taylor::Tape::to_lane_tokens`]), and LLVM turns the fixed-length loops into
//! packed instructions. Why not a SIMD crate: `std::simd` is nightly; the stable crates
//! (`wide`, `pulp`, `simdeez`) fix a register width or dispatch at run time, and each would
//! be a dependency of every generated scene, while plain arrays are portable to any `L` and
//! any target, need no `unsafe`, and give LLVM the same information (a fixed trip count,
//! no aliasing). The lanes are the innermost index (`[Lanes<L>; N]` per order), so one
//! operation of the recurrence is one packed instruction for `L` = the register's width.
//!
//! # What the target decides
//! The default `x86_64-unknown-linux-gnu` target has SSE2 only: two doubles per register, so
//! `L = 4` is two `mulpd xmm` per operation. AVX2 (4 doubles, `vmulpd ymm`) and AVX-512 (8,
//! `zmm`) need the user to build with `RUSTFLAGS="-C target-cpu=native"` (or
//! `-C target-feature=+avx2,+fma`); precess does not set it (the binary would not run on
//! older processors). No fused multiply-add is used even where the target has one: Rust
//! contracts no `a * b + c`, which is what keeps a lane bitwise equal to a scalar run.
//!
//! # Divergence
//! Each lane has its own step size (from its own coefficients), its own end time and its own
//! event. The batch computes every jet to the highest order an active lane asks; a lane that
//! has finished, failed or met its event is **masked** (its slot refilled with an active
//! lane's point, its values unread), and an event's root is refined **in scalar** on that
//! lane's step polynomial ([`BatchTaylor`]).
//!
//! - [`Lanes`]: the lane type and its arithmetic.
//! - [`kernels`]: the sums of the recurrences in lanes, bitwise the scalar ones per lane.
//! - [`TaylorLanes`]: what a system implements (the generated ones do).
//! - [`BatchTaylor`]: the stepper.

mod integrator;
pub mod kernels;
mod lanes;
mod system;

pub use integrator::{BatchTaylor, LaneEnd};
pub use lanes::Lanes;
pub use system::TaylorLanes;
