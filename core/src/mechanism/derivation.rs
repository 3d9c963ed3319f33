//! From a [`MechanismScene`] to `M(q) q̈ = f(q, q̇, t)` and its solution by the cheapest route.
//!
//! - Kinetic energy T = Σ_b ½ m_b |v_c|² + ½ ω_bᵀ I_b ω_b (ω_b in body axes, I_b about the
//!   centre of mass in the body's axes; see [`super::kinematics`]).
//! - Potential V = −Σ_b m_b g·c_b + Σ ½ k (q − rest)² (gravity and joint springs).
//! - Non-conservative generalised forces Q_i = −c_i q̇_i + e_i + Σ_b τ_b·∂ω_b/∂q̇_i, with
//!   τ_b the body torque plus R_bᵀ times the space torque.
//! - [`EquationsOfMotion::derive`] turns L = T − V and Q into M q̈ = f.
//!
//! The solve is one of the [`Route`]s; [`Route::Auto`] lowers each available one and keeps
//! the cheapest program.

use super::error::MechanismError;
use super::factored::ldlt_solve;
use super::kinematics::BodyKinematics;
use super::scene::MechanismScene;
use crate::codegen::Program;
use crate::lagrange::{Coordinates, EquationsOfMotion, LagrangeError};
use crate::sym::mat3::{dot, mat_vec, transpose};
use crate::sym::{Arena, ExprId, Rational, SymbolKind};

/// How q̈ is solved from M q̈ = f.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Route {
    /// Up to [`MAX_LAGRANGIAN`] coordinates, lower every route and keep the one with the
    /// fewest weighted operations; past it, the recursive route.
    #[default]
    Auto,
    /// The block adjugate solve of [`EquationsOfMotion::solve`], for few coordinates.
    Symbolic,
    /// The symbolic M and f followed by an unexpanded LDLᵀ solve (straight-line code).
    Factored,
    /// A recursive (articulated-body) algorithm specialised to the mechanism.
    Recursive,
}

impl Route {
    /// Every route, in the order of [`Route::NAMES`].
    pub const ALL: [Route; 4] = [
        Route::Auto,
        Route::Symbolic,
        Route::Factored,
        Route::Recursive,
    ];

    /// The routes' names, as `#[mechanism(route = ..)]` takes them: the one list the derive
    /// reads too.
    pub const NAMES: [&'static str; 4] = ["auto", "symbolic", "factored", "recursive"];

    /// The route's name.
    pub fn name(self) -> &'static str {
        match self {
            Route::Auto => Route::NAMES[0],
            Route::Symbolic => Route::NAMES[1],
            Route::Factored => Route::NAMES[2],
            Route::Recursive => Route::NAMES[3],
        }
    }

    /// The route called `name`, if there is one.
    ///
    /// ```
    /// use precess_core::mechanism::Route;
    /// assert_eq!(Route::from_name("factored"), Some(Route::Factored));
    /// assert_eq!(Route::from_name("adjugate"), None);
    /// for route in Route::ALL {
    ///     assert_eq!(Route::from_name(route.name()), Some(route));
    /// }
    /// ```
    pub fn from_name(name: &str) -> Option<Route> {
        Route::ALL.into_iter().find(|r| r.name() == name)
    }
}

/// The largest coupled block of M for which [`Route::Auto`] tries the symbolic route. Its
/// adjugates are expanded and grow as n!: measured on spatial chains, a coupled block of
/// three already derives 2–400× slower than the factored route (0.2 s with literal mass
/// properties, 98 s with all of them parameters) and lowers to 1.5–7× more operations, while
/// at two the symbolic route is as fast and sometimes a few operations smaller.
pub const MAX_SYMBOLIC: usize = 2;

/// The most coordinates for which [`Route::Auto`] forms the Euler–Lagrange equations and
/// compares the Lagrangian routes with the recursive one. Past it the expanded M and f grow
/// faster than the chain (planar chains: 1,046 weighted operations factored against 454
/// recursive at five coordinates, and five to eight times the derivation time per link),
/// so Auto takes the recursive route without deriving them.
pub const MAX_LAGRANGIAN: usize = 3;

/// Everything derived from a mechanism.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanismDerivation {
    /// q, q̇, q̈ symbols in [`MechanismScene::coordinate_names`] order.
    pub coordinates: Coordinates,
    /// The time symbol (for user-function inputs).
    pub time: ExprId,
    /// q̈ in q, q̇ and the parameters.
    pub accelerations: Vec<ExprId>,
    /// What must be > 0 for M to be regular: the LDLᵀ pivots, or the block determinants on
    /// the symbolic route.
    pub pivots: Vec<ExprId>,
    /// Kinetic energy T.
    pub kinetic: ExprId,
    /// Potential energy V (gravity and springs).
    pub potential: ExprId,
    /// T + V.
    pub energy: ExprId,
    /// dE/dt = Σ Q_i q̇_i, the power of the non-conservative loads (dampers, efforts,
    /// torques).
    pub power: ExprId,
    /// `(i, ∂L/∂q̇_i)` for each coordinate absent from L with no load on it (conserved).
    pub conserved_momenta: Vec<(usize, ExprId)>,
    /// The route taken ([`Route::Auto`] resolved).
    pub route: Route,
}

impl MechanismDerivation {
    /// The names of the parameters the derivation reads (q̈, pivots, energies, momenta), in
    /// alphabetical order: what [`super::MechanismModel`] needs values for.
    pub fn parameters(&self, arena: &Arena) -> Vec<String> {
        let mut roots: Vec<ExprId> = self.accelerations.clone();
        roots.extend(&self.pivots);
        roots.extend([self.kinetic, self.potential, self.power]);
        roots.extend(self.conserved_momenta.iter().map(|&(_, p)| p));
        let mut names: Vec<String> = roots
            .iter()
            .flat_map(|&e| arena.free_symbols(e))
            .filter(|&s| arena.symbol(s).kind == SymbolKind::Parameter)
            .map(|s| arena.symbol(s).name.clone())
            .collect();
        names.sort();
        names.dedup();
        names
    }
}

/// The Lagrangian pieces shared by the routes (and the rolling derivation).
pub(crate) struct Lagrangian {
    pub(crate) coords: Coordinates,
    pub(crate) time: ExprId,
    pub(crate) kinetic: ExprId,
    pub(crate) potential: ExprId,
    pub(crate) forces: Vec<ExprId>,
}

fn half(arena: &mut Arena) -> ExprId {
    arena.constant(Rational::new(1, 2).unwrap_or(Rational::ONE))
}

/// −c q̇ + effort per coordinate (no springs: they are in V).
fn non_conservative_joint_forces(
    arena: &mut Arena,
    scene: &MechanismScene,
    coords: &Coordinates,
) -> Vec<ExprId> {
    let mut out = Vec::with_capacity(coords.len());
    let mut i = 0;
    for body in &scene.bodies {
        for load in &body.joint.loads {
            let mut terms = Vec::new();
            if let Some(c) = load.damper {
                let t = arena.mul(c, coords.rates[i]);
                terms.push(arena.neg(t));
            }
            if let Some(e) = load.effort {
                terms.push(e);
            }
            out.push(arena.sum(&terms));
            i += 1;
        }
    }
    out
}

impl MechanismScene {
    pub(crate) fn lagrangian(
        &self,
        arena: &mut Arena,
    ) -> Result<(Lagrangian, Vec<BodyKinematics>), MechanismError> {
        let order = self.validate(arena)?;
        let names = self.coordinate_names();
        let coords = Coordinates::new(arena, &names);
        let time = arena.time();
        let kin = self.kinematics(arena, &order, &coords)?;
        let h = half(arena);
        // The expanded T of a 3D chain grows far faster than the chain (a 10-link one did
        // not expand in minutes); past MAX_LAGRANGIAN coordinates only the energy reads T
        // and V, and their unexpanded, hash-consed forms lower to the same values.
        let expand = |arena: &mut Arena, e: ExprId| {
            if coords.len() <= MAX_LAGRANGIAN {
                arena.expand(e)
            } else {
                e
            }
        };
        let mut t_terms = Vec::new();
        let mut v_terms = Vec::new();
        for (body, k) in self.bodies.iter().zip(&kin) {
            let v2 = dot(arena, &k.center_velocity, &k.center_velocity);
            let i_omega = mat_vec(arena, &body.inertia, &k.omega);
            let w2 = dot(arena, &k.omega, &i_omega);
            let translational = arena.product(&[h, body.mass, v2]);
            let rotational = arena.mul(h, w2);
            let t = arena.add(translational, rotational);
            t_terms.push(expand(arena, t));
            if let Some(g) = self.gravity {
                let height = dot(arena, &g, &k.center);
                let v = arena.mul(body.mass, height);
                let v = arena.neg(v);
                v_terms.push(expand(arena, v));
            }
        }
        let mut i = 0;
        for body in &self.bodies {
            for load in &body.joint.loads {
                if let Some(spring) = load.spring {
                    let stretch = arena.sub(coords.q[i], spring.rest);
                    let v = arena.product(&[h, spring.stiffness, stretch, stretch]);
                    v_terms.push(expand(arena, v));
                }
                i += 1;
            }
        }
        let kinetic = arena.sum(&t_terms);
        let potential = arena.sum(&v_terms);
        let mut forces = non_conservative_joint_forces(arena, self, &coords);
        for (body, k) in self.bodies.iter().zip(&kin) {
            let mut tau: Option<[ExprId; 3]> = body.body_torque;
            if let Some(ts) = body.space_torque {
                let local = mat_vec(arena, &transpose(&k.rotation), &ts);
                tau = Some(match tau {
                    Some(tb) => [0, 1, 2].map(|j| arena.add(tb[j], local[j])),
                    None => local,
                });
            }
            let Some(tau) = tau else { continue };
            for (f, &rate) in forces.iter_mut().zip(&coords.rates) {
                let Some(s) = arena.as_symbol(rate) else {
                    continue;
                };
                let partial = k.omega.map(|w| arena.diff(w, s));
                let q = dot(arena, &tau, &partial);
                let total = arena.add(*f, q);
                *f = expand(arena, total);
            }
        }
        Ok((
            Lagrangian {
                coords,
                time,
                kinetic,
                potential,
                forces,
            },
            kin,
        ))
    }

    /// The Euler–Lagrange equations `M(q) q̈ = f(q, q̇, t)`, every entry expanded.
    ///
    /// # Errors
    /// As [`MechanismScene::validate`]; [`MechanismError::Lagrange`] if the engine fails.
    pub fn mass_matrix(&self, arena: &mut Arena) -> Result<EquationsOfMotion, MechanismError> {
        let (lag, _) = self.lagrangian(arena)?;
        let l = arena.sub(lag.kinetic, lag.potential);
        Ok(EquationsOfMotion::derive(
            arena,
            l,
            lag.coords,
            &lag.forces,
        )?)
    }

    /// Derives the mechanism and solves for q̈ by `route`.
    ///
    /// # Errors
    /// As [`MechanismScene::validate`]; [`MechanismError::SingularMassMatrix`] if M is
    /// singular everywhere (a pivot or block determinant is identically zero);
    /// [`MechanismError::Lagrange`] for a coupled block too large for [`Route::Symbolic`].
    ///
    /// # Examples
    ///
    /// A pendulum of mass m on a massless rod of length l, hinged about the ground's x axis
    /// with gravity −g ẑ: θ̈ = −(g/l) sin θ.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::mechanism::{JointKind, MechanismModel, MechanismScene, Parent, Route};
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (o, z) = (a.one(), a.zero());
    /// let (m, l, g) = (a.parameter("m"), a.parameter("l"), a.parameter("g"));
    /// let mut bob = MechanismScene::body(&mut a, "bob", Parent::Ground,
    ///     JointKind::Revolute { axis: [o, z, z] }, &["theta"]);
    /// bob.mass = m;
    /// bob.center = [z, z, a.neg(l)];
    /// let mut scene = MechanismScene::new();
    /// scene.bodies.push(bob);
    /// scene.gravity = Some([z, z, a.neg(g)]);
    /// let derivation = scene.derive(&mut a, Route::Auto)?;
    /// let model = MechanismModel::from_derivation(&a, &derivation,
    ///     &[("m", 2.0), ("l", 0.5), ("g", 9.81)])?;
    /// let qdd = model.accelerations(0.0, &[0.3], &[1.0])?;
    /// assert_relative_eq!(qdd[0], -9.81 / 0.5 * 0.3f64.sin(), epsilon = 1e-12);
    /// # Ok::<(), precess_core::mechanism::MechanismError>(())
    /// ```
    pub fn derive(
        &self,
        arena: &mut Arena,
        route: Route,
    ) -> Result<MechanismDerivation, MechanismError> {
        let (lag, _) = self.lagrangian(arena)?;
        let l = arena.sub(lag.kinetic, lag.potential);
        let coords = lag.coords.clone();
        let n = coords.len();
        let (accelerations, pivots, route) = match route {
            Route::Recursive => {
                let (a, p) = self.recursive(arena, &coords)?;
                (a, p, Route::Recursive)
            }
            Route::Symbolic => {
                let eom = EquationsOfMotion::derive(arena, l, coords.clone(), &lag.forces)?;
                let (a, p) = symbolic(arena, &eom)?;
                (a, p, Route::Symbolic)
            }
            Route::Factored => {
                let eom = EquationsOfMotion::derive(arena, l, coords.clone(), &lag.forces)?;
                let (a, p) = ldlt_solve(arena, &eom.mass, &eom.forcing)?;
                (a, p, Route::Factored)
            }
            Route::Auto if n > MAX_LAGRANGIAN => {
                let (a, p) = self.recursive(arena, &coords)?;
                (a, p, Route::Recursive)
            }
            Route::Auto => {
                let eom = EquationsOfMotion::derive(arena, l, coords.clone(), &lag.forces)?;
                let (fa, fp) = ldlt_solve(arena, &eom.mass, &eom.forcing)?;
                let mut best = (fa, fp, Route::Factored);
                if largest_coupled_block(arena, &eom.mass) <= MAX_SYMBOLIC {
                    let (sa, sp) = symbolic(arena, &eom)?;
                    if cost(arena, &sa, &sp) < cost(arena, &best.0, &best.1) {
                        best = (sa, sp, Route::Symbolic);
                    }
                }
                let (ra, rp) = self.recursive(arena, &coords)?;
                if cost(arena, &ra, &rp) < cost(arena, &best.0, &best.1) {
                    best = (ra, rp, Route::Recursive);
                }
                best
            }
        };
        let energy = arena.add(lag.kinetic, lag.potential);
        let power_terms: Vec<ExprId> = lag
            .forces
            .iter()
            .zip(&coords.rates)
            .map(|(&f, &r)| arena.mul(f, r))
            .collect();
        let power = arena.sum(&power_terms);
        // Expanded only where the kinematics are (see `MechanismScene::kinematics`).
        let power = if n <= MAX_LAGRANGIAN {
            arena.expand(power)
        } else {
            power
        };
        let mut conserved_momenta = Vec::new();
        for i in 0..n {
            let (Some(qs), Some(rs)) = (
                arena.as_symbol(coords.q[i]),
                arena.as_symbol(coords.rates[i]),
            ) else {
                continue;
            };
            if lag.forces[i] != arena.zero() {
                continue;
            }
            // A coordinate L does not read is cyclic; one it reads may still cancel, which
            // only the expansion shows, affordable for few coordinates.
            let cyclic = if !arena.free_symbols(l).contains(&qs) {
                true
            } else if n <= MAX_LAGRANGIAN {
                let dl = arena.diff(l, qs);
                arena.expand(dl) == arena.zero()
            } else {
                false
            };
            if cyclic {
                let p = arena.diff(l, rs);
                conserved_momenta.push((i, arena.expand(p)));
            }
        }
        Ok(MechanismDerivation {
            coordinates: coords,
            time: lag.time,
            accelerations,
            pivots,
            kinetic: lag.kinetic,
            potential: lag.potential,
            energy,
            power,
            conserved_momenta,
            route,
        })
    }

    /// q̈ and the pivots by the recursive (articulated-body) route.
    fn recursive(
        &self,
        arena: &mut Arena,
        coords: &Coordinates,
    ) -> Result<(Vec<ExprId>, Vec<ExprId>), MechanismError> {
        // The recursive algorithm applies gravity and torques itself; the joint loads,
        // springs included, enter as forces along the coordinates.
        let forces = super::recursive::coordinate_forces(arena, self, coords);
        let form = super::recursive::recursive_accelerations(arena, self, coords, &forces)?;
        Ok((form.accelerations, form.pivots))
    }

    /// The Jacobian of the state derivative `(q̇, q̈)` with respect to the state `(q, q̇)`:
    /// 2n rows of 2n entries, for linearisation and implicit steppers.
    pub fn jacobian(&self, arena: &mut Arena, d: &MechanismDerivation) -> Vec<Vec<ExprId>> {
        let c = &d.coordinates;
        let n = c.len();
        let state: Vec<ExprId> = c.q.iter().chain(&c.rates).copied().collect();
        let mut rows = Vec::with_capacity(2 * n);
        for i in 0..n {
            let mut row = vec![arena.zero(); 2 * n];
            row[n + i] = arena.one();
            rows.push(row);
        }
        for &a in &d.accelerations {
            let row = state
                .iter()
                .map(|&x| match arena.as_symbol(x) {
                    Some(s) => arena.diff(a, s),
                    None => arena.zero(),
                })
                .collect();
            rows.push(row);
        }
        rows
    }
}

/// The size of the largest connected block of M's non-zero pattern.
fn largest_coupled_block(arena: &Arena, mass: &[Vec<ExprId>]) -> usize {
    let n = mass.len();
    let mut seen = vec![false; n];
    let mut largest = 0;
    for start in 0..n {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut stack = vec![start];
        let mut size = 0;
        while let Some(i) = stack.pop() {
            size += 1;
            for j in 0..n {
                if !seen[j] && mass[i][j] != arena.zero() {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        largest = largest.max(size);
    }
    largest
}

/// The block adjugate solve; pivots are the block determinants.
fn symbolic(
    arena: &mut Arena,
    eom: &EquationsOfMotion,
) -> Result<(Vec<ExprId>, Vec<ExprId>), MechanismError> {
    match eom.solve(arena) {
        Ok(acc) => Ok((acc.accel, acc.determinants)),
        Err(LagrangeError::SingularMassMatrix { block }) => {
            Err(MechanismError::SingularMassMatrix {
                pivot: block.first().copied().unwrap_or(0),
                value: 0.0,
            })
        }
        Err(e) => Err(e.into()),
    }
}

/// The weighted operation count of the program computing q̈ and the pivots together.
pub(crate) fn cost(arena: &Arena, accelerations: &[ExprId], pivots: &[ExprId]) -> usize {
    let outputs: Vec<ExprId> = accelerations.iter().chain(pivots).copied().collect();
    Program::lower(arena, &outputs).op_count().weighted()
}
