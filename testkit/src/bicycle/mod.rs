//! The Whipple bicycle of Meijaard, Papadopoulos, Ruina & Schwab (Proc. R. Soc. A 463,
//! 2007): rear wheel R, rear frame B with a rigid rider, front frame H (fork and handlebar)
//! and front wheel F, knife-edge wheels rolling without slip on level ground.
//!
//! The equations are nonlinear and derived by precess's symbolic engine at run time: the
//! Lagrangian of the four bodies in eight coordinates q = (x, y, ψ, φ, θ, δ, θ_R, θ_F)
//! (rear contact, yaw, roll, pitch, steer, wheel angles) gives M(q) q̈ = f(q, q̇); the four
//! rolling rows and the front contact's height give five constraints A(q) q̇ = 0, each row
//! derived from the contact point's material velocity.
//!
//! **Why the elimination is numeric.** The engine's Maggi elimination forms the adjugate of
//! the 5 × 5 dependent block A_D symbolically (entries of up to 27 trig monomials, with
//! √(1 − n_z²), the front contact's distance below the hub, in the front rows) and the
//! products Sᵀ M S with mass-matrix entries of up to 609 terms. Tried on this system
//! (`EquationsOfMotion::constrain`, release build) it had not finished after 4 min 54 s of
//! CPU and held 8.5 GB, growing by about 1 GB every 30 s, when stopped. So the symbolic
//! engine derives M, f, A and Ȧq̇ exactly and lowers them to straight-line programs; at
//! each evaluation A_D q̇_D = −A_I u is solved by LU, and the reduced equations
//! Sᵀ M S u̇ = Sᵀ (f − M s), S = [I; −A_D⁻¹ A_I], s_D = −A_D⁻¹ Ȧq̇, are formed and solved
//! numerically: the engine's projection, evaluated in floating point.
//!
//! The free speeds are the roll rate φ̇, the steer rate δ̇ and the rear wheel rate θ̇_R (the
//! paper's choice); the pitch θ is dependent and found by Newton's method from the front
//! contact's height (the paper's coordinate partitioning).

mod derive;
mod linear;
mod scene;

pub use linear::{CAPSIZE_SPEED, Linear, STANDSTILL, TABLE_2, WEAVE_FREQUENCY, WEAVE_SPEED};
pub use scene::mechanism_scene;

use precess::codegen::{Bindings, Program};
use precess::lagrange::{LagrangeError, MAX_NEWTON};
use precess::nalgebra::{Matrix3, SMatrix, SVector, Vector3};
use precess::ode::System;
use precess::sym::{Arena, SymbolId};

/// Number of coordinates.
pub const COORDINATES: usize = 8;
/// State length: the eight coordinates, then the free speeds (φ̇, δ̇, θ̇_R).
pub const STATE: usize = 11;
/// Indices of the free speeds' coordinates: roll, steer, rear wheel.
pub const INDEPENDENT: [usize; 3] = [3, 5, 6];
/// Indices of the dependent coordinates: x, y, yaw, pitch, front wheel.
pub const DEPENDENT: [usize; 5] = [0, 1, 2, 4, 7];
/// Constraint row of the front contact's height (holonomic).
const HEIGHT_ROW: usize = 2;
const PITCH: usize = 4;

/// The benchmark's parameters (the paper's Table 1), SI units, z down.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameters {
    /// Every parameter by the name the derivation reads.
    pub values: Vec<(&'static str, f64)>,
}

impl Parameters {
    /// Table 1 of Meijaard et al. (2007): w = 1.02 m, c = 0.08 m, λ = π/10, g = 9.81 m/s²;
    /// R: r = 0.3, m = 2, (I_xx, I_yy) = (0.0603, 0.12); B: (x, z) = (0.3, −0.9), m = 85,
    /// I = [[9.2, 0, 2.4], [0, 11, 0], [2.4, 0, 2.8]]; H: (x, z) = (0.9, −0.7), m = 4,
    /// I = [[0.05892, 0, −0.00756], [0, 0.06, 0], [−0.00756, 0, 0.00708]]; F: r = 0.35,
    /// m = 3, (I_xx, I_yy) = (0.1405, 0.28).
    pub fn benchmark() -> Parameters {
        Parameters {
            values: vec![
                ("w", 1.02),
                ("c", 0.08),
                ("lambda", std::f64::consts::PI / 10.0),
                ("g", 9.81),
                ("rR", 0.3),
                ("mR", 2.0),
                ("IRxx", 0.0603),
                ("IRyy", 0.12),
                ("xB", 0.3),
                ("zB", -0.9),
                ("mB", 85.0),
                ("IBxx", 9.2),
                ("IByy", 11.0),
                ("IBzz", 2.8),
                ("IBxz", 2.4),
                ("xH", 0.9),
                ("zH", -0.7),
                ("mH", 4.0),
                ("IHxx", 0.05892),
                ("IHyy", 0.06),
                ("IHzz", 0.00708),
                ("IHxz", -0.00756),
                ("rF", 0.35),
                ("mF", 3.0),
                ("IFxx", 0.1405),
                ("IFyy", 0.28),
            ],
        }
    }

    /// The value of `name`, NaN if there is none.
    pub fn get(&self, name: &str) -> f64 {
        self.values
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(f64::NAN, |&(_, v)| v)
    }
}

/// The derived bicycle, lowered and bound to its parameters.
#[derive(Debug)]
pub struct Whipple {
    /// Outputs: M row-major (64), then f (8).
    dynamics: Program,
    /// Outputs: A row-major (40), then Ȧq̇ (5), then the front contact's height.
    constraints: Program,
    /// Outputs: T + V, then the rear and front contact points' material velocities.
    extra: Program,
    bindings: Bindings,
    q: Vec<SymbolId>,
    qd: Vec<SymbolId>,
    rear_radius: f64,
    gravity: f64,
    /// The size of the symbolic forms: M and f, then A and Ȧq̇ (operations of the lowered
    /// programs).
    pub op_counts: [usize; 2],
}

type Mat8 = SMatrix<f64, 8, 8>;
type Vec8 = SVector<f64, 8>;

impl Whipple {
    /// Derives the equations symbolically and lowers them with `parameters` bound.
    ///
    /// # Errors
    /// [`LagrangeError::Binding`] for a missing or non-finite parameter;
    /// [`LagrangeError::Sym`] if a symbolic step fails.
    pub fn new(parameters: &Parameters) -> Result<Whipple, LagrangeError> {
        let mut a = Arena::new();
        let d = derive::derive(&mut a)?;
        let mut dyn_out: Vec<_> = d.eom.mass.iter().flatten().copied().collect();
        dyn_out.extend(&d.eom.forcing);
        let mut con_out: Vec<_> = d
            .constraints
            .coefficients
            .iter()
            .flatten()
            .copied()
            .collect();
        con_out.extend(&d.rate_terms);
        let height = d.constraints.positions[HEIGHT_ROW].unwrap_or_else(|| a.zero());
        con_out.push(height);
        let mut extra_out = vec![d.energy];
        extra_out.extend(d.contact_velocities);
        let programs = [
            Program::lower(&a, &dyn_out),
            Program::lower(&a, &con_out),
            Program::lower(&a, &extra_out),
        ];
        let symbol = |e| {
            a.as_symbol(e)
                .unwrap_or_else(|| unreachable!("coordinates are symbols"))
        };
        let q: Vec<SymbolId> = d.coords.q.iter().map(|&e| symbol(e)).collect();
        let qd: Vec<SymbolId> = d.coords.rates.iter().map(|&e| symbol(e)).collect();
        let supplied: Vec<SymbolId> = q.iter().chain(&qd).copied().collect();
        let bindings = Bindings::new(&a, &programs, &supplied, &parameters.values)?;
        let op_counts = [
            programs[0].op_count().total(),
            programs[1].op_count().total(),
        ];
        let [dynamics, constraints, extra] = programs;
        Ok(Whipple {
            dynamics,
            constraints,
            extra,
            bindings,
            q,
            qd,
            rear_radius: parameters.get("rR"),
            gravity: parameters.get("g"),
            op_counts,
        })
    }

    fn eval(&self, program: &Program, q: &[f64; 8], qd: &[f64; 8], out: &mut [f64]) {
        let inputs = self
            .q
            .iter()
            .copied()
            .zip(q.iter().copied())
            .chain(self.qd.iter().copied().zip(qd.iter().copied()));
        self.bindings.eval(program, inputs, out);
    }

    fn mass_forcing(&self, q: &[f64; 8], qd: &[f64; 8]) -> (Mat8, Vec8) {
        let mut out = [0.0; 72];
        self.eval(&self.dynamics, q, qd, &mut out);
        (
            Mat8::from_row_slice(&out[..64]),
            Vec8::from_column_slice(&out[64..]),
        )
    }

    /// A (5 × 8), Ȧq̇ (5) and the front contact's height.
    fn constraint_terms(
        &self,
        q: &[f64; 8],
        qd: &[f64; 8],
    ) -> (SMatrix<f64, 5, 8>, SVector<f64, 5>, f64) {
        let mut out = [0.0; 46];
        self.eval(&self.constraints, q, qd, &mut out);
        (
            SMatrix::<f64, 5, 8>::from_row_slice(&out[..40]),
            SVector::<f64, 5>::from_column_slice(&out[40..45]),
            out[45],
        )
    }

    /// The front contact's height above the ground (zero on the constraint).
    pub fn front_height(&self, q: &[f64; 8]) -> f64 {
        self.constraint_terms(q, &[0.0; 8]).2
    }

    /// Puts the front wheel on the ground: solves the height for the pitch θ = `q[4]` by
    /// Newton's method from its current value; returns the iterations taken.
    ///
    /// # Errors
    /// [`LagrangeError::LoopNotClosed`] if |height| stays above 1e-15 m after
    /// [`MAX_NEWTON`] iterations; [`LagrangeError::SingularAtState`] if ∂height/∂θ
    /// vanishes.
    pub fn close_front_contact(&self, q: &mut [f64; 8]) -> Result<usize, LagrangeError> {
        let tolerance = 1e-15;
        let mut residual = f64::NAN;
        for k in 0..MAX_NEWTON {
            let (a, _, h) = self.constraint_terms(q, &[0.0; 8]);
            residual = h;
            if h.abs() <= tolerance {
                return Ok(k);
            }
            let slope = a[(HEIGHT_ROW, PITCH)];
            if slope.abs() < 1e-12 || !slope.is_finite() {
                return Err(LagrangeError::SingularAtState {
                    determinant: slope,
                    scale: 1.0,
                });
            }
            let step = h / slope;
            q[PITCH] -= step;
            if step.abs() <= 1e-17 {
                return Ok(k + 1);
            }
        }
        Err(LagrangeError::LoopNotClosed {
            residual,
            iterations: MAX_NEWTON,
            tolerance,
        })
    }

    /// Every rate q̇ from the coordinates and the free speeds u = (φ̇, δ̇, θ̇_R), with the
    /// projection S = [I; −A_D⁻¹ A_I] and the drift s_D = −A_D⁻¹ Ȧq̇ it needs.
    fn solve_rates(
        &self,
        q: &[f64; 8],
        u: &[f64; 3],
    ) -> Result<([f64; 8], SMatrix<f64, 8, 3>), LagrangeError> {
        let (a, _, _) = self.constraint_terms(q, &[0.0; 8]);
        let a_d = SMatrix::<f64, 5, 5>::from_fn(|r, c| a[(r, DEPENDENT[c])]);
        let a_i = SMatrix::<f64, 5, 3>::from_fn(|r, c| a[(r, INDEPENDENT[c])]);
        let lu = a_d.lu();
        let Some(c) = lu.solve(&(-a_i)) else {
            return Err(LagrangeError::SingularAtState {
                determinant: lu.determinant(),
                scale: a_d.norm(),
            });
        };
        let mut s = SMatrix::<f64, 8, 3>::zeros();
        for (j, &i) in INDEPENDENT.iter().enumerate() {
            s[(i, j)] = 1.0;
        }
        for (r, &d) in DEPENDENT.iter().enumerate() {
            for j in 0..3 {
                s[(d, j)] = c[(r, j)];
            }
        }
        let qd = s * Vector3::from_column_slice(u);
        let mut out = [0.0; 8];
        out.copy_from_slice(qd.as_slice());
        Ok((out, s))
    }

    /// The rates q̇ at `state` (dependent ones from the constraints).
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular.
    pub fn rates(&self, state: &[f64; STATE]) -> Result<[f64; 8], LagrangeError> {
        let (q, u) = split(state);
        Ok(self.solve_rates(&q, &u)?.0)
    }

    /// The reduced equations K u̇ = r at (q, u): K = Sᵀ M S, r = Sᵀ (f − M s).
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular.
    pub fn reduced(
        &self,
        q: &[f64; 8],
        u: &[f64; 3],
    ) -> Result<(Matrix3<f64>, Vector3<f64>), LagrangeError> {
        let (qd, s) = self.solve_rates(q, u)?;
        let (a, adot_qd, _) = self.constraint_terms(q, &qd);
        let (m, f) = self.mass_forcing(q, &qd);
        let a_d = SMatrix::<f64, 5, 5>::from_fn(|r, c| a[(r, DEPENDENT[c])]);
        let drift_d = a_d
            .lu()
            .solve(&(-adot_qd))
            .ok_or(LagrangeError::SingularAtState {
                determinant: a_d.determinant(),
                scale: a_d.norm(),
            })?;
        let mut drift = Vec8::zeros();
        for (r, &d) in DEPENDENT.iter().enumerate() {
            drift[d] = drift_d[r];
        }
        let k = s.transpose() * m * s;
        let r = s.transpose() * (f - m * drift);
        Ok((k, r))
    }

    /// dy/dt at `state`: the rates, then the free speeds' accelerations.
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D or the reduced mass matrix is
    /// singular.
    pub fn derivative(&self, state: &[f64; STATE]) -> Result<[f64; STATE], LagrangeError> {
        let (q, u) = split(state);
        let (qd, _) = self.solve_rates(&q, &u)?;
        let (k, r) = self.reduced(&q, &u)?;
        let ud = k.lu().solve(&r).ok_or(LagrangeError::SingularAtState {
            determinant: k.determinant(),
            scale: k.norm(),
        })?;
        let mut out = [0.0; STATE];
        out[..8].copy_from_slice(&qd);
        out[8..].copy_from_slice(ud.as_slice());
        Ok(out)
    }

    /// T + V, then the rear and the front contact points' material velocities (yaw
    /// frame, x y z each).
    ///
    /// # Errors
    /// [`LagrangeError::SingularAtState`] where A_D is singular.
    pub fn outputs(&self, state: &[f64; STATE]) -> Result<[f64; 7], LagrangeError> {
        let (q, _) = split(state);
        let qd = self.rates(state)?;
        let mut out = [0.0; 7];
        self.eval(&self.extra, &q, &qd, &mut out);
        Ok(out)
    }

    /// The upright straight run at forward speed `v` (θ̇_R = −v / r_R: the wheel turns
    /// backwards about y when the bicycle runs forwards along x, z being down), with
    /// `roll_rate` as a disturbance.
    ///
    /// # Errors
    /// As [`Whipple::close_front_contact`].
    pub fn upright(&self, v: f64, roll_rate: f64) -> Result<[f64; STATE], LagrangeError> {
        let mut q = [0.0; 8];
        self.close_front_contact(&mut q)?;
        let mut y = [0.0; STATE];
        y[..8].copy_from_slice(&q);
        y[8] = roll_rate;
        y[10] = -v / self.rear_radius;
        Ok(y)
    }

    /// This model as a [`System`] for the steppers (a state where A_D or K is singular
    /// yields NaN, which the steppers report).
    pub fn system(&self) -> WhippleSystem<'_> {
        WhippleSystem(self)
    }
}

fn split(state: &[f64; STATE]) -> ([f64; 8], [f64; 3]) {
    let mut q = [0.0; 8];
    q.copy_from_slice(&state[..8]);
    (q, [state[8], state[9], state[10]])
}

/// [`Whipple`] as an ODE system over the state (q, u).
#[derive(Debug, Clone, Copy)]
pub struct WhippleSystem<'a>(pub &'a Whipple);

impl System<STATE> for WhippleSystem<'_> {
    fn rhs(&self, _t: f64, y: &[f64; STATE], dydt: &mut [f64; STATE]) {
        *dydt = self.0.derivative(y).unwrap_or([f64::NAN; STATE]);
    }
}
