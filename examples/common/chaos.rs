//! The heavy top of `examples/chaos_map.rs` and its maximal Lyapunov exponent, kept apart so
//! that the physics test (`tests/it/chaos_map.rs`) runs the same code.
//!
//! The top is built at run time as a `TopScene` in Eulerian form — state (ω, R), body rates
//! and the attitude body → space row by row, twelve entries and no chart to leave — with its
//! principal moments, centre of mass and weight as parameters, so one construction serves
//! the asymmetric top of the map and the integrable tops that check it. The variational
//! equations carry one tangent vector (m = 1, N = 24), enough for the largest exponent by
//! Benettin's method.

#![allow(dead_code)] // the example and the test each use the part they need

use precess::ode::AdaptiveConfig;
use precess::sym::Arena;
use precess::top::TopScene;
use precess::variational::{BenettinConfig, VariationalEquations, VariationalError};

/// The augmented system: 12 states and one tangent vector of 12.
pub type System = precess::variational::VariationalSystem<24>;

/// A heavy top about its pivot: principal moments, centre of mass in body axes, and the
/// weight M g (gravity along −z in space).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Top {
    /// I1, I2, I3 about the pivot, along the body axes.
    pub inertia: [f64; 3],
    /// The centre of mass relative to the pivot, body axes.
    pub center: [f64; 3],
    /// M g; 0 for a torque-free body.
    pub weight: f64,
}

/// The map's top: the asymmetric top of `examples/chaotic_top.rs` (I = 1, 1.5, 0.6; centre
/// of mass (0.3, 0.2, 1) off every axis; M g = 1), integrable in no known way.
pub const ASYMMETRIC: Top = Top {
    inertia: [1.0, 1.5, 0.6],
    center: [0.3, 0.2, 1.0],
    weight: 1.0,
};

/// Lagrange's top: I1 = I2, centre of mass on the figure axis. Integrable (energy, the
/// vertical and the axial angular momentum): its exponents are zero.
pub const LAGRANGE: Top = Top {
    inertia: [1.0, 1.0, 0.6],
    center: [0.0, 0.0, 1.0],
    weight: 1.0,
};

/// Kovalevskaya's top: I1 = I2 = 2 I3, centre of mass in the equatorial plane. Integrable
/// through her fourth integral: its exponents are zero.
pub const KOVALEVSKAYA: Top = Top {
    inertia: [2.0, 2.0, 1.0],
    center: [1.0, 0.0, 0.0],
    weight: 1.0,
};

/// The map's top with gravity off: a torque-free body whose rotation about the axis of
/// intermediate moment (body x, I = 1 between 0.6 and 1.5) is unstable.
pub const TORQUE_FREE: Top = Top {
    weight: 0.0,
    ..ASYMMETRIC
};

impl Top {
    /// The variational equations of the top in Eulerian form with one tangent vector,
    /// lowered and bound to this top's values.
    ///
    /// # Errors
    /// As [`VariationalEquations::from_eulerian_top`] and [`System::new`].
    pub fn system(&self) -> Result<System, VariationalError> {
        let mut a = Arena::new();
        let z = a.zero();
        let i = ["I1", "I2", "I3"].map(|n| a.parameter(n));
        let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
        scene.center = ["cx", "cy", "cz"].map(|n| a.parameter(n));
        // Mass 1 and gravity M g: the torque reads only their product.
        scene.gravity = Some(a.parameter("Mg"));
        let eq = VariationalEquations::from_eulerian_top(&mut a, &scene, 1, &[])?;
        let [i1, i2, i3] = self.inertia;
        let [cx, cy, cz] = self.center;
        let values = [
            ("I1", i1),
            ("I2", i2),
            ("I3", i3),
            ("cx", cx),
            ("cy", cy),
            ("cz", cz),
            ("Mg", self.weight),
        ];
        System::new(&a, &eq, &values)
    }
}

/// The state (ω, R) of a top whose figure axis (body z) is tilted `theta0` from the vertical
/// about the space x axis, turning at `omega` (body axes).
pub fn state(theta0: f64, omega: [f64; 3]) -> [f64; 12] {
    let (s, c) = theta0.sin_cos();
    // R = Rx(θ0), rows.
    [
        omega[0], omega[1], omega[2], 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c,
    ]
}

/// The integrator of every run: DOP853 at 10⁻¹⁰, tight enough that its error seeds no
/// separation over the runs' times, loose enough for seconds per map.
pub fn tolerances() -> AdaptiveConfig {
    AdaptiveConfig::with_tol(1e-10, 1e-10)
}

/// Benettin's settings for an averaging time `duration`: re-orthonormalised every unit of
/// time (exponents here are below 1, so a vector grows at most e-fold in between), after a
/// transient of 10 that aligns the vector.
pub fn benettin(duration: f64) -> BenettinConfig {
    BenettinConfig {
        interval: 1.0,
        duration,
        transient: 10.0,
    }
}

/// The largest Lyapunov exponent of `top`'s system from `x0`, averaged over `duration`.
///
/// # Errors
/// As [`System::lyapunov`].
pub fn largest_exponent(
    system: &System,
    x0: &[f64; 12],
    duration: f64,
) -> Result<f64, VariationalError> {
    let spectrum = system.lyapunov(0.0, x0, &benettin(duration), tolerances())?;
    Ok(spectrum.exponents[0])
}

/// The exact exponent of the rotation at rate `omega` about the intermediate axis of a
/// torque-free body with moments `small < middle < large`:
/// λ = ω √((I_m − I_s)(I_l − I_m) / (I_s I_l)).
pub fn intermediate_axis_exponent(small: f64, middle: f64, large: f64, omega: f64) -> f64 {
    omega * ((middle - small) * (large - middle) / (small * large)).sqrt()
}

/// A grid of initial conditions: tilts θ0 along x, spins ω3 about the figure axis along
/// y, each cell's centre one run, run `index = iy · nx + ix`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Map {
    /// Tilts across the map.
    pub nx: usize,
    /// Spins up the map.
    pub ny: usize,
    /// θ0 from the first to the last cell's edge [rad].
    pub theta: (f64, f64),
    /// ω3 from the first to the last cell's edge [rad/s].
    pub spin: (f64, f64),
    /// The averaging time of every run.
    pub duration: f64,
}

impl Map {
    /// The number of runs.
    pub fn runs(&self) -> usize {
        self.nx * self.ny
    }

    /// (θ0, ω3) of run `index`: the centre of its cell.
    pub fn cell(&self, index: usize) -> (f64, f64) {
        let (ix, iy) = (index % self.nx.max(1), index / self.nx.max(1));
        let at =
            |(lo, hi): (f64, f64), k: usize, n: usize| lo + (hi - lo) * (k as f64 + 0.5) / n as f64;
        (at(self.theta, ix, self.nx), at(self.spin, iy, self.ny))
    }

    /// The initial state of run `index`: tilted θ0, spinning at ω3 about the figure axis.
    pub fn state(&self, index: usize) -> [f64; 12] {
        let (theta0, spin) = self.cell(index);
        state(theta0, [0.0, 0.0, spin])
    }
}
