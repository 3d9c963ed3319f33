//! Bodies on a table, in one criterion run: the right-hand side `#[contact(...)]` generates
//! for Kane & Levinson's rattleback against the same equations written by hand with nalgebra
//! and against the interpreted model of the same scene; the generated right-hand sides of the
//! tippe top, the Chaplygin ball and the rolling disk; and the time to derive and lower each
//! scene at run time (what the macro does while it expands), the figure SymPy's KanesMethod is
//! compared with in docs/performance.md (`scripts/sympy_contact.py`). The operation counts are
//! printed first.

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::{Matrix3, Quaternion, Vector3};
use precess::contact::{
    ContactDynamics, ContactLaw, ContactModel, ContactScene, Friction, Phase, STATE_LEN, Surface,
};
use precess::prelude::*;
use precess_core::sym::Arena;
use std::hint::black_box;

/// Kane & Levinson's rattleback: the centre of mass 0.01 m below the ellipsoid's centre.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[2e-4, -2e-5, 0.0], [-2e-5, 1.6e-3, 0.0], [0.0, 0.0, 1.7e-3]]))]
#[contact(
    surface = ellipsoid(semi_axes = [0.2, 0.03, 0.02], center = [0.0, 0.0, 0.01]),
    law = rolling,
    gravity = 9.81,
)]
struct Rattleback;

/// A tippe top: a sphere with a heavier cap, gliding under viscous friction.
#[derive(RigidBody)]
#[rigid(sphere(mass = 0.015, radius = 0.02), particle(mass = 0.001, at = [0.0, 0.0, 0.015]))]
#[contact(surface = sphere(radius = 0.02), law = sliding(viscous = 0.3), gravity = 9.81)]
struct TippeTop;

/// Chaplygin's ball: the centre of mass at the centre, unequal moments.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = [[1e-3, 0.0, 0.0], [0.0, 2e-3, 0.0], [0.0, 0.0, 3e-3]]))]
#[contact(surface = sphere(radius = 0.1), law = rolling, gravity = 9.81)]
struct ChaplyginBall;

/// A thin uniform disk rolling on its rim.
#[derive(RigidBody)]
#[rigid(disk(mass = 1.0, radius = 0.1))]
#[contact(surface = disk_rim(radius = 0.1), law = rolling, gravity = 9.81)]
struct Disk;

/// The rattleback's rolling equations written by hand, as a user would with nalgebra: body
/// axes, γ = Rᵀẑ, the contact point from the ellipsoid's support map, and the 3×3 system
/// (I + M(|r|²1 − r rᵀ)) ω̇ = −ω × Iω + M r × (−ω × ṙ + ω × v + g γ), v = −ω × r.
struct HandRattleback {
    mass: f64,
    inertia: Matrix3<f64>,
    semi_axes2: Vector3<f64>,
    center: Vector3<f64>,
    gravity: f64,
}

impl HandRattleback {
    fn kane_levinson() -> Self {
        HandRattleback {
            mass: 1.0,
            inertia: Matrix3::new(2e-4, -2e-5, 0.0, -2e-5, 1.6e-3, 0.0, 0.0, 0.0, 1.7e-3),
            semi_axes2: Vector3::new(0.04, 0.0009, 0.0004),
            center: Vector3::new(0.0, 0.0, 0.01),
            gravity: 9.81,
        }
    }

    #[inline]
    fn rhs(&self, y: &[f64; STATE_LEN], d: &mut [f64; STATE_LEN]) {
        let q = Quaternion::new(y[4], y[5], y[6], y[7]);
        let w = Vector3::new(y[8], y[9], y[10]);
        let r = nalgebra::UnitQuaternion::from_quaternion(q);
        let gamma = r.inverse_transform_vector(&Vector3::z());
        // The support point of the ellipsoid for the outward normal n = −γ, and its rate.
        let n = -gamma;
        let d2n = self.semi_axes2.component_mul(&n);
        let s = n.dot(&d2n).sqrt();
        let arm = self.center + d2n / s;
        let n_dot = -gamma.cross(&w);
        let d2nd = self.semi_axes2.component_mul(&n_dot);
        let arm_dot = (d2nd - d2n * (d2n.dot(&n_dot) / (s * s))) / s;
        let v = -w.cross(&arm);
        let m = self.mass;
        let lhs =
            self.inertia + m * (Matrix3::identity() * arm.norm_squared() - arm * arm.transpose());
        let rhs = -w.cross(&(self.inertia * w))
            + m * arm.cross(&(-w.cross(&arm_dot) + w.cross(&v) + self.gravity * gamma));
        let w_dot = lhs.cholesky().map_or(Vector3::zeros(), |c| c.solve(&rhs));
        let v_dot = -w_dot.cross(&arm) - w.cross(&arm_dot);
        let v_space = r * v;
        let a_space = r * (v_dot + w.cross(&v));
        let qd = q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        d[0] = v_space.x;
        d[1] = v_space.y;
        d[2] = a_space.x;
        d[3] = a_space.y;
        d[4] = qd.w;
        d[5] = qd.i;
        d[6] = qd.j;
        d[7] = qd.k;
        d[8] = w_dot.x;
        d[9] = w_dot.y;
        d[10] = w_dot.z;
    }
}

/// The rattleback as the run-time API builds it: the same scene interpreted.
fn interpreted_rattleback() -> ContactModel {
    let mut a = Arena::new();
    let num = |a: &mut Arena, t: &str| a.number(t).expect("a literal the arena reads");
    let z = a.zero();
    let inertia = [
        [num(&mut a, "2e-4"), num(&mut a, "-2e-5"), z],
        [num(&mut a, "-2e-5"), num(&mut a, "1.6e-3"), z],
        [z, z, num(&mut a, "1.7e-3")],
    ];
    let scene = ContactScene {
        mass: a.one(),
        center: [z; 3],
        inertia,
        surface: Surface::Ellipsoid {
            center: [z, z, num(&mut a, "0.01")],
            semi_axes: [num(&mut a, "0.2"), num(&mut a, "0.03"), num(&mut a, "0.02")],
        },
        law: ContactLaw::Rolling {
            rolling_resistance: None,
            spin_resistance: None,
        },
        gravity: num(&mut a, "9.81"),
    };
    let derivation = scene.derive(&mut a).expect("the rattleback derives");
    ContactModel::new(&mut a, &derivation, &[]).expect("no parameters to bind")
}

/// The scenes derived at run time, for the derivation's timing: each literal body as the
/// macro sees it.
fn scene(a: &mut Arena, which: &str) -> ContactScene {
    let num = |a: &mut Arena, t: &str| a.number(t).expect("a literal the arena reads");
    let z = a.zero();
    let rolling = ContactLaw::Rolling {
        rolling_resistance: None,
        spin_resistance: None,
    };
    let diag = |a: &mut Arena, d: [&str; 3]| {
        [
            [num(a, d[0]), z, z],
            [z, num(a, d[1]), z],
            [z, z, num(a, d[2])],
        ]
    };
    let g = num(a, "9.81");
    match which {
        "rattleback" => {
            let dd = num(a, "-2e-5");
            let mut inertia = diag(a, ["2e-4", "1.6e-3", "1.7e-3"]);
            inertia[0][1] = dd;
            inertia[1][0] = dd;
            ContactScene {
                mass: a.one(),
                center: [z; 3],
                inertia,
                surface: Surface::Ellipsoid {
                    center: [z, z, num(a, "0.01")],
                    semi_axes: [num(a, "0.2"), num(a, "0.03"), num(a, "0.02")],
                },
                law: rolling,
                gravity: g,
            }
        }
        "tippe_top" => ContactScene {
            mass: num(a, "0.016"),
            center: [z, z, num(a, "0.0009375")],
            inertia: diag(a, ["2.6109375e-6", "2.6109375e-6", "2.4e-6"]),
            surface: Surface::Sphere {
                center: [z; 3],
                radius: num(a, "0.02"),
            },
            law: ContactLaw::Sliding(Friction::Viscous(num(a, "0.3"))),
            gravity: g,
        },
        "chaplygin_ball" => ContactScene {
            mass: a.one(),
            center: [z; 3],
            inertia: diag(a, ["1e-3", "2e-3", "3e-3"]),
            surface: Surface::Sphere {
                center: [z; 3],
                radius: num(a, "0.1"),
            },
            law: rolling,
            gravity: g,
        },
        _ => ContactScene {
            mass: a.one(),
            center: [z; 3],
            inertia: diag(a, ["0.0025", "0.0025", "0.005"]),
            surface: Surface::DiskRim {
                center: [z; 3],
                radius: num(a, "0.1"),
            },
            law: rolling,
            gravity: g,
        },
    }
}

/// A rolling state of `body` tilted by 0.3 and 0.2 rad, spinning.
fn rolling_state<D: ContactDynamics>(body: &D) -> [f64; STATE_LEN] {
    let attitude = nalgebra::UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1);
    body.rolling_state([0.0, 0.0], &attitude, &Vector3::new(0.4, -0.7, -5.0))
        .unwrap()
}

fn contact(c: &mut Criterion) {
    let hand = HandRattleback::kane_levinson();
    let model = interpreted_rattleback();
    let y = rolling_state(&Rattleback);
    let (mut d_gen, mut d_hand, mut d_int) = ([0.0; STATE_LEN], [0.0; STATE_LEN], [0.0; STATE_LEN]);
    Rattleback.phase_rhs(Phase::Rolling, 0.0, &y, &mut d_gen);
    hand.rhs(&y, &mut d_hand);
    model.phase_rhs(Phase::Rolling, 0.0, &y, &mut d_int);
    // The three are one function: a benchmark of different equations would say nothing.
    for k in 0..STATE_LEN {
        let scale = d_gen[k].abs().max(1e-3);
        assert!(
            (d_gen[k] - d_hand[k]).abs() <= 1e-12 * scale
                && (d_gen[k] - d_int[k]).abs() <= 1e-12 * scale,
            "component {k}: generated {}, hand {}, interpreted {}",
            d_gen[k],
            d_hand[k],
            d_int[k]
        );
    }
    if let Some(count) = model.op_count(Phase::Rolling) {
        println!("rattleback rolling right-hand side: {count:?}");
    }

    let mut group = c.benchmark_group("contact_rhs");
    let mut d = [0.0; STATE_LEN];
    group.bench_function("rattleback/generated", |b| {
        b.iter(|| Rattleback.phase_rhs(Phase::Rolling, 0.0, black_box(&y), &mut d))
    });
    group.bench_function("rattleback/hand_nalgebra", |b| {
        b.iter(|| hand.rhs(black_box(&y), &mut d))
    });
    group.bench_function("rattleback/interpreted", |b| {
        b.iter(|| model.phase_rhs(Phase::Rolling, 0.0, black_box(&y), &mut d))
    });
    let tippe = {
        let mut s = rolling_state(&TippeTop);
        s[2] += 0.01;
        s
    };
    group.bench_function("tippe_top_sliding/generated", |b| {
        b.iter(|| TippeTop.phase_rhs(Phase::Sliding, 0.0, black_box(&tippe), &mut d))
    });
    let ball = rolling_state(&ChaplyginBall);
    group.bench_function("chaplygin_ball/generated", |b| {
        b.iter(|| ChaplyginBall.phase_rhs(Phase::Rolling, 0.0, black_box(&ball), &mut d))
    });
    let disk = rolling_state(&Disk);
    group.bench_function("rolling_disk/generated", |b| {
        b.iter(|| Disk.phase_rhs(Phase::Rolling, 0.0, black_box(&disk), &mut d))
    });
    group.finish();

    let mut group = c.benchmark_group("contact_derive");
    for which in ["rolling_disk", "rattleback", "tippe_top", "chaplygin_ball"] {
        // The derivation alone, then with the lowering to programs: where the time goes.
        group.bench_function(format!("{which}/derive_only"), |b| {
            b.iter(|| {
                let mut a = Arena::new();
                let s = scene(&mut a, which);
                black_box(s.derive(&mut a).expect("the scene derives"))
            })
        });
        group.bench_function(which, |b| {
            b.iter(|| {
                let mut a = Arena::new();
                let s = scene(&mut a, which);
                let derivation = s.derive(&mut a).expect("the scene derives");
                black_box(ContactModel::new(&mut a, &derivation, &[]).expect("no parameters"))
            })
        });
    }
    group.finish();
}

criterion_group!(benches, contact);
criterion_main!(benches);
