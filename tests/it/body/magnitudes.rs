//! Literal bodies from atoms to galaxies: the derive folds their values exactly and rounds
//! once, so they compile at every magnitude f64 holds and agree with the closed forms and
//! with the run-time `BodyBuilder` to a few ulp.

use crate::common;

use common::body::{check_euler, ulps};
use precess::prelude::*;

/// The largest distance in ulps allowed between a derived value (exact, rounded once) and a
/// value computed in f64 from the same literals (each literal rounded, then ≤ 4 roundings).
const ULPS: u64 = 4;

/// Declares a derived sphere and the test comparing it with 2/5 M R² and the builder.
macro_rules! spheres {
    ($($name:ident, $test:ident: $mass:tt, $radius:tt;)*) => {$(
        #[derive(RigidBody)]
        #[rigid(sphere(mass = $mass, radius = $radius))]
        struct $name;

        #[test]
        // Some literals carry more digits than f64 holds, on purpose: the derive reads them
        // exactly, and this compares with the f64 Rust rounds them to.
        #[allow(clippy::excessive_precision)]
        fn $test() {
            check_sphere(&$name, $mass, $radius);
        }
    )*};
}

spheres! {
    // The electron at its classical radius: I ≈ 2.9e-60 kg m².
    Electron, electron: 9.1093837015e-31, 2.8179403262e-15;
    // Hydrogen's mass in a Bohr-radius ball.
    Atom, hydrogen_atom: 1.67353284e-27, 5.29177210903e-11;
    Grain, grain: 1e-20, 1e-9;
    Ball, ball: 0.43, 0.11;
    Earth, earth: 5.972e24, 6.371e6;
    Sun, sun: 1.989e30, 6.957e8;
    NeutronStar, neutron_star: 2.8e30, 1.2e4;
    // The Milky Way as a ball: I ≈ 1.5e83 kg m².
    Galaxy, galaxy: 1.5e42, 5e20;
    // 17 significant digits each: the exact 2/5 M R² leaves the 128-bit odd parts, so it is
    // folded in f64 (still within a few ulp).
    PreciseSun, sun_to_17_digits: 1.9884754153381438e30, 6.9570000000000001e8;
    // Near the ends of the normal range.
    Light, light_end_of_the_range: 1e-290, 1e-5;
    Heavy, heavy_end_of_the_range: 1e290, 1e5;
}

fn check_sphere(body: &impl RigidBody, mass: f64, radius: f64) {
    let closed = 0.4 * mass * radius * radius;
    let built = BodyBuilder::new()
        .part(Shape::Sphere { mass, radius }, [0.0; 3])
        .build()
        .expect("the builder takes the same sphere");
    assert_eq!(body.mass(), mass);
    for k in 0..3 {
        let moment = body.principal().moments[k];
        assert!(
            ulps(moment, closed) <= ULPS,
            "{moment:e} vs 2/5 M R² = {closed:e}"
        );
        assert!(ulps(moment, built.principal().moments[k]) <= ULPS);
        assert!(ulps(body.inertia()[(k, k)], built.inertia()[(k, k)]) <= ULPS);
    }
    // A sphere has no gyroscopic term: ω̇ = G / I, with 1/I folded to one literal.
    let g = Vector3::new(1.0, -2.0, 0.5);
    let w_dot = body.euler_rhs_principal(&Vector3::new(3.0, 1.0, -2.0), &g);
    for k in 0..3 {
        assert!(
            ulps(w_dot[k], g[k] / closed) <= ULPS,
            "{:e} vs {:e}",
            w_dot[k],
            g[k] / closed
        );
    }
    check_euler(body, 17);
}

/// Jupiter as an oblate ellipsoid (equatorial and polar radii).
#[derive(RigidBody)]
#[rigid(ellipsoid(mass = 1.898e27, semi_axes = [7.1492e7, 7.1492e7, 6.6854e7]))]
struct Jupiter;

#[test]
fn jupiter_as_an_ellipsoid() {
    let (m, a, c) = (1.898e27, 7.1492e7, 6.6854e7);
    // I1 = I2 = M (a² + c²)/5, I3 = 2 M a²/5.
    let (i1, i3) = (m * (a * a + c * c) / 5.0, 2.0 * m * a * a / 5.0);
    let p = Jupiter.principal();
    for (k, want) in [(0, i1), (1, i1), (2, i3)] {
        assert!(
            ulps(p.moments[k], want) <= ULPS,
            "I{} = {:e} vs {want:e}",
            k + 1,
            p.moments[k]
        );
    }
    let built = BodyBuilder::new()
        .part(
            Shape::Ellipsoid {
                mass: m,
                semi_axes: [a, a, c],
            },
            [0.0; 3],
        )
        .build()
        .unwrap();
    let w = Vector3::new(1e-4, 2e-4, 1.76e-4);
    let g = Vector3::new(1e20, -3e20, 2e19);
    let (got, want) = (
        Jupiter.euler_rhs_principal(&w, &g),
        built.euler_rhs_principal(&w, &g),
    );
    for k in 0..3 {
        assert!(
            (got[k] - want[k]).abs() <= 1e-15 * want.norm(),
            "{got} vs {want}"
        );
    }
    // The oblateness coefficient (I3 − I1)/I1 = (a² − c²)/(a² + c²) exactly: only ω₁ω₂
    // feeds ω̇₂ through it, and the symmetric axis has none.
    let k = (a * a - c * c) / (a * a + c * c);
    let x = Jupiter.euler_rhs_principal(&Vector3::new(0.0, 1.0, 1.0), &Vector3::zeros());
    assert!((x[0] + k).abs() <= 1e-15 * k, "{} vs {}", x[0], -k);
    check_euler(&Jupiter, 18);
}

/// Earth and Moon about their barycentre, the Moon off every axis: the tensor is not
/// diagonal, so its frame is decomposed at compile time and its moments enter as constants.
#[derive(RigidBody)]
#[rigid(
    sphere(mass = 5.972e24, radius = 6.371e6),
    sphere(mass = 7.342e22, radius = 1.7374e6, at = [3.0e8, 2.0e8, 1.0e8]),
)]
struct EarthMoon;

#[test]
fn earth_moon_decomposed_at_compile_time() {
    let built = BodyBuilder::new()
        .part(
            Shape::Sphere {
                mass: 5.972e24,
                radius: 6.371e6,
            },
            [0.0; 3],
        )
        .part(
            Shape::Sphere {
                mass: 7.342e22,
                radius: 1.7374e6,
            },
            [3.0e8, 2.0e8, 1.0e8],
        )
        .build()
        .unwrap();
    let (d, b) = (EarthMoon.principal(), built.principal());
    let scale = b.moments.max();
    assert!((d.moments - b.moments).abs().max() <= 1e-14 * scale);
    assert!((d.rotation.matrix() - b.rotation.matrix()).abs().max() <= 1e-12);
    let t = (EarthMoon.inertia() - built.inertia()).abs().max();
    assert!(t <= 1e-15 * scale, "inertia differs by {t:e}");
    check_euler(&EarthMoon, 19);
}

/// A rod along x at the scale of a molecule: the derived and the built body agree where one
/// of the moments is zero apart from the rod's own thickness (a cylinder here).
#[derive(RigidBody)]
#[rigid(cylinder(mass = 4.65e-26, radius = 1e-11, length = 1.1e-10, axis = x))]
struct Molecule;

#[test]
fn a_molecule_sized_cylinder() {
    let (m, r, l) = (4.65e-26, 1e-11, 1.1e-10);
    let axial = m * r * r / 2.0;
    let transverse = m * (3.0 * r * r + l * l) / 12.0;
    let p = Molecule.principal();
    assert!(ulps(p.moments[0], axial) <= ULPS);
    assert!(ulps(p.moments[1], transverse) <= ULPS);
    assert!(ulps(p.moments[2], transverse) <= ULPS);
    let built = BodyBuilder::new()
        .part(
            Shape::Cylinder {
                mass: m,
                radius: r,
                length: l,
                axis: Axis::X,
            },
            [0.0; 3],
        )
        .build()
        .unwrap();
    let w = Vector3::new(1e12, 3e11, -2e11);
    let g = Vector3::new(1e-40, 2e-40, 0.0);
    let (got, want) = (
        Molecule.euler_rhs_principal(&w, &g),
        built.euler_rhs_principal(&w, &g),
    );
    assert!((got - want).abs().max() <= 1e-14 * want.norm());
    check_euler(&Molecule, 20);
}
