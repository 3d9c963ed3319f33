//! From a [`MechanismScene`] to `M(q) q̈ = f(q, q̇, t)` and its solution by the cheapest route.
//!
//! Every route starts from the Lagrangian pieces T, V and Q ([`super::routes::lagrangian`]);
//! the solve is one of the [`Route`]s, each in its own file under `routes/`, and
//! [`Route::Auto`] lowers each available one and keeps the cheapest program. The energy,
//! the power of the loads and the conserved momenta come from the same pieces whatever the
//! route.

use super::error::MechanismError;
use super::kinematics::MAX_LAGRANGIAN;
use super::routes::factored::ldlt_solve;
use super::routes::lagrangian::{largest_coupled_block, symbolic};
use super::routes::recursive;
use super::scene::MechanismScene;
use crate::codegen::Program;
use crate::lagrange::Coordinates;
use crate::sym::{Arena, ExprId, SymbolKind};

/// How q̈ is solved from M q̈ = f.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Route {
    /// Up to [`MAX_LAGRANGIAN`] coordinates, lower every route and keep the one with the
    /// fewest weighted operations; past it, the recursive route.
    #[default]
    Auto,
    /// The block adjugate solve of [`EquationsOfMotion::solve`](crate::lagrange::EquationsOfMotion::solve), for few coordinates.
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

impl MechanismScene {
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
        let l = lag.lagrangian(arena);
        let coords = lag.coords.clone();
        let n = coords.len();
        let (accelerations, pivots, route) = match route {
            Route::Recursive => {
                let (a, p) = self.recursive(arena, &coords)?;
                (a, p, Route::Recursive)
            }
            Route::Symbolic => {
                let eom = lag.equations(arena)?;
                let (a, p) = symbolic(arena, &eom)?;
                (a, p, Route::Symbolic)
            }
            Route::Factored => {
                let eom = lag.equations(arena)?;
                let (a, p) = ldlt_solve(arena, &eom.mass, &eom.forcing)?;
                (a, p, Route::Factored)
            }
            Route::Auto if n > MAX_LAGRANGIAN => {
                let (a, p) = self.recursive(arena, &coords)?;
                (a, p, Route::Recursive)
            }
            Route::Auto => {
                let eom = lag.equations(arena)?;
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
        let power = lag.power(arena);
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
        let forces = recursive::coordinate_forces(arena, self, coords);
        let form = recursive::recursive_accelerations(arena, self, coords, &forces)?;
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

/// The weighted operation count of the program computing q̈ and the pivots together.
pub(crate) fn cost(arena: &Arena, accelerations: &[ExprId], pivots: &[ExprId]) -> usize {
    let outputs: Vec<ExprId> = accelerations.iter().chain(pivots).copied().collect();
    Program::lower(arena, &outputs).op_count().weighted()
}
