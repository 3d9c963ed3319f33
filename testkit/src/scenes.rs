//! Scenes built by hand at run time (through the arena, not the derive), so that a test or a
//! bench can compare a derived scene with an independent construction of the same one.

use precess::mechanism::{JointKind, MechanismScene, Parent};
use precess::sym::Arena;

/// The double pendulum built by hand at run time: point masses m0, m1 on massless rods l0,
/// l1 hinged about x, gravity −g ẑ, the second angle relative to the first, parameters by
/// name, an optional damper on the second joint.
pub fn double_pendulum(a: &mut Arena, damper: Option<&str>) -> MechanismScene {
    let (o, z) = (a.one(), a.zero());
    let mut scene = MechanismScene::new();
    for i in 0..2 {
        let parent = if i == 0 {
            Parent::Ground
        } else {
            Parent::Body(0)
        };
        let hinge = JointKind::Revolute { axis: [o, z, z] };
        let name = format!("phi{i}");
        let mut b = MechanismScene::body(a, &format!("bob{i}"), parent, hinge, &[&name]);
        b.mass = a.parameter(&format!("m{i}"));
        let l = a.parameter(&format!("l{i}"));
        b.center = [z, z, a.neg(l)];
        if i == 1 {
            let l0 = a.parameter("l0");
            b.joint.at = [z, z, a.neg(l0)];
            if let Some(d) = damper {
                b.joint.loads[0].damper = Some(a.parameter(d));
            }
        }
        scene.bodies.push(b);
    }
    let g = a.parameter("g");
    scene.gravity = Some([z, z, a.neg(g)]);
    scene
}
