//! The thin uniform disk rolling without slip, in yaw φ, lean θ (0 upright), spin ψ and the
//! contact point (x, y), with x and y eliminated through the two nonholonomic rolling
//! constraints ẋ = r ψ̇ cos φ, ẏ = r ψ̇ sin φ: against the textbook equations derived by
//! Newton–Euler below, the friction force against m a_G, the contact point's velocity, the
//! energy along a run and the upright stability threshold Ω² = g/(3r).

use std::cell::RefCell;

use precess::lagrange::{ConstrainedEquations, ConstrainedModel, Constraints, Coordinates};
use precess::lagrange::{EquationsOfMotion, LagrangeError};
use precess::linalg::LinearSystem;
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::mat3::cross;
use precess::sym::{Arena, ExprId};
use proptest::prelude::*;

use crate::common::rng::Rng;

pub const M: f64 = 1.3;
pub const R: f64 = 0.4;
pub const G: f64 = 9.81;
const VALUES: [(&str, f64); 3] = [("m", M), ("r", R), ("g", G)];

/// The disk's Lagrangian, constraints and outputs: energy, the velocity of the material
/// point at the contact (3 components), and the normal force m (z̈_G + g).
pub fn rolling_disk(a: &mut Arena) -> Result<(ConstrainedEquations, Vec<ExprId>), LagrangeError> {
    let c = Coordinates::new(a, &["phi", "theta", "psi", "x", "y"]);
    let (m, r, g) = (a.parameter("m"), a.parameter("r"), a.parameter("g"));
    let [phi, theta, _, x, y] = [c.q[0], c.q[1], c.q[2], c.q[3], c.q[4]];
    let [dphi, dtheta, dpsi, _, _] = [c.rates[0], c.rates[1], c.rates[2], c.rates[3], c.rates[4]];
    let (sf, cf, st, ct) = (a.sin(phi), a.cos(phi), a.sin(theta), a.cos(theta));
    // Centre G = contact + r ẑ_L, ẑ_L = (sin φ sin θ, −cos φ sin θ, cos θ).
    let z_l = [
        a.mul(sf, st),
        {
            let p = a.mul(cf, st);
            a.neg(p)
        },
        ct,
    ];
    let (rz0, rz1) = (a.mul(r, z_l[0]), a.mul(r, z_l[1]));
    let centre = [a.add(x, rz0), a.add(y, rz1), a.mul(r, ct)];
    let v: Vec<ExprId> = centre.iter().map(|&p| a.dt(p)).collect();
    // ω in the lean frame L: (θ̇, φ̇ sin θ + ψ̇, φ̇ cos θ); moments m r²/4, m r²/2, m r²/4.
    let w1 = dtheta;
    let w2 = {
        let p = a.mul(dphi, st);
        a.add(p, dpsi)
    };
    let w3 = a.mul(dphi, ct);
    let quarter = a.number("0.25").map_err(LagrangeError::Sym)?;
    let half = a.number("0.5").map_err(LagrangeError::Sym)?;
    let r2 = a.mul(r, r);
    let mut t_terms = Vec::new();
    for vi in &v {
        t_terms.push(a.product(&[half, m, *vi, *vi]));
    }
    for (w, k) in [(w1, quarter), (w2, half), (w3, quarter)] {
        t_terms.push(a.product(&[half, k, m, r2, w, w]));
    }
    let kinetic = a.sum(&t_terms);
    let potential = a.product(&[m, g, r, ct]);
    let lagrangian = a.sub(kinetic, potential);
    let energy = a.add(kinetic, potential);
    let zero = a.zero();
    let eom = EquationsOfMotion::derive(a, lagrangian, c.clone(), &[zero; 5])?;
    let mut k = Constraints::new();
    let minus_r = a.neg(r);
    let row_x = [zero, zero, a.mul(minus_r, cf), a.one(), zero];
    let row_y = [zero, zero, a.mul(minus_r, sf), zero, a.one()];
    k.nonholonomic(a, &c, &row_x, zero)?;
    k.nonholonomic(a, &c, &row_y, zero)?;
    let eqs = eom.constrain(a, &k, None)?;
    // The contact's material velocity v_G + ω × (−r ẑ_L), ω = φ̇ ẑ + θ̇ x̂_Y + ψ̇ ŷ_L in space.
    let y_l = [
        {
            let p = a.mul(sf, ct);
            a.neg(p)
        },
        a.mul(cf, ct),
        st,
    ];
    let omega: Vec<ExprId> = (0..3)
        .map(|i| {
            let yaw = if i == 2 { dphi } else { zero };
            let lean = [a.mul(dtheta, cf), a.mul(dtheta, sf), zero][i];
            let spin = a.mul(dpsi, y_l[i]);
            a.sum(&[yaw, lean, spin])
        })
        .collect();
    let arm = z_l.map(|e| a.mul(minus_r, e));
    let turn = cross(a, &[omega[0], omega[1], omega[2]], &arm);
    let mut outputs = vec![energy];
    for i in 0..3 {
        outputs.push(a.add(v[i], turn[i]));
    }
    let z_dd = a.dt(v[2]);
    let lift = a.add(z_dd, g);
    outputs.push(a.mul(m, lift));
    Ok((eqs, outputs))
}

/// The textbook accelerations of the thin disk, from Newton–Euler in the lean frame
/// (m a_G = F − m g ẑ, dH_G/dt = −r ẑ_L × F, H_G = (A ω₁, B ω₂, A ω₃), A = m r²/4,
/// B = m r²/2): ω̇₁ = (6/5) ω₂ω₃ − (1/5) φ̇ sin θ ω₃ + (4g/5r) sin θ, ω̇₂ = −(2/3) ω₁ω₃,
/// ω̇₃ = −2 ω₁ω₂ + φ̇ sin θ ω₁, which in the angles read
/// φ̈ = −2 θ̇ ψ̇ / cos θ,
/// θ̈ = φ̇² sin θ cos θ + (6/5) φ̇ ψ̇ cos θ + (4g/5r) sin θ,
/// ψ̈ = −(5/3) φ̇ θ̇ cos θ + 2 θ̇ ψ̇ tan θ
/// (the forms SymPy issue 27631 quotes).
pub fn textbook(theta: f64, rates: [f64; 3]) -> [f64; 3] {
    let [dphi, dtheta, dpsi] = rates;
    let (s, c) = theta.sin_cos();
    [
        -2.0 * dtheta * dpsi / c,
        dphi * dphi * s * c + 1.2 * dphi * dpsi * c + 0.8 * G / R * s,
        -5.0 / 3.0 * dphi * dtheta * c + 2.0 * dtheta * dpsi * s / c,
    ]
}

/// m a_G (horizontal) from the angles' accelerations by hand: G = (x + r sin φ sin θ,
/// y − r cos φ sin θ), with ẍ = r (ψ̈ cos φ − ψ̇ φ̇ sin φ), ÿ = r (ψ̈ sin φ + ψ̇ φ̇ cos φ).
pub fn newton_friction(q: [f64; 3], qd: [f64; 3], qdd: [f64; 3]) -> [f64; 2] {
    let ([phi, th, _], [dp, dt, ds], [ap, at, as_]) = (q, qd, qdd);
    let (sf, cf) = phi.sin_cos();
    let (st, ct) = th.sin_cos();
    let xdd = R * (as_ * cf - ds * dp * sf);
    let ydd = R * (as_ * sf + ds * dp * cf);
    let f2 = -sf * st * dp * dp + 2.0 * cf * ct * dp * dt - sf * st * dt * dt
        + cf * st * ap
        + sf * ct * at;
    let g2 = cf * st * dp * dp + 2.0 * sf * ct * dp * dt + cf * st * dt * dt + sf * st * ap
        - cf * ct * at;
    [M * (xdd + R * f2), M * (ydd + R * g2)]
}

thread_local! {
    static DISK: RefCell<Option<ConstrainedModel>> = const { RefCell::new(None) };
}

fn with_disk<T>(f: impl FnOnce(&ConstrainedModel) -> T) -> T {
    DISK.with(|cell| {
        let mut slot = cell.borrow_mut();
        let model = slot.get_or_insert_with(|| {
            let mut a = Arena::new();
            let (eqs, outputs) = rolling_disk(&mut a).expect("the disk derives");
            assert_eq!(
                eqs.dependent,
                [3, 4],
                "x and y are the dependent coordinates"
            );
            ConstrainedModel::new(&mut a, &eqs, &outputs, &VALUES).expect("binds")
        });
        f(model)
    })
}

fn scale(x: &[f64]) -> f64 {
    x.iter().fold(1.0_f64, |s, v| s.max(v.abs()))
}

fn check_state(q: [f64; 5], u: [f64; 3]) {
    with_disk(|model| {
        let state: Vec<f64> = q.iter().chain(&u).copied().collect();
        let qdd = model.accelerations(0.0, &state).expect("regular");
        let want = textbook(q[1], u);
        let tol = 1e-13 * scale(&want);
        for i in 0..3 {
            assert!(
                (qdd[i] - want[i]).abs() <= tol,
                "q̈[{i}] = {} against {} at q = {q:?}, u = {u:?}",
                qdd[i],
                want[i]
            );
        }
        let lambda = model.multipliers(0.0, &state).expect("regular");
        let friction = newton_friction([q[0], q[1], q[2]], u, want);
        // Rounding of the largest terms, m r ψ̇² and m r ψ̈, not of their small sum.
        let tol = 1e-13 * M * R * (scale(&u).powi(2) + scale(&want));
        for i in 0..2 {
            assert!(
                (lambda[i] - friction[i]).abs() <= tol,
                "λ[{i}] = {} against m a_G = {}",
                lambda[i],
                friction[i]
            );
        }
        let out = model.outputs(0.0, &state).expect("finite");
        let slip = out[1..4].iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        assert!(
            slip <= 1e-15 * R * scale(&u) * 8.0,
            "contact slips at {slip:e}"
        );
        // The normal force, an output reading θ̈: m g − m r (cos θ θ̇² + sin θ θ̈).
        let (st, ct) = q[1].sin_cos();
        let normal = M * G - M * R * (ct * u[1] * u[1] + st * want[1]);
        let tol = 1e-13 * M * (G + R * (u[1] * u[1] + want[1].abs()));
        assert!(
            (out[4] - normal).abs() <= tol,
            "N = {} against {normal}",
            out[4]
        );
    });
}

#[test]
fn accelerations_and_friction_match_newton_euler_at_fixed_states() {
    let mut rng = Rng::new(24);
    for _ in 0..200 {
        let q = [
            rng.uniform(-3.0, 3.0),
            rng.uniform(-1.3, 1.3),
            rng.uniform(-3.0, 3.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        ];
        let u = [
            rng.uniform(-6.0, 6.0),
            rng.uniform(-6.0, 6.0),
            rng.uniform(-20.0, 20.0),
        ];
        check_state(q, u);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any state off the chart's singularity (|θ| < 1.5): the three accelerations, the
    /// friction and the contact's zero velocity.
    #[test]
    fn accelerations_match_newton_euler_at_any_state(
        phi in -6.3..6.3_f64, theta in -1.5..1.5_f64, psi in -6.3..6.3_f64,
        x in -10.0..10.0_f64, y in -10.0..10.0_f64,
        dphi in -30.0..30.0_f64, dtheta in -30.0..30.0_f64, dpsi in -100.0..100.0_f64,
    ) {
        check_state([phi, theta, psi, x, y], [dphi, dtheta, dpsi]);
    }
}

#[test]
fn energy_is_conserved_and_the_contact_stays_still_along_a_run() {
    with_disk(|model| {
        // Rolling on a circle while wobbling: lean 0.3 rad, yaw rate 1, spin 8.
        let y0 = [0.0, 0.3, 0.0, 0.0, 0.0, 1.0, 0.2, 8.0];
        let e0 = model.outputs(0.0, &y0).expect("finite")[0];
        let cfg = AdaptiveConfig::with_tol(1e-13, 1e-13);
        let mut ode =
            Dop853::new(model.system::<8>().expect("n + k = 8"), 0.0, y0, cfg).expect("starts");
        let mut worst = 0.0_f64;
        for k in 1..=100 {
            ode.advance_to(k as f64 * 0.5).expect("integrates");
            let out = model.outputs(ode.t(), ode.y()).expect("finite");
            worst = worst.max(((out[0] - e0) / e0).abs());
            let slip = out[1..4].iter().fold(0.0_f64, |s, v| s.max(v.abs()));
            assert!(slip < 1e-13, "slip {slip:e} at t = {}", ode.t());
        }
        // Measured: 3.5e-13 relative over 50 s (about 64 spin turns) at rtol 1e-13.
        assert!(worst < 1e-12, "energy drifts by {worst:e}");
    });
}

/// The growth rate of a lean disturbance of upright rolling at spin Ω, linearised from
/// θ̈ = (6/5) Ω φ̇ + (4g/5r) θ and φ̈ = −2 Ω θ̇: λ² = 4g/(5r) − (12/5) Ω², so upright
/// rolling is stable exactly for Ω² > g/(3r).
fn growth_rate(omega: f64) -> f64 {
    (0.8 * G / R - 2.4 * omega * omega).max(0.0).sqrt()
}

#[test]
fn upright_rolling_is_stable_above_omega_squared_g_over_3r() {
    let threshold = (G / (3.0 * R)).sqrt();
    with_disk(|model| {
        let system = model.system::<8>().expect("n + k = 8");
        for factor in [0.5, 0.9, 0.99, 1.01, 1.1, 2.0] {
            let omega = factor * threshold;
            let y0 = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, omega];
            let lin = LinearSystem::from_system(&system, 0.0, &y0).expect("finite");
            let eig = lin.eigenvalues().expect("converges");
            let largest = eig.iter().map(|z| z.re).fold(f64::NEG_INFINITY, f64::max);
            let want = growth_rate(omega);
            if factor < 1.0 {
                assert!(
                    (largest - want).abs() < 1e-7 * want,
                    "Ω = {factor} Ω_c: growth {largest} against {want}"
                );
            } else {
                assert!(largest.abs() < 1e-7, "Ω = {factor} Ω_c: growth {largest}");
                // The wobble frequency √((12/5) Ω² − 4g/(5r)).
                let freq = (2.4 * omega * omega - 0.8 * G / R).sqrt();
                let got = eig.iter().map(|z| z.im).fold(0.0_f64, f64::max);
                assert!(
                    (got - freq).abs() < 1e-7 * freq,
                    "wobble {got} against {freq}"
                );
            }
        }
    });
}
