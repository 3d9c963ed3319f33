//! From a Lagrangian and generalised forces to `M(q) q̈ = f(q, q̇)`.

use super::error::LagrangeError;
use crate::sym::{Arena, ExprId, SymbolId};

/// Generalised coordinates with their rate and acceleration symbols.
#[derive(Clone, Debug, PartialEq)]
pub struct Coordinates {
    /// The coordinates q.
    pub q: Vec<ExprId>,
    /// Their rates q̇.
    pub rates: Vec<ExprId>,
    /// Their accelerations q̈.
    pub accels: Vec<ExprId>,
}

impl Coordinates {
    /// Creates (or finds) the coordinates named `names` and their derivative symbols.
    ///
    /// ```
    /// use precess_core::{lagrange::Coordinates, sym::Arena};
    /// let mut a = Arena::new();
    /// let c = Coordinates::new(&mut a, &["theta"]);
    /// assert_eq!(a.display(c.accels[0]), "theta_ddot");
    /// ```
    pub fn new(arena: &mut Arena, names: &[&str]) -> Coordinates {
        let q: Vec<ExprId> = names.iter().map(|n| arena.coordinate(n)).collect();
        Self::from_symbols(arena, &q)
            .unwrap_or_else(|_| unreachable!("just created as coordinates"))
    }

    /// Wraps existing coordinate expressions.
    ///
    /// # Errors
    /// [`LagrangeError::NotACoordinate`] if an expression is not a coordinate symbol.
    pub fn from_symbols(arena: &mut Arena, q: &[ExprId]) -> Result<Coordinates, LagrangeError> {
        let mut rates = Vec::with_capacity(q.len());
        let mut accels = Vec::with_capacity(q.len());
        for &qi in q {
            let not = |a: &Arena| LagrangeError::NotACoordinate {
                expr: a.display(qi),
            };
            let is_coordinate = arena
                .as_symbol(qi)
                .is_some_and(|s| arena.symbol(s).kind == crate::sym::SymbolKind::Coordinate);
            if !is_coordinate {
                return Err(not(arena));
            }
            let Some(r) = arena.rate(qi) else {
                return Err(not(arena));
            };
            let Some(acc) = arena.rate(r) else {
                return Err(not(arena));
            };
            rates.push(r);
            accels.push(acc);
        }
        Ok(Coordinates {
            q: q.to_vec(),
            rates,
            accels,
        })
    }

    /// Number of coordinates.
    pub fn len(&self) -> usize {
        self.q.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.q.is_empty()
    }

    fn symbols(arena: &Arena, v: &[ExprId]) -> Vec<SymbolId> {
        v.iter().filter_map(|&e| arena.as_symbol(e)).collect()
    }
}

/// The Euler–Lagrange equations `d/dt ∂L/∂q̇ − ∂L/∂q = Q` written as `M(q) q̈ = f(q, q̇)`.
///
/// Every entry is in expanded, trig-canonical form, so structural zeros of M are exact.
#[derive(Clone, Debug, PartialEq)]
pub struct EquationsOfMotion {
    /// The coordinates.
    pub coords: Coordinates,
    /// `M_ij = ∂²L/∂q̇_i∂q̇_j` (symmetric).
    pub mass: Vec<Vec<ExprId>>,
    /// `f_i = Q_i + ∂L/∂q_i − Σ_j ∂²L/∂q̇_i∂q_j q̇_j − ∂²L/∂q̇_i∂t`.
    pub forcing: Vec<ExprId>,
    /// The residuals `d/dt ∂L/∂q̇_i − ∂L/∂q_i − Q_i` (zero on a solution).
    pub residuals: Vec<ExprId>,
    /// The momenta `p_i = ∂L/∂q̇_i`.
    pub momenta: Vec<ExprId>,
}

impl EquationsOfMotion {
    /// M's entries row by row, then f: the outputs that one straight-line program lowers
    /// to compute both (the derive's `(M, f)` methods and the export's `mass` and `forcing`).
    pub fn mass_then_forcing(&self) -> Vec<ExprId> {
        self.mass
            .iter()
            .flatten()
            .chain(&self.forcing)
            .copied()
            .collect()
    }

    /// Derives the equations of motion of the Lagrangian `l` under the generalised forces
    /// `forces` (one per coordinate).
    ///
    /// ```
    /// use precess_core::{lagrange::{Coordinates, EquationsOfMotion}, sym::Arena};
    /// // Pendulum: L = ½ m l² θ̇² + m g l cos θ  ⇒  m l² θ̈ = −m g l sin θ
    /// let mut a = Arena::new();
    /// let c = Coordinates::new(&mut a, &["theta"]);
    /// let (m, g, l) = (a.parameter("m"), a.parameter("g"), a.parameter("l"));
    /// let half = a.number("0.5").unwrap();
    /// let l2 = a.mul(l, l);
    /// let td2 = a.mul(c.rates[0], c.rates[0]);
    /// let t = a.product(&[half, m, l2, td2]);
    /// let cos = a.cos(c.q[0]);
    /// let v = a.product(&[m, g, l, cos]);
    /// let lag = a.add(t, v);
    /// let zero = a.zero();
    /// let eom = EquationsOfMotion::derive(&mut a, lag, c, &[zero]).unwrap();
    /// assert_eq!(eom.mass[0][0], a.mul(m, l2));
    /// let sin = a.sin(eom.coords.q[0]);
    /// let minus = a.product(&[m, g, l, sin]);
    /// assert_eq!(eom.forcing[0], a.neg(minus));
    /// ```
    ///
    /// # Errors
    /// [`LagrangeError::ForceCount`] if `forces.len()` differs from the coordinates;
    /// [`LagrangeError::AccelerationInInput`] if the Lagrangian or a force holds a q̈.
    pub fn derive(
        arena: &mut Arena,
        lagrangian: ExprId,
        coords: Coordinates,
        forces: &[ExprId],
    ) -> Result<EquationsOfMotion, LagrangeError> {
        let n = coords.len();
        if forces.len() != n {
            return Err(LagrangeError::ForceCount {
                coordinates: n,
                forces: forces.len(),
            });
        }
        let q = Coordinates::symbols(arena, &coords.q);
        let qd = Coordinates::symbols(arena, &coords.rates);
        let qdd = Coordinates::symbols(arena, &coords.accels);
        let time = arena.time_symbol();
        let mut mass = vec![vec![arena.zero(); n]; n];
        let mut forcing = Vec::with_capacity(n);
        let mut residuals = Vec::with_capacity(n);
        let mut momenta = Vec::with_capacity(n);
        for i in 0..n {
            let p = arena.diff(lagrangian, qd[i]);
            let p = arena.expand(p);
            momenta.push(p);
            let dl_dq = arena.diff(lagrangian, q[i]);
            let mut f_terms = vec![forces[i], dl_dq];
            for j in 0..n {
                let m = arena.diff(p, qd[j]);
                mass[i][j] = arena.expand(m);
                let cross = arena.diff(p, q[j]);
                let t = arena.mul(cross, coords.rates[j]);
                f_terms.push(arena.neg(t));
            }
            if let Some(t) = time {
                let explicit = arena.diff(p, t);
                f_terms.push(arena.neg(explicit));
            }
            let f = arena.sum(&f_terms);
            let f = arena.expand(f);
            let depends_on_accel =
                |a: &Arena, e: ExprId| a.free_symbols(e).iter().any(|s| qdd.contains(s));
            if depends_on_accel(arena, f) || mass[i].iter().any(|&m| depends_on_accel(arena, m)) {
                return Err(LagrangeError::AccelerationInInput { index: i });
            }
            forcing.push(f);
            let dp = arena.dt(p);
            let r1 = arena.sub(dp, dl_dq);
            let r = arena.sub(r1, forces[i]);
            residuals.push(arena.expand(r));
        }
        Ok(EquationsOfMotion {
            coords,
            mass,
            forcing,
            residuals,
            momenta,
        })
    }
}
