//! The support maps as the model evaluates them: the contact point lies on the surface, the
//! surface's outward normal there is −γ, the point is on the table (z = 0), and along rolling
//! runs of every surface the contact point stays at rest and the energy holds.

use nalgebra::{UnitQuaternion, Vector3};
use precess::contact::{ContactDynamics, ContactError, ContactRun, Phase};
use precess::ode::AdaptiveConfig;
use proptest::prelude::*;

use super::reference::{
    NumBody, NumSurface, ROLLING, chaplygin_ball, model, offset_sphere, rattleback, thin_disk,
};

fn torus() -> NumBody {
    NumBody {
        mass: 0.5,
        center: [0.0, 0.0, 0.002],
        inertia: [[1e-3, 0.0, 0.0], [0.0, 1.1e-3, 1e-5], [0.0, 1e-5, 1.9e-3]],
        surface: NumSurface::Torus {
            c: [0.0; 3],
            big: 0.06,
            tube: 0.01,
        },
        gravity: 9.81,
    }
}

fn bowl() -> NumBody {
    NumBody {
        mass: 0.3,
        center: [0.001, 0.0, 0.05],
        inertia: [[4e-4, 0.0, 0.0], [0.0, 5e-4, 0.0], [0.0, 0.0, 3e-4]],
        surface: NumSurface::Paraboloid {
            v: [0.0; 3],
            big: 0.2,
        },
        gravity: 9.81,
    }
}

fn bodies() -> [NumBody; 6] {
    [
        rattleback(),
        chaplygin_ball(),
        offset_sphere(),
        thin_disk(),
        torus(),
        bowl(),
    ]
}

/// The surface's implicit value at p (zero on it) and its outward gradient, by hand.
fn implicit(surface: &NumSurface, p: &Vector3<f64>) -> (f64, Vector3<f64>) {
    match *surface {
        NumSurface::Sphere { c, rho } => {
            let d = p - Vector3::from(c);
            (d.norm() / rho - 1.0, d)
        }
        NumSurface::Ellipsoid { c, axes } => {
            let d = p - Vector3::from(c);
            let a = Vector3::from(axes);
            let s = d.component_div(&a);
            (s.norm_squared() - 1.0, s.component_div(&a))
        }
        NumSurface::DiskRim { c, rho } => {
            // On the rim: in the disk's plane at distance ρ; the "normal" is radial.
            let d = p - Vector3::from(c);
            (
                (d.x.hypot(d.y) / rho - 1.0).abs() + d.z.abs() / rho,
                Vector3::new(d.x, d.y, 0.0),
            )
        }
        NumSurface::Torus { c, big, tube } => {
            let d = p - Vector3::from(c);
            let radial = d.x.hypot(d.y);
            let centre_line = Vector3::new(d.x, d.y, 0.0) * (big / radial);
            let off = d - centre_line;
            (off.norm() / tube - 1.0, off)
        }
        NumSurface::Paraboloid { v, big } => {
            let d = p - Vector3::from(v);
            (
                ((d.x * d.x + d.y * d.y) / (2.0 * big) - d.z) / big,
                Vector3::new(d.x / big, d.y / big, -1.0),
            )
        }
    }
}

fn tilted(body: &NumBody, yaw: f64, tilt: f64, axis: f64) -> UnitQuaternion<f64> {
    let tilt = match body.surface {
        NumSurface::DiskRim { .. } | NumSurface::Torus { .. } => std::f64::consts::FRAC_PI_2 - tilt,
        NumSurface::Paraboloid { .. } => tilt.min(0.6),
        _ => tilt,
    };
    let axis = nalgebra::Unit::new_normalize(Vector3::new(axis.cos(), axis.sin(), 0.0));
    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), yaw)
        * UnitQuaternion::from_axis_angle(&axis, tilt)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The contact point is on the surface with outward normal −γ, and on the table.
    #[test]
    fn the_contact_point_is_the_support_point(
        which in 0usize..6, yaw in -3.0f64..3.0, tilt in 0.05f64..1.2, axis in -3.0f64..3.0,
    ) {
        let body = bodies()[which];
        let m = model(&body, ROLLING);
        let y = m.rolling_state([0.2, 0.1], &tilted(&body, yaw, tilt, axis), &Vector3::zeros()).unwrap();
        let c = m.contact(&y);
        let p = c.body + Vector3::from(body.center);
        let (value, normal) = implicit(&body.surface, &p);
        prop_assert!(value.abs() < 1e-13, "off the surface by {value:e}");
        // A sharp rim's normals fill a cone: −γ projected on the disk's plane is radial.
        let n = match body.surface {
            NumSurface::DiskRim { .. } => Vector3::new(-c.gamma.x, -c.gamma.y, 0.0),
            _ => -c.gamma,
        };
        let along = normal.normalize().dot(&n.normalize());
        prop_assert!((along - 1.0).abs() < 1e-13, "normal off −γ: cos = {along}");
        prop_assert!(c.space.z.abs() < 1e-15, "contact point at z = {:e}", c.space.z);
        prop_assert!((c.height + c.body.dot(&c.gamma)).abs() < 1e-16);
    }

    /// Along a rolling run of any surface the contact point stays at rest to rounding (the
    /// integrated (vx, vy) follow −R(ω × r)) and the energy holds.
    #[test]
    fn the_contact_point_stays_at_rest_while_rolling(
        which in 0usize..6, yaw in -3.0f64..3.0, tilt in 0.05f64..0.6, axis in -3.0f64..3.0,
        w in prop::array::uniform3(-5.0f64..5.0),
    ) {
        let body = bodies()[which];
        let m = model(&body, ROLLING);
        let y0 = m.rolling_state([0.0, 0.0], &tilted(&body, yaw, tilt, axis), &Vector3::from(w)).unwrap();
        let cfg = AdaptiveConfig::with_tol(1e-12, 1e-14);
        // A start that would need the table to pull (N < 0) is refused, not run.
        let run = ContactRun::new(&m, Phase::Rolling, 0.0, y0, cfg);
        if let Err(ContactError::NotPressed { normal, .. }) = run {
            prop_assert!(normal < 0.0);
            return Ok(());
        }
        let mut run = run.unwrap();
        let e0 = m.energy(Phase::Rolling, &y0);
        for k in 1..=10 {
            if run.advance_to(0.05 * k as f64).is_err() {
                break;
            }
            let y = *run.y();
            let c = m.contact(&y);
            let w = Vector3::new(y[8], y[9], y[10]);
            let scale = w.norm() * c.body.norm() + 1e-3;
            prop_assert!(c.velocity.norm() < 1e-10 * scale, "slip {:e} at scale {scale}", c.velocity.norm());
            // Rolling without resistance does no work: the energy holds on every surface.
            let e = m.energy(Phase::Rolling, &y);
            prop_assert!(((e - e0) / e0).abs() < 1e-10, "energy {e0} → {e}");
        }
    }
}
