//! `#[contact(...)]` end to end: the generated methods against the interpreted
//! [`ContactModel`] of the same scene built by hand at run time (its mass properties worked
//! out here, not read from the macro, so a wrong reading of the attribute shows), and
//! against closed forms: a uniform ball rolls with ω̇ = 0 and N = M g, an upright disk
//! rolling straight has N = m g, Jellett's λ = −(I ω)·r from the state by hand.

use approx::assert_relative_eq;
use precess::contact::{
    ContactDynamics, ContactError, ContactLaw, ContactModel, ContactScene, Friction, Phase,
    Surface, layout,
};
use precess::prelude::*;
use precess::sym::Arena;

use crate::common::rng::Rng;

/// The tippe top of the attribute's docs: a ball with a small mass inside, sliding with
/// viscous friction.
#[derive(RigidBody)]
#[rigid(sphere(mass = 0.015, radius = 0.02), particle(mass = 0.001, at = [0.0, 0.0, 0.015]))]
#[contact(surface = sphere(radius = 0.02), law = sliding(viscous = 0.3), gravity = 9.81)]
struct TippeTop;

/// Kane & Levinson's rattleback: the centre of mass 0.01 m below the ellipsoid's centre.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]]))]
#[contact(
    surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02], center = [0.0, 0.0, 0.01]),
    law = rolling,
    gravity = 9.81,
)]
struct Rattleback;

/// A coin of field parameters under stick–slip.
#[derive(RigidBody)]
#[rigid(disk(mass = m, radius = r))]
#[contact(surface = disk_rim(radius = r), law = stick_slip(mu = mu), gravity = g)]
struct Coin {
    m: f64,
    r: f64,
    mu: f64,
    g: f64,
}

/// A wheel with a tyre, rolling against both resistances.
#[derive(RigidBody)]
#[rigid(disk(mass = 0.5, radius = 0.06))]
#[contact(
    surface = torus(radius = 0.05, tube = 0.01),
    law = rolling(rolling_resistance = 1e-4, spin_resistance = 2e-4),
    gravity = 9.81,
)]
struct Wheel;

/// A ball held 0.1 m above the vertex of a bowl, sliding under Coulomb friction.
#[derive(RigidBody)]
#[rigid(sphere(mass = 1.0, radius = 0.05, at = [0.0, 0.0, 0.1]))]
#[contact(surface = paraboloid(curvature_radius = 0.3), law = sliding(coulomb = 0.2), gravity = 9.81)]
struct Rocker;

/// A uniform ball rolling.
#[derive(RigidBody)]
#[rigid(sphere(mass = 2.0, radius = 0.1))]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = 9.81)]
struct Ball;

/// A scene built by hand: centre of mass, inertia about it (description axes), surface,
/// law, as numbers; every value is a parameter of the interpreted model.
struct Hand {
    mass: f64,
    center: [f64; 3],
    inertia: [[f64; 3]; 3],
    surface: fn(&mut Arena) -> Surface,
    law: fn(&mut Arena) -> ContactLaw,
    /// The extra parameters `surface` and `law` read.
    extra: Vec<(&'static str, f64)>,
}

impl Hand {
    fn model(&self) -> ContactModel {
        let mut a = Arena::new();
        let mass = a.parameter("M");
        let center = ["cx", "cy", "cz"].map(|n| a.parameter(n));
        let names = [
            ["i11", "i12", "i13"],
            ["i12", "i22", "i23"],
            ["i13", "i23", "i33"],
        ];
        let inertia = names.map(|row| row.map(|n| a.parameter(n)));
        let scene = ContactScene {
            mass,
            center,
            inertia,
            surface: (self.surface)(&mut a),
            law: (self.law)(&mut a),
            gravity: a.parameter("g"),
        };
        let d = scene.derive(&mut a).expect("the scene derives");
        let i = self.inertia;
        let mut values = vec![
            ("M", self.mass),
            ("cx", self.center[0]),
            ("cy", self.center[1]),
            ("cz", self.center[2]),
            ("i11", i[0][0]),
            ("i12", i[0][1]),
            ("i13", i[0][2]),
            ("i22", i[1][1]),
            ("i23", i[1][2]),
            ("i33", i[2][2]),
            ("g", 9.81),
        ];
        values.extend(self.extra.iter().copied());
        ContactModel::new(&mut a, &d, &values).expect("the hand scene's parameters")
    }
}

/// An attitude whose body z axis is tilted from the vertical by an angle in `tilt`, about a
/// random horizontal axis, then spun about z in space.
fn attitude(rng: &mut Rng, tilt: (f64, f64)) -> UnitQuaternion<f64> {
    let spin = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(-3.0, 3.0));
    let tip = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), rng.uniform(tilt.0, tilt.1));
    let yaw = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rng.uniform(-3.0, 3.0));
    yaw * tip * spin
}

/// |a − b| within `tol` of the scale of b (at least 1).
fn close(what: &str, a: &[f64], b: &[f64], tol: f64) {
    let scale = b.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= tol * scale,
            "{what}[{k}]: generated {x}, interpreted {y} (scale {scale})"
        );
    }
}

/// The generated methods agree with the interpreted model at `n` random states of each
/// phase the law derives.
fn agree<D: ContactDynamics>(derived: &D, model: &ContactModel, tilt: (f64, f64), seed: u64) {
    assert_eq!(derived.law(), model.law());
    assert_eq!(derived.surface_kind(), model.surface_kind());
    assert_eq!(derived.friction_coefficient(), model.friction_coefficient());
    derived.check_parameters().expect("the derived parameters");
    let mut rng = Rng::new(seed);
    for phase in [Phase::Rolling, Phase::Sliding] {
        if !derived.law().has(phase) {
            let mut d = [0.0; 11];
            derived.phase_rhs(phase, 0.0, &[0.0; 11], &mut d);
            assert!(d.iter().all(|v| v.is_nan()), "{phase:?}: {d:?}");
            continue;
        }
        for _ in 0..40 {
            let q = attitude(&mut rng, tilt);
            let w = rng.vector(-20.0, 20.0);
            let mut y = model
                .rolling_state([rng.uniform(-1.0, 1.0), 0.3], &q, &w)
                .unwrap();
            if phase == Phase::Sliding {
                y[layout::VELOCITY] = rng.uniform(-1.0, 1.0);
                y[layout::VELOCITY + 1] = rng.uniform(-1.0, 1.0);
            }
            let (mut a, mut b) = ([0.0; 11], [0.0; 11]);
            derived.phase_rhs(phase, 0.0, &y, &mut a);
            model.phase_rhs(phase, 0.0, &y, &mut b);
            close("rhs", &a, &b, 1e-10);
            let (ra, rb) = (derived.reaction(phase, &y), model.reaction(phase, &y));
            close("reaction", &[ra.normal], &[rb.normal], 1e-10);
            close(
                "friction",
                ra.friction.as_slice(),
                rb.friction.as_slice(),
                1e-10,
            );
            close(
                "energy",
                &[derived.energy(phase, &y)],
                &[model.energy(phase, &y)],
                1e-12,
            );
            let (ma, mb) = (derived.momenta(phase, &y), model.momenta(phase, &y));
            close("linear", ma.linear.as_slice(), mb.linear.as_slice(), 1e-12);
            close("center", ma.center.as_slice(), mb.center.as_slice(), 1e-12);
            close(
                "contact K",
                ma.contact.as_slice(),
                mb.contact.as_slice(),
                1e-12,
            );
            let (ca, cb) = (derived.contact(&y), model.contact(&y));
            close("gamma", ca.gamma.as_slice(), cb.gamma.as_slice(), 1e-14);
            close("r", ca.body.as_slice(), cb.body.as_slice(), 1e-14);
            close("point", ca.space.as_slice(), cb.space.as_slice(), 1e-14);
            close("height", &[ca.height], &[cb.height], 1e-14);
            close(
                "slip",
                ca.velocity.as_slice(),
                cb.velocity.as_slice(),
                1e-12,
            );
            close(
                "jellett",
                &[derived.jellett(&y)],
                &[model.jellett(&y)],
                1e-12,
            );
        }
    }
}

/// A diagonal tensor.
fn diag(a: f64, b: f64, c: f64) -> [[f64; 3]; 3] {
    [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]]
}

/// The tippe top's centre of mass height and its inertia about it, from its two parts.
fn tippe_top_mass() -> (f64, [[f64; 3]; 3]) {
    let (ms, rho, mp, hp) = (0.015, 0.02, 0.001, 0.015);
    let zc = mp * hp / (ms + mp);
    let ball = 0.4 * ms * rho * rho;
    let across = ball + ms * zc * zc + mp * (hp - zc) * (hp - zc);
    (zc, diag(across, across, ball))
}

#[test]
fn the_tippe_top_agrees_with_its_scene_built_by_hand() {
    let (zc, inertia) = tippe_top_mass();
    let hand = Hand {
        mass: 0.016,
        center: [0.0, 0.0, zc],
        inertia,
        surface: |a| {
            let z = a.zero();
            Surface::Sphere {
                center: [z; 3],
                radius: a.parameter("rho"),
            }
        },
        law: |a| ContactLaw::Sliding(Friction::Viscous(a.parameter("c"))),
        extra: vec![("rho", 0.02), ("c", 0.3)],
    };
    agree(&TippeTop, &hand.model(), (0.0, 3.1), 1);
}

#[test]
fn the_rattleback_agrees_with_its_scene_built_by_hand() {
    let hand = Hand {
        mass: 1.0,
        center: [0.0; 3],
        inertia: [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]],
        surface: |a| {
            let z = a.zero();
            Surface::Ellipsoid {
                center: [z, z, a.parameter("h")],
                semi_axes: ["a", "b", "c"].map(|n| a.parameter(n)),
            }
        },
        law: |_| ContactLaw::Rolling {
            rolling_resistance: None,
            spin_resistance: None,
        },
        extra: vec![("h", 0.01), ("a", 0.2), ("b", 0.03), ("c", 0.02)],
    };
    agree(&Rattleback, &hand.model(), (0.0, 3.1), 2);
}

/// The coin's scene by hand, for mass m and radius r.
fn coin_hand(m: f64, r: f64, mu: f64) -> Hand {
    Hand {
        mass: m,
        center: [0.0; 3],
        inertia: diag(m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0),
        surface: |a| {
            let z = a.zero();
            Surface::DiskRim {
                center: [z; 3],
                radius: a.parameter("rho"),
            }
        },
        law: |a| ContactLaw::StickSlip {
            mu: a.parameter("mu"),
        },
        extra: vec![("rho", r), ("mu", mu)],
    }
}

#[test]
fn a_coin_of_fields_agrees_in_both_phases() {
    let coin = Coin {
        m: 0.3,
        r: 0.04,
        mu: 0.25,
        g: 9.81,
    };
    agree(&coin, &coin_hand(0.3, 0.04, 0.25).model(), (0.3, 1.5), 3);
    assert_eq!(coin.friction_coefficient(), Some(0.25));
}

#[test]
fn a_wheel_with_a_tyre_and_resistances_agrees() {
    let hand = Hand {
        mass: 0.5,
        center: [0.0; 3],
        inertia: diag(4.5e-4, 4.5e-4, 9e-4),
        surface: |a| {
            let z = a.zero();
            Surface::Torus {
                center: [z; 3],
                radius: a.parameter("R"),
                tube: a.parameter("tube"),
            }
        },
        law: |a| ContactLaw::Rolling {
            rolling_resistance: Some(a.parameter("cr")),
            spin_resistance: Some(a.parameter("cs")),
        },
        extra: vec![("R", 0.05), ("tube", 0.01), ("cr", 1e-4), ("cs", 2e-4)],
    };
    agree(&Wheel, &hand.model(), (0.3, 1.5), 4);
}

#[test]
fn a_ball_on_a_bowl_sliding_under_coulomb_agrees() {
    let hand = Hand {
        mass: 1.0,
        center: [0.0, 0.0, 0.1],
        inertia: diag(1e-3, 1e-3, 1e-3),
        surface: |a| {
            let z = a.zero();
            Surface::Paraboloid {
                vertex: [z; 3],
                curvature_radius: a.parameter("R"),
            }
        },
        law: |a| ContactLaw::Sliding(Friction::Coulomb(a.parameter("mu"))),
        extra: vec![("R", 0.3), ("mu", 0.2)],
    };
    agree(&Rocker, &hand.model(), (0.05, 1.0), 5);
}

/// A uniform ball rolling keeps its velocity and spin: ω̇ = 0, v̇ = 0, no friction and
/// N = M g, at any rolling state; its contact point is at rest.
#[test]
fn a_uniform_ball_rolls_uniformly_with_its_weight_on_the_table() {
    let mut rng = Rng::new(6);
    for _ in 0..50 {
        let q = attitude(&mut rng, (0.0, 3.1));
        let y = Ball
            .rolling_state([0.2, -0.1], &q, &rng.vector(-30.0, 30.0))
            .unwrap();
        let dy = Ball
            .accelerations(Phase::Rolling, 0.0, &y)
            .expect("a rolling state");
        for k in [2, 3, 8, 9, 10] {
            assert!(dy[k].abs() < 1e-12, "ẏ[{k}] = {}", dy[k]);
        }
        let reaction = Ball.reaction(Phase::Rolling, &y);
        assert_relative_eq!(reaction.normal, 2.0 * 9.81, max_relative = 1e-14);
        assert!(reaction.friction.norm() < 1e-12, "{}", reaction.friction);
        let c = Ball.contact(&y);
        assert!(c.velocity.norm() < 1e-14, "slip {}", c.velocity);
        assert_relative_eq!(c.height, 0.1, max_relative = 1e-14);
    }
}

/// An upright coin rolling straight: its axis horizontal, ω along it. It carries its weight,
/// keeps rolling (no acceleration) and its centre stands one radius high.
#[test]
fn an_upright_coin_rolling_straight_carries_its_weight() {
    let coin = Coin {
        m: 0.3,
        r: 0.04,
        mu: 0.25,
        g: 9.81,
    };
    // Body z (the coin's axis) along space x.
    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), std::f64::consts::FRAC_PI_2);
    let spin = 12.0;
    let y = coin
        .rolling_state([0.0, 0.0], &q, &Vector3::new(0.0, 0.0, spin))
        .unwrap();
    // Rolling without slip: |v| = Ω r, along space y.
    assert_relative_eq!(
        y[layout::VELOCITY].abs() + y[layout::VELOCITY + 1].abs(),
        spin * 0.04,
        max_relative = 1e-14
    );
    let dy = coin
        .accelerations(Phase::Rolling, 0.0, &y)
        .expect("a rolling state");
    for k in [2, 3, 8, 9, 10] {
        assert!(dy[k].abs() < 1e-12, "ẏ[{k}] = {}", dy[k]);
    }
    assert_relative_eq!(
        coin.reaction(Phase::Rolling, &y).normal,
        0.3 * 9.81,
        max_relative = 1e-14
    );
    assert_relative_eq!(coin.contact(&y).height, 0.04, max_relative = 1e-14);
}

/// Jellett's λ = −(I ω)·r with r = −ρ γ − c for a sphere about the origin, worked out from
/// the state here.
#[test]
fn the_tippe_tops_jellett_quantity_is_minus_l_dot_r() {
    let (zc, inertia) = tippe_top_mass();
    let i = Matrix3::from_fn(|r, c| inertia[r][c]);
    let mut rng = Rng::new(7);
    for _ in 0..20 {
        let q = attitude(&mut rng, (0.0, 3.1));
        let w = rng.vector(-50.0, 50.0);
        let y = TippeTop.rolling_state([0.0, 0.0], &q, &w).unwrap();
        let gamma = q.inverse_transform_vector(&Vector3::z());
        let r = -0.02 * gamma - Vector3::new(0.0, 0.0, zc);
        let lambda = -(i * w).dot(&r);
        assert_relative_eq!(TippeTop.jellett(&y), lambda, max_relative = 1e-13);
    }
}

#[test]
fn check_parameters_refuses_a_negative_or_nan_field() {
    let coin = |m: f64, r: f64, mu: f64| Coin { m, r, mu, g: 9.81 };
    assert_eq!(coin(0.3, 0.04, 0.25).check_parameters(), Ok(()));
    assert_eq!(
        coin(0.3, 0.04, -0.1).check_parameters(),
        Err(ContactError::NegativeCoefficient {
            name: "mu",
            value: -0.1
        })
    );
    match coin(0.3, f64::NAN, 0.25).check_parameters() {
        Err(ContactError::BadParameter {
            name: "r", value, ..
        }) => assert!(value.is_nan()),
        other => panic!("{other:?}"),
    }
    match coin(0.3, -0.04, 0.25).check_parameters() {
        Err(ContactError::BadSurface {
            name: "radius",
            value,
            ..
        }) => assert_eq!(value, -0.04),
        Err(ContactError::Body(_)) => {}
        other => panic!("{other:?}"),
    }
}

macro_rules! named_alike {
    ($($name:ident: $field:ident),* $(,)?) => {
        $(
            /// A tippe top whose small mass and friction are a field named like a symbol of
            /// the derivation or a local of the generated code.
            #[derive(RigidBody)]
            #[rigid(sphere(mass = 0.015, radius = 0.02), particle(mass = $field / 100.0, at = [0.0, 0.0, 0.015]))]
            #[contact(surface = sphere(radius = 0.02), law = stick_slip(mu = $field), gravity = 9.81)]
            #[allow(non_snake_case)]
            struct $name {
                $field: f64,
            }
        )*

        /// A field may take any name the derivation's state or the generated methods use:
        /// the physics is the plain field's, exactly.
        #[test]
        fn fields_named_like_the_state_change_nothing() {
            let plain = NamedM { m: 0.1 };
            let mut rng = Rng::new(8);
            let q = attitude(&mut rng, (0.0, 3.0));
            let mut y = plain.rolling_state([0.1, 0.2], &q, &rng.vector(-20.0, 20.0)).unwrap();
            $({
                let other = $name { $field: 0.1 };
                for phase in [Phase::Rolling, Phase::Sliding] {
                    if phase == Phase::Sliding {
                        y[layout::VELOCITY] += 0.3;
                    }
                    let (mut a, mut b) = ([0.0; 11], [0.0; 11]);
                    plain.phase_rhs(phase, 0.0, &y, &mut a);
                    other.phase_rhs(phase, 0.0, &y, &mut b);
                    assert_eq!(a, b, "{}", stringify!($field));
                    assert_eq!(plain.reaction(phase, &y), other.reaction(phase, &y));
                    assert_eq!(plain.energy(phase, &y), other.energy(phase, &y));
                }
                assert_eq!(other.friction_coefficient(), Some(0.1));
                assert_eq!(other.check_parameters(), Ok(()));
            })*
        }
    };
}

named_alike! {
    NamedM: m, NamedX: x, NamedY: y, NamedVx: v_x, NamedQw: q_w, NamedQz: q_z,
    NamedOmega1: omega_1, NamedGamma: contact_gamma_1, NamedPhase: phase, NamedT: t,
    NamedDydt: dydt, NamedM2: M, NamedG: g,
}
