//! The augmented system built symbolically: J = ∂f/∂x by [`Arena::diff`], then J Φ and
//! J S + ∂f/∂p as expressions, so that lowering shares every subexpression of f and J with
//! the products and drops the structural zeros of J.

use super::error::VariationalError;
use super::layout::Layout;
use crate::codegen::{OpCount, Program};
use crate::sym::{Arena, ExprId, SymbolId, SymbolKind};

/// First-order variational equations of `x' = f(t, x; p)`:
/// `(x, Φ, S)' = (f, J Φ, J S + ∂f/∂p)` with `J = ∂f/∂x`, laid out as [`Layout`] says.
///
/// Higher orders are not built: the second-order tensor would need n³ outputs and no check
/// of this module asks for it.
///
/// ```
/// use precess_core::sym::Arena;
/// use precess_core::variational::VariationalEquations;
/// // x' = −k x: J = −k, ∂f/∂k = −x.
/// let mut a = Arena::new();
/// let (x, k) = (a.input("x"), a.parameter("k"));
/// let kx = a.mul(k, x);
/// let f = a.neg(kx);
/// let eq = VariationalEquations::new(&mut a, &[x], &[f], 1, &[k])?;
/// assert_eq!(eq.layout().len(), 3);
/// let minus_k = a.neg(k);
/// assert_eq!(eq.jacobian(), &[minus_k]); // canonical forms: equal expressions, equal ids
/// # Ok::<(), precess_core::variational::VariationalError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct VariationalEquations {
    layout: Layout,
    /// Every symbol of the augmented state, in layout order.
    symbols: Vec<SymbolId>,
    /// The parameters whose sensitivities are carried.
    parameters: Vec<SymbolId>,
    /// f.
    rhs: Vec<ExprId>,
    /// J, row-major.
    jacobian: Vec<ExprId>,
    /// The right-hand side of the augmented state, in layout order.
    outputs: Vec<ExprId>,
}

impl VariationalEquations {
    /// Builds the augmented right-hand side of `x' = rhs` for the state symbols `state`,
    /// carrying `tangents` tangent vectors (n for the whole state transition matrix, 1 for
    /// the maximal Lyapunov exponent) and the sensitivities to the parameter symbols
    /// `parameters`. Time, if `rhs` reads it, stays an input supplied per call.
    ///
    /// # Errors
    /// [`VariationalError::EmptyState`], [`VariationalError::RhsLength`],
    /// [`VariationalError::NotAStateSymbol`] for a state entry that is not a coordinate,
    /// rate or input symbol, [`VariationalError::RepeatedStateSymbol`],
    /// [`VariationalError::TooManyTangents`] past n, [`VariationalError::NotAParameter`],
    /// [`VariationalError::RepeatedParameter`], [`VariationalError::UnreadParameter`] for a
    /// parameter `rhs` does not read (its sensitivity would be zero for ever, as the derive's
    /// `variational(...)` refuses it at compile time).
    pub fn new(
        arena: &mut Arena,
        state: &[ExprId],
        rhs: &[ExprId],
        tangents: usize,
        parameters: &[ExprId],
    ) -> Result<VariationalEquations, VariationalError> {
        let n = state.len();
        if n == 0 {
            return Err(VariationalError::EmptyState);
        }
        if rhs.len() != n {
            return Err(VariationalError::RhsLength {
                state: n,
                rhs: rhs.len(),
            });
        }
        if tangents > n {
            return Err(VariationalError::TooManyTangents { tangents, state: n });
        }
        let x = state_symbols(arena, state)?;
        let params = parameters
            .iter()
            .enumerate()
            .map(|(index, &e)| match arena.as_symbol(e) {
                Some(s) if arena.symbol(s).kind == SymbolKind::Parameter => Ok(s),
                _ => Err(VariationalError::NotAParameter { index }),
            })
            .collect::<Result<Vec<_>, _>>()?;
        for (second, p) in params.iter().enumerate() {
            if let Some(first) = params[..second].iter().position(|q| q == p) {
                return Err(VariationalError::RepeatedParameter { first, second });
            }
        }
        let zero = arena.zero();
        for (index, &p) in params.iter().enumerate() {
            if rhs.iter().all(|&f| arena.diff(f, p) == zero) {
                return Err(VariationalError::UnreadParameter { index });
            }
        }
        let layout = Layout {
            n,
            tangents,
            sensitivities: params.len(),
        };
        let mut jacobian = Vec::with_capacity(n * n);
        for &f in rhs {
            for &s in &x {
                jacobian.push(arena.diff(f, s));
            }
        }
        let mut symbols = x.clone();
        let mut outputs = rhs.to_vec();
        // Tangent vectors first, then sensitivities: the same product J v for each column,
        // plus ∂f/∂p for a sensitivity.
        let columns = (0..tangents).map(|j| (format!("dx_{j}"), None)).chain(
            params
                .iter()
                .enumerate()
                .map(|(j, &p)| (format!("dx_dp{j}"), Some(p))),
        );
        for (name, param) in columns {
            let v: Vec<ExprId> = (0..n)
                .map(|i| arena.input(&format!("{name}_{i}")))
                .collect();
            for e in &v {
                symbols.extend(arena.as_symbol(*e));
            }
            for (i, &f) in rhs.iter().enumerate() {
                let zero = arena.zero();
                let mut terms: Vec<ExprId> = Vec::with_capacity(n + 1);
                for (&jij, &vj) in jacobian[i * n..(i + 1) * n].iter().zip(&v) {
                    if jij != zero {
                        terms.push(arena.mul(jij, vj));
                    }
                }
                if let Some(p) = param {
                    terms.push(arena.diff(f, p));
                }
                outputs.push(arena.sum(&terms));
            }
        }
        Ok(VariationalEquations {
            layout,
            symbols,
            parameters: params,
            rhs: rhs.to_vec(),
            jacobian,
            outputs,
        })
    }

    /// The sizes of the augmented state.
    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// J = ∂f/∂x, row-major (n × n).
    pub fn jacobian(&self) -> &[ExprId] {
        &self.jacobian
    }

    /// The augmented right-hand side `(f, J Φ, J S + ∂f/∂p)`, in layout order.
    pub fn outputs(&self) -> &[ExprId] {
        &self.outputs
    }

    /// The symbols of the augmented state, in layout order (x, then the input symbols of Φ
    /// and S).
    pub fn symbols(&self) -> &[SymbolId] {
        &self.symbols
    }

    /// The parameters whose sensitivities are carried, in the order of S's columns.
    pub fn parameters(&self) -> &[SymbolId] {
        &self.parameters
    }

    /// The operations of f alone and of the whole augmented program, each lowered with its
    /// subexpressions shared: what carrying Φ and S costs per right-hand side.
    pub fn op_counts(&self, arena: &Arena) -> (OpCount, OpCount) {
        (
            Program::lower(arena, &self.rhs).op_count(),
            Program::lower(arena, &self.outputs).op_count(),
        )
    }
}

/// The state's symbols, refusing parameters, time and repeats.
fn state_symbols(arena: &Arena, state: &[ExprId]) -> Result<Vec<SymbolId>, VariationalError> {
    let mut x: Vec<SymbolId> = Vec::with_capacity(state.len());
    for (index, &e) in state.iter().enumerate() {
        let s = arena
            .as_symbol(e)
            .filter(|&s| {
                matches!(
                    arena.symbol(s).kind,
                    SymbolKind::Coordinate | SymbolKind::Input | SymbolKind::Derivative { .. }
                )
            })
            .ok_or(VariationalError::NotAStateSymbol { index })?;
        if let Some(first) = x.iter().position(|&t| t == s) {
            return Err(VariationalError::RepeatedStateSymbol {
                first,
                second: index,
            });
        }
        x.push(s);
    }
    Ok(x)
}
