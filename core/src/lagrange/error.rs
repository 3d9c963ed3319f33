//! Errors of the Euler–Lagrange engine.

use thiserror::Error;

use crate::sym::SymError;

/// What can go wrong while deriving or solving equations of motion.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LagrangeError {
    /// The number of generalised forces differs from the number of coordinates.
    #[error("{forces} generalised forces given for {coordinates} coordinates")]
    ForceCount {
        /// Coordinates.
        coordinates: usize,
        /// Forces given.
        forces: usize,
    },
    /// An expression given as a coordinate is not a coordinate symbol.
    #[error("`{expr}` is not a coordinate symbol (create one with Arena::coordinate)")]
    NotACoordinate {
        /// The expression.
        expr: String,
    },
    /// The mass matrix or the forcing depends on accelerations: the Lagrangian or a force
    /// already contains a second derivative.
    #[error(
        "equation {index} is not linear in the accelerations (an input holds a second derivative)"
    )]
    AccelerationInInput {
        /// Which equation.
        index: usize,
    },
    /// A block of the mass matrix has a determinant that is identically zero.
    #[error(
        "the mass matrix is singular everywhere (block of coordinates {block:?} has zero determinant)"
    )]
    SingularMassMatrix {
        /// Coordinate indices of the singular block.
        block: Vec<usize>,
    },
    /// A coupled block larger than the symbolic solver handles.
    #[error(
        "a coupled block of {size} coordinates is larger than the symbolic solve supports ({max})"
    )]
    BlockTooLarge {
        /// Block size.
        size: usize,
        /// The largest supported.
        max: usize,
    },
    /// A constructor of the symbolic engine failed.
    #[error(transparent)]
    Sym(#[from] SymError),
}
