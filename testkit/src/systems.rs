//! Reference systems with published or closed-form values, written by hand and independent
//! of what the derive generates: DETEST B5, the torque-free body with the GNI values (Hairer,
//! Lubich, Wanner) and the harmonic oscillator, each as a right-hand side and as a Taylor
//! recurrence (Cauchy products); and the heavy top of `examples/heavy_top.rs` as the derive
//! sees it. Shared by the tests, the benches and the work-precision report.
// Reference constants are quoted with all their published digits.
#![allow(clippy::excessive_precision)]

use precess::exact::Jacobi;
use precess::ode::System;
use precess::prelude::*;
use precess::sym::{Arena, ExprId};
use precess::taylor::{TaylorSystem, TaylorTape};
use precess::top::{TopDynamics, TopScene};

/// Σ_{j=0}^{k} a_j b_{k−j}: the k-th coefficient of the product of components `a` and `b`.
fn cauchy<const N: usize>(c: &[[f64; N]], a: usize, b: usize, k: usize) -> f64 {
    (0..=k).map(|j| c[j][a] * c[k - j][b]).sum()
}

/// DETEST B5: y′ = (y₂ y₃, −y₁ y₃, −0.51 y₁ y₂), y(0) = (0, 1, 1), whose solution is
/// (sn, cn, dn)(t | m = 0.51).
#[derive(Clone, Copy, Debug)]
pub struct B5;

/// y(0) of B5.
pub const B5_Y0: [f64; 3] = [0.0, 1.0, 1.0];
/// The end of the B5 run.
pub const B5_T: f64 = 20.0;
/// B5's y(12) to the published digits (Hull et al. 1972).
pub const B5_Y12: [f64; 3] = [
    -0.705_397_809_522_571_74,
    -0.708_811_632_467_158_09,
    0.863_846_690_370_222_10,
];
/// B5's y(20) to the published digits (Hull et al. 1972).
pub const B5_Y20: [f64; 3] = [
    -0.939_657_079_872_920_396_19,
    -0.342_117_775_400_074_906_53,
    0.741_412_659_619_995_300_78,
];

/// B5's closed form (sn, cn, dn)(t | m = 0.51), by the complementary parameter 0.49.
pub fn b5_exact(t: f64) -> [f64; 3] {
    let (s, c, d) = Jacobi::new(0.49)
        .expect("0.49 lies in the parameter's range")
        .sncndn(t);
    [s, c, d]
}

impl System<3> for B5 {
    fn rhs(&self, _t: f64, y: &[f64; 3], d: &mut [f64; 3]) {
        d[0] = y[1] * y[2];
        d[1] = -y[0] * y[2];
        d[2] = -0.51 * y[0] * y[1];
    }
}

impl TaylorSystem<3> for B5 {
    fn max_order(&self) -> usize {
        60
    }
    type Workspace = ();
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        c[0] = *y;
        for k in 0..order {
            let d = (k + 1) as f64;
            c[k + 1] = [
                cauchy(c, 1, 2, k) / d,
                -cauchy(c, 0, 2, k) / d,
                -0.51 * cauchy(c, 0, 1, k) / d,
            ];
        }
    }
}

/// The torque-free rigid body in body angular momentum: ṁ = m × (I⁻¹ m), principal moments
/// in the field.
#[derive(Clone, Copy, Debug)]
pub struct FreeBody(pub [f64; 3]);

impl System<3> for FreeBody {
    fn rhs(&self, _t: f64, m: &[f64; 3], d: &mut [f64; 3]) {
        let w = [m[0] / self.0[0], m[1] / self.0[1], m[2] / self.0[2]];
        d[0] = m[1] * w[2] - m[2] * w[1];
        d[1] = m[2] * w[0] - m[0] * w[2];
        d[2] = m[0] * w[1] - m[1] * w[0];
    }
}

/// ṁ = (a₀ m₁ m₂, a₁ m₂ m₀, a₂ m₀ m₁) with aᵢ = 1/Iₖ − 1/Iⱼ: three products with constants.
impl TaylorSystem<3> for FreeBody {
    fn max_order(&self) -> usize {
        60
    }
    type Workspace = ();
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 3],
        order: usize,
        c: &mut [[f64; 3]],
    ) {
        let i = self.0;
        let a = [
            1.0 / i[2] - 1.0 / i[1],
            1.0 / i[0] - 1.0 / i[2],
            1.0 / i[1] - 1.0 / i[0],
        ];
        c[0] = *y;
        for k in 0..order {
            let d = (k + 1) as f64;
            c[k + 1] = [
                a[0] * cauchy(c, 1, 2, k) / d,
                a[1] * cauchy(c, 2, 0, k) / d,
                a[2] * cauchy(c, 0, 1, k) / d,
            ];
        }
    }
}

/// GNI body: I = (2, 1, 2/3), m(0) = (cos 1.1, 0, sin 1.1).
pub const GNI_I: [f64; 3] = [2.0, 1.0, 2.0 / 3.0];
/// m(1) to 30 digits (rounded to f64).
pub const GNI_M1: [f64; 3] = [
    0.369_110_080_850_460_6,
    -0.372_846_321_121_433_4,
    0.851_318_606_069_889_3,
];
/// m(10).
pub const GNI_M10: [f64; 3] = [
    0.407_066_136_588_040_8,
    0.283_007_426_812_843_7,
    0.868_449_167_661_561_7,
];

/// The harmonic oscillator x″ = −x as (x, v): x = cos t from (1, 0). Taylor's steps on it
/// are long (about 1.4 at tol 1e-12): c_{k+1} = (v_k, −x_k)/(k + 1).
#[derive(Clone, Copy, Debug)]
pub struct Oscillator;

impl System<2> for Oscillator {
    fn rhs(&self, _t: f64, y: &[f64; 2], d: &mut [f64; 2]) {
        *d = [y[1], -y[0]];
    }
}

impl TaylorSystem<2> for Oscillator {
    fn max_order(&self) -> usize {
        40
    }
    type Workspace = ();
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; 2],
        order: usize,
        c: &mut [[f64; 2]],
    ) {
        c[0] = *y;
        for k in 0..order {
            let d = (k + 1) as f64;
            c[k + 1] = [c[k][1] / d, -c[k][0] / d];
        }
    }
}

/// The max-norm distance of two vectors.
pub fn max_diff<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// A disk (brass, 40 mm radius) 50 mm up a stem (steel, 80 mm) on a pivot: the heavy top of
/// `examples/heavy_top.rs`, with its generated angle equations and their generated Taylor
/// recurrences to order 20.
#[derive(RigidBody)]
#[rigid(
    disk(mass = 0.2, radius = 0.04, at = [0.0, 0.0, 0.05]),
    cylinder(mass = 0.01, radius = 0.003, length = 0.08, at = [0.0, 0.0, 0.04]),
    pivot = [0.0, 0.0, 0.0],
)]
#[top(gravity = 9.81, taylor = 20)]
pub struct SpinningTop;

/// A derived top's Lagrangian Taylor tape built again at run time, from its mass properties
/// only, through precess-core's `TopScene` and the interpreter: the second formulation the
/// generated `taylor = K` code is checked (tests) and timed (benches) against.
///
/// # Panics
/// If the scene does not derive or the tape cannot be built: a fixture, not user input.
pub fn interpreted_top<T: RigidBody + TopDynamics>(top: &T, g: f64, order: usize) -> TaylorTape<6> {
    let mut a = Arena::new();
    let num = |a: &mut Arena, x: f64| a.float(x).expect("a finite mass property");
    let i = top.inertia();
    let c = top.center_of_mass() - top.reference_point();
    let inertia = std::array::from_fn(|r| std::array::from_fn(|k| num(&mut a, i[(r, k)])));
    let center = std::array::from_fn(|k| num(&mut a, c[k]));
    let scene = TopScene {
        sequence: T::SEQUENCE,
        inertia,
        mass: num(&mut a, top.mass()),
        center,
        gravity: Some(num(&mut a, g)),
        body_torque: None,
        space_torque: None,
        damping: None,
        user_torque: None,
        rotors: Vec::new(),
    };
    let d = scene.derive(&mut a).expect("a top's scene derives");
    let co = d.coords();
    let state: [ExprId; 6] = std::array::from_fn(|k| if k < 3 { co.q[k] } else { co.rates[k - 3] });
    let rhs: [ExprId; 6] = std::array::from_fn(|k| {
        if k < 3 {
            co.rates[k]
        } else {
            d.accelerations.accel[k - 3]
        }
    });
    TaylorTape::new(&a, state, rhs, None, &[], order).expect("a top's tape builds")
}

precess::taylor_system! {
    /// The symmetric heavy top about its fixed tip in Euler–Poisson form, through
    /// `taylor_system!`: ω and the upward vertical γ in body axes,
    /// ω̇1 = r ω2 ω3 + s γ2, ω̇2 = −r ω3 ω1 − s γ1, ω̇3 = 0, γ̇ = γ × ω, with
    /// r = (I1 − I3)/I1 and s = M g l / I1; cos θ = γ3. `ThetaRate` is θ̇ up to a positive
    /// factor (its sign is that of γ2 ω1 − γ1 ω2), compiled with the system's recurrences.
    #[derive(Clone, Copy, Debug)]
    pub struct EulerPoissonTop {
        pub r: f64,
        pub s: f64,
    }
    state [w1, w2, w3, g1, g2, g3];
    taylor = 24;
    d/dt w1 = r * (w2 * w3) + s * g2;
    d/dt w2 = -r * (w3 * w1) - s * g1;
    d/dt w3 = 0.0;
    d/dt g1 = g2 * w3 - g3 * w2;
    d/dt g2 = g3 * w1 - g1 * w3;
    d/dt g3 = g1 * w2 - g2 * w1;
    event ThetaRate = g2 * w1 - g1 * w2;
}
