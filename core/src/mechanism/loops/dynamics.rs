//! The run-time side of a mechanism with closed loops, shared by the derive's generated code
//! and any other implementation: a type gives the numbers of M, f, φ, A and Ȧq̇; the provided
//! methods choose the dependent coordinates at the configuration, finish the engine's
//! projection ([`Partition`]) and put a state back on the loop.
//!
//! The state is `[q, q̇]`, 2n numbers, as for a tree. The accelerations are the unique
//! solution of M q̈ = f + Aᵀ λ, A q̈ = −Ȧq̇ at the state's own rates; every choice of the
//! dependent coordinates whose block A_D is regular gives that same q̈ (the projection
//! S = [I; −A_D⁻¹ A_I] only parametrises the null space of A), so choosing them anew at each
//! evaluation keeps the right-hand side smooth, and a four-bar's crank passing a dead point
//! (its A_D singular) hands the motion to the rocker rather than stopping.

use nalgebra::{DMatrix, DVector, SMatrix, SVector};

use crate::lagrange::{LagrangeError, MAX_NEWTON, Partition, SINGULAR_BLOCK, START_RESIDUAL};
use crate::mechanism::error::MechanismError;
use crate::ode::{AdaptiveConfig, Dop853, Hybrid, OdeError, System};

/// The loop residual max |φ| that [`LoopDynamics::close_loop`] reaches (lengths of the
/// description; Newton also stops at a step at rounding level).
pub const LOOP_TOLERANCE: f64 = 1e-14;

/// The dependent coordinates best conditioned at `a`: Gaussian elimination on A with
/// complete pivoting picks one column per row, the largest remaining entry each time
/// (Wehage and Haug's choice); those columns are the dependent coordinates, the others the
/// independent ones, each list in coordinate order.
///
/// # Errors
/// [`LagrangeError::SingularAtState`] when A has no full row rank at this configuration
/// (every block singular: a four-bar folded flat), with the product of the pivots and of
/// the rows' norms.
///
/// ```
/// use nalgebra::SMatrix;
/// use precess::mechanism::loops::best_partition;
/// // A crank at its dead point: its column of A is zero, so the rows cannot be solved for
/// // it; it is the free coordinate and the two others follow.
/// let a = SMatrix::<f64, 2, 3>::new(0.0, 1.0, 0.5, 0.0, 0.2, -1.0);
/// let p = best_partition::<2, 3, 1>(&a)?;
/// assert_eq!((p.independent, p.dependent), ([0], [1, 2]));
/// # Ok::<(), precess::lagrange::LagrangeError>(())
/// ```
pub fn best_partition<const M: usize, const N: usize, const K: usize>(
    a: &SMatrix<f64, M, N>,
) -> Result<Partition<M, K>, LagrangeError> {
    const { assert!(M + K == N, "k = n − m free coordinates") };
    let scale: f64 = a.row_iter().map(|r| r.norm()).product();
    let mut w = *a;
    let mut taken = [false; N];
    let mut dependent = [0; M];
    let mut determinant = 1.0;
    for r in 0..M {
        let mut best = (r, 0, -1.0);
        for i in r..M {
            for (j, _) in taken.iter().enumerate().filter(|(_, t)| !**t) {
                if w[(i, j)].abs() > best.2 {
                    best = (i, j, w[(i, j)].abs());
                }
            }
        }
        let (i, j, _) = best;
        w.swap_rows(r, i);
        determinant *= w[(r, j)];
        if determinant.abs().partial_cmp(&(SINGULAR_BLOCK * scale))
            != Some(std::cmp::Ordering::Greater)
        {
            return Err(LagrangeError::SingularAtState { determinant, scale });
        }
        for below in r + 1..M {
            let f = w[(below, j)] / w[(r, j)];
            for c in 0..N {
                w[(below, c)] -= f * w[(r, c)];
            }
        }
        taken[j] = true;
        dependent[r] = j;
    }
    dependent.sort_unstable();
    let mut independent = [0; K];
    for (slot, j) in independent.iter_mut().zip((0..N).filter(|j| !taken[*j])) {
        *slot = j;
    }
    Ok(Partition {
        independent,
        dependent,
    })
}

/// M (n × n) and f (n) of a mechanism's tree at one state.
pub type MassForcing<const N: usize> = (SMatrix<f64, N, N>, SVector<f64, N>);

/// A mechanism of n coordinates whose loop closures give m rows, leaving k = n − m free.
/// `#[derive(Mechanism)]` implements it for a struct with `closes = ..` bodies.
pub trait LoopDynamics<const N: usize, const M: usize, const K: usize> {
    /// φ(q), the closing points' separations (ground axes), and A = ∂φ/∂q.
    fn closure(&self, q: &[f64; N]) -> ([f64; M], SMatrix<f64, M, N>);

    /// Ȧq̇ at (q, q̇).
    fn rate_terms(&self, q: &[f64; N], qdot: &[f64; N]) -> SVector<f64, M>;

    /// M(q) and f(t, q, q̇) of the tree cut open at its closures.
    fn mass_forcing(&self, t: f64, q: &[f64; N], qdot: &[f64; N]) -> MassForcing<N>;

    /// T + V.
    fn energy(&self, q: &[f64; N], qdot: &[f64; N]) -> f64;

    /// The coordinates' names, in state order.
    fn coordinate_names(&self) -> [&'static str; N];

    /// Checks the parameters read from fields (the derive overrides it): the tree's rules,
    /// and each planar loop's sides against [`super::check_loop_sides`].
    ///
    /// # Errors
    /// [`MechanismError::LoopCannotClose`], [`MechanismError::NonFiniteParameter`],
    /// [`MechanismError::NegativeParameter`], [`MechanismError::Part`].
    fn check_parameters(&self) -> Result<(), MechanismError> {
        Ok(())
    }

    /// The loop residual max |φ(q)|.
    fn residual(&self, q: &[f64; N]) -> f64 {
        let (phi, _) = self.closure(q);
        phi.iter().fold(
            0.0,
            |m, v| if v.is_nan() { f64::NAN } else { m.max(v.abs()) },
        )
    }

    /// The dependent coordinates chosen at q ([`best_partition`]).
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A has no full row rank.
    fn partition(&self, q: &[f64; N]) -> Result<Partition<M, K>, MechanismError> {
        Ok(best_partition(&self.closure(q).1)?)
    }

    /// Every rate at q from the rates `u` of the coordinates `free` (A q̇ = 0 solved for the
    /// others): how to set a run up with, say, the crank's rate given.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`] for a coordinate or rate;
    /// [`LagrangeError::DependentChoice`] (naming the dependent coordinates left) when
    /// `free` repeats a coordinate or names one past n; [`LagrangeError::SingularAtState`] where the other coordinates' block is singular
    /// (`free` at a dead point).
    fn rates_from(
        &self,
        q: &[f64; N],
        free: [usize; K],
        u: [f64; K],
    ) -> Result<[f64; N], MechanismError> {
        if q.iter().chain(&u).any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "coordinates or free rates",
                values: q.iter().chain(&u).copied().collect(),
            });
        }
        let mut dependent = [0; M];
        let mut rest = (0..N).filter(|i| !free.contains(i));
        for slot in &mut dependent {
            *slot = rest.next().unwrap_or(N);
        }
        let distinct = (0..K).all(|j| free[j] < N && !free[..j].contains(&free[j]));
        if !distinct || dependent.contains(&N) {
            return Err(LagrangeError::DependentChoice {
                dependent: dependent.to_vec(),
                constraints: M,
                coordinates: N,
            }
            .into());
        }
        let partition = Partition {
            independent: free,
            dependent,
        };
        Ok(partition.rates(&self.closure(q).1, &u)?.rates)
    }

    /// q̈ at (t, q, q̇), checked: the parameters, a finite state, a regular configuration.
    ///
    /// # Errors
    /// As [`LoopDynamics::check_parameters`]; [`MechanismError::NonFinite`];
    /// [`LagrangeError::SingularAtState`], [`LagrangeError::SingularReducedMass`].
    fn accelerations(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<[f64; N], MechanismError> {
        self.check_parameters()?;
        Ok(self.solve(t, q, qdot)?.0)
    }

    /// The closures' multipliers λ at (t, q, q̇), M q̈ = f + Aᵀ λ: row by row the force the
    /// closing joint exerts on the closing body at its point, ground axes (the other body
    /// feels −λ).
    ///
    /// # Errors
    /// As [`LoopDynamics::accelerations`].
    fn multipliers(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<[f64; M], MechanismError> {
        self.check_parameters()?;
        Ok(self.solve(t, q, qdot)?.1)
    }

    /// q̈ and λ, without checking the parameters.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`]; [`LagrangeError::SingularAtState`],
    /// [`LagrangeError::SingularReducedMass`].
    fn solve(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> Result<([f64; N], [f64; M]), MechanismError> {
        if !(t.is_finite() && q.iter().chain(qdot).all(|v| v.is_finite())) {
            let mut values = vec![t];
            values.extend_from_slice(q);
            values.extend_from_slice(qdot);
            return Err(MechanismError::NonFinite {
                quantity: "time, coordinates or rates",
                values,
            });
        }
        let (_, a) = self.closure(q);
        let partition = best_partition::<M, N, K>(&a)?;
        let u: [f64; K] = partition.independent.map(|i| qdot[i]);
        let projected = partition.rates(&a, &u)?;
        // f and Ȧq̇ at the state's own rates: then q̈ is the one solution of the
        // unreduced equations whatever the partition (see the module's notes).
        let (mass, forcing) = self.mass_forcing(t, q, qdot);
        let rate_terms = self.rate_terms(q, qdot);
        let ud = partition.accelerations(&mass, &forcing, &a, &rate_terms, &projected)?;
        let qdd = partition.full_accelerations(&a, &rate_terms, &projected, &ud)?;
        let lambda = partition.multipliers(&mass, &forcing, &a, &qdd)?;
        let mut out = [0.0; N];
        out.copy_from_slice(qdd.as_slice());
        if out.iter().chain(&lambda).any(|v| !v.is_finite()) {
            return Err(MechanismError::NonFinite {
                quantity: "accelerations or multipliers",
                values: out.iter().chain(&lambda).copied().collect(),
            });
        }
        Ok((out, lambda))
    }

    /// Puts (q, q̇) back on the loop: Newton's method on φ(q) = 0 over the dependent
    /// coordinates chosen at q, to [`LOOP_TOLERANCE`] or a step at rounding level, then the
    /// dependent rates from the independent ones (A q̇ = 0). Returns the Newton iterations.
    /// On error q and q̇ are left as they were.
    ///
    /// # Errors
    /// [`MechanismError::NonFinite`]; [`LagrangeError::SingularAtState`] where no block is
    /// regular; [`LagrangeError::LoopNotClosed`] with the residual left after
    /// [`MAX_NEWTON`] iterations (a loop that cannot close at these coordinates).
    fn close_loop(&self, q: &mut [f64; N], qdot: &mut [f64; N]) -> Result<usize, MechanismError> {
        if let Some(bad) = q.iter().chain(qdot.iter()).position(|v| !v.is_finite()) {
            return Err(LagrangeError::NonFiniteState {
                index: bad,
                value: q
                    .iter()
                    .chain(qdot.iter())
                    .nth(bad)
                    .copied()
                    .unwrap_or(f64::NAN),
            }
            .into());
        }
        let (_, a) = self.closure(q);
        let partition = best_partition::<M, N, K>(&a)?;
        let mut trial = *q;
        let mut iterations = 0;
        loop {
            let (phi, a) = self.closure(&trial);
            let residual = phi.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            if residual <= LOOP_TOLERANCE {
                break;
            }
            if iterations == MAX_NEWTON || residual.is_nan() {
                return Err(LagrangeError::LoopNotClosed {
                    residual,
                    iterations,
                    tolerance: LOOP_TOLERANCE,
                }
                .into());
            }
            // Once per accepted step: a dynamic matrix, as nalgebra's LU needs a known size.
            let a_d = DMatrix::from_fn(M, M, |r, c| a[(r, partition.dependent[c])]);
            let singular = LagrangeError::SingularAtState {
                determinant: a_d.determinant(),
                scale: a_d.row_iter().map(|r| r.norm()).product(),
            };
            let step = a_d
                .lu()
                .solve(&DVector::from_column_slice(&phi))
                .ok_or(singular)?;
            let mut at_rounding = true;
            for (r, &d) in partition.dependent.iter().enumerate() {
                at_rounding &= step[r].abs() <= 4.0 * f64::EPSILON * trial[d].abs().max(1.0);
                trial[d] -= step[r];
            }
            iterations += 1;
            if at_rounding {
                break;
            }
        }
        let (_, a) = self.closure(&trial);
        let u: [f64; K] = partition.independent.map(|i| qdot[i]);
        *qdot = partition.rates(&a, &u)?.rates;
        *q = trial;
        Ok(iterations)
    }

    /// This mechanism as a [`System`] over `[q, q̇]` (2n entries). Where the projection
    /// fails the derivative is NaN, which the steppers report; [`LoopDynamics::closed_run`] wraps it in
    /// the run loop, which keeps the loop closed.
    fn loop_system(&self) -> LoopSystem<'_, Self, N, M, K>
    where
        Self: Sized,
    {
        LoopSystem { model: self }
    }

    /// Starts a run at `(t0, y0)`, `y0 = [q, q̇]` (S = 2n), in the one run loop with
    /// DOP853: a [`Stepper`](crate::ode::Stepper) for [`Run`](crate::ode::Run), trajectories
    /// and ensembles, which closes the loop after every step ([`super::LoopRun`]).
    ///
    /// # Errors
    /// As [`LoopDynamics::check_parameters`]; [`LagrangeError::StartOffLoop`] when y0 is off
    /// the loop by more than [`crate::lagrange::START_RESIDUAL`] (close it first with
    /// [`LoopDynamics::close_loop`], on the branch you mean); [`MechanismError::Ode`] for a
    /// bad configuration of the stepper or a right-hand side not finite at the start.
    fn closed_run<const S: usize>(
        &self,
        t0: f64,
        y0: [f64; S],
        cfg: AdaptiveConfig,
    ) -> Result<super::LoopRun<'_, Self, N, M, K, S>, MechanismError>
    where
        Self: Sized,
    {
        self.check_parameters()?;
        let residual = self.residual(&halves::<N, S>(&y0).0);
        if residual.is_nan() || residual > START_RESIDUAL {
            return Err(LagrangeError::StartOffLoop {
                residual,
                allowed: START_RESIDUAL,
            }
            .into());
        }
        let ode = Dop853::new(self.loop_system(), t0, y0, cfg)?;
        Ok(Hybrid::new(ode)?.with_max_steps(cfg.max_steps))
    }
}

/// A loop mechanism as an ODE system: `y = [q, q̇]`, `y' = [q̇, q̈]` (a `System<S>` for
/// S = 2n only, checked when it is built).
#[derive(Debug)]
pub struct LoopSystem<'a, T, const N: usize, const M: usize, const K: usize> {
    /// The mechanism.
    pub model: &'a T,
}

/// q and q̇ of a state `[q, q̇]`.
pub(super) fn halves<const N: usize, const S: usize>(y: &[f64; S]) -> ([f64; N], [f64; N]) {
    let (mut q, mut qdot) = ([0.0; N], [0.0; N]);
    q.copy_from_slice(&y[..N]);
    qdot.copy_from_slice(&y[N..2 * N]);
    (q, qdot)
}

impl<T, const N: usize, const M: usize, const K: usize, const S: usize> System<S>
    for LoopSystem<'_, T, N, M, K>
where
    T: LoopDynamics<N, M, K>,
{
    fn rhs(&self, t: f64, y: &[f64; S], dydt: &mut [f64; S]) {
        const { assert!(S == 2 * N, "the state is [q, q̇], 2n numbers") };
        let (q, qdot) = halves::<N, S>(y);
        // A refused state gives NaN accelerations, which the stepper reports.
        let qdd = self
            .model
            .solve(t, &q, &qdot)
            .map_or([f64::NAN; N], |(qdd, _)| qdd);
        dydt[..N].copy_from_slice(&qdot);
        dydt[N..].copy_from_slice(&qdd);
    }

    /// The model's [`LoopDynamics::check_parameters`], before any step.
    fn check_parameters(&self) -> Result<(), OdeError> {
        LoopDynamics::check_parameters(self.model).map_err(MechanismError::into_ode_error)
    }
}
