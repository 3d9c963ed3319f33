//! The shared support map turned onto an axis (`Surface::support_along`, what a mechanism's
//! wheel uses) against the table's hand-written map in the surface's own axes: a surface
//! turned by R about its placement has s(n) = c + R (s₀(Rᵀ n) − c), whatever R takes ẑ to
//! the axis, for random axes, normals and sizes; and the ellipsoid, which has no single axis,
//! is refused by type.

use precess::nalgebra::{Rotation3, Unit, Vector3};
use precess::rigid::{Rim, Surface, SurfaceError};
use precess::sym::{Arena, ExprId};
use precess_testkit::rng::Rng;

use crate::contact::reference::{NumSurface, support};

/// The symbolic surface of a case from its placement, radius and tube.
type Build = fn([ExprId; 3], ExprId, ExprId) -> Surface;

/// Symbols for a vector, their values pushed on `env` (indexed by symbol).
fn symbols(a: &mut Arena, env: &mut Vec<f64>, name: &str, v: &Vector3<f64>) -> [ExprId; 3] {
    std::array::from_fn(|k| symbol(a, env, &format!("{name}{k}"), v[k]))
}

/// A symbol and its value.
fn symbol(a: &mut Arena, env: &mut Vec<f64>, name: &str, v: f64) -> ExprId {
    let e = a.parameter(name);
    let index = a.as_symbol(e).expect("a symbol").index();
    if env.len() <= index {
        env.resize(index + 1, f64::NAN);
    }
    env[index] = v;
    e
}

#[test]
fn the_support_map_turned_onto_an_axis_is_the_map_turned() {
    let mut rng = Rng::new(360);
    let mut worst = 0.0_f64;
    for case in 0..40 {
        let axis = rng.vector(-1.0, 1.0).normalize();
        // R takes ẑ to the axis, then turns about it by a random angle (which the maps of
        // these axisymmetric surfaces must not see).
        let r = Rotation3::rotation_between(&Vector3::z(), &axis).expect("not opposite")
            * Rotation3::from_axis_angle(&Vector3::z_axis(), rng.uniform(-3.0, 3.0));
        let c = rng.vector(-0.1, 0.1);
        let (rho, tube) = (rng.uniform(0.05, 0.2), rng.uniform(0.001, 0.04));
        // A normal the paraboloid can place (n·a < 0); any other for the rest.
        let mut n = Unit::new_normalize(rng.vector(-1.0, 1.0)).into_inner();
        if n.dot(&axis) > -0.2 {
            n = (n - axis * (n.dot(&axis) + 0.6)).normalize();
        }
        let (surface_num, local): (NumSurface, Build) = match case % 4 {
            0 => (NumSurface::Sphere { c: c.into(), rho }, |c, r, _| {
                Surface::Sphere {
                    center: c,
                    radius: r,
                }
            }),
            1 => (NumSurface::DiskRim { c: c.into(), rho }, |c, r, _| {
                Surface::DiskRim {
                    center: c,
                    radius: r,
                }
            }),
            2 => (
                NumSurface::Torus {
                    c: c.into(),
                    big: rho,
                    tube,
                },
                |c, r, t| Surface::Torus {
                    center: c,
                    radius: r,
                    tube: t,
                },
            ),
            _ => (
                NumSurface::Paraboloid {
                    v: c.into(),
                    big: rho,
                },
                |c, r, _| Surface::Paraboloid {
                    vertex: c,
                    curvature_radius: r,
                },
            ),
        };
        let mut a = Arena::new();
        let mut env = Vec::new();
        let cs = symbols(&mut a, &mut env, "c", &c);
        let ns = symbols(&mut a, &mut env, "n", &n);
        let axs = symbols(&mut a, &mut env, "a", &axis);
        let rs = symbol(&mut a, &mut env, "rho", rho);
        let ts = symbol(&mut a, &mut env, "tube", tube);
        let surface = local(cs, rs, ts);
        let s = surface.support_along(&mut a, &ns, &axs).expect("supports");
        let got = Vector3::from_fn(|k, _| a.eval(s[k], &env));
        // The hand-written map in the surface's own axes, turned back.
        let (s0, _) = support(&surface_num, &(r.inverse() * n));
        let want = c + r * (s0 - c);
        worst = worst.max((got - want).norm() / (rho + c.norm()));
        if case % 4 == 1 {
            // The rim's tilt is |n × a|, the sine of the angle between n and the axis.
            let rim = Rim::new(&mut a, &ns, &axs).expect("a rim");
            let tilt = a.eval(rim.tilt, &env);
            worst = worst.max((tilt - n.cross(&axis).norm()).abs());
        }
    }
    println!("support_along against the turned hand-written map: {worst:e}");
    assert!(worst < 1e-13, "{worst:e}");
    let mut a = Arena::new();
    let (z, o) = (a.zero(), a.one());
    let ellipsoid = Surface::Ellipsoid {
        center: [z; 3],
        semi_axes: [o; 3],
    };
    assert!(matches!(
        ellipsoid.support_along(&mut a, &[z, z, o], &[o, z, z]),
        Err(SurfaceError::NotAxisymmetric {
            surface: "ellipsoid"
        })
    ));
}
