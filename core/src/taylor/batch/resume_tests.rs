//! A lane's integrator before and after its batch: stepped in scalar first, then in the
//! batch, then its clone in scalar again, it ends on the bits of a run stepped in scalar
//! throughout, with the same counts of steps, jets and evaluations.

use super::{BatchTaylor, Lanes, TaylorLanes};
use crate::taylor::{Taylor, TaylorConfig, TaylorSystem};

/// y″ = −k y as y₁′ = y₂, y₂′ = −k y₁: c_{j+1} = (y₂, −k y₁)_j / (j + 1).
#[derive(Debug, Clone, Copy)]
struct Spring {
    k: f64,
}

impl TaylorSystem<2> for Spring {
    type Workspace = ();
    fn max_order(&self) -> usize {
        30
    }
    fn coefficients_into(
        &self,
        _: &mut (),
        _: f64,
        y: &[f64; 2],
        order: usize,
        c: &mut [[f64; 2]],
    ) {
        c[0] = *y;
        for j in 0..order {
            let d = (j + 1) as f64;
            c[j + 1] = [c[j][1] / d, -self.k * c[j][0] / d];
        }
    }
}

impl<const L: usize> TaylorLanes<2, L> for Spring {
    type LaneWorkspace = ();
    fn lane_coefficients_into(
        s: [&Self; L],
        _: &mut (),
        _: Lanes<L>,
        y: &[Lanes<L>; 2],
        order: usize,
        c: &mut [[Lanes<L>; 2]],
    ) {
        let k = Lanes(s.map(|s| s.k));
        c[0] = *y;
        for j in 0..order {
            let d = (j + 1) as f64;
            c[j + 1] = [c[j][1] / d, -k * c[j][0] / d];
        }
    }
}

fn start(k: f64) -> Taylor<Spring, 2> {
    let cfg = TaylorConfig::with_tol(1e-12, 1e-12);
    Taylor::new(Spring { k }, 0.0, [1.0, 0.0], cfg).expect("a finite start")
}

#[test]
fn a_lane_between_scalar_steps_ends_on_its_scalar_runs_bits_and_counts() {
    // Alone: one step towards 10, then on to 3 and to 6.
    let mut alone = start(1.0);
    alone.step(10.0).unwrap();
    alone.advance_to(3.0).unwrap();
    let (at_3, stats_3) = (*alone.y(), alone.stats());
    alone.advance_to(6.0).unwrap();
    // The same run with its middle in a batch beside another spring. The scalar step keeps
    // the jet at its end for the next step; the batch must not leave that jet behind once
    // the lane has moved on, or the clone's next scalar step starts from it.
    let mut first = start(1.0);
    first.step(10.0).unwrap();
    let mut batch = BatchTaylor::from_integrators([Ok(first), Ok(start(2.0))]);
    let end = batch.advance_to([3.0, 3.0])[0].clone().unwrap();
    assert_eq!(end.y.map(f64::to_bits), at_3.map(f64::to_bits));
    let mut lane = batch.lane(0).unwrap().unwrap().clone();
    assert_eq!(lane.stats(), stats_3);
    lane.advance_to(6.0).unwrap();
    assert_eq!(lane.y().map(f64::to_bits), alone.y().map(f64::to_bits));
    assert_eq!((lane.jets(), lane.stats()), (alone.jets(), alone.stats()));
}
