//! `taylor = K` on `#[rigid]`: the generated `System<3>` and `TaylorSystem<3>` of the
//! torque-free Euler equations in principal-axis ω, against the exact torque-free motion
//! (precess's Jacobi-elliptic `FreeBodyExact`, m(t) = I ω(t)) for a diagonal literal tensor,
//! a tilted literal one (principal frame found at compile time), a diagonal one of fields and
//! a tilted one of fields (principal frame found at run time); and no impl without the key.

use std::marker::PhantomData;

use precess::exact::FreeBodyExact;
use precess::ode::System;
use precess::prelude::*;
use precess::taylor::{TaylorConfig, TaylorSystem};

/// The body I = (3, 5, 7), given by its tensor.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = diag(3.0, 5.0, 7.0)), taylor = 24)]
struct Asymmetric;

/// A box turned about x: its tensor is not diagonal, so the principal frame is decomposed
/// while the macro expands.
#[derive(RigidBody)]
#[rigid(cuboid(mass = 2.0, size = [0.3, 0.2, 0.1], rotate = x(0.4)), taylor = 20)]
struct TiltedBox;

/// A box of fields: a diagonal tensor whose moments are expressions of the fields.
#[derive(RigidBody)]
#[rigid(cuboid(mass = m, size = [a, b, c]), taylor = 20)]
struct FieldBox {
    m: f64,
    a: f64,
    b: f64,
    c: f64,
}

/// A rod and a disk turned by a field about a pivot: the principal frame of the pivot is
/// found at run time, from the fields' values.
#[derive(RigidBody)]
#[rigid(
    rod(mass = 0.1, length = 0.5, at = [0.0, 0.0, 0.25]),
    disk(mass = 1.0, radius = 0.2, at = [0.0, 0.0, 0.5], rotate = x(tilt)),
    pivot = [0.0, 0.0, 0.0],
    taylor = 20,
)]
struct Wobbly {
    tilt: f64,
}

/// A symmetric body (I₁ = I₂): ω₃'s equation folds to zero.
#[derive(RigidBody)]
#[rigid(cylinder(mass = 0.5, radius = 0.1, length = 0.6), taylor = 16)]
struct Symmetric;

/// Three equal moments: every equation folds to zero.
#[derive(RigidBody)]
#[rigid(sphere(mass = 2.0, radius = 0.3), taylor = 8)]
struct Ball;

/// A body without the key.
#[derive(RigidBody)]
#[rigid(body(mass = 1.0, inertia = diag(3.0, 5.0, 7.0)))]
struct Plain;

/// ω(t) = m(t)/I of the exact torque-free motion from ω(0) = `w0`, moments `inertia`.
fn exact_omega(inertia: [f64; 3], w0: [f64; 3], t: f64) -> [f64; 3] {
    let m0: [f64; 3] = std::array::from_fn(|i| inertia[i] * w0[i]);
    let m = FreeBodyExact::new(inertia, m0)
        .expect("positive moments")
        .m_at(t)
        .expect("a moderate time");
    std::array::from_fn(|i| m[i] / inertia[i])
}

/// Euler's torque-free equations and their time derivative, directly in f64:
/// ω̇ᵢ = aᵢ ω_j ω_k, ω̈ᵢ = aᵢ (ω̇_j ω_k + ω_j ω̇_k), aᵢ = (I_j − I_k)/I_i.
fn euler_and_derivative(i: [f64; 3], w: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let a: [f64; 3] = std::array::from_fn(|n| (i[(n + 1) % 3] - i[(n + 2) % 3]) / i[n]);
    let d: [f64; 3] = std::array::from_fn(|n| a[n] * w[(n + 1) % 3] * w[(n + 2) % 3]);
    let dd: [f64; 3] = std::array::from_fn(|n| {
        let (j, k) = ((n + 1) % 3, (n + 2) % 3);
        a[n] * (d[j] * w[k] + w[j] * d[k])
    });
    (d, dd)
}

/// The generated coefficients at ω(t0) of the exact motion: c₀ = ω, c₁ and c₂ against
/// Euler's equations in f64, and the series summed h ahead against the exact ω(t0 + h).
fn check_coefficients<B: RigidBody + TaylorSystem<3> + System<3>>(body: &B, w0: [f64; 3], t0: f64) {
    let inertia: [f64; 3] = body.principal().moments.into();
    let order = body.max_order();
    let w = exact_omega(inertia, w0, t0);
    let mut c = vec![[0.0; 3]; order + 1];
    body.coefficients(t0, &w, order, &mut c);
    let (d, dd) = euler_and_derivative(inertia, w);
    let mut f = [0.0; 3];
    body.rhs(t0, &w, &mut f);
    let scale = w.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for n in 0..3 {
        assert_eq!(c[0][n], w[n]);
        assert!((c[1][n] - d[n]).abs() <= 1e-14 * scale * scale, "c1[{n}]");
        assert!((f[n] - d[n]).abs() <= 1e-14 * scale * scale, "rhs[{n}]");
        assert!(
            (c[2][n] - dd[n] / 2.0).abs() <= 1e-14 * scale.powi(3),
            "c2[{n}]: {} against {}",
            c[2][n],
            dd[n] / 2.0
        );
    }
    // h a fraction of the radius of convergence: the order-K sum is at rounding.
    let h = 0.1 / scale;
    let want = exact_omega(inertia, w0, t0 + h);
    for n in 0..3 {
        let sum = c.iter().rev().fold(0.0, |acc, ck| acc * h + ck[n]);
        assert!(
            (sum - want[n]).abs() <= 1e-14 * scale,
            "component {n}: series {sum} against exact {}",
            want[n]
        );
    }
}

/// Taylor's method to T = 50 against the exact motion, errors relative to |ω|.
fn check_integration<B: RigidBody + TaylorSystem<3>>(body: &B, w0: [f64; 3], bound: f64) {
    let inertia: [f64; 3] = body.principal().moments.into();
    let t_end = 50.0;
    let s = precess::taylor::solve(
        body,
        0.0,
        w0,
        t_end,
        &[],
        TaylorConfig::with_tol(1e-15, 1e-15),
    )
    .expect("Taylor integrates the free body");
    let want = exact_omega(inertia, w0, t_end);
    let scale = w0.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let error = (0..3).fold(0.0f64, |m, n| m.max((s.y[n] - want[n]).abs())) / scale;
    eprintln!(
        "I = {inertia:?}, ω0 = {w0:?}: relative error {error:.1e} at T = 50, {:?}",
        s.stats
    );
    for (n, (got, want)) in s.y.iter().zip(want).enumerate() {
        assert!(
            (got - want).abs() <= bound * scale,
            "component {n}: Taylor {got} against exact {want}"
        );
    }
}

#[test]
fn diagonal_literal_body_matches_the_exact_motion() {
    // m(0) = (0, 2, 0.01) of the benchmark: near the middle axis's separatrix.
    let w0 = [0.0, 2.0 / 5.0, 0.01 / 7.0];
    for t0 in [0.0, 3.7, 41.0] {
        check_coefficients(&Asymmetric, w0, t0);
    }
    check_coefficients(&Asymmetric, [0.3, -0.2, 0.5], 1.3);
    check_integration(&Asymmetric, w0, 1e-13);
    check_integration(&Asymmetric, [0.3, -0.2, 0.5], 1e-13);
    assert_eq!(TaylorSystem::<3>::max_order(&Asymmetric), 24);
}

#[test]
fn tilted_literal_body_matches_the_exact_motion() {
    let moments = TiltedBox.principal().moments;
    // Three distinct moments, not those of the untilted box's axes in that order.
    assert!(moments[0] < moments[1] && moments[1] < moments[2]);
    let w0 = [1.5, -0.4, 2.2];
    for t0 in [0.0, 2.9] {
        check_coefficients(&TiltedBox, w0, t0);
    }
    check_integration(&TiltedBox, w0, 1e-13);
}

#[test]
fn bodies_of_fields_match_the_exact_motion() {
    let boxed = FieldBox {
        m: 1.7,
        a: 0.4,
        b: 0.25,
        c: 0.1,
    };
    let w0 = [0.2, 1.1, -0.6];
    for t0 in [0.0, 6.1] {
        check_coefficients(&boxed, w0, t0);
    }
    check_integration(&boxed, w0, 1e-13);
    let wobbly = Wobbly { tilt: 0.35 };
    let w0 = [0.8, 0.3, -1.4];
    for t0 in [0.0, 4.4] {
        check_coefficients(&wobbly, w0, t0);
    }
    check_integration(&wobbly, w0, 1e-13);
}

#[test]
fn symmetric_bodies_precess_and_spheres_keep_their_rate() {
    // I₁ = I₂: ω₃ is constant and (ω₁, ω₂) turns at a = (I₁ − I₃) ω₃ / I₁:
    // ω₁ = ω₁₀ cos at + ω₂₀ sin at, ω₂ = ω₂₀ cos at − ω₁₀ sin at.
    let i = Symmetric.principal().moments;
    assert!((i[0] - i[1]).abs() < 1e-15 && (i[0] - i[2]).abs() > 1e-3);
    let w0 = [0.7, -0.3, 2.5];
    let a = (i[0] - i[2]) * w0[2] / i[0];
    let t_end = 50.0;
    let cfg = TaylorConfig::with_tol(1e-15, 1e-15);
    let s = precess::taylor::solve(&Symmetric, 0.0, w0, t_end, &[], cfg).expect("a run");
    let (c, sn) = ((a * t_end).cos(), (a * t_end).sin());
    let want = [w0[0] * c + w0[1] * sn, w0[1] * c - w0[0] * sn, w0[2]];
    for (n, (got, want)) in s.y.iter().zip(want).enumerate() {
        assert!(
            (got - want).abs() <= 1e-13 * 2.5,
            "component {n}: {got} against {want}"
        );
    }
    let mut k = [[f64::NAN; 3]; 17];
    Symmetric.coefficients(0.0, &w0, 16, &mut k);
    assert!(k[1..].iter().all(|ck| ck[2] == 0.0));
    // A sphere: every coefficient past the state is zero, the state never moves.
    let mut k = [[f64::NAN; 3]; 9];
    Ball.coefficients(0.0, &w0, 8, &mut k);
    assert_eq!(k[0], w0);
    assert!(k[1..].iter().flatten().all(|&v| v == 0.0));
    let s = precess::taylor::solve(&Ball, 0.0, w0, t_end, &[], cfg).expect("a run");
    assert_eq!(s.y, w0);
}

/// `Probe::<T>::TAYLOR` is the inherent constant when `T: TaylorSystem<3>` and the trait's
/// otherwise: whether the impl exists, decided at compile time.
struct Probe<T>(PhantomData<T>);
trait Absent {
    const TAYLOR: bool = false;
}
impl<T> Absent for Probe<T> {}
impl<T: TaylorSystem<3> + System<3>> Probe<T> {
    const TAYLOR: bool = true;
}

#[test]
fn the_key_absent_emits_no_impl() {
    // Decided at compile time: a wrong answer does not compile.
    const { assert!(!Probe::<Plain>::TAYLOR) };
    const { assert!(Probe::<Asymmetric>::TAYLOR) };
    const { assert!(Probe::<Wobbly>::TAYLOR) };
    // The body itself is the same without the key.
    assert_eq!(Plain.principal().moments, Asymmetric.principal().moments);
}
