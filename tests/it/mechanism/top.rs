//! A single body on a spherical joint is the heavy top: its q̈ reproduces the top scene's
//! (TopScene / TopModel, a separate derivation about the pivot) to 1e-13.

use crate::common::mechanism as mechanism_support;

use mechanism_support::relative_difference;
use mechanism_support::rng::Rng;
use precess::mechanism::{JointKind, MechanismModel, MechanismScene, Parent, Route};
use precess::rigid::AngleSequence;
use precess::sym::mat3::Mat3;
use precess::sym::{Arena, ExprId};
use precess::top::{TopModel, TopScene};

const NAMES: [[&str; 3]; 3] = [["A", "F", "E"], ["F", "B", "D"], ["E", "D", "C"]];

fn inertia_about_pivot(a: &mut Arena) -> Mat3 {
    NAMES.map(|row| row.map(|n| a.parameter(n)))
}

fn torque(a: &mut Arena, prefix: &str) -> [ExprId; 3] {
    [0, 1, 2].map(|k| a.parameter(&format!("{prefix}{k}")))
}

fn top_model(seq: AngleSequence, values: &[(&str, f64)]) -> TopModel {
    let mut a = Arena::new();
    let inertia = inertia_about_pivot(&mut a);
    let mut top = TopScene::free(&mut a, inertia);
    top.sequence = seq;
    top.mass = a.parameter("m");
    top.center = [0, 1, 2].map(|k| a.parameter(&format!("c{k}")));
    top.gravity = Some(a.parameter("g"));
    top.body_torque = Some(torque(&mut a, "tb"));
    top.space_torque = Some(torque(&mut a, "ts"));
    let d = top.derive(&mut a).expect("top derives");
    TopModel::new(&mut a, &d, values).expect("top binds")
}

/// The same body as a mechanism: its inertia about the centre of mass is the pivot's minus
/// the parallel-axis term m (|c|² 𝟙 − c cᵀ), written symbolically in the same parameters.
fn mechanism_model(seq: AngleSequence, route: Route, values: &[(&str, f64)]) -> MechanismModel {
    let mut a = Arena::new();
    let pivot = inertia_about_pivot(&mut a);
    let m = a.parameter("m");
    let c: [ExprId; 3] = [0, 1, 2].map(|k| a.parameter(&format!("c{k}")));
    let squares: Vec<ExprId> = c.iter().map(|&x| a.mul(x, x)).collect();
    let c2 = a.sum(&squares);
    let mut central = pivot;
    for r in 0..3 {
        for k in 0..3 {
            let outer = a.mul(c[r], c[k]);
            let shift = if r == k {
                a.sub(c2, outer)
            } else {
                a.neg(outer)
            };
            let ms = a.mul(m, shift);
            central[r][k] = a.sub(pivot[r][k], ms);
        }
    }
    let names = seq.names();
    let mut body = MechanismScene::body(
        &mut a,
        "top",
        Parent::Ground,
        JointKind::Spherical { sequence: seq },
        &names,
    );
    body.mass = m;
    body.center = c;
    body.inertia = central;
    body.body_torque = Some(torque(&mut a, "tb"));
    body.space_torque = Some(torque(&mut a, "ts"));
    let mut scene = MechanismScene::new();
    scene.bodies.push(body);
    let g = a.parameter("g");
    let z = a.zero();
    scene.gravity = Some([z, z, a.neg(g)]);
    MechanismModel::new(&mut a, &scene, route, values).expect("mechanism derives")
}

#[test]
fn a_spherical_joint_reproduces_the_heavy_top() {
    let values = [
        ("A", 0.9),
        ("B", 0.7),
        ("C", 0.4),
        ("D", 0.03),
        ("E", -0.02),
        ("F", 0.05),
        ("m", 1.7),
        ("c0", 0.05),
        ("c1", -0.03),
        ("c2", 0.3),
        ("g", 9.81),
        ("tb0", 0.1),
        ("tb1", -0.05),
        ("tb2", 0.2),
        ("ts0", 0.0),
        ("ts1", 0.15),
        ("ts2", -0.1),
    ];
    for seq in [AngleSequence::Zxz, AngleSequence::Zyx] {
        let top = top_model(seq, &values);
        for route in [Route::Symbolic, Route::Factored, Route::Recursive] {
            let mech = mechanism_model(seq, route, &values);
            let mut rng = Rng::new(21);
            let mut worst: f64 = 0.0;
            for _ in 0..1000 {
                let middle = match seq {
                    AngleSequence::Zxz => rng.uniform(0.3, 2.8),
                    AngleSequence::Zyx => rng.uniform(-1.2, 1.2),
                };
                let q = [rng.uniform(-3.0, 3.0), middle, rng.uniform(-3.0, 3.0)];
                let qd = [0, 1, 2].map(|_| rng.uniform(-5.0, 5.0));
                let ours = mech.accelerations(0.0, &q, &qd).expect("regular");
                let state = [q[0], q[1], q[2], qd[0], qd[1], qd[2]];
                let theirs = top.accelerations(&state).expect("regular chart");
                worst = worst.max(relative_difference(&ours, &theirs, 1.0));
            }
            assert!(worst <= 1e-13, "{seq:?} {route:?}: {worst:e}");
        }
    }
}
