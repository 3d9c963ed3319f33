//! The physics `examples/chaos_map.rs` relies on, through its own code (`common/chaos.rs`):
//! the finite-time exponent of an integrable top falls as ln T / T, the intermediate-axis
//! rotation of a torque-free body has its closed-form exponent, and a chaotic cell of the
//! map has the exponent that two nearby trajectories, renormalised, give without the
//! tangent equations.

#[path = "../../examples/common/chaos.rs"]
mod chaos;

use chaos::{ASYMMETRIC, KOVALEVSKAYA, LAGRANGE, TORQUE_FREE};
use precess::ode::{AdaptiveConfig, Dop853};

/// The generic start the example's table uses: tilted 1 rad, turning about all three axes.
fn generic() -> [f64; 12] {
    chaos::state(1.0, [0.7, -0.2, 2.5])
}

/// Lagrange's and Kovalevskaya's tops are integrable: a tangent vector on their tori grows
/// linearly, so λ₁(T) ≈ ln(c T) / T. Both stay below 1.5 ln T / T at T = 100 and 400 (they
/// reach 0.6 to 0.85 of ln T / T), and four times the time at least halves the exponent (a
/// chaotic orbit's would stay where it is).
/// Two starts each: the example's generic one, and the cell where the map's top is chaotic
/// (θ0 = 0.5 rad, ω3 = 1 rad/s), where a top that is not integrable is likely to be chaotic
/// too (an asymmetric top may have regular orbits, so one start alone proves little).
#[test]
fn integrable_tops_have_exponents_falling_as_ln_t_over_t() {
    let starts = [generic(), chaos::state(0.5, [0.0, 0.0, 1.0])];
    for (name, top, x0) in [
        ("Lagrange", LAGRANGE, starts[0]),
        ("Lagrange", LAGRANGE, starts[1]),
        ("Kovalevskaya", KOVALEVSKAYA, starts[0]),
        ("Kovalevskaya", KOVALEVSKAYA, starts[1]),
    ] {
        let system = top.system().unwrap();
        let short = chaos::largest_exponent(&system, &x0, 100.0).unwrap();
        let long = chaos::largest_exponent(&system, &x0, 400.0).unwrap();
        eprintln!(
            "{name}: λ₁(100) = {short:.5} (ln T / T = {:.5}), λ₁(400) = {long:.5} ({:.5}), ratio {:.3}",
            100f64.ln() / 100.0,
            400f64.ln() / 400.0,
            long / short
        );
        assert!(
            short > 0.0 && short < 1.5 * 100f64.ln() / 100.0,
            "{name}: {short}"
        );
        assert!(long < 1.5 * 400f64.ln() / 400.0, "{name}: {long}");
        assert!(long < 0.5 * short, "{name}: {short} then {long}");
    }
}

/// The map's top with gravity off, turning at ω = 2 about body x (I = 1, between 0.6 and
/// 1.5): an equilibrium whose exponent is λ = ω √((I_m − I_s)(I_l − I_m)/(I_s I_l)) exactly.
#[test]
fn the_intermediate_axis_exponent_is_the_closed_form() {
    let omega = 2.0;
    let [i1, i2, i3] = TORQUE_FREE.inertia;
    let exact = chaos::intermediate_axis_exponent(i3, i1, i2, omega);
    let system = TORQUE_FREE.system().unwrap();
    let measured =
        chaos::largest_exponent(&system, &chaos::state(0.0, [omega, 0.0, 0.0]), 40.0).unwrap();
    eprintln!("intermediate axis: λ = {exact}, Benettin {measured}");
    assert!(
        (measured - exact).abs() < 1e-7 * exact,
        "{measured} vs {exact}"
    );
}

/// A cell of the map's chaotic region (θ0 = 0.5 rad, ω3 = 1 rad/s): Benettin's λ₁ against
/// the original two-trajectory estimate, which integrates only the state: a companion run
/// δ = 10⁻⁷ away, its separation measured and scaled back to δ every unit of time, the mean
/// of ln(d/δ) the exponent. It uses neither J nor the tangent equations. Over one orbit
/// both give its finite-time exponent, three times and more the integrable tops' level.
#[test]
fn a_chaotic_cell_agrees_with_two_nearby_trajectories() {
    let system = ASYMMETRIC.system().unwrap();
    let x0 = chaos::state(0.5, [0.0, 0.0, 1.0]);
    // Short enough that both methods follow one orbit: integration errors of 10⁻¹² grow
    // by e^{λ T} ≈ 10⁷ over the transient and the average, to 10⁻⁵ at most.
    let duration = 60.0;
    let tight = AdaptiveConfig::with_tol(1e-12, 1e-12);
    let benettin = system
        .lyapunov(0.0, &x0, &chaos::benettin(duration), tight)
        .unwrap()
        .exponents[0];

    // The augmented system's first twelve entries are the state; its tangent block rides
    // along unused (started at zero, it stays zero).
    let lift = |x: &[f64; 12]| {
        let mut y = [0.0; 24];
        y[..12].copy_from_slice(x);
        y
    };
    let delta = 1e-7;
    let mut companion = x0;
    companion[0] += delta; // ω1
    let mut a = Dop853::new(&system, 0.0, lift(&x0), tight).unwrap();
    let mut b = Dop853::new(&system, 0.0, lift(&companion), tight).unwrap();
    let (transient, mut sum) = (10.0, 0.0);
    let steps = (transient + duration) as usize;
    for k in 1..=steps {
        let t = k as f64;
        a.advance_to(t).unwrap();
        b.advance_to(t).unwrap();
        let (ya, yb) = (*a.y(), *b.y());
        let d = (0..12).map(|i| (yb[i] - ya[i]).powi(2)).sum::<f64>().sqrt();
        if t > transient {
            sum += (d / delta).ln();
        }
        let mut scaled = ya;
        for i in 0..12 {
            scaled[i] += (yb[i] - ya[i]) * delta / d;
        }
        b = Dop853::new(&system, t, scaled, tight).unwrap();
    }
    let two_trajectories = sum / duration;
    let regular = chaos::largest_exponent(&LAGRANGE.system().unwrap(), &generic(), duration)
        .unwrap()
        .max(
            chaos::largest_exponent(&KOVALEVSKAYA.system().unwrap(), &generic(), duration).unwrap(),
        );
    eprintln!(
        "chaotic cell, T = {duration}: Benettin {benettin:.5}, two trajectories \
         {two_trajectories:.5}, integrable level {regular:.5}"
    );
    assert!(benettin > 3.0 * regular, "{benettin} vs {regular}");
    assert!(
        (benettin - two_trajectories).abs() < 0.03 * benettin,
        "{benettin} vs {two_trajectories}"
    );
}
