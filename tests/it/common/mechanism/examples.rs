//! The example mechanisms — the very structs the examples derive, included from
//! examples/mechanisms/ — and each one's description for the Newton–Euler reference
//! (`rnea`), shared by the mechanism tests `examples` and `jacobian`. The example files are
//! included by path, not copied, so the tests check the very mechanisms the examples run.

#[path = "../../../../examples/mechanisms/babyboot.rs"]
pub mod babyboot;
#[path = "../../../../examples/mechanisms/bicycle.rs"]
pub mod bicycle;
#[path = "../../../../examples/mechanisms/chain.rs"]
pub mod chain;
#[path = "../../../../examples/mechanisms/double_pendulum.rs"]
pub mod double_pendulum;
#[path = "../../../../examples/mechanisms/free_floating.rs"]
pub mod free_floating;
#[path = "../../../../examples/mechanisms/gimballed_gyroscope.rs"]
pub mod gimballed_gyroscope;

use nalgebra::Matrix3;

use super::rng::Rng;
use super::{NumBody, NumJoint, NumMechanism};
use chain::LINKS;
use double_pendulum::DoublePendulum;
use gimballed_gyroscope::Gyroscope;

/// The gravity every example declares [m/s²].
pub const G: f64 = 9.81;

/// The double pendulum as the reference sees it: point masses, no inertia.
pub fn double_pendulum_reference(p: &DoublePendulum) -> NumMechanism {
    let mut upper = NumBody::new(None, [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    upper.mass = p.m1;
    upper.center = [0.0, 0.0, -p.l1];
    upper.inertia = Matrix3::zeros();
    let mut lower = NumBody::new(
        Some(0),
        [0.0, 0.0, -p.l1],
        NumJoint::Revolute([1.0, 0.0, 0.0]),
    );
    lower.mass = p.m2;
    lower.center = [0.0, 0.0, -p.l2];
    lower.inertia = Matrix3::zeros();
    NumMechanism {
        bodies: vec![upper, lower],
        gravity: [0.0, 0.0, -G],
    }
}

/// The gyroscope: rings of radius r normal to y (m r² about y, ½ m r² across), a thin disk
/// normal to z (½ m r² about z, ¼ m r² across) 0.04 above the centre.
pub fn gyroscope_reference(p: &Gyroscope) -> NumMechanism {
    let ring = |m: f64, r: f64| {
        Matrix3::from_diagonal(&[m * r * r / 2.0, m * r * r, m * r * r / 2.0].into())
    };
    let mut outer = NumBody::new(None, [0.0; 3], NumJoint::Revolute([0.0, 0.0, 1.0]));
    outer.mass = p.m_outer;
    outer.inertia = ring(p.m_outer, 0.08);
    let mut inner = NumBody::new(Some(0), [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    inner.mass = p.m_inner;
    inner.inertia = ring(p.m_inner, 0.07);
    let (m, r) = (0.4, 0.05);
    let mut rotor = NumBody::new(Some(1), [0.0; 3], NumJoint::Revolute([0.0, 0.0, 1.0]));
    rotor.mass = m;
    rotor.center = [0.0, 0.0, 0.04];
    rotor.inertia =
        Matrix3::from_diagonal(&[m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0].into());
    NumMechanism {
        bodies: vec![outer, inner, rotor],
        gravity: [0.0, 0.0, -G],
    }
}

/// The babyboot with Drake's parameters, as the example's struct writes them.
pub fn babyboot_reference() -> NumMechanism {
    let mut rod = NumBody::new(None, [0.0; 3], NumJoint::Revolute([1.0, 0.0, 0.0]));
    rod.mass = 0.01;
    rod.center = [0.0, 0.0, -0.075];
    rod.inertia = Matrix3::from_diagonal(&[5.0e-6, 5.0e-6, 1.0e-7].into());
    let mut plate = NumBody::new(
        Some(0),
        [0.0, 0.0, -0.2],
        NumJoint::Revolute([0.0, 0.0, 1.0]),
    );
    plate.mass = 0.1;
    plate.inertia = Matrix3::from_diagonal(&[2.5e-4, 5.0e-5, 2.0e-4].into());
    NumMechanism {
        bodies: vec![rod, plate],
        gravity: [0.0, 0.0, -G],
    }
}

/// Four thin rods (1 kg, 0.5 m along z: m l²/12 across, none along) on universal joints.
pub fn chain_reference() -> NumMechanism {
    let across = 0.25 / 12.0;
    let bodies = (0..LINKS)
        .map(|k| {
            let (parent, at) = if k == 0 {
                (None, [0.0; 3])
            } else {
                (Some(k - 1), [0.0, 0.0, -0.5])
            };
            let mut rod = NumBody::new(
                parent,
                at,
                NumJoint::Universal([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            );
            rod.mass = 1.0;
            rod.center = [0.0, 0.0, -0.25];
            rod.inertia = Matrix3::from_diagonal(&[across, across, 0.0].into());
            rod
        })
        .collect();
    NumMechanism {
        bodies,
        gravity: [0.0, 0.0, -G],
    }
}

pub fn angles<const N: usize>(rng: &mut Rng) -> [f64; N] {
    std::array::from_fn(|_| rng.uniform(-3.0, 3.0))
}
