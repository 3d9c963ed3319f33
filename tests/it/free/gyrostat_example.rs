//! The `gyrostat` example's scene — the very struct it declares, included by path — against
//! the linear theory of a spin about the intermediate axis with a wheel on it.

#[path = "../../../examples/free_bodies/satellite.rs"]
mod satellite;

use approx::assert_relative_eq;
use satellite::{RPM, SPIN, Satellite, run};

#[test]
fn the_example_satellite_wobbles_and_flips_as_the_linear_theory_says() {
    let fast = Satellite {
        wheel: 3000.0 * RPM,
    };
    // The body's moments from its parts: bus ((b² + c²)/12 per kg) and wheel (½ m r²
    // about x, m (3 r² + l²)/12 across).
    let wheel_across = 2.0 * (3.0 * 0.01 + 0.0016) / 12.0;
    let expected = [
        100.0 * (1.44 + 0.64) / 12.0 + 0.01,
        100.0 * (1.0 + 0.64) / 12.0 + wheel_across,
        100.0 * (1.0 + 1.44) / 12.0 + wheel_across,
    ];
    for (m, e) in fast.moments().iter().zip(expected) {
        assert_relative_eq!(*m, e, max_relative = 1e-14);
    }
    let a = 1e-4 * SPIN;
    let stable = run(&fast, a, f64::INFINITY, 0.01, 300.0).unwrap();
    let period = 2.0 * std::f64::consts::PI / fast.k(SPIN).sqrt();
    assert_relative_eq!(stable.period, period, max_relative = 1e-3);
    // ω_y starts at its peak a, so this says only that the wobble does not grow; the
    // amplitude it drives in ω_z is the linear theory's a √k I_y/(h − (I_z − I_x) n).
    assert_relative_eq!(stable.largest, a, max_relative = 1e-3);
    assert_relative_eq!(
        stable.largest_z(),
        fast.z_amplitude(SPIN, a),
        max_relative = 1e-5
    );
    assert_relative_eq!(stable.momentum.1, stable.momentum.0, max_relative = 1e-11);
    assert_relative_eq!(stable.energy.1, stable.energy.0, max_relative = 1e-11);
    let slow = Satellite {
        wheel: 1000.0 * RPM,
    };
    assert!(slow.wheel < slow.threshold(SPIN) && fast.wheel > fast.threshold(SPIN));
    let growing = run(&slow, a, 100.0 * a, 0.01, 300.0).unwrap();
    let sigma = (-slow.k(SPIN)).sqrt();
    assert_relative_eq!(
        100f64.acosh() / growing.grown_at,
        sigma,
        max_relative = 2e-3
    );
}
