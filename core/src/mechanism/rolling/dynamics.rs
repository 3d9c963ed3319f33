//! The run-time side of a rolling mechanism, shared by the derive's generated code and the
//! interpreted [`super::RollingModel`]: a type gives the numbers of M, f, A, Ȧq̇, the
//! wheels' heights and tilts; the provided methods finish Maggi's projection
//! ([`Partition`]) and put the wheels on the floor.
//!
//! The state is `[q₀ … q_{n−1}, u₀ … u_{k−1}]`: every coordinate, then the free speeds.

use nalgebra::{SMatrix, SVector};

use super::partials::{AtState, RollingPartials, jacobian};
use crate::lagrange::{Inverted, LagrangeError, MAX_NEWTON, Partition, START_RESIDUAL, solve};
use crate::mechanism::error::MechanismError;
use crate::ode::{OdeError, System};

/// The tolerance on the wheels' heights that [`RollingDynamics::close_contacts`] reaches
/// (metres, or the length unit of the description).
pub const CONTACT_TOLERANCE: f64 = 1e-14;

/// The smallest tilt |d| a disk may have ([`MechanismError::WheelFlat`]): the one flatness
/// limit of every rolling surface, shared with a body on a table
/// ([`crate::rigid::MIN_TILT`], where its value is argued).
pub use crate::rigid::MIN_TILT;

/// A mechanism with n coordinates whose wheels give m constraint rows, leaving k free
/// speeds. Implemented by `#[derive(Mechanism)]` for a struct with `rolls = ..` bodies and by
/// [`super::RollingModel`].
pub trait RollingDynamics<const N: usize, const M: usize, const K: usize> {
    /// Which coordinates' rates are free and which follow.
    fn partition(&self) -> Partition<M, K>;

    /// The coordinates' names, in state order.
    fn coordinate_names(&self) -> [&'static str; N];

    /// M(q) and f(t, q, q̇) of the unconstrained tree.
    fn mass_forcing(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> (SMatrix<f64, N, N>, SVector<f64, N>);

    /// A(q) and Ȧq̇.
    fn constraint_rows(
        &self,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> (SMatrix<f64, M, N>, SVector<f64, M>);

    /// The partial derivatives of M q̈, f, A and Ȧq̇ at (t, q, q̇, q̈), differentiated
    /// exactly ([`RollingPartials`], from [`super::RollingDerivation::partials`]): the derive
    /// emits them as straight-line code, the interpreted [`super::RollingModel`] lowers them
    /// on its first call. A derived mechanism with user-function efforts τ (`effort = f`,
    /// whose dependence on q and q̇ the engine cannot see) differentiates with τ held at
    /// its values (the functions called at (t, q, q̇)) and adds the chain rule's
    /// G ∂τ/∂q to ∂f/∂q and G ∂τ/∂q̇ to ∂f/∂q̇: G = ∂f/∂τ exact, ∂τ/∂(q, q̇) central
    /// differences of the user functions alone ([`crate::mechanism::effort_jacobian`]).
    /// `None` (this default) where they are not known; then
    /// [`RollingDynamics::acceleration_jacobian`] differences every entry.
    fn partials(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
        qddot: &[f64; N],
    ) -> Option<RollingPartials<N, M>> {
        let _ = (t, q, qdot, qddot);
        None
    }

    /// Which rows are holonomic (a wheel's height), the others nonholonomic (no slip).
    fn holonomic_rows(&self) -> [bool; M];

    /// Each row's position function: a wheel's height above the floor for a holonomic row,
    /// 0 for a nonholonomic one.
    fn heights(&self, q: &[f64; N]) -> [f64; M];

    /// The wheel with the smallest tilt |d| (the cosine of a disk's lean from the
    /// vertical; 1 for a ball) and that tilt.
    fn lowest_tilt(&self, q: &[f64; N]) -> (usize, f64);

    /// The total energy T + V.
    fn energy(&self, q: &[f64; N], qdot: &[f64; N]) -> f64;

    /// The largest speed of a wheel's material contact point (zero on a rolling motion).
    fn contact_speed(&self, q: &[f64; N], qdot: &[f64; N]) -> f64;

    /// Checks the parameters a description reads from fields (masses and radii not
    /// negative, inertias physical, everything finite), as literals are checked at compile
    /// time. The derive overrides it; an interpreted model checks its values when built.
    ///
    /// # Errors
    /// [`MechanismError::NonFiniteParameter`], [`MechanismError::NegativeParameter`],
    /// [`MechanismError::Part`].
    fn check_parameters(&self) -> Result<(), MechanismError> {
        Ok(())
    }

    /// Checks a configuration: the parameters ([`RollingDynamics::check_parameters`]),
    /// finite coordinates, and every disk standing (tilt > [`MIN_TILT`]).
    ///
    /// # Errors
    /// As [`RollingDynamics::check_parameters`]; [`MechanismError::NonFinite`],
    /// [`MechanismError::WheelFlat`].
    fn check_configuration(&self, q: &[f64; N]) -> Result<(), MechanismError> {
        self.check_parameters()?;
        if q.iter().any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "coordinates",
                values: q.to_vec(),
            });
        }
        let (wheel, tilt) = self.lowest_tilt(q);
        if tilt.is_nan() || tilt <= MIN_TILT {
            return Err(MechanismError::WheelFlat { wheel, tilt });
        }
        Ok(())
    }

    /// Checks that a run may start at `q`: the configuration is valid and every wheel is on
    /// the floor to within [`START_RESIDUAL`] (a run only keeps the heights where they
    /// start; put the wheels down first with [`RollingDynamics::close_contacts`]).
    ///
    /// # Errors
    /// As [`RollingDynamics::check_configuration`]; [`MechanismError::WheelOffFloor`]
    /// naming the first row whose height is past [`START_RESIDUAL`].
    fn check_start(&self, q: &[f64; N]) -> Result<(), MechanismError> {
        self.check_configuration(q)?;
        match self
            .heights(q)
            .iter()
            .position(|h| h.abs() > START_RESIDUAL || h.is_nan())
        {
            Some(row) => Err(MechanismError::WheelOffFloor {
                row,
                height: self.heights(q)[row],
                allowed: START_RESIDUAL,
            }),
            None => Ok(()),
        }
    }

    /// Every rate q̇ from the coordinates and the free speeds.
    ///
    /// # Errors
    /// As [`RollingDynamics::check_configuration`]; [`MechanismError::NonFinite`] for a
    /// speed; [`LagrangeError::SingularAtState`] where the dependent block is singular.
    fn rates(&self, q: &[f64; N], u: &[f64; K]) -> Result<[f64; N], MechanismError> {
        self.check_configuration(q)?;
        if u.iter().any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "free speeds",
                values: u.to_vec(),
            });
        }
        let (a, _) = self.constraint_rows(q, &[0.0; N]);
        Ok(self.partition().rates(&a, u)?.rates)
    }

    /// The rates and the free speeds' accelerations at (t, q, u).
    ///
    /// # Errors
    /// As [`RollingDynamics::rates`]; [`LagrangeError::SingularReducedMass`] where
    /// Sᵀ M S is singular.
    fn derivative(
        &self,
        t: f64,
        q: &[f64; N],
        u: &[f64; K],
    ) -> Result<([f64; N], [f64; K]), MechanismError> {
        self.check_configuration(q)?;
        let partition = self.partition();
        let (a, _) = self.constraint_rows(q, &[0.0; N]);
        let projected = partition.rates(&a, u)?;
        let (a, rate_terms) = self.constraint_rows(q, &projected.rates);
        let (mass, forcing) = self.mass_forcing(t, q, &projected.rates);
        let ud = partition.accelerations(&mass, &forcing, &a, &rate_terms, &projected)?;
        Ok((projected.rates, ud))
    }

    /// The Jacobian of the free accelerations u̇(t, q, u) of [`RollingDynamics::derivative`]:
    /// `(∂u̇/∂q, ∂u̇/∂u)`, k × n and k × k, every coordinate taken as independent (the
    /// heights are not held: a caller that keeps the wheels on the floor chains the
    /// coordinates' tangent to the height rows in, as `Bicycle::canonical` does).
    ///
    /// Built from [`RollingDynamics::partials`] where it gives the derivatives (every
    /// interpreted [`super::RollingModel`] and every derived rolling mechanism): they are
    /// carried through the projection by the product rule (d(K⁻¹) = −K⁻¹ dK K⁻¹ and the
    /// like; see docs/linearisation.md), exact but for a derived mechanism's user-function
    /// efforts' own derivatives, which `partials` differences. Where `partials` is `None`
    /// (a hand-written implementation that does not give them) every entry is a central
    /// difference of [`RollingDynamics::derivative`] in (q, u) with Richardson
    /// extrapolation ([`crate::linalg::jacobian`], about 1e-12 relative).
    ///
    /// # Errors
    /// As [`RollingDynamics::derivative`]; [`MechanismError::NonFinite`] if a derivative is
    /// not finite.
    #[allow(clippy::type_complexity)]
    fn acceleration_jacobian(
        &self,
        t: f64,
        q: &[f64; N],
        u: &[f64; K],
    ) -> Result<(SMatrix<f64, K, N>, SMatrix<f64, K, K>), MechanismError> {
        let (rates, ud) = self.derivative(t, q, u)?;
        let partition = self.partition();
        let (a, rate_terms) = self.constraint_rows(q, &rates);
        let projected = partition.rates(&a, u)?;
        let q_ddot = partition.full_accelerations(&a, &rate_terms, &projected, &ud)?;
        let mut qddot = [0.0; N];
        qddot.copy_from_slice(q_ddot.as_slice());
        let (by_q, by_u) = match self.partials(t, q, &rates, &qddot) {
            Some(partials) => {
                let (mass, forcing) = self.mass_forcing(t, q, &rates);
                let at = AtState {
                    mass,
                    forcing,
                    a,
                    rate_terms,
                    partials: &partials,
                };
                jacobian(&partition, &at, u)?
            }
            None => {
                let state: Vec<f64> = q.iter().chain(u.iter()).copied().collect();
                let jac = crate::linalg::jacobian(
                    |y, out| {
                        let (mut q, mut u) = ([0.0; N], [0.0; K]);
                        q.copy_from_slice(&y[..N]);
                        u.copy_from_slice(&y[N..]);
                        match self.derivative(t, &q, &u) {
                            Ok((qd, ud)) => {
                                out[..N].copy_from_slice(&qd);
                                out[N..].copy_from_slice(&ud);
                            }
                            Err(_) => out.fill(f64::NAN),
                        }
                    },
                    &state,
                )
                .map_err(|_| MechanismError::NonFinite {
                    quantity: "difference quotients of the accelerations",
                    values: state.clone(),
                })?;
                (
                    SMatrix::from_fn(|i, j| jac[(N + i, j)]),
                    SMatrix::from_fn(|i, j| jac[(N + i, N + j)]),
                )
            }
        };
        if by_q.iter().chain(by_u.iter()).any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "derivatives of the free accelerations",
                values: by_q.iter().chain(by_u.iter()).copied().collect(),
            });
        }
        Ok((by_q, by_u))
    }

    /// ∂u̇/∂τ for inputs τ that enter as generalised forces Q = G τ (column j of `g` the
    /// generalised force of a unit of input j: for a torque at a hinge, the unit vector of
    /// the hinge's coordinate, as a bicycle's steer torque on δ): K⁻¹ Sᵀ G, K = Sᵀ M S,
    /// exact, since u̇ is linear in Q. With [`RollingDynamics::acceleration_jacobian`] it
    /// gives B of ẋ = A x + B τ about a steady motion.
    ///
    /// # Errors
    /// As [`RollingDynamics::rates`]; [`LagrangeError::SingularReducedMass`] where K is
    /// singular; [`MechanismError::NonFinite`] for a non-finite entry of `g`.
    fn input_matrix<const P: usize>(
        &self,
        t: f64,
        q: &[f64; N],
        u: &[f64; K],
        g: &SMatrix<f64, N, P>,
    ) -> Result<SMatrix<f64, K, P>, MechanismError> {
        if g.iter().any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "input matrix G",
                values: g.iter().copied().collect(),
            });
        }
        let rates = self.rates(q, u)?;
        let (a, _) = self.constraint_rows(q, &rates);
        let s = self.partition().rates(&a, u)?.projection;
        let (mass, _) = self.mass_forcing(t, q, &rates);
        let k = s.transpose() * mass * s;
        Ok(solve(k, s.transpose() * g, Inverted::ReducedMass)?)
    }

    /// The constraints' multipliers λ at (t, q, u): M q̈ = f + Aᵀ λ. For a wheel's two
    /// horizontal rows they are the friction force's components (ground axes) that keep it
    /// rolling, for its height row the normal force.
    ///
    /// # Errors
    /// As [`RollingDynamics::derivative`].
    fn multipliers(&self, t: f64, q: &[f64; N], u: &[f64; K]) -> Result<[f64; M], MechanismError> {
        let partition = self.partition();
        let (rates, ud) = self.derivative(t, q, u)?;
        let (a, rate_terms) = self.constraint_rows(q, &rates);
        let projected = partition.rates(&a, u)?;
        let q_ddot = partition.full_accelerations(&a, &rate_terms, &projected, &ud)?;
        let (mass, forcing) = self.mass_forcing(t, q, &rates);
        Ok(partition.multipliers(&mass, &forcing, &a, &q_ddot)?)
    }

    /// Puts every wheel on the floor: Newton's method on the height rows over the dependent
    /// coordinates (the least-norm step), from `q`. Returns the iterations taken.
    ///
    /// # Errors
    /// As [`RollingDynamics::check_configuration`]; [`LagrangeError::LoopNotClosed`] if a
    /// height stays above [`CONTACT_TOLERANCE`] after [`MAX_NEWTON`] iterations;
    /// [`LagrangeError::SingularAtState`] if the heights do not depend on the dependent
    /// coordinates there.
    fn close_contacts(&self, q: &mut [f64; N]) -> Result<usize, MechanismError> {
        let mut residual = f64::NAN;
        for k in 0..MAX_NEWTON {
            self.check_configuration(q)?;
            let h = self.heights(q);
            residual = h.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            if residual <= CONTACT_TOLERANCE {
                return Ok(k);
            }
            let step = self.height_step(q, &h)?;
            for (qi, di) in q.iter_mut().zip(step) {
                *qi -= di;
            }
        }
        Err(LagrangeError::LoopNotClosed {
            residual,
            iterations: MAX_NEWTON,
            tolerance: CONTACT_TOLERANCE,
        }
        .into())
    }

    /// The least-norm change of the dependent coordinates that changes the heights by `b`
    /// to first order (one value per row of A; only the holonomic rows are read): J_D dq_D =
    /// b, J the holonomic rows of A at `q`, dq_D = J_Dᵀ (J_D J_Dᵀ)⁻¹ b, returned in the
    /// coordinates' order (zero at the free ones). [`RollingDynamics::close_contacts`]
    /// steps by it; [`RollingDynamics::height_tangent`] follows it.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] if the heights do not depend on the dependent
    /// coordinates at `q` (or the step is not finite).
    fn height_step(&self, q: &[f64; N], b: &[f64; M]) -> Result<[f64; N], MechanismError> {
        let dependent = self.partition().dependent;
        let (a, _) = self.constraint_rows(q, &[0.0; N]);
        let holonomic = self.holonomic_rows();
        let rows: Vec<usize> = (0..M).filter(|&r| holonomic[r]).collect();
        let jacobian = nalgebra::DMatrix::from_fn(rows.len(), M, |i, c| a[(rows[i], dependent[c])]);
        let values = nalgebra::DVector::from_fn(rows.len(), |i, _| b[rows[i]]);
        let normal = &jacobian * jacobian.transpose();
        let singular = LagrangeError::SingularAtState {
            determinant: normal.determinant(),
            scale: normal.norm(),
        };
        let Some(y) = normal.lu().solve(&values) else {
            return Err(singular.into());
        };
        let step = jacobian.transpose() * y;
        if step.iter().any(|v| !v.is_finite()) {
            return Err(singular.into());
        }
        let mut out = [0.0; N];
        for (c, &d) in dependent.iter().enumerate() {
            out[d] = step[c];
        }
        Ok(out)
    }

    /// dq/dq_j on the floor at `q`, `free` = j a free coordinate: its unit change, the
    /// dependent coordinates following so that every wheel's height stays zero to first
    /// order (the implicit-function theorem, least-norm where the rows leave freedom, as
    /// [`RollingDynamics::close_contacts`] steps). Chained into the coordinate columns of
    /// [`RollingDynamics::acceleration_jacobian`], it gives the Jacobian on the floor.
    ///
    /// # Errors
    /// As [`RollingDynamics::height_step`]; [`MechanismError::NotFreeCoordinate`] for a
    /// `free` that is a dependent coordinate or none.
    fn height_tangent(&self, q: &[f64; N], free: usize) -> Result<[f64; N], MechanismError> {
        let dependent = self.partition().dependent;
        if free >= N || dependent.contains(&free) {
            return Err(MechanismError::NotFreeCoordinate {
                index: free,
                coordinates: N,
                dependent: dependent.to_vec(),
            });
        }
        let (a, _) = self.constraint_rows(q, &[0.0; N]);
        let column: [f64; M] = std::array::from_fn(|r| a[(r, free)]);
        let step = self.height_step(q, &column)?;
        let mut t = step.map(|v| -v);
        t[free] += 1.0;
        Ok(t)
    }

    /// This mechanism as a [`System`] over the state (q, u) of S = n + k entries (a state
    /// where the projection fails yields NaN, which the steppers report). Wrapped in the run
    /// loop ([`super::rolling_run`]) a wheel falling flat halts the run by name instead.
    fn rolling_system<const S: usize>(&self) -> RollingSystem<'_, Self, N, M, K, S>
    where
        Self: Sized,
    {
        RollingSystem { model: self }
    }
}

/// A rolling mechanism as an ODE system: `y = (q, u)`, `y' = (q̇, u̇)`.
#[derive(Debug)]
pub struct RollingSystem<'a, T, const N: usize, const M: usize, const K: usize, const S: usize> {
    model: &'a T,
}

impl<'a, T, const N: usize, const M: usize, const K: usize, const S: usize>
    RollingSystem<'a, T, N, M, K, S>
{
    /// The mechanism.
    pub fn model(&self) -> &'a T {
        self.model
    }
}

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> Clone
    for RollingSystem<'_, T, N, M, K, S>
{
    fn clone(&self) -> Self {
        *self
    }
}

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> Copy
    for RollingSystem<'_, T, N, M, K, S>
{
}

/// Splits a state (q, u) of S = n + k entries.
pub fn split_rolling<const N: usize, const K: usize, const S: usize>(
    y: &[f64; S],
) -> ([f64; N], [f64; K]) {
    const {
        assert!(
            S == N + K,
            "a rolling state holds n coordinates and k speeds"
        )
    };
    let mut q = [0.0; N];
    let mut u = [0.0; K];
    q.copy_from_slice(&y[..N]);
    u.copy_from_slice(&y[N..]);
    (q, u)
}

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> System<S>
    for RollingSystem<'_, T, N, M, K, S>
where
    T: RollingDynamics<N, M, K>,
{
    fn rhs(&self, t: f64, y: &[f64; S], dydt: &mut [f64; S]) {
        let (q, u) = split_rolling::<N, K, S>(y);
        match self.model.derivative(t, &q, &u) {
            Ok((qd, ud)) => {
                dydt[..N].copy_from_slice(&qd);
                dydt[N..].copy_from_slice(&ud);
            }
            Err(_) => dydt.fill(f64::NAN),
        }
    }

    /// The model's [`RollingDynamics::check_parameters`], before any step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        self.model
            .check_parameters()
            .map_err(MechanismError::into_ode_error)
    }
}
