//! Events compiled by `taylor_system!` (`event Name = g;`): their Taylor coefficients against
//! the interpreted `TaylorEvent` of the same expression on random jets (bit for bit: the
//! emitted code runs the interpreter's steps in its order), the component event g = yᵢ
//! against the jet's column, and the heavy top's θ̇ = 0 maxima against the nutation period of
//! `HeavyTopTheory` (closed form, elliptic functions).

use precess::ode::{Direction, Event, Run};
use precess::prelude::*;
use precess::sym::{Arena, ExprId};
use precess::taylor::{EventSeries, Taylor, TaylorConfig, TaylorEvent};
use precess::top::HeavyTopTheory;
use precess_testkit::systems::SpinningTop;

precess::taylor_system! {
    /// The symmetric heavy top in Euler–Poisson form (ω and the upward vertical γ in body
    /// axes), r = (I1 − I3)/I1, s = M g l / I1, with three events: θ̇ up to a positive factor,
    /// cos θ = γ3 (a state component), and a g of the time, a quotient and a sine.
    #[derive(Clone, Copy, Debug)]
    struct Top {
        r: f64,
        s: f64,
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
    event CosTheta = g3;
    event Mixed = (w1 * g3).sin() / (g1 * g1 + 2.0) - r * t;
    event Clock = t - r;
    event Constant = r + 1.0;
}

/// The same event functions as interpreted `TaylorEvent`s, built as the macro lowers them.
fn interpreted(top: &Top) -> [TaylorEvent<6>; 5] {
    let mut a = Arena::new();
    let y: [ExprId; 6] = ["w1", "w2", "w3", "g1", "g2", "g3"].map(|n| a.coordinate(n));
    let [w1, w2, _, g1, g2, g3] = y;
    let r = a.parameter("r");
    let t = a.time();
    let (p, q) = (a.mul(g2, w1), a.mul(g1, w2));
    let theta_rate = a.sub(p, q);
    let arg = a.mul(w1, g3);
    let sine = a.sin(arg);
    let sq = a.mul(g1, g1);
    let two = a.integer(2);
    let den = a.add(sq, two);
    let quotient = a.div(sine, den).unwrap();
    let rt = a.mul(r, t);
    let mixed = a.sub(quotient, rt);
    let clock = a.sub(t, r);
    let one = a.integer(1);
    let constant = a.add(r, one);
    let values = [("r", top.r)];
    [
        TaylorEvent::new(&a, y, None, theta_rate, &[]).unwrap(),
        TaylorEvent::new(&a, y, None, g3, &[]).unwrap(),
        TaylorEvent::new(&a, y, Some(t), mixed, &values).unwrap(),
        TaylorEvent::new(&a, y, Some(t), clock, &values).unwrap(),
        TaylorEvent::new(&a, y, None, constant, &values).unwrap(),
    ]
}

/// A deterministic pseudo-random jet (xorshift), entries in (−1, 1).
fn random_jet(seed: u64, p: usize) -> Vec<[f64; 6]> {
    let mut s = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    (0..=p).map(|_| std::array::from_fn(|_| next())).collect()
}

/// gₖ of `g` for k = 0 … p along `jet` at time `t`.
fn series<G: EventSeries<6>>(g: &G, t: f64, jet: &[[f64; 6]], p: usize) -> Vec<u64> {
    let mut out = vec![0.0; p + 1];
    g.coefficients_into(
        &mut G::Workspace::default(),
        t,
        &jet[0],
        &jet[1..],
        &mut out,
    );
    out.into_iter().map(f64::to_bits).collect()
}

#[test]
fn compiled_events_are_the_interpreted_ones_bit_for_bit_on_random_jets() {
    let top = Top { r: 0.73, s: 169.7 };
    let [theta_rate, cos_theta, mixed, clock, constant] = interpreted(&top);
    for seed in 0..200u64 {
        // Orders 0 … 24 (the system's maximum), jets of every length up to it.
        let p = (seed % 25) as usize;
        let jet = random_jet(seed, p);
        let t = 0.1 * seed as f64;
        assert_eq!(
            series(&ThetaRate(&top), t, &jet, p),
            series(&theta_rate, t, &jet, p)
        );
        assert_eq!(
            series(&CosTheta(&top), t, &jet, p),
            series(&cos_theta, t, &jet, p)
        );
        assert_eq!(series(&Mixed(&top), t, &jet, p), series(&mixed, t, &jet, p));
        // A g of the time alone (the time's series t, 1, 0, …) and a constant one.
        assert_eq!(series(&Clock(&top), t, &jet, p), series(&clock, t, &jet, p));
        assert_eq!(
            series(&Constant(&top), t, &jet, p),
            series(&constant, t, &jet, p)
        );
        // The component event is the jet's column itself.
        let column: Vec<u64> = jet.iter().map(|row| row[5].to_bits()).collect();
        assert_eq!(series(&CosTheta(&top), t, &jet, p), column);
    }
}

#[test]
fn a_short_output_or_a_short_jet_bounds_the_orders_written() {
    let top = Top { r: 0.73, s: 169.7 };
    let jet = random_jet(7, 10);
    // Four orders asked of a jet of eleven: g₀ … g₃, the rows past them unread.
    let mut short = [0.0; 4];
    ThetaRate(&top).coefficients_into(&mut Vec::new(), 0.0, &jet[0], &jet[1..], &mut short);
    let mut long = [0.0; 11];
    ThetaRate(&top).coefficients_into(&mut Vec::new(), 0.0, &jet[0], &jet[1..], &mut long);
    assert_eq!(short, long[..4]);
    // Eleven asked of a jet of four: g₀ … g₃ written, the rest left as they were.
    let mut out = [f64::NAN; 11];
    ThetaRate(&top).coefficients_into(&mut Vec::new(), 0.0, &jet[0], &jet[1..4], &mut out);
    assert_eq!(out[..4], long[..4]);
    assert!(out[4..].iter().all(|v| v.is_nan()));
}

/// The top released at rest 20° from the vertical spinning at 150 rad/s about its axis:
/// the system, its initial state and the exact nutation period.
fn heavy_top() -> (Top, [f64; 6], f64) {
    let top = SpinningTop;
    let moments = top.principal().moments;
    let (i1, i3) = (moments[0], moments[2]);
    let mgl = top.mass() * 9.81 * top.center_of_mass().z;
    let theta0 = 20f64.to_radians();
    let period = HeavyTopTheory::new(i1, i3, mgl)
        .unwrap()
        .motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, 150.0])
        .unwrap()
        .nutation_period();
    let system = Top {
        r: (i1 - i3) / i1,
        s: mgl / i1,
    };
    (
        system,
        [0.0, 0.0, 150.0, 0.0, theta0.sin(), theta0.cos()],
        period,
    )
}

/// The times of the falling crossings of `g` over `periods` nutation periods.
fn maxima<G: EventSeries<6>>(top: Top, y0: [f64; 6], t_end: f64, g: &G) -> Vec<f64> {
    let mut ode = Taylor::new(top, 0.0, y0, TaylorConfig::with_tol(1e-12, 1e-12)).unwrap();
    let out = Run::new(&mut ode, t_end)
        .sample_none()
        .taylor_event(Event::new("maximum").falling(), g)
        .integrate()
        .unwrap();
    out.events
        .iter()
        .filter(|h| h.direction == Direction::Falling)
        .map(|h| h.t)
        .collect()
}

#[test]
fn the_compiled_theta_rate_event_finds_the_nutation_maxima_of_the_closed_form() {
    let (top, y0, period) = heavy_top();
    let t_end = 10.25 * period;
    let compiled = maxima(top, y0, t_end, &ThetaRate(&top));
    // Released at rest at θ0, the top falls: θ0 is θ's minimum, and the maxima are half a
    // period later and then once a period, at (k + ½) T, k = 0 … 9.
    assert_eq!(compiled.len(), 10, "{compiled:?}");
    for (k, t) in compiled.iter().enumerate() {
        let exact = (k as f64 + 0.5) * period;
        assert!(
            (t - exact).abs() < 1e-11 * exact.max(1.0),
            "maximum {k}: {t} against {exact}"
        );
    }
    // The interpreted event's run is the same run: its coefficients are the same bits.
    let [theta_rate, ..] = interpreted(&top);
    let interpreted = maxima(top, y0, t_end, &theta_rate);
    assert_eq!(
        compiled.iter().map(|t| t.to_bits()).collect::<Vec<_>>(),
        interpreted.iter().map(|t| t.to_bits()).collect::<Vec<_>>()
    );
}

#[test]
fn the_component_event_finds_where_the_closed_form_s_cos_theta_crosses_zero() {
    // Released at rest 85° from the vertical, the fast top nods down past the horizontal
    // (θ_max > 90°) and back once a period: γ3 = cos θ, a state component, crosses 0 twice
    // a period. Each hit against the closed form's cos θ there, and their count against the
    // closed form's sign changes on a fine grid.
    let (top, _, _) = heavy_top();
    let theta0 = 85f64.to_radians();
    let y0 = [0.0, 0.0, 150.0, 0.0, theta0.sin(), theta0.cos()];
    let sm = SpinningTop;
    let moments = sm.principal().moments;
    let mgl = sm.mass() * 9.81 * sm.center_of_mass().z;
    let motion = HeavyTopTheory::new(moments[0], moments[2], mgl)
        .unwrap()
        .motion_from_angles(&[0.0, theta0, 0.0], &[0.0, 0.0, 150.0])
        .unwrap();
    assert!(motion.theta_max() > std::f64::consts::FRAC_PI_2 + 0.01);
    let t_end = 5.3 * motion.nutation_period();
    let mut ode = Taylor::new(top, 0.0, y0, TaylorConfig::with_tol(1e-12, 1e-12)).unwrap();
    let out = Run::new(&mut ode, t_end)
        .sample_none()
        .taylor_event(Event::new("horizontal"), &CosTheta(&top))
        .integrate()
        .unwrap();
    let hits: Vec<f64> = out.events.iter().map(|h| h.t).collect();
    for t in &hits {
        let c = motion.cos_theta_at(*t).unwrap();
        assert!(c.abs() < 1e-9, "cos θ({t}) = {c} in the closed form");
    }
    let grid = 20_000;
    let signs: Vec<bool> = (0..=grid)
        .map(|i| motion.cos_theta_at(t_end * i as f64 / grid as f64).unwrap() > 0.0)
        .collect();
    let changes = signs.windows(2).filter(|w| w[0] != w[1]).count();
    assert_eq!(hits.len(), changes, "{hits:?}");
    assert!(changes >= 10);
}
