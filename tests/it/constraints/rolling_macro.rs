//! A ball rolling by `#[derive(Mechanism)]` (`rolls = sphere(..)`), against the closed form:
//! a uniform ball rolling without slip under a constant force F along the floor moves its
//! centre at a = F / (m + I/r²) = (5/7) F/m whatever its spin, since the friction's torque
//! about the centre only turns the spin about the vertical, which the rolling leaves free.

use precess::mechanism::rolling::RollingDynamics;
use precess::prelude::*;
use precess_testkit::rng::Rng;

/// A uniform ball of mass m and radius r on the floor z = 0, gravity tilted by α off the
/// floor's normal (the ball on an incline of slope α): g = [g sin α, 0, −g cos α].
#[derive(Clone, Copy, Debug, Mechanism)]
#[mechanism(gravity = [g_x, 0.0, g_z], up = z, speeds = [a, b, c])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y,
       parts(particle(mass = 0.0)))]
#[body(ball, parent = slide_y, joint = spherical(sequence = zyx, at = [0.0, 0.0, r]),
       q = [a, b, c], parts(sphere(mass = m, radius = r)), rolls = sphere(radius = r))]
struct Ball {
    m: f64,
    r: f64,
    g_x: f64,
    g_z: f64,
}

#[test]
fn a_rolling_ball_accelerates_at_five_sevenths_of_the_force_whatever_its_spin() {
    let slope: f64 = 0.3;
    let ball = Ball {
        m: 2.0,
        r: 0.1,
        g_x: 9.81 * slope.sin(),
        g_z: -9.81 * slope.cos(),
    };
    assert_eq!(Ball::STATE, 8);
    let mut rng = Rng::new(57);
    let mut worst = [0.0_f64; 2];
    for _ in 0..20 {
        let q: [f64; 5] = std::array::from_fn(|_| rng.uniform(-1.0, 1.0));
        let u: [f64; 3] = std::array::from_fn(|_| rng.uniform(-30.0, 30.0));
        let (rates, ud) = ball.derivative(0.0, &q, &u).expect("derivative");
        let partition = ball.partition();
        let (a, rate_terms) = ball.constraint_rows(&q, &rates);
        let projected = partition.rates(&a, &u).expect("projects");
        let q_ddot = partition
            .full_accelerations(&a, &rate_terms, &projected, &ud)
            .expect("accelerations");
        let want = 5.0 / 7.0 * ball.g_x;
        worst[0] = worst[0].max(((q_ddot[Ball::X] - want) / want).abs());
        worst[0] = worst[0].max((q_ddot[Ball::Y] / want).abs());
        worst[1] = worst[1].max(ball.contact_speed(&q, &rates));
    }
    println!(
        "centre's acceleration {:e} (relative), contact speed {:e} m/s",
        worst[0], worst[1]
    );
    // Measured: 2.1e-15 relative, contact speed 6.3e-16 m/s at spins up to 30 rad/s.
    assert!(
        worst[0] < 1e-12,
        "centre's acceleration off (5/7) g sin α by {:e}",
        worst[0]
    );
    assert!(
        worst[1] < 1e-13,
        "contact point slips at {:e} m/s",
        worst[1]
    );
    // The ball has no height row: its joint holds its centre r above the floor.
    assert!(ball.holonomic_rows().iter().all(|&h| !h));
}

#[test]
fn a_ball_with_a_negative_radius_field_is_refused() {
    let ball = Ball {
        m: 2.0,
        r: -0.1,
        g_x: 1.0,
        g_z: -9.0,
    };
    let err = ball
        .rates(&[0.0; 5], &[0.0; 3])
        .expect_err("a negative radius");
    // The sphere part is checked first: its radius breaks the body language's rule.
    assert!(
        matches!(&err, MechanismError::Part { body, .. } if body == "ball"),
        "{err}"
    );
}

/// The cart of docs/attributes.md: a wheel of radius r on a cart along x.
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [theta])]
#[body(cart, parent = ground, joint = prismatic(axis = x), q = s,
       parts(particle(mass = 1.0)))]
#[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, r]), q = theta,
       parts(disk(mass = 0.5, radius = r, axis = y)),
       rolls = disk(radius = r, axle = y))]
struct Cart {
    r: f64,
}

#[test]
fn the_docs_cart_rolls_at_r_theta_dot_and_keeps_rolling_at_constant_speed() {
    let cart = Cart { r: 0.2 };
    // The foot of the wheel is still: ṡ + (θ̇ ŷ × (−r ẑ))·x̂ = ṡ − r θ̇ = 0.
    let rates = cart.rates(&[0.0, 0.0], &[1.0]).expect("rates");
    assert!((rates[Cart::S] - 0.2).abs() < 1e-15, "{rates:?}");
    // One row (the horizontal one along the rail); the height is held by the joints.
    assert_eq!(Cart::STATE, 3);
    assert_eq!(Cart::SPEEDS, [Cart::THETA]);
    // Level floor, no force along it: θ̈ = 0 at any angle and speed.
    let (_, ud) = cart
        .derivative(0.0, &[0.3, 1.1], &[-4.0])
        .expect("derivative");
    assert!(ud[0].abs() < 1e-14, "{ud:?}");
}
