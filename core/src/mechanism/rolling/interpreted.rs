//! A rolling derivation evaluated at run time through the code generator's interpreter: the
//! path for mechanisms built without the macro, and the reference the tests use.
//!
//! Its [`RollingDynamics::acceleration_jacobian`] is exact, as the derive's: the same
//! engine derivatives ([`RollingDerivation::partials`]), lowered on the first call. It has
//! no case of differences: an effort here is an expression the engine differentiates with
//! the rest, and a user function's value (an input symbol) cannot be interpreted at all
//! ([`crate::codegen::BindingError::RunTimeInput`] from [`RollingModel::new`]).

use std::sync::{Mutex, OnceLock, PoisonError};

use nalgebra::{SMatrix, SVector};

use super::derivation::RollingDerivation;
use super::dynamics::RollingDynamics;
use super::partials::{Differentiated, RollingPartials};
use super::scene::{RollingScene, WheelSurface};
use crate::codegen::{Bindings, Program};
use crate::lagrange::Partition;
use crate::mechanism::checks::ParameterChecks;
use crate::mechanism::error::MechanismError;
use crate::mechanism::scene::MechanismScene;
use crate::sym::{Arena, ExprId, SymbolId, SymbolKind};

/// A rolling mechanism's M, f, A, Ȧq̇, heights and reports, lowered once and interpreted,
/// for n = `N` coordinates, m = `M` rows and k = `K` free speeds.
#[derive(Debug)]
pub struct RollingModel<const N: usize, const M: usize, const K: usize> {
    /// Outputs: M row-major (n²), then f (n).
    dynamics: Program,
    /// Outputs: A row-major (m n), then Ȧq̇ (m).
    rows: Program,
    /// Outputs: the heights (m, zero in nonholonomic rows), then the tilts (one per wheel).
    positions: Program,
    /// Outputs: T + V, then every wheel's contact velocity (three each).
    reports: Program,
    /// The engine's derivatives of M q̈, f, A and Ȧq̇, lowered on the first call of
    /// [`RollingDynamics::partials`].
    partials: LazyPartials,
    holonomic: [bool; M],
    wheels: usize,
    partition: Partition<M, K>,
    names: [&'static str; N],
    q: Vec<SymbolId>,
    rates: Vec<SymbolId>,
    /// q̈, read by `partials` alone.
    accels: Vec<SymbolId>,
    time: Option<SymbolId>,
    bindings: Bindings,
    /// The values made of parameters, checked at construction and on every `set`.
    checks: ParameterChecks,
}

/// The derivatives [`RollingDerivation::partials`] of a model, differentiated and lowered
/// when first asked for. Eagerly they took [`RollingModel::new`] on the bicycle from about
/// 22 ms to 210 ms (100–160 ms differentiating, 60–90 ms lowering 34 499 operations), a
/// cost a model that is only integrated need not pay. Until then the model keeps M, f, A
/// and Ȧq̇ in an arena of their own ([`Arena::extract`]: 7 310 of the derivation's 49 283
/// nodes, 3 ms, where a copy of the whole arena took 14–21 ms), which the first call frees.
struct LazyPartials {
    program: OnceLock<Option<Program>>,
    source: Mutex<Option<Box<(Arena, Differentiated)>>>,
}

impl LazyPartials {
    fn new(arena: &Arena, derivation: &RollingDerivation) -> Result<LazyPartials, MechanismError> {
        let source = Differentiated::extract(arena, derivation)?;
        Ok(LazyPartials {
            program: OnceLock::new(),
            source: Mutex::new(Some(Box::new(source))),
        })
    }

    /// The program, lowered on the first call (one thread lowers, the others wait), or
    /// `None` if it reads a symbol `bound` refuses.
    fn get(&self, bound: impl Fn(&Arena, SymbolId) -> bool) -> Option<&Program> {
        self.program
            .get_or_init(|| {
                let mut source = self.source.lock().unwrap_or_else(PoisonError::into_inner);
                let (arena, pieces) = &mut **source.as_mut()?;
                let outputs = pieces.partials(arena);
                let program = Program::lower(arena, &outputs);
                let readable = program.inputs().into_iter().all(|s| bound(arena, s));
                *source = None;
                readable.then_some(program)
            })
            .as_ref()
    }
}

impl std::fmt::Debug for LazyPartials {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.program.get() {
            Some(Some(p)) => write!(
                f,
                "LazyPartials(lowered, {} operations)",
                p.op_count().total()
            ),
            Some(None) => f.write_str("LazyPartials(unreadable)"),
            None => f.write_str("LazyPartials(not yet lowered)"),
        }
    }
}

impl<const N: usize, const M: usize, const K: usize> RollingModel<N, M, K> {
    /// Lowers `derivation` with a value for each parameter it reads. `names` are the
    /// coordinates' names (kept for reports).
    ///
    /// # Errors
    /// [`MechanismError::RollingSizes`] if the derivation's sizes are not (N, M, K);
    /// [`MechanismError::Binding`] for a parameter missing, unknown or not finite;
    /// [`MechanismError::Sym`] for a derivation made in another arena.
    pub fn new(
        arena: &mut Arena,
        derivation: &RollingDerivation,
        names: [&'static str; N],
        parameters: &[(&str, f64)],
    ) -> Result<RollingModel<N, M, K>, MechanismError> {
        let coords = derivation.coordinates();
        let (n, m, k) = (
            coords.len(),
            derivation.rows(),
            derivation.independent.len(),
        );
        if (n, m, k) != (N, M, K) {
            return Err(MechanismError::RollingSizes {
                coordinates: n,
                rows: m,
                speeds: k,
                asked: [N, M, K],
            });
        }
        let eqs = &derivation.equations;
        let mut dyn_out: Vec<ExprId> = eqs.mass.iter().flatten().copied().collect();
        dyn_out.extend(&eqs.forcing);
        let mut row_out: Vec<ExprId> = derivation
            .constraints
            .coefficients
            .iter()
            .flatten()
            .copied()
            .collect();
        row_out.extend(&derivation.rate_terms);
        let zero = arena.zero();
        let mut pos_out: Vec<ExprId> = derivation
            .constraints
            .positions
            .iter()
            .map(|p| p.unwrap_or(zero))
            .collect();
        pos_out.extend(&derivation.tilts);
        let mut report_out = vec![arena.add(derivation.kinetic, derivation.potential)];
        report_out.extend(derivation.contact_velocities.iter().flatten());
        let arena = &*arena;
        let programs = [
            Program::lower(arena, &dyn_out),
            Program::lower(arena, &row_out),
            Program::lower(arena, &pos_out),
            Program::lower(arena, &report_out),
        ];
        let symbol = |e: ExprId| arena.as_symbol(e);
        let q: Vec<SymbolId> = coords.q.iter().filter_map(|&e| symbol(e)).collect();
        let rates: Vec<SymbolId> = coords.rates.iter().filter_map(|&e| symbol(e)).collect();
        let accels: Vec<SymbolId> = coords.accels.iter().filter_map(|&e| symbol(e)).collect();
        let time = arena.as_symbol(derivation.time);
        let mut supplied: Vec<SymbolId> = q.iter().chain(&rates).chain(&accels).copied().collect();
        supplied.extend(time);
        let bindings = Bindings::new(arena, &programs, &supplied, parameters)?;
        let mut holonomic = [false; M];
        for (h, p) in holonomic.iter_mut().zip(&derivation.constraints.positions) {
            *h = p.is_some();
        }
        let mut independent = [0; K];
        independent.copy_from_slice(&derivation.independent);
        let mut dependent = [0; M];
        dependent.copy_from_slice(&derivation.dependent);
        let [dynamics, rows, positions, reports] = programs;
        Ok(RollingModel {
            dynamics,
            rows,
            positions,
            reports,
            partials: LazyPartials::new(arena, derivation)?,
            holonomic,
            wheels: derivation.tilts.len(),
            partition: Partition {
                independent,
                dependent,
            },
            names,
            q,
            rates,
            accels,
            time,
            checks: ParameterChecks::none(arena),
            bindings,
        })
    }

    /// Derives `scene` with its wheels rolling and lowers it, checking every value made of
    /// parameters by the rules literals meet (axes with a direction, masses and wheel radii
    /// finite and not negative, physical inertias), as [`crate::mechanism::MechanismModel`]
    /// does.
    ///
    /// # Errors
    /// As [`MechanismScene::derive_rolling`] and [`RollingModel::new`];
    /// [`MechanismError::ZeroAxis`], [`MechanismError::ParallelAxes`],
    /// [`MechanismError::NonFiniteParameter`], [`MechanismError::NegativeParameter`],
    /// [`MechanismError::Part`] for values no mechanism can have.
    pub fn from_scene(
        arena: &mut Arena,
        scene: &MechanismScene,
        rolling: &RollingScene,
        names: [&'static str; N],
        parameters: &[(&str, f64)],
    ) -> Result<RollingModel<N, M, K>, MechanismError> {
        let derivation = scene.derive_rolling(arena, rolling)?;
        let mut model = RollingModel::new(arena, &derivation, names, parameters)?;
        let lengths: Vec<((String, String), ExprId)> = rolling
            .wheels
            .iter()
            .filter_map(|w| {
                let body = scene.bodies.get(w.body)?;
                let radius = match w.surface {
                    WheelSurface::Disk { radius, .. } | WheelSurface::Sphere { radius, .. } => {
                        radius
                    }
                };
                Some((
                    (
                        format!("rolling wheel `{}`", body.name),
                        "radius".to_owned(),
                    ),
                    radius,
                ))
            })
            .collect();
        let known: Vec<String> = model.bindings.parameters().map(str::to_owned).collect();
        model.checks = ParameterChecks::new(arena, scene, &lengths, &known);
        model.checks.check(&model.bindings)?;
        Ok(model)
    }

    /// Changes the parameter `name`; a value the checks of [`RollingModel::from_scene`]
    /// refuse leaves the model as it was.
    ///
    /// # Errors
    /// [`MechanismError::Binding`] for an unknown name or a value that is not finite; those
    /// of [`RollingModel::from_scene`] for a value no mechanism can have.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, MechanismError> {
        let previous = self.bindings.value(name);
        self.bindings.set(name, value)?;
        if let Err(e) = self.checks.check(&self.bindings) {
            if let Some(previous) = previous {
                self.bindings.set(name, previous)?;
            }
            return Err(e);
        }
        Ok(self)
    }

    /// The operation counts of the lowered M and f, and of A and Ȧq̇.
    pub fn op_counts(&self) -> [usize; 2] {
        [
            self.dynamics.op_count().total(),
            self.rows.op_count().total(),
        ]
    }

    /// The operation count of the lowered derivatives of M q̈, f, A and Ȧq̇
    /// ([`RollingDynamics::partials`]), lowering them if no call has yet.
    pub fn partials_op_count(&self) -> Option<usize> {
        Some(self.partials_program()?.op_count().total())
    }

    /// The derivatives' program, differentiated and lowered on the first call: `None` only
    /// if it would read a symbol the bindings do not give (the derivatives of M, f, A and
    /// Ȧq̇ read no symbol those do not, so this is a guard, not a case).
    fn partials_program(&self) -> Option<&Program> {
        self.partials.get(|arena, s| {
            let supplied = self.q.contains(&s)
                || self.rates.contains(&s)
                || self.accels.contains(&s)
                || self.time == Some(s);
            let symbol = arena.symbol(s);
            supplied
                || (symbol.kind == SymbolKind::Parameter
                    && self.bindings.value(&symbol.name).is_some())
        })
    }

    fn eval(&self, program: &Program, t: f64, q: &[f64; N], qdot: &[f64; N], out: &mut [f64]) {
        let inputs = self
            .q
            .iter()
            .copied()
            .zip(q.iter().copied())
            .chain(self.rates.iter().copied().zip(qdot.iter().copied()))
            .chain(self.time.map(|s| (s, t)));
        self.bindings.eval(program, inputs, out);
    }
}

impl<const N: usize, const M: usize, const K: usize> RollingDynamics<N, M, K>
    for RollingModel<N, M, K>
{
    fn partition(&self) -> Partition<M, K> {
        self.partition
    }

    fn coordinate_names(&self) -> [&'static str; N] {
        self.names
    }

    fn mass_forcing(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> (SMatrix<f64, N, N>, SVector<f64, N>) {
        let mut out = vec![0.0; N * N + N];
        self.eval(&self.dynamics, t, q, qdot, &mut out);
        (
            SMatrix::from_row_slice(&out[..N * N]),
            SVector::from_column_slice(&out[N * N..]),
        )
    }

    fn constraint_rows(
        &self,
        q: &[f64; N],
        qdot: &[f64; N],
    ) -> (SMatrix<f64, M, N>, SVector<f64, M>) {
        let mut out = vec![0.0; M * N + M];
        self.eval(&self.rows, 0.0, q, qdot, &mut out);
        (
            SMatrix::from_row_slice(&out[..M * N]),
            SVector::from_column_slice(&out[M * N..]),
        )
    }

    /// The engine's derivatives ([`RollingDerivation::partials`]), the same expressions the
    /// derive emits as code, lowered on the first call and interpreted, so
    /// [`RollingDynamics::acceleration_jacobian`] is exact here too.
    fn partials(
        &self,
        t: f64,
        q: &[f64; N],
        qdot: &[f64; N],
        qddot: &[f64; N],
    ) -> Option<RollingPartials<N, M>> {
        let program = self.partials_program()?;
        let mut out = vec![0.0; RollingPartials::<N, M>::LEN];
        let inputs = self
            .q
            .iter()
            .copied()
            .zip(q.iter().copied())
            .chain(self.rates.iter().copied().zip(qdot.iter().copied()))
            .chain(self.accels.iter().copied().zip(qddot.iter().copied()))
            .chain(self.time.map(|s| (s, t)));
        self.bindings.eval(program, inputs, &mut out);
        Some(RollingPartials::from_slice(&out))
    }

    fn holonomic_rows(&self) -> [bool; M] {
        self.holonomic
    }

    fn heights(&self, q: &[f64; N]) -> [f64; M] {
        let mut out = vec![0.0; M + self.wheels];
        self.eval(&self.positions, 0.0, q, &[0.0; N], &mut out);
        let mut h = [0.0; M];
        h.copy_from_slice(&out[..M]);
        h
    }

    fn lowest_tilt(&self, q: &[f64; N]) -> (usize, f64) {
        let mut out = vec![0.0; M + self.wheels];
        self.eval(&self.positions, 0.0, q, &[0.0; N], &mut out);
        out[M..]
            .iter()
            .copied()
            .enumerate()
            .fold((0, f64::INFINITY), |best, (i, v)| {
                if v < best.1 || v.is_nan() {
                    (i, v)
                } else {
                    best
                }
            })
    }

    fn energy(&self, q: &[f64; N], qdot: &[f64; N]) -> f64 {
        let mut out = vec![0.0; 1 + 3 * self.wheels];
        self.eval(&self.reports, 0.0, q, qdot, &mut out);
        out[0]
    }

    fn contact_speed(&self, q: &[f64; N], qdot: &[f64; N]) -> f64 {
        let mut out = vec![0.0; 1 + 3 * self.wheels];
        self.eval(&self.reports, 0.0, q, qdot, &mut out);
        out[1..]
            .chunks(3)
            .map(|v| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt())
            .fold(0.0, f64::max)
    }
}
