//! A top described on a struct and the same top built at run time: their mass properties,
//! principal frames and Euler's equations agree, because both come from precess-core.
//!
//! Run with `cargo run --example bodies`.

use precess::prelude::*;

/// The design's top: a stem and a disk whose mass, radius and height are fields.
#[derive(RigidBody)]
#[rigid(
    cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
    disk(mass = m, radius = r, at = [0.0, 0.0, h]),
    pivot = [0.0, 0.0, 0.0],
)]
struct Top {
    m: f64,
    r: f64,
    h: f64,
}

fn main() -> Result<(), BodyError> {
    let derived = Top {
        m: 0.5,
        r: 0.03,
        h: 0.05,
    }
    .validated()?;
    let built = BodyBuilder::new()
        .part(
            Shape::Cylinder {
                mass: 0.2,
                radius: 0.004,
                length: 0.06,
                axis: Axis::Z,
            },
            [0.0, 0.0, 0.03],
        )
        .part(
            Shape::Disk {
                mass: 0.5,
                radius: 0.03,
                axis: Axis::Z,
            },
            [0.0, 0.0, 0.05],
        )
        .pivot([0.0, 0.0, 0.0])
        .build()?;
    for (name, body) in [("derived", &derived as &dyn RigidBody), ("built", &built)] {
        let p = body.principal();
        let w = Vector3::new(1.0, 0.5, 100.0);
        println!(
            "{name:8} M = {:.3} kg, G = {:.5?} m, moments = {:?} kg m², ω̇ = {:.6?} rad/s²",
            body.mass(),
            body.center_of_mass().as_slice(),
            p.moments.as_slice(),
            body.euler_rhs_principal(&w, &Vector3::zeros()).as_slice(),
        );
    }
    // An invalid parameter is caught at run time with the numbers.
    if let Err(e) = (Top {
        m: -1.0,
        r: 0.03,
        h: 0.05,
    })
    .validated()
    {
        println!("rejected: {e}");
    }
    Ok(())
}
