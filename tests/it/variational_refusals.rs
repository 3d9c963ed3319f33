//! Variational equations that refuse what would give a made-up answer, and Lyapunov
//! exponents of a tangent vector that shrinks far between renormalisations, against the
//! exponent of a linear equation, which is its coefficient.

use nalgebra::DMatrix;
use precess::ode::{AdaptiveConfig, Dop853};
use precess::sym::Arena;
use precess::variational::{
    BenettinConfig, FlowMap, Layout, VariationalEquations, VariationalError, VariationalSystem,
    benettin,
};

/// x′ = −k x: its one Lyapunov exponent is −k exactly.
fn decay(a: &mut Arena) -> VariationalEquations {
    let (x, k) = (a.input("x"), a.parameter("k"));
    let kx = a.mul(k, x);
    let f = a.neg(kx);
    VariationalEquations::new(a, &[x], &[f], 1, &[]).unwrap()
}

/// x′ = −1000 x renormalised every 1 and every 0.01: −1000 both times. The vector shrank to
/// e⁻¹⁰⁰⁰ within the long interval, far below atol, and the run gave −27.8.
#[test]
fn a_tangent_vector_shrinking_below_atol_keeps_its_exponent() {
    let mut a = Arena::new();
    let eq = decay(&mut a);
    let sys = VariationalSystem::<2>::new(&a, &eq, &[("k", 1000.0)]).unwrap();
    let ode = AdaptiveConfig::with_tol(1e-10, 1e-10);
    for interval in [1.0, 0.01] {
        let cfg = BenettinConfig {
            interval,
            duration: 5.0,
            transient: 0.0,
        };
        let spectrum = sys.lyapunov(0.0, &[1.0], &cfg, ode).unwrap();
        let lambda = spectrum.exponents[0];
        assert!(
            (lambda + 1000.0).abs() < 1e-6 * 1000.0,
            "interval {interval}: λ = {lambda} against −1000"
        );
    }
}

/// A layout built by hand with three tangent vectors of a state of two: `benettin` made up
/// an exponent from the sensitivity's slots, `initial_state` indexed past the end.
#[test]
fn a_hand_built_layout_with_too_many_tangents_is_refused() {
    let mut a = Arena::new();
    let x = ["x", "v"].map(|n| a.input(n));
    let k = a.parameter("k");
    let kx = a.mul(k, x[0]);
    let f = a.neg(kx);
    // n = 2, two tangents and one sensitivity: 2 + 4 + 2 = 8 entries, as many as
    // n = 2 with three tangents (2 + 6).
    let eq = VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[k]).unwrap();
    let sys = VariationalSystem::<8>::new(&a, &eq, &[("k", 1.0)]).unwrap();
    let too_many = Layout {
        n: 2,
        tangents: 3,
        sensitivities: 0,
    };
    let refusal = VariationalError::TooManyTangents {
        tangents: 3,
        state: 2,
    };
    assert_eq!(
        too_many.initial_state::<8>(&[1.0, 0.0]),
        Err(refusal.clone())
    );
    let y0 = sys.initial_state(&[1.0, 0.0]).unwrap();
    let mut stepper = Dop853::new(&sys, 0.0, y0, AdaptiveConfig::with_tol(1e-9, 1e-9)).unwrap();
    let cfg = BenettinConfig {
        interval: 0.5,
        duration: 5.0,
        transient: 0.0,
    };
    assert_eq!(benettin(&mut stepper, too_many, &cfg).err(), Some(refusal));
}

/// A sensitivity to a parameter the equations do not read is zero for ever, and one given
/// twice is carried twice: both refused, as the derive refuses them.
#[test]
fn unread_and_repeated_sensitivities_are_refused() {
    let mut a = Arena::new();
    let x = ["x", "v"].map(|n| a.input(n));
    let (k, c) = (a.parameter("k"), a.parameter("c"));
    let kx = a.mul(k, x[0]);
    let f = a.neg(kx);
    assert_eq!(
        VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[k, c]),
        Err(VariationalError::UnreadParameter { index: 1 })
    );
    assert_eq!(
        VariationalEquations::new(&mut a, &x, &[x[1], f], 2, &[k, k]),
        Err(VariationalError::RepeatedParameter {
            first: 0,
            second: 1
        })
    );
}

/// Φ = 10²⁰⁰ I is finite, but Φ P₀ Φᵀ = 10⁴⁰⁰ P₀ and Φ δx₀ for δx₀ = 10²⁰⁰ are not: errors,
/// where `Ok([inf, …])` came back.
#[test]
fn a_flow_map_that_overflows_is_an_error() {
    let layout = Layout {
        n: 2,
        tangents: 2,
        sensitivities: 0,
    };
    let big = 1e200;
    let map = FlowMap::new(layout, &[0.0, 0.0, big, 0.0, 0.0, big]).unwrap();
    assert!(matches!(
        map.covariance(&DMatrix::identity(2, 2)),
        Err(VariationalError::Overflow { index: 0, value, largest })
            if value == f64::INFINITY && largest == big
    ));
    assert!(matches!(
        map.apply(&[big, 0.0]),
        Err(VariationalError::Overflow { index: 0, .. })
    ));
    // Small enough, the same map is fine: Φ δx₀ = 10²⁰⁰ · ½, exact in binary.
    assert_eq!(map.apply(&[0.5, 0.0]), Ok(vec![0.5e200, 0.0]));
}
