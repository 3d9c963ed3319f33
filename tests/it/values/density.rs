//! `density = ρ` instead of `mass`: the mass of every solid part is ρ V against the
//! closed-form volume, and a density read from a field is checked as a mass is.

use approx::assert_relative_eq;
use precess::prelude::*;

const PI: f64 = std::f64::consts::PI;
const RHO: f64 = 7.8e3;

#[derive(RigidBody)]
#[rigid(sphere(density = 7.8e3, radius = 0.05))]
struct Ball;

#[derive(RigidBody)]
#[rigid(cuboid(density = 7.8e3, size = [0.1, 0.2, 0.3]))]
struct Brick;

#[derive(RigidBody)]
#[rigid(cylinder(density = 7.8e3, radius = 0.04, length = 0.25))]
struct Bar;

#[derive(RigidBody)]
#[rigid(tube(density = 7.8e3, inner = 0.03, outer = 0.04, length = 0.25))]
struct Pipe;

#[derive(RigidBody)]
#[rigid(cone(density = 7.8e3, radius = 0.04, height = 0.09))]
struct Cone;

#[derive(RigidBody)]
#[rigid(ellipsoid(density = 7.8e3, semi_axes = [0.03, 0.05, 0.07]))]
struct Egg;

#[test]
fn each_solid_weighs_its_density_times_its_volume() {
    let cases = [
        ("sphere", Ball.mass(), 4.0 / 3.0 * PI * 0.05f64.powi(3)),
        ("cuboid", Brick.mass(), 0.1 * 0.2 * 0.3),
        ("cylinder", Bar.mass(), PI * 0.04 * 0.04 * 0.25),
        ("tube", Pipe.mass(), PI * (0.04 * 0.04 - 0.03 * 0.03) * 0.25),
        ("cone", Cone.mass(), PI * 0.04 * 0.04 * 0.09 / 3.0),
        ("ellipsoid", Egg.mass(), 4.0 / 3.0 * PI * 0.03 * 0.05 * 0.07),
    ];
    for (shape, mass, volume) in cases {
        assert_relative_eq!(mass, RHO * volume, max_relative = 1e-15);
        eprintln!("{shape}: {mass} kg");
    }
    // The mass is exact where no π enters: 7800 · 0.006 = 46.8 to the bit.
    assert_eq!(Brick.mass(), 46.8);
    // The inertia follows from that mass: a solid sphere's 2/5 m r².
    assert_relative_eq!(
        Ball.inertia()[(0, 0)],
        0.4 * Ball.mass() * 0.05 * 0.05,
        max_relative = 1e-15
    );
}

/// A ball of a density and radius read from fields.
#[derive(RigidBody)]
#[rigid(sphere(density = rho, radius = r))]
struct FieldBall {
    rho: f64,
    r: f64,
}

#[test]
fn a_density_from_a_field_gives_its_mass_and_is_checked_as_a_mass() {
    let ball = FieldBall {
        rho: 1000.0,
        r: 0.1,
    };
    assert_relative_eq!(
        ball.mass(),
        1000.0 * 4.0 / 3.0 * PI * 1e-3,
        max_relative = 1e-15
    );
    assert!(ball.validate().is_ok());
    // A negative density is a negative mass: the typed error of any mass.
    let e = FieldBall { rho: -1.0, r: 0.1 }.validate();
    assert!(
        matches!(e, Err(BodyError::NonPositiveMass { part: 0, value, .. }) if value < 0.0),
        "{e:?}"
    );
}
