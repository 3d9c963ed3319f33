//! The principal frame about the centre of mass of a symbolic body, decided at compile time
//! where it can be: the frame a free body's attitude and ω live in.

use super::error::FreeError;
use crate::body::{Principal, matrix, principal_frame};
use crate::sym::mat3::Mat3;
use crate::sym::{Arena, ExprId};

/// How the principal frame about the centre of mass is known.
#[derive(Clone, Debug, PartialEq)]
pub enum CmFrame {
    /// The tensor about the centre of mass is symbolically diagonal: the description axes
    /// are principal, with these moments.
    Diagonal([ExprId; 3]),
    /// A constant tensor that is not diagonal, decomposed now.
    Constant(Principal),
    /// A tensor depending on parameters and not symbolically diagonal: decomposed when the
    /// code runs.
    AtRunTime,
}

/// The principal frame of `inertia_cm` (the tensor about the centre of mass, description
/// axes), by the rules of [`crate::body::SymbolicBody`]: diagonal, constant, or decided at
/// run time.
///
/// ```
/// use precess_core::free::{CmFrame, cm_frame};
/// use precess_core::sym::Arena;
/// let mut a = Arena::new();
/// let (i1, z) = (a.parameter("I1"), a.zero());
/// let (two, three) = (a.integer(2), a.integer(3));
/// let frame = cm_frame(&mut a, &[[i1, z, z], [z, two, z], [z, z, three]])?;
/// assert_eq!(frame, CmFrame::Diagonal([i1, two, three]));
/// # Ok::<(), precess_core::free::FreeError>(())
/// ```
///
/// # Errors
/// [`FreeError::ZeroInertia`] if a moment is zero (for every value of the parameters, or as
/// the constant it is): all the mass on a line through the centre of mass, which Euler's
/// equations cannot turn.
pub fn cm_frame(arena: &mut Arena, inertia_cm: &Mat3) -> Result<CmFrame, FreeError> {
    const MOMENTS: [&str; 3] = [
        "principal moment I1 about the centre of mass",
        "principal moment I2 about the centre of mass",
        "principal moment I3 about the centre of mass",
    ];
    let t = inertia_cm;
    let diagonal = [(0, 1), (0, 2), (1, 2)]
        .iter()
        .all(|&(i, j)| arena.is_zero(t[i][j]).unwrap_or(false));
    let constant = t
        .iter()
        .flatten()
        .all(|&e| arena.free_symbols(e).is_empty());
    if diagonal {
        let moments = [t[0][0], t[1][1], t[2][2]];
        for (k, &m) in moments.iter().enumerate() {
            if arena.is_zero(m).unwrap_or(false) {
                return Err(FreeError::ZeroInertia {
                    quantity: MOMENTS[k],
                });
            }
        }
        return Ok(CmFrame::Diagonal(moments));
    }
    if !constant {
        return Ok(CmFrame::AtRunTime);
    }
    let numeric = t.map(|row| row.map(|e| arena.eval(e, &[])));
    let principal = principal_frame(&matrix(&numeric));
    let largest = principal.moments.amax();
    for (k, &m) in principal.moments.iter().enumerate() {
        // A moment that is rounding noise of the largest is zero.
        if m <= largest * 1e-14 {
            return Err(FreeError::ZeroInertia {
                quantity: MOMENTS[k],
            });
        }
    }
    Ok(CmFrame::Constant(principal))
}
