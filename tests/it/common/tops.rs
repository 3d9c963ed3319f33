//! The reference top of the published heavy-top values, shared by the tests that check the
//! derived equations, the closed forms, the linearisation and the charts against them, as
//! the derive generates it and as a scene built at run time and interpreted.

use precess::prelude::*;
use precess_core::sym::Arena;
use precess_core::top::{TopModel, TopScene};

/// I1 = I2 = 1, I3 = ½ about the pivot, M g l = 1 (M = 1, l = 1, g = 1), in ZXZ.
#[derive(RigidBody)]
#[rigid(
    body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 1.0)]
pub struct ReferenceTop;

/// The reference top built at run time in one angle sequence and interpreted.
pub fn reference_model(sequence: AngleSequence) -> TopModel {
    let mut a = Arena::new();
    let (one, half, z) = (a.one(), a.number("0.5").unwrap(), a.zero());
    let mut scene = TopScene::free(&mut a, [[one, z, z], [z, one, z], [z, z, half]]);
    scene.sequence = sequence;
    scene.center = [z, z, one];
    scene.gravity = Some(one);
    let top = scene.derive(&mut a).unwrap();
    TopModel::new(&mut a, &top, &[]).unwrap()
}
