//! The Whipple bicycle of examples/mechanisms/bicycle.rs built at run time as the derive
//! builds it (the parameters named as the struct's fields): the scene the cross-check test
//! interprets and the derivation bench times (what `#[derive(Mechanism)]` runs while it
//! expands).

use precess::mechanism::rolling::{RollingScene, RollingWheel, WheelSurface};
use precess::mechanism::{JointKind, MechanismScene, Parent};
use precess::sym::Arena;

/// The bicycle's tree (three massless carriers, the rear frame, the rear wheel, the front
/// frame, the front wheel) and its two knife-edge wheels rolling on the floor z = 0, z down.
pub fn mechanism_scene(a: &mut Arena) -> (MechanismScene, RollingScene) {
    let (o, z) = (a.one(), a.zero());
    let mut p = |n: &str| a.parameter(n);
    let [w, c, lambda, g, r_r, m_r, i_rxx, i_ryy] =
        ["w", "c", "lambda", "g", "r_r", "m_r", "i_rxx", "i_ryy"].map(&mut p);
    let [x_b, z_b, m_b, i_bxx, i_byy, i_bzz, i_bxz] =
        ["x_b", "z_b", "m_b", "i_bxx", "i_byy", "i_bzz", "i_bxz"].map(&mut p);
    let [x_h, z_h, m_h, i_hxx, i_hyy, i_hzz, i_hxz] =
        ["x_h", "z_h", "m_h", "i_hxx", "i_hyy", "i_hzz", "i_hxz"].map(&mut p);
    let [r_f, m_f, i_fxx, i_fyy] = ["r_f", "m_f", "i_fxx", "i_fyy"].map(&mut p);
    let (x_axis, y_axis, z_axis) = ([o, z, z], [z, o, z], [z, z, o]);
    let body = MechanismScene::body;
    let mut s = MechanismScene::new();
    let carriers: [(&str, Parent, JointKind, &[&str]); 3] = [
        (
            "rear_x",
            Parent::Ground,
            JointKind::Prismatic { axis: x_axis },
            &["x"],
        ),
        (
            "rear_y",
            Parent::Body(0),
            JointKind::Prismatic { axis: y_axis },
            &["y"],
        ),
        (
            "lean",
            Parent::Body(1),
            JointKind::Universal {
                axes: [z_axis, x_axis],
            },
            &["psi", "phi"],
        ),
    ];
    for (name, parent, joint, q) in carriers {
        s.bodies.push(body(a, name, parent, joint, q));
    }
    let mut b = body(
        a,
        "rear_frame",
        Parent::Body(2),
        JointKind::Revolute { axis: y_axis },
        &["theta"],
    );
    b.joint.at = [z, z, a.neg(r_r)];
    b.mass = m_b;
    b.center = [x_b, z, a.add(z_b, r_r)];
    b.inertia = [[i_bxx, z, i_bxz], [z, i_byy, z], [i_bxz, z, i_bzz]];
    s.bodies.push(b);
    let mut r = body(
        a,
        "rear_wheel",
        Parent::Body(3),
        JointKind::Revolute { axis: y_axis },
        &["theta_r"],
    );
    r.mass = m_r;
    r.inertia = [[i_rxx, z, z], [z, i_ryy, z], [z, z, i_rxx]];
    s.bodies.push(r);
    let steer = [a.sin(lambda), z, a.cos(lambda)];
    let mut h = body(
        a,
        "front_frame",
        Parent::Body(3),
        JointKind::Revolute { axis: steer },
        &["delta"],
    );
    let wc = a.add(w, c);
    h.joint.at = [wc, z, r_r];
    h.mass = m_h;
    h.center = [a.sub(x_h, wc), z, z_h];
    h.inertia = [[i_hxx, z, i_hxz], [z, i_hyy, z], [i_hxz, z, i_hzz]];
    s.bodies.push(h);
    let mut f = body(
        a,
        "front_wheel",
        Parent::Body(5),
        JointKind::Revolute { axis: y_axis },
        &["theta_f"],
    );
    f.joint.at = [a.neg(c), z, a.neg(r_f)];
    f.mass = m_f;
    f.inertia = [[i_fxx, z, z], [z, i_fyy, z], [z, z, i_fxx]];
    s.bodies.push(f);
    s.gravity = Some([z, z, g]);
    let disk = |radius| WheelSurface::Disk {
        center: [z; 3],
        axle: y_axis,
        radius,
    };
    let rolling = RollingScene {
        up: [z, z, a.integer(-1)],
        wheels: vec![
            RollingWheel {
                body: 4,
                surface: disk(r_r),
            },
            RollingWheel {
                body: 6,
                surface: disk(r_f),
            },
        ],
        speeds: vec!["phi".into(), "delta".into(), "theta_r".into()],
    };
    (s, rolling)
}
