//! Batch lanes: `L` trajectories of one Taylor system stepped at once, their jets computed in
//! SIMD lanes.
//!
//! # How: plain arrays the compiler vectorises, compiled per instruction set
//! A value of the recurrences is a [`Lanes<L>`], a newtype over `[f64; L]` whose every
//! operation is a loop over the `L` lanes; `taylor_system!` emits the same straight-line
//! recurrences as for one trajectory with `Lanes<L>` in place of `f64`
//! ([`crate::taylor::Tape::to_lane_tokens`]), and LLVM turns the fixed-length loops into
//! packed instructions. The lanes are the innermost index (`[Lanes<L>; N]` per order), so one
//! operation of the recurrence is one packed instruction for `L` = the register's width. The
//! step control of the ordinary step (the radius, the step size, the sum with its slope) is
//! the same kind of loop over the lanes, on the batch's jet as it lies.
//!
//! # The width, chosen at run time
//! [`BatchTaylor::advance_until`] runs its whole loop inside `pulp::Arch::dispatch`: the
//! loop, the jets and the lanes' step control are `#[inline(always)]` down to the lanes'
//! arithmetic, so they are compiled into each of pulp's `#[target_feature]` functions —
//! AVX-512 (8 doubles a register), AVX2 (4) and the target's baseline (SSE2 on x86-64, 2) —
//! and the one the processor has is called. A default build thus uses the wide registers
//! with no `RUSTFLAGS`, and the `unsafe` of calling a `#[target_feature]` function stays in
//! pulp (precess's crates forbid it). Why pulp: it is maintained (faer's SIMD layer), its
//! `dispatch` takes any operation whose `with_simd` is inlined, and nothing of it reaches the
//! generated code, which stays plain arrays; `std::simd` is nightly, and `multiversion`
//! emits its `unsafe` into the calling crate. No instruction set changes a lane's bits: Rust
//! contracts no `a * b + c` into a fused multiply-add even where the set has FMA, and the
//! logarithms and exponentials of the step control are the library's calls, as in a scalar
//! run.
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

mod events;
mod integrator;
pub mod kernels;
mod lanes;
#[cfg(test)]
mod resume_tests;
mod system;

pub use integrator::{BatchTaylor, LaneEnd};
pub use lanes::Lanes;
pub use system::TaylorLanes;
