//! [`TaylorLanes`]: what the batch stepper asks of a system, the jets of `L` trajectories
//! in one call.

use super::Lanes;
use crate::taylor::TaylorSystem;

/// A [`TaylorSystem`] whose jets can be computed for `L` trajectories at once, lane `l` from
/// `systems[l]` (its own parameters), `t.0[l]` and the lane-`l` entries of `y`.
///
/// Implemented by `taylor_system!` for every `L` (`impl<const L: usize>`), with recurrences
/// straight-line on [`Lanes<L>`]. A lane's coefficients must equal
/// [`TaylorSystem::coefficients_into`] of `systems[l]` on that lane's point bit for bit:
/// [`BatchTaylor`](super::BatchTaylor) promises scalar results on that ground (the emitted
/// code does the scalar operations in the scalar order, lane by lane).
///
/// ```
/// use precess_core::taylor::TaylorSystem;
/// use precess_core::taylor::batch::{Lanes, TaylorLanes};
/// /// y' = −k y: c_k = −k c_{k−1}/k.
/// struct Decay { k: f64 }
/// impl TaylorSystem<1> for Decay {
///     type Workspace = ();
///     fn max_order(&self) -> usize { 30 }
///     fn coefficients_into(&self, _ws: &mut (), _t: f64, y: &[f64; 1], order: usize, c: &mut [[f64; 1]]) {
///         c[0] = *y;
///         for j in 1..=order {
///             c[j][0] = -self.k * c[j - 1][0] / j as f64;
///         }
///     }
/// }
/// impl<const L: usize> TaylorLanes<1, L> for Decay {
///     type LaneWorkspace = ();
///     fn lane_coefficients_into(s: [&Self; L], _ws: &mut (), _t: Lanes<L>, y: &[Lanes<L>; 1], order: usize, c: &mut [[Lanes<L>; 1]]) {
///         let k = Lanes(s.map(|s| s.k));
///         c[0] = *y;
///         for j in 1..=order {
///             c[j][0] = -k * c[j - 1][0] / j as f64;
///         }
///     }
/// }
/// let mut c = [[Lanes::splat(0.0); 1]; 3];
/// let (a, b) = (Decay { k: 1.0 }, Decay { k: 2.0 });
/// Decay::lane_coefficients_into([&a, &b], &mut (), Lanes::splat(0.0), &[Lanes([1.0, 1.0])], 2, &mut c);
/// assert_eq!(c[2][0], Lanes([0.5, 2.0]));
/// ```
pub trait TaylorLanes<const N: usize, const L: usize>: TaylorSystem<N> + Sized {
    /// Scratch storage of one batch computation (`()` when there is none); as
    /// [`TaylorSystem::Workspace`], it carries nothing from one call to the next.
    type LaneWorkspace: Default + Clone + std::fmt::Debug;

    /// Writes the coefficients of orders 0 … `order` of every lane into `coeffs[k]`.
    ///
    /// The caller guarantees `order ≤ max_order()` of every system and
    /// `coeffs.len() > order`.
    fn lane_coefficients_into(
        systems: [&Self; L],
        ws: &mut Self::LaneWorkspace,
        t: Lanes<L>,
        y: &[Lanes<L>; N],
        order: usize,
        coeffs: &mut [[Lanes<L>; N]],
    );
}
