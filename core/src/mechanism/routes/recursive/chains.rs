//! The n-link chains the scale benchmark, the tests and the peers' scripts share.
//!
//! - [`pendulum_on_cart`]: PyDy's `n_link_pendulum_on_cart(n)` (planar; a cart of mass m₀
//!   sliding along x under a force F, n particles mᵢ at distances lᵢ along their links, every
//!   link turning about z, gravity −g ŷ), with every constant a parameter as in PyDy. PyDy
//!   measures each angle from the ground; here each joint's angle is relative to its parent
//!   link, the same mechanism in other coordinates.
//! - [`spatial_chain`]: a 3D chain of n uniform rods hanging along −z on revolutes whose axes
//!   alternate x, y, with literal (exact) constants, so the derivation folds them.

use quote::quote;

use super::derive_recursive;
use crate::codegen::Program;
use crate::lagrange::Coordinates;
use crate::mechanism::{CoordinateLoad, JointKind, MechanismError, MechanismScene, Parent};
use crate::sym::{Arena, ExprId, Rational, SymbolId};

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

/// The two chains of the scale benchmark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChainKind {
    /// [`pendulum_on_cart`] (n links, n + 1 coordinates).
    Planar,
    /// [`spatial_chain`] (n links, n coordinates).
    Spatial,
}

impl ChainKind {
    /// `"planar"` or `"spatial"`.
    pub fn name(self) -> &'static str {
        match self {
            ChainKind::Planar => "planar",
            ChainKind::Spatial => "spatial",
        }
    }

    /// The chain of n links.
    pub fn scene(self, arena: &mut Arena, n: usize) -> MechanismScene {
        match self {
            ChainKind::Planar => pendulum_on_cart(arena, n),
            ChainKind::Spatial => spatial_chain(arena, n),
        }
    }
}

/// The chain's q̈ by the recursive route, lowered: the program, its coordinates and its
/// parameters (the program's other inputs) in the order the generated code reads them.
///
/// # Errors
/// As [`crate::mechanism::recursive_accelerations`] (never, for these chains).
pub fn lowered_chain(
    kind: ChainKind,
    n: usize,
) -> Result<(Arena, Program, Coordinates, Vec<SymbolId>), MechanismError> {
    let mut arena = Arena::new();
    let scene = kind.scene(&mut arena, n);
    let (coords, form) = derive_recursive(&mut arena, &scene)?;
    let program = Program::lower(&arena, &form.accelerations);
    let state: Vec<SymbolId> = coords
        .q
        .iter()
        .chain(&coords.rates)
        .filter_map(|&e| arena.as_symbol(e))
        .collect();
    let parameters = program
        .inputs()
        .into_iter()
        .filter(|s| !state.contains(s))
        .collect();
    Ok((arena, program, coords, parameters))
}

/// Rust source of `accelerations(q, q̇, p) -> q̈` for the chain, as the derive would emit it,
/// with `PARAMETERS` naming the entries of `p`: what `benches/generated/` holds.
///
/// # Errors
/// As [`lowered_chain`].
pub fn generated_source(kind: ChainKind, n: usize) -> Result<String, MechanismError> {
    let (arena, program, coords, parameters) = lowered_chain(kind, n)?;
    let dof = coords.q.len();
    let position =
        |list: &[ExprId], s: SymbolId| list.iter().position(|&e| arena.as_symbol(e) == Some(s));
    let emitted = program.to_tokens(&mut |s| {
        if let Some(i) = position(&coords.q, s) {
            quote!(q[#i])
        } else if let Some(i) = position(&coords.rates, s) {
            quote!(qd[#i])
        } else {
            let k = parameters
                .iter()
                .position(|&p| p == s)
                .unwrap_or(usize::MAX);
            quote!(p[#k])
        }
    });
    let names: Vec<String> = parameters
        .iter()
        .map(|&s| format!("{:?}", arena.symbol(s).name))
        .collect();
    let lets = emitted.lets.to_string().replace("; ", ";\n    ");
    let outputs: Vec<String> = emitted.outputs.iter().map(|o| o.to_string()).collect();
    let ops = program.op_count();
    Ok(format!(
        "// @generated by precess_core::mechanism::recursive::chains::generated_source({kind:?}, {n}).\n\
         // Do not edit: the test `generated_chains_are_current` regenerates and compares.\n\
         // {ops}\n\n\
         /// The parameters `p` holds, in order.\n\
         pub const PARAMETERS: [&str; {np}] = [{names}];\n\n\
         /// q̈ of the {name} chain of {n} links at (q, q̇) with parameters `p`.\n\
         pub fn accelerations(q: &[f64; {dof}], qd: &[f64; {dof}], p: &[f64; {np}]) -> [f64; {dof}] {{\n    \
         let _ = (q, qd, p);\n    \
         {lets}\n    \
         [{outs}]\n}}\n",
        np = parameters.len(),
        names = names.join(", "),
        name = kind.name(),
        outs = outputs.join(", "),
    ))
}
