//! Derivation times and operation counts per route for n-link chains, printed (not asserted:
//! speed belongs in benches). Run with `cargo test --test mechanism_timing -- --ignored
//! --nocapture`.

use std::time::Instant;

use precess::codegen::Program;
use precess::mechanism::{JointKind, MechanismScene, Parent, Route};
use precess::sym::{Arena, ExprId};

/// An n-link chain of uniform rods with parameter masses and lengths; `spatial` alternates
/// the hinge axes between x and y, otherwise every hinge is about x (a planar chain).
pub fn chain(arena: &mut Arena, n: usize, spatial: bool) -> MechanismScene {
    let (o, z) = (arena.one(), arena.zero());
    let mut scene = MechanismScene::new();
    for i in 0..n {
        let axis = if spatial && i % 2 == 1 {
            [z, o, z]
        } else {
            [o, z, z]
        };
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(i - 1)
        };
        let name = format!("q{i}");
        let mut b = MechanismScene::body(
            arena,
            &format!("link{i}"),
            parent,
            JointKind::Revolute { axis },
            &[&name],
        );
        let m = arena.parameter(&format!("m{i}"));
        let l = arena.parameter(&format!("l{i}"));
        let half = arena.number("-0.5").unwrap_or(z);
        b.mass = m;
        b.center = [z, z, arena.mul(half, l)];
        let ml2 = arena.product(&[m, l, l]);
        let twelfth = arena
            .number("0.0833333333333333333333333333333333")
            .unwrap_or(z);
        let i_rod = arena.mul(twelfth, ml2);
        b.inertia = [[i_rod, z, z], [z, i_rod, z], [z, z, z]];
        if i > 0 {
            let prev = arena.parameter(&format!("l{}", i - 1));
            b.joint.at = [z, z, arena.neg(prev)];
        }
        scene.bodies.push(b);
    }
    let g = arena.parameter("g");
    scene.gravity = Some([z, z, arena.neg(g)]);
    scene
}

fn ops(arena: &Arena, outputs: &[ExprId]) -> usize {
    Program::lower(arena, outputs).op_count().total()
}

#[test]
#[ignore = "prints timings"]
fn derivation_stages() {
    for spatial in [false, true] {
        for n in [4, 5] {
            let mut a = Arena::new();
            let scene = chain(&mut a, n, spatial);
            let start = Instant::now();
            let order = scene.validate(&a).expect("valid");
            let names = scene.coordinate_names();
            let c = precess::lagrange::Coordinates::new(&mut a, &names);
            let _ = scene.kinematics(&mut a, &order, &c).expect("kinematics");
            let kin = start.elapsed();
            let mut a = Arena::new();
            let scene = chain(&mut a, n, spatial);
            let start = Instant::now();
            let _ = scene.mass_matrix(&mut a).expect("mass matrix");
            let mm = start.elapsed();
            println!(
                "spatial={spatial} n={n}: kinematics {:.1} ms, M and f {:.1} ms",
                kin.as_secs_f64() * 1e3,
                mm.as_secs_f64() * 1e3
            );
        }
    }
}

#[test]
#[ignore = "prints timings"]
fn derivation_times_per_route() {
    for spatial in [false, true] {
        for n in 1..=5 {
            for route in [Route::Symbolic, Route::Factored, Route::Auto] {
                if route == Route::Symbolic && n > 3 {
                    continue;
                }
                let mut a = Arena::new();
                let scene = chain(&mut a, n, spatial);
                let start = Instant::now();
                let d = scene.derive(&mut a, route);
                let elapsed = start.elapsed();
                match d {
                    Ok(d) => {
                        let outputs: Vec<ExprId> =
                            d.accelerations.iter().chain(&d.pivots).copied().collect();
                        println!(
                            "{} n={n} {:?}->{:?}: {:.3} ms, {} ops",
                            if spatial { "spatial" } else { "planar" },
                            route,
                            d.route,
                            elapsed.as_secs_f64() * 1e3,
                            ops(&a, &outputs)
                        );
                    }
                    Err(e) => println!("n={n} {route:?}: {e}"),
                }
            }
        }
    }
}

use crate::common::mechanism as mechanism_support;

/// A universal joint and a tilted revolute, every mass property a parameter: the case where
/// the symbolic route's expanded adjugate is slowest.
#[test]
#[ignore = "prints timings"]
fn parametric_spatial_chain_per_route() {
    use mechanism_support::{NumBody, NumJoint, NumMechanism, Values, scene};
    let mut root = NumBody::new(
        None,
        [0.0; 3],
        NumJoint::Universal([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    );
    root.center = [0.0, 0.1, -0.5];
    let mut tip = NumBody::new(
        Some(0),
        [0.0, 0.0, -1.0],
        NumJoint::Revolute([0.0, 0.6, 0.8]),
    );
    tip.center = [0.2, 0.0, -0.3];
    let m = NumMechanism {
        bodies: vec![root, tip],
        gravity: [0.0, 0.0, -9.81],
    };
    for values in [Values::Literals, Values::Parameters] {
        for route in [Route::Factored, Route::Symbolic] {
            let mut a = Arena::new();
            let (s, _) = scene(&mut a, &m, values);
            let start = Instant::now();
            let d = s.derive(&mut a, route).expect("derives");
            let outputs: Vec<ExprId> = d.accelerations.iter().chain(&d.pivots).copied().collect();
            println!(
                "{values:?} {route:?}: {:.1} ms, {} ops",
                start.elapsed().as_secs_f64() * 1e3,
                ops(&a, &outputs)
            );
        }
    }
}
