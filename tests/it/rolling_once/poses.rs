//! A rolling mechanism's link poses (what `precess::animate::mechanism` draws): the wheel's
//! rotation and hub against the joint's own definition R = Rz(ψ) Ry(θ) Rx(φ) at the slides'
//! (x, y, z), a nalgebra product written from the declaration, not from the derive's code.

use precess::prelude::*;

use super::scenes::{WheelDisk, rotation};

#[test]
fn a_rolling_wheel_s_poses_are_its_slides_and_its_zyx_rotation() {
    let model = WheelDisk;
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = |lo: f64, hi: f64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        lo + (hi - lo) * (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..50 {
        let q: [f64; 6] = [
            uniform(-2.0, 2.0),
            uniform(-2.0, 2.0),
            uniform(0.0, 0.1),
            uniform(-3.0, 3.0),
            uniform(-1.4, 1.4),
            uniform(-3.0, 3.0),
        ];
        let poses = model.link_poses(&q);
        assert_eq!(
            poses.iter().map(|p| p.name).collect::<Vec<_>>(),
            ["slide_x", "slide_y", "slide_z", "disk"]
        );
        let disk = &poses[3];
        let r = rotation(q[3], q[4], q[5]);
        assert!(
            (disk.rotation - r).abs().max() < 1e-14,
            "R at {q:?}: {} against {r}",
            disk.rotation
        );
        for k in 0..3 {
            assert!((disk.origin[k] - q[k]).abs() < 1e-14, "hub {k} at {q:?}");
            // The disk's mass sits at its hub: the centre is the origin.
            assert!((disk.center[k] - q[k]).abs() < 1e-14, "centre {k} at {q:?}");
        }
    }
}
