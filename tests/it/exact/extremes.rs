//! The exact side at the edges of f64: Carlson's integrals from 1e-320 to 1e308, F at m = 1,
//! torque-free states 1e-170 off a principal axis (against the linearised motion, which is
//! exact there to O(ε²)), and a top 1e-155 rad from vertical through the exact free flow.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess_core::exact::carlson::{ellip_f, ellip_f_sc, rf, rj};
use precess_core::exact::{ExactError, FreeBodyAttitude, FreeBodyExact, Regime};
use precess_core::rigid::{
    BodyMomentum, ExactFreeFlow, FreeBodySplitting, Gravity, PotentialSplitting, SplittingOrder,
};

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn carlson_integrals_over_the_whole_f64_range() {
    // R_F(x, x, x) = 1/√x: the sum x + y + z overflowed and the duplication never ended.
    assert!(rel(rf(1e308, 1e308, 1e308).unwrap(), 1e-154) < 1e-15);
    assert!(
        rel(
            rf(f64::MAX, f64::MAX, f64::MAX).unwrap(),
            1.0 / f64::MAX.sqrt()
        ) < 1e-15
    );
    // Homogeneity, R_F(λ·) = R_F(·)/√λ, far outside the range the duplication takes directly.
    let base = rf(1.0, 2.0, 3.0).unwrap();
    for e in [1000, 1020, -1000, -1030, -1070] {
        // 2^e in two factors (2f64.powi alone underflows below 2^-1022); 2^e·{1, 2, 3} is
        // exact even where subnormal.
        let l = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        let v = rf(l, 2.0 * l, 3.0 * l).unwrap();
        assert!(rel(v, base / l.sqrt()) < 1e-15, "λ = 2^{e}: {v:e}");
    }
    // R_F(0, y, y) = π/(2√y) with subnormal y.
    let y = 1e-320;
    assert!(
        rel(
            rf(0.0, y, y).unwrap(),
            std::f64::consts::FRAC_PI_2 / y.sqrt()
        ) < 1e-3
    );
    // Two arguments 1e-300 of the third: the logarithmic limit ln(4√z/(√x + √y))/√z.
    let v = rf(1e-300, 4e-300, 1.0).unwrap();
    assert!(rel(v, (4.0 / (1e-150 + 2e-150f64)).ln()) < 1e-15, "{v}");

    // R_J at p ≫ x, y, z: (3/p) R_F(x, y, z) − 3π/(2p^{3/2}) + …; the products of the
    // duplication overflowed and the error reported NaN arguments.
    let v = rj(1.0, 2.0, 3.0, 1e308).unwrap();
    assert!(rel(v, 3.0 * base / 1e308) < 1e-13, "{v:e}");
    // The same regime inside the directly-taken range, where the duplication crawled (p
    // shrinks by 4 per step while x, y, z stay) until its factors 4⁻³ⁿ underflowed.
    let v = rj(1e-110, 2e-110, 3e-110, 1.0).unwrap();
    assert!(
        rel(v, 3.0 * base * 1e55 - 1.5 * std::f64::consts::PI) < 1e-13,
        "{v:e}"
    );
    // Homogeneity of degree −3/2 at 2^±400, and an overflow named as one.
    let rj0 = rj(0.0, 1.0, 2.0, 3.0).unwrap();
    for e in [400, -400] {
        let l = 2f64.powi(e);
        let v = rj(0.0, l, 2.0 * l, 3.0 * l).unwrap();
        assert!(
            rel(v, rj0 * 2f64.powi(-3 * e / 2)) < 1e-13,
            "λ = 2^{e}: {v:e}"
        );
    }
    let tiny = 1e-300;
    assert_eq!(
        rj(0.0, tiny, 2.0 * tiny, 3.0 * tiny),
        Err(ExactError::CarlsonRange {
            x: 0.0,
            y: tiny,
            z: 2.0 * tiny,
            p: 3.0 * tiny
        })
    );
    let msg = rj(0.0, tiny, 2.0 * tiny, 3.0 * tiny)
        .unwrap_err()
        .to_string();
    assert!(msg.contains("outside the range of f64"), "{msg}");
}

#[test]
fn legendre_f_at_m_one_has_no_value_past_a_quarter_turn() {
    // F(φ | 1) = atanh(sin φ) for |φ| < π/2, and ∞ at π/2: ellip_f(2, 0) returned Ok(inf).
    assert!(rel(ellip_f(1.2, 0.0).unwrap(), 1.2f64.sin().atanh()) < 1e-14);
    assert_eq!(ellip_f(2.0, 0.0), Err(ExactError::Diverges { phi: 2.0 }));
    assert!(matches!(
        ellip_f(-4.0, 0.0),
        Err(ExactError::Diverges { .. })
    ));
    assert!(matches!(
        ellip_f_sc(0.0, -1.0, 0.0),
        Err(ExactError::Diverges { .. })
    ));
    assert!(matches!(
        ellip_f_sc(1.0, 0.0, 0.0),
        Err(ExactError::Diverges { .. })
    ));
    // With m_c > 0 the same amplitudes are fine: F(π | m) = 2K.
    assert!(ellip_f(2.0, 1e-12).unwrap().is_finite());
}

/// ṁ = m × I⁻¹m linearised about m = m_a e_a (exact to O(ε²) while the other components
/// are ε-small): the two small components obey a 2×2 linear system with
/// ṁ_b = m_a m_c (1/I_a − 1/I_c), ṁ_c = m_a m_b (1/I_b − 1/I_a) for (a, b, c) cyclic,
/// solved in closed form with cos/cosh.
fn linearised(i: [f64; 3], m0: [f64; 3], a: usize, t: f64) -> [f64; 3] {
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    let ma = m0[a];
    let p = ma * (1.0 / i[a] - 1.0 / i[c]); // ṁ_b = p m_c
    let q = ma * (1.0 / i[b] - 1.0 / i[a]); // ṁ_c = q m_b
    let k = p * q;
    let mut out = [0.0; 3];
    out[a] = ma;
    if k < 0.0 {
        let w = (-k).sqrt();
        let (s, co) = (w * t).sin_cos();
        out[b] = m0[b] * co + p * m0[c] * s / w;
        out[c] = m0[c] * co + q * m0[b] * s / w;
    } else {
        let w = k.sqrt();
        let (s, co) = ((w * t).sinh(), (w * t).cosh());
        out[b] = m0[b] * co + p * m0[c] * s / w;
        out[c] = m0[c] * co + q * m0[b] * s / w;
    }
    out
}

#[test]
fn states_1e_170_off_a_principal_axis() {
    let i = [1.0, 2.0, 3.0];
    let eps = 1e-170;
    // About the largest and the smallest axis (stable), and the state off the
    // intermediate axis (unstable: it grows like cosh(0.289 t) and is still 1e-45 at
    // t = 1000). Before, D₃ (or D₁, D₂) underflowed and each failed with a domain error.
    let cases = [
        ([eps, 2.0 * eps, 1.0], 2, Regime::AboutLargest),
        ([-1.0, eps, -3.0 * eps], 0, Regime::AboutSmallest),
        ([eps, 1.0, 0.0], 1, Regime::AboutSmallest),
        ([0.0, 1.0, eps], 1, Regime::AboutLargest),
    ];
    for (m0, axis, regime) in cases {
        let fb = FreeBodyExact::new(i, m0).unwrap();
        assert_eq!(fb.regime(), regime, "{m0:?}");
        for t in [0.5, 7.0, 100.0, 1000.0] {
            let m = fb.m_at(t).unwrap();
            let r = linearised(i, m0, axis, t);
            let scale = r.iter().map(|v| v.abs()).fold(0.0, f64::max);
            for k in 0..3 {
                let e = (m[k] - r[k]).abs();
                // Components of size ε: relative accuracy of the elliptic functions.
                let tol = if k == axis {
                    1e-15
                } else {
                    1e-11 * r[(axis + 1) % 3].abs().max(r[(axis + 2) % 3].abs())
                };
                assert!(
                    e <= tol.max(1e-300),
                    "{m0:?} t = {t}: m[{k}] = {:e}, linear {:e} (scale {scale:e})",
                    m[k],
                    r[k]
                );
            }
        }
    }
    // Off the intermediate axis the body leaves along the separatrix and comes back: the
    // motion is periodic with K ≈ ln(4/k') ≈ 392, and |m|, H stay put through it.
    let fb = FreeBodyExact::new(i, [eps, 1.0, 0.0]).unwrap();
    assert!(fb.k() > 390.0 && fb.k() < 395.0, "K = {}", fb.k());
    let h0 = 0.5 / i[1];
    for t in [1300.0, 1400.0, 2000.0, 4000.0, fb.period() / 2.0] {
        let m = fb.m_at(t).unwrap();
        let g2: f64 = m.iter().map(|v| v * v).sum();
        let h = 0.5 * (m[0] * m[0] / i[0] + m[1] * m[1] / i[1] + m[2] * m[2] / i[2]);
        assert!(
            (g2 - 1.0).abs() < 1e-14 && (h - h0).abs() < 1e-14,
            "t = {t}: {m:?}"
        );
    }
    // Half a period later m₂ has turned over: m ≈ (∓ε-ish, −1, 0).
    let m = fb.m_at(fb.period() / 2.0).unwrap();
    assert!((m[1] + 1.0).abs() < 1e-12, "{m:?}");
}

#[test]
fn attitude_1e_170_off_the_intermediate_axis() {
    let i = [1.0, 2.0, 3.0];
    let q0 = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.1);
    let m0 = [1e-170, 1.0, 0.0];
    let ex = FreeBodyAttitude::new(i, q0, m0).unwrap();
    // While m stays on the axis the body spins uniformly about body axis 2 at ω₂ = 1/2.
    for t in [1.0, 10.0, 100.0] {
        let (q, _) = ex.at(t).unwrap();
        let spin = q0 * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.5 * t);
        assert!(
            q.angle_to(&spin) < 1e-13,
            "t = {t}: {:e}",
            q.angle_to(&spin)
        );
    }
    // Through the excursion the spatial momentum π = q m stays that of t = 0.
    let pi0 = q0 * Vector3::from(m0);
    for t in [1300.0, 1400.0, 3000.0] {
        let (q, m) = ex.at(t).unwrap();
        let e = (q * Vector3::from(m) - pi0).amax();
        assert!(e < 1e-12, "t = {t}: {e:e}");
    }
}

#[test]
fn a_quaternion_that_is_no_rotation_is_refused() {
    let zero = UnitQuaternion::new_unchecked(Quaternion::new(0.0, 0.0, 0.0, 0.0));
    assert_eq!(
        FreeBodyAttitude::new([1.0, 2.0, 3.0], zero, [1.0, 0.2, 0.0]),
        Err(ExactError::NotUnitQuaternion { norm: 0.0 })
    );
    let long = UnitQuaternion::new_unchecked(Quaternion::new(1.0, 1.0, 0.0, 0.0));
    assert!(matches!(
        FreeBodyAttitude::new([1.0, 2.0, 3.0], long, [1.0, 0.2, 0.0]),
        Err(ExactError::NotUnitQuaternion { .. })
    ));
}

#[test]
fn a_top_1e_155_rad_from_vertical_through_the_exact_flow() {
    // A symmetric top (I₁ = I₂ = 1, I₃ = 0.5 about the pivot, Mgl = 1) spinning at ω₃ = 50,
    // tilted 1e-155: the kicks give m₁, m₂ ~ 1e-157, whose squares underflowed. For a
    // symmetric body the axis splitting is itself exact, so it is the reference.
    let gravity = Gravity {
        weight: 1.0,
        c: Vector3::new(0.0, 0.0, 1.0),
    };
    let exact = PotentialSplitting {
        free: ExactFreeFlow::new([1.0, 1.0, 0.5]).unwrap(),
        potential: gravity,
    };
    let axis = PotentialSplitting {
        free: FreeBodySplitting::new([1.0, 1.0, 0.5], SplittingOrder::Two).unwrap(),
        potential: gravity,
    };
    for tilt in [1e-155, 1e-200, 1e-300] {
        let y0 = BodyMomentum {
            q: UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt),
            m: Vector3::new(0.0, 0.0, 25.0),
        };
        let (mut a, mut b) = (y0, y0);
        exact.run(&mut a, 0.01, 200).unwrap();
        axis.run(&mut b, 0.01, 200).unwrap();
        assert!(
            a.q.angle_to(&b.q) < 1e-12,
            "tilt {tilt:e}: {:e}",
            a.q.angle_to(&b.q)
        );
        // The transverse momentum stays ε-sized and agrees in relative terms.
        let (ta, tb) = (a.m.xy(), b.m.xy());
        assert!(
            (ta - tb).amax() <= 1e-9 * tb.amax() && tb.amax() < 1e3 * tilt,
            "tilt {tilt:e}: {ta:?} vs {tb:?}"
        );
    }
}
