//! The four-link chain's struct, shared by the `chain` example and
//! tests/mechanism_examples.rs (each includes this file with `#[path]`), so the test checks
//! the very mechanism the example derives.

use precess::prelude::*;

/// Four rods on universal joints.
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(link1, parent = ground, joint = universal(axes = [x, y]), q = [a1, b1],
       parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
#[body(link2, parent = link1, joint = universal(axes = [x, y], at = [0.0, 0.0, -0.5]),
       q = [a2, b2], parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
#[body(link3, parent = link2, joint = universal(axes = [x, y], at = [0.0, 0.0, -0.5]),
       q = [a3, b3], parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
#[body(link4, parent = link3, joint = universal(axes = [x, y], at = [0.0, 0.0, -0.5]),
       q = [a4, b4], parts(rod(mass = 1.0, length = 0.5, at = [0.0, 0.0, -0.25])))]
pub struct Chain;

/// The number of links.
pub const LINKS: usize = 4;
