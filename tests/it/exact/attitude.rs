//! The exact free-body attitude against DOP853 on q̇ = ½ q ⊗ (0, I⁻¹m), ṁ = m × I⁻¹m, in
//! every regime, and as a splitting step.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess_core::exact::{ExactError, FreeBodyAttitude, Regime};
use precess_core::ode::{AdaptiveConfig, Dop853Pair, System, solve};

struct Ode([f64; 3]);
impl System<7> for Ode {
    fn rhs(&self, _t: f64, y: &[f64; 7], d: &mut [f64; 7]) {
        let i = self.0;
        let w = [y[4] / i[0], y[5] / i[1], y[6] / i[2]];
        d[0] = -0.5 * (y[1] * w[0] + y[2] * w[1] + y[3] * w[2]);
        d[1] = 0.5 * (y[0] * w[0] + y[2] * w[2] - y[3] * w[1]);
        d[2] = 0.5 * (y[0] * w[1] + y[3] * w[0] - y[1] * w[2]);
        d[3] = 0.5 * (y[0] * w[2] + y[1] * w[1] - y[2] * w[0]);
        d[4] = y[5] * w[2] - y[6] * w[1];
        d[5] = y[6] * w[0] - y[4] * w[2];
        d[6] = y[4] * w[1] - y[5] * w[0];
    }
}

#[test]
fn every_regime_matches_dop853() {
    let q0 = UnitQuaternion::from_euler_angles(0.4, -1.2, 2.5);
    let cases: [([f64; 3], [f64; 3], Regime); 10] = [
        (
            [2.0, 1.0, 2.0 / 3.0],
            [1.1f64.cos(), 0.0, 1.1f64.sin()],
            Regime::AboutSmallest,
        ),
        ([1.0, 2.0, 3.0], [0.3, -0.2, 1.0], Regime::AboutLargest),
        ([1.0, 2.0, 3.0], [0.3, -0.2, -1.0], Regime::AboutLargest),
        ([1.0, 2.0, 3.0], [-1.0, 0.4, -0.3], Regime::AboutSmallest),
        ([3.0, 1.0, 2.0], [0.2, 1.0, -0.4], Regime::AboutSmallest),
        ([2.0, 3.0, 6.0], [1.0, 0.5, 1.0], Regime::Separatrix),
        ([3.0, 5.0, 9.0], [0.0, 2.0, 0.01], Regime::AboutLargest),
        ([1.0, 1.0, 2.0], [0.6, 0.3, 0.8], Regime::AboutLargest),
        ([1.0, 2.0, 2.0], [0.6, 0.3, 0.8], Regime::AboutSmallest),
        ([1.0, 2.0, 3.0], [0.0, 1.5, 0.0], Regime::Steady),
    ];
    let cfg = AdaptiveConfig::with_tol(1e-14, 1e-14);
    let mut worst = 0.0f64;
    for (i, m0, regime) in cases {
        let ex = FreeBodyAttitude::new(i, q0, m0).unwrap();
        assert_eq!(ex.regime(), regime);
        for t in [0.3, 7.0, 30.0] {
            let y0 = [q0.w, q0.i, q0.j, q0.k, m0[0], m0[1], m0[2]];
            let r = solve::<Dop853Pair, _, 7>(Ode(i), 0.0, y0, t, &[], cfg)
                .unwrap()
                .y;
            let qr = UnitQuaternion::from_quaternion(Quaternion::new(r[0], r[1], r[2], r[3]));
            let (q, m) = ex.at(t).unwrap();
            let e = q
                .angle_to(&qr)
                .max((Vector3::from(m) - Vector3::new(r[4], r[5], r[6])).amax());
            worst = worst.max(e);
            assert!(e <= 1e-10, "{i:?} {m0:?} t = {t}: {e:e}");
        }
    }
    eprintln!("exact attitude vs DOP853 (1e-14), worst over regimes and t ≤ 30: {worst:e}");
}

/// The flow composes: φ_{a+b} = φ_b ∘ φ_a, here for a long run cut into 100 pieces.
#[test]
fn flow_composes_over_long_times() {
    let (i, m0) = ([2.0, 1.0, 2.0 / 3.0], [1.1f64.cos(), 0.0, 1.1f64.sin()]);
    let q0 = UnitQuaternion::identity();
    let whole = FreeBodyAttitude::new(i, q0, m0)
        .unwrap()
        .at(1000.0)
        .unwrap();
    let (mut q, mut m) = (q0, Vector3::from(m0));
    for _ in 0..100 {
        (q, m) = FreeBodyAttitude::new(i, q, m).unwrap().at(10.0).unwrap();
    }
    let e = q
        .angle_to(&whole.0)
        .max((Vector3::from(m) - Vector3::from(whole.1)).amax());
    eprintln!("composition over t = 1000: {e:e}");
    assert!(e <= 1e-11, "{e:e}");
}

#[test]
fn bad_input() {
    let q0 = UnitQuaternion::identity();
    assert!(matches!(
        FreeBodyAttitude::new([0.0, 1.0, 2.0], q0, [1.0, 0.0, 0.0]),
        Err(ExactError::InvalidInertia { .. })
    ));
    let ex = FreeBodyAttitude::new([1.0, 2.0, 3.0], q0, [1.0, 0.2, 0.0]).unwrap();
    assert!(matches!(ex.at(f64::NAN), Err(ExactError::NonFinite { .. })));
}

/// Huge and tiny inputs: m → s m, I → c I gives m(t) → s m(t s/c); nothing overflows.
#[test]
fn scaling_law_with_extreme_magnitudes() {
    let (i, m0) = ([1.0, 2.0, 3.0], [0.3, -0.2, 1.0]);
    let q0 = UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3);
    let base = FreeBodyAttitude::new(i, q0, m0).unwrap();
    for (s, c) in [
        (1e150, 1e150),
        (1e-150, 1e-150),
        (1e200, 1e200),
        (3e-100, 7e-100),
    ] {
        let scaled = FreeBodyAttitude::new(i.map(|x| x * c), q0, m0.map(|x| x * s)).unwrap();
        let t = 2.5;
        let (qa, ma) = scaled.at(t * c / s).unwrap();
        let (qb, mb) = base.at(t).unwrap();
        let em = (Vector3::from(ma) / s - Vector3::from(mb)).amax();
        assert!(
            em <= 1e-13 && qa.angle_to(&qb) <= 1e-12,
            "s = {s:e}, c = {c:e}: {em:e} {:e}",
            qa.angle_to(&qb)
        );
    }
}

mod no_nan {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        /// Any f64 moments, momenta and times: a typed error or a finite unit quaternion.
        #[test]
        fn exact_attitude_finite_or_typed_error(
            i in prop::array::uniform3(any::<f64>()),
            m0 in prop::array::uniform3(any::<f64>()),
            euler in prop::array::uniform3(-4.0f64..4.0),
            t in any::<f64>(),
        ) {
            let q0 = UnitQuaternion::from_euler_angles(euler[0], euler[1], euler[2]);
            if let Ok(ex) = FreeBodyAttitude::new(i, q0, m0)
                && let Ok((q, m)) = ex.at(t)
            {
                prop_assert!(q.coords.iter().chain(m.iter()).all(|v| v.is_finite()));
                prop_assert!((q.quaternion().norm() - 1.0).abs() < 1e-15);
            }
        }

        /// Moderate random bodies: q(t) reproduces the conserved spatial momentum π = q m.
        #[test]
        fn spatial_momentum_is_conserved(
            i in prop::array::uniform3(0.1f64..10.0),
            m0 in prop::array::uniform3(-3.0f64..3.0),
            t in 0.0f64..100.0,
        ) {
            let q0 = UnitQuaternion::identity();
            let (q, m) = FreeBodyAttitude::new(i, q0, m0).unwrap().at(t).unwrap();
            let pi = q * Vector3::from(m);
            let g = Vector3::from(m0).norm().max(1e-300);
            prop_assert!((pi - Vector3::from(m0)).amax() <= 1e-13 * g, "{:e}", (pi - Vector3::from(m0)).amax());
        }
    }
}
