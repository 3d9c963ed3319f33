//! Event functions with planted roots, shared by the event tests of every stepper: sums of
//! sines, a shallow dip planted at one of their local minima, and the roots found by brute
//! force to adjacent doubles.

/// Σ Aᵢ sin(ωᵢ t + φᵢ) for three terms.
pub fn sum_of_sines(
    amps: [f64; 3],
    omegas: [f64; 3],
    phases: [f64; 3],
) -> impl Fn(f64) -> f64 + Copy {
    move |t: f64| {
        (0..3)
            .map(|i| amps[i] * (omegas[i] * t + phases[i]).sin())
            .sum::<f64>()
    }
}

/// The derivative of [`sum_of_sines`].
pub fn sum_of_sines_slope(
    amps: [f64; 3],
    omegas: [f64; 3],
    phases: [f64; 3],
) -> impl Fn(f64) -> f64 + Copy {
    move |t: f64| {
        (0..3)
            .map(|i| amps[i] * omegas[i] * (omegas[i] * t + phases[i]).cos())
            .sum::<f64>()
    }
}

/// The roots of `g` on [0, t_end] by brute force: sign changes on a grid of `n` points,
/// each bisected to adjacent doubles.
pub fn brute_roots(g: &dyn Fn(f64) -> f64, t_end: f64, n: usize) -> Vec<f64> {
    let mut out = Vec::new();
    let mut prev = (0.0, g(0.0));
    for i in 1..=n {
        let t = t_end * i as f64 / n as f64;
        let v = g(t);
        if prev.1 != 0.0 && (prev.1 < 0.0) != (v < 0.0) {
            let (mut a, mut b) = (prev.0, t);
            let fa = prev.1;
            loop {
                let m = 0.5 * (a + b);
                if m <= a || m >= b {
                    break;
                }
                if (g(m) < 0.0) == (fa < 0.0) {
                    a = m;
                } else {
                    b = m;
                }
            }
            out.push(b);
        }
        prev = (t, v);
    }
    out
}

/// A local minimum of `s` (with derivative `ds`) near `t0`: downhill in steps of 1e-3 to
/// a change of sign of s′, then bisection on s′.
pub fn local_minimum(ds: impl Fn(f64) -> f64, t0: f64) -> f64 {
    let h = 1e-3;
    let mut t = t0;
    while ds(t) > 0.0 {
        t -= h;
    }
    while ds(t) < 0.0 {
        t += h;
    }
    let (mut lo, mut hi) = (t - h, t);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if ds(m) < 0.0 { lo = m } else { hi = m }
    }
    0.5 * (lo + hi)
}

/// The root of `g` nearest `from` in the direction `dir` (±1), g(from) < 0: steps of 1e-4
/// (within 1 of `from`) to a change of sign, then bisection on g to adjacent doubles.
pub fn root_beside(g: impl Fn(f64) -> f64, from: f64, dir: f64) -> Option<f64> {
    let mut t = from;
    while g(t + dir * 1e-4) < 0.0 {
        t += dir * 1e-4;
        if (t - from).abs() > 1.0 {
            return None;
        }
    }
    let (mut neg, mut pos) = (t, t + dir * 1e-4);
    loop {
        let m = 0.5 * (neg + pos);
        if m == neg || m == pos {
            return Some(pos);
        }
        if g(m) < 0.0 { neg = m } else { pos = m }
    }
}
