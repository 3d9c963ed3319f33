//! What rolls: wheels of a mechanism on the floor, the plane through the ground origin
//! normal to `up`. A wheel's surface is one of the shared [`Surface`]s (a disk rim, a
//! sphere) with the direction its axis takes in the body: the geometry of a body on a table.

use crate::rigid::Surface;
use crate::sym::ExprId;

/// The surface of a body that touches the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WheelSurface {
    /// A knife-edge wheel: the rim of a disk of `radius` about `center` (the hub, in the
    /// body's frame) in the plane normal to `axle` (body frame, need not be a unit vector).
    /// It is the shared [`Surface::DiskRim`] turned so that its axis lies along the axle
    /// ([`WheelSurface::surface`]): the contact is the rim's lowest point, the support point
    /// for the outward normal −up, hub + r d/|d| with d = −up + (up·n) n for the axle's unit
    /// vector n; it is defined while the wheel is not lying flat (|d| above
    /// [`crate::rigid::MIN_TILT`]).
    Disk {
        /// The hub, in the body's frame.
        center: [ExprId; 3],
        /// The axle, in the body's frame.
        axle: [ExprId; 3],
        /// The rim's radius r > 0.
        radius: ExprId,
    },
    /// A ball of `radius` about `center` (body frame), the shared [`Surface::Sphere`]: the
    /// contact is center − r up.
    Sphere {
        /// The ball's centre, in the body's frame.
        center: [ExprId; 3],
        /// Its radius r > 0.
        radius: ExprId,
    },
}

impl WheelSurface {
    /// The same geometry in the vocabulary every rolling scene shares: the surface (its
    /// centre the hub, body frame) and, for a disk, the direction of its axis in the body (the
    /// axle, not necessarily a unit vector); a sphere has none.
    ///
    /// ```
    /// use precess_core::mechanism::rolling::WheelSurface;
    /// use precess_core::rigid::Surface;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (z, o, r) = (a.zero(), a.one(), a.parameter("r"));
    /// let wheel = WheelSurface::Disk { center: [z; 3], axle: [z, o, z], radius: r };
    /// let shared = Surface::DiskRim { center: [z; 3], radius: r };
    /// assert_eq!(wheel.surface(), (shared, Some([z, o, z])));
    /// ```
    pub fn surface(&self) -> (Surface, Option<[ExprId; 3]>) {
        match *self {
            WheelSurface::Disk {
                center,
                axle,
                radius,
            } => (Surface::DiskRim { center, radius }, Some(axle)),
            WheelSurface::Sphere { center, radius } => (Surface::Sphere { center, radius }, None),
        }
    }
}

/// One body rolling without slip on the floor: its contact point's material velocity is
/// zero (two nonholonomic rows), and its contact point is on the floor (a holonomic row,
/// unless the mechanism's joints already hold it there).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollingWheel {
    /// The body, by its index in [`super::super::MechanismScene::bodies`].
    pub body: usize,
    /// Its surface.
    pub surface: WheelSurface,
}

/// The wheels that roll, the floor they roll on and the speeds left free.
#[derive(Clone, Debug, PartialEq)]
pub struct RollingScene {
    /// The floor's upward normal: a signed ground axis (±x, ±y or ±z as a constant
    /// vector). The floor is the plane through the ground origin normal to it.
    pub up: [ExprId; 3],
    /// The rolling bodies.
    pub wheels: Vec<RollingWheel>,
    /// The coordinates whose rates are the free speeds u (the state holds q, then u); the
    /// others' rates follow from the constraints. There must be as many as coordinates
    /// less constraint rows.
    pub speeds: Vec<String>,
}
