//! The new laws through `#[contact(...)]` against the interpreted `ContactModel` of the same
//! scene built at run time: resistances and pivoting friction under stick–slip with a user
//! couple (`torque = f`, `ContactModel::with_torque`), and F = −μ N u; and the run-time
//! rule on a field's value.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactError, ContactLaw, ContactModel, ContactScene, ContactTorques,
    Friction, Phase, STATE_LEN, Surface,
};
use precess::prelude::RigidBody;
use precess::sym::Arena;

use super::reference::state;

/// The tests' tippe top (the eccentric sphere) under stick–slip with every new torque.
#[derive(RigidBody)]
#[rigid(body(mass = 0.02, inertia = diag(3.2e-6, 3.2e-6, 2.9e-6)))]
#[contact(
    surface = sphere(radius = 0.02, center = [0.0, 0.0, 0.006]),
    law = stick_slip(mu = mu, rolling_resistance = 2e-6, spin_resistance = cs, pivoting = 0.002),
    gravity = 9.81,
    torque = air,
)]
struct Resisted {
    mu: f64,
    cs: f64,
}

/// A couple of the attitude and ω: a drag −k ω growing as the axis tilts, and a steady twist.
fn air(_: &Resisted, r: &Matrix3<f64>, w: &Vector3<f64>) -> Vector3<f64> {
    couple(r, w)
}

fn couple(r: &Matrix3<f64>, w: &Vector3<f64>) -> Vector3<f64> {
    -1e-7 * w / (0.5 + r[(2, 2)] * r[(2, 2)]) + Vector3::new(0.0, 1e-6, 0.0)
}

type Couple = fn(&Matrix3<f64>, &Vector3<f64>) -> Vector3<f64>;

/// The same top gliding under F = −μ N u.
#[derive(RigidBody)]
#[rigid(body(mass = 0.02, inertia = diag(3.2e-6, 3.2e-6, 2.9e-6)))]
#[contact(
    surface = sphere(radius = 0.02, center = [0.0, 0.0, 0.006]),
    law = sliding(normal_viscous = 0.3),
    gravity = 9.81,
)]
struct Gliding;

/// The scene of `Resisted` or `Gliding` by hand, and its model.
fn interpreted(law: &str, f: Couple) -> ContactModel {
    let mut a = Arena::new();
    let p = |a: &mut Arena, n: &str| a.parameter(n);
    let (m, i1, i3, rho, h, g) = (
        p(&mut a, "m"),
        p(&mut a, "i1"),
        p(&mut a, "i3"),
        p(&mut a, "rho"),
        p(&mut a, "h"),
        p(&mut a, "g"),
    );
    let z = a.zero();
    let mut values = vec![
        ("m", 0.02),
        ("i1", 3.2e-6),
        ("i3", 2.9e-6),
        ("rho", 0.02),
        ("h", 0.006),
        ("g", 9.81),
    ];
    let (law, torques) = if law == "stick_slip" {
        let u = [a.input("u1"), a.input("u2"), a.input("u3")];
        values.extend([("mu", 0.3), ("cs", 1e-6), ("cr", 2e-6), ("l", 0.002)]);
        let torques = ContactTorques {
            rolling_resistance: Some(p(&mut a, "cr")),
            spin_resistance: Some(p(&mut a, "cs")),
            pivoting: Some(p(&mut a, "l")),
            user: Some(u),
        };
        (
            ContactLaw::StickSlip {
                mu: p(&mut a, "mu"),
            },
            torques,
        )
    } else {
        values.push(("mu", 0.3));
        let mu = p(&mut a, "mu");
        (
            ContactLaw::Sliding(Friction::NormalViscous(mu)),
            ContactTorques::default(),
        )
    };
    let scene = ContactScene {
        mass: m,
        center: [z; 3],
        inertia: [[i1, z, z], [z, i1, z], [z, z, i3]],
        surface: Surface::Sphere {
            center: [z, z, h],
            radius: rho,
        },
        law,
        gravity: g,
    };
    let d = scene.derive_with(&mut a, &torques).unwrap();
    if torques.user.is_some() {
        ContactModel::with_torque(&mut a, &d, &values, f).unwrap()
    } else {
        ContactModel::new(&mut a, &d, &values).unwrap()
    }
}

/// The largest gap between two bodies' right-hand sides and normal forces over `states`,
/// relative to each quantity's size.
fn gap(
    a: &dyn ContactDynamics,
    b: &dyn ContactDynamics,
    phase: Phase,
    states: &[[f64; STATE_LEN]],
) -> f64 {
    let mut worst: f64 = 0.0;
    for y in states {
        let (mut da, mut db) = ([0.0; STATE_LEN], [0.0; STATE_LEN]);
        a.phase_rhs(phase, 0.0, y, &mut da);
        b.phase_rhs(phase, 0.0, y, &mut db);
        let scale = db.iter().map(|v| v.abs()).fold(1.0, f64::max);
        for k in 0..STATE_LEN {
            worst = worst.max((da[k] - db[k]).abs() / scale);
        }
        let (na, nb) = (a.reaction(phase, y), b.reaction(phase, y));
        worst = worst.max((na.normal - nb.normal).abs() / nb.normal.abs());
        worst = worst.max((na.friction - nb.friction).norm() / nb.normal.abs());
    }
    worst
}

fn states(sliding: bool, body: &dyn ContactDynamics) -> Vec<[f64; STATE_LEN]> {
    (0..30)
        .map(|k| {
            let x = k as f64;
            let q = UnitQuaternion::from_euler_angles(0.8 * x.sin(), 1.1 * (0.7 * x).cos(), x);
            // Spins of either sign, so both sides of the pivoting friction are read.
            let w = Vector3::new(5.0 * (1.3 * x).sin(), 4.0 * x.cos(), 60.0 * (0.9 * x).cos());
            if sliding {
                state([0.0, 0.1], [0.2 * x.cos(), 0.3 * x.sin()], &q, &w)
            } else {
                body.rolling_state([0.0, 0.1], &q, &w).unwrap()
            }
        })
        .collect()
}

#[test]
fn the_derived_resistances_pivoting_and_couple_match_the_interpreted_model() {
    let derived = Resisted { mu: 0.3, cs: 1e-6 };
    let model = interpreted("stick_slip", couple);
    let rolling = gap(&derived, &model, Phase::Rolling, &states(false, &model));
    let sliding = gap(&derived, &model, Phase::Sliding, &states(true, &model));
    println!("derived against interpreted: rolling {rolling:e}, sliding {sliding:e}");
    assert!(
        rolling < 1e-12 && sliding < 1e-12,
        "{rolling:e} {sliding:e}"
    );
    // The couple is read: against a model without it the two differ.
    let bare = interpreted("stick_slip", |_, _| Vector3::zeros());
    let without = gap(&derived, &bare, Phase::Rolling, &states(false, &model));
    assert!(without > 1e-6, "{without:e}");
    let g = Gliding;
    let model = interpreted("sliding", couple);
    let sliding = gap(&g, &model, Phase::Sliding, &states(true, &model));
    println!("F = −μ N u derived against interpreted: {sliding:e}");
    assert!(sliding < 1e-12, "{sliding:e}");
}

#[test]
fn a_negative_field_coefficient_is_a_typed_error() {
    let bad = Resisted { mu: 0.3, cs: -1e-6 };
    assert_eq!(
        bad.check_parameters(),
        Err(ContactError::NegativeCoefficient {
            name: "spin_resistance",
            value: -1e-6
        })
    );
    let good = Resisted { mu: 0.3, cs: 1e-6 };
    assert_eq!(good.check_parameters(), Ok(()));
}
