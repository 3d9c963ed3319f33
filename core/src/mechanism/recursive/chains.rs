//! The n-link chains the scale benchmark, the tests and the peers' scripts share.
//!
//! - [`pendulum_on_cart`]: PyDy's `n_link_pendulum_on_cart(n)` (planar; a cart of mass m₀
//!   sliding along x under a force F, n particles mᵢ at distances lᵢ along their links, every
//!   link turning about z, gravity −g ŷ), with every constant a parameter as in PyDy. PyDy
//!   measures each angle from the ground; here each joint's angle is relative to its parent
//!   link, the same mechanism in other coordinates.
//! - [`spatial_chain`]: a 3D chain of n uniform rods hanging along −z on revolutes whose axes
//!   alternate x, y, with literal (exact) constants, so the derivation folds them.

use crate::mechanism::{CoordinateLoad, JointKind, MechanismScene, Parent};
use crate::sym::{Arena, ExprId, Rational};

/// PyDy's planar n-link pendulum on a cart (n + 1 coordinates `q0` … `qn`): parameters
/// `m0` … `mn`, `l0` … `l{n−1}`, `g` and the cart force `F`.
///
/// ```
/// use precess_core::mechanism::recursive::chains::pendulum_on_cart;
/// let mut a = precess_core::sym::Arena::new();
/// let scene = pendulum_on_cart(&mut a, 3);
/// assert_eq!(scene.dof(), 4);
/// ```
pub fn pendulum_on_cart(arena: &mut Arena, n: usize) -> MechanismScene {
    let (z, o) = (arena.zero(), arena.one());
    let mut scene = MechanismScene::new();
    let mut cart = MechanismScene::body(
        arena,
        "cart",
        Parent::Ground,
        JointKind::Prismatic { axis: [o, z, z] },
        &["q0"],
    );
    cart.mass = arena.parameter("m0");
    cart.joint.loads = vec![CoordinateLoad {
        effort: Some(arena.parameter("F")),
        ..CoordinateLoad::default()
    }];
    scene.bodies.push(cart);
    let mut previous_length: Option<ExprId> = None;
    for i in 0..n {
        let name = format!("link{}", i + 1);
        let coordinate = format!("q{}", i + 1);
        let mut link = MechanismScene::body(
            arena,
            &name,
            Parent::Body(i),
            JointKind::Revolute { axis: [z, z, o] },
            &[coordinate.as_str()],
        );
        link.mass = arena.parameter(&format!("m{}", i + 1));
        let length = arena.parameter(&format!("l{i}"));
        link.center = [z, length, z];
        if let Some(l) = previous_length {
            link.joint.at = [z, l, z];
        }
        previous_length = Some(length);
        scene.bodies.push(link);
    }
    let g = arena.parameter("g");
    scene.gravity = Some([z, arena.neg(g), z]);
    scene
}

/// A 3D chain of n uniform rods (mass 1/2 kg, length 3/10 m, radius 1/50 m), each hanging
/// along −z from the end of the last on a revolute about x (odd links) or y (even links),
/// gravity 981/100 m/s² along −z. Coordinates `q1` … `qn`.
///
/// ```
/// use precess_core::mechanism::recursive::chains::spatial_chain;
/// let mut a = precess_core::sym::Arena::new();
/// assert_eq!(spatial_chain(&mut a, 5).dof(), 5);
/// ```
pub fn spatial_chain(arena: &mut Arena, n: usize) -> MechanismScene {
    let (z, o) = (arena.zero(), arena.one());
    // Nonzero denominators: `Rational::new` cannot fail here.
    let rational = |arena: &mut Arena, p: i128, q: i128| match Rational::new(p, q) {
        Some(r) => arena.constant(r),
        None => arena.zero(),
    };
    let mass = rational(arena, 1, 2);
    let length = rational(arena, 3, 10);
    let half = rational(arena, -3, 20);
    // A rod about its centre: m l²/12 across, m r²/2 along (r = 1/50).
    let across = rational(arena, 3, 800);
    let along = rational(arena, 1, 10000);
    let down = arena.neg(length);
    let mut scene = MechanismScene::new();
    for i in 0..n {
        let axis = if i % 2 == 0 { [o, z, z] } else { [z, o, z] };
        let coordinate = format!("q{}", i + 1);
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(i - 1)
        };
        let mut rod = MechanismScene::body(
            arena,
            &format!("rod{}", i + 1),
            parent,
            JointKind::Revolute { axis },
            &[coordinate.as_str()],
        );
        rod.mass = mass;
        rod.center = [z, z, half];
        rod.inertia = [[across, z, z], [z, across, z], [z, z, along]];
        if i > 0 {
            rod.joint.at = [z, z, down];
        }
        scene.bodies.push(rod);
    }
    let g = rational(arena, -981, 100);
    scene.gravity = Some([z, z, g]);
    scene
}
