//! A loop closure: the description of one closing joint, and the rule its sides must meet.

use crate::mechanism::error::MechanismError;
use crate::mechanism::scene::Parent;
use crate::sym::ExprId;

/// A closing joint: the point `at` of body `body` (its own frame) is held on the point
/// `to_at` of `to` (that body's frame, or the ground's). The joint transmits a force and no
/// moment, a pin for a planar loop of parallel revolutes (the four-bar's coupler–rocker
/// joint), a ball joint otherwise.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopClosure {
    /// The closure's name (the body's, as the derive writes it), for errors.
    pub name: String,
    /// The body that closes the loop, by index in `MechanismScene::bodies`.
    pub body: usize,
    /// The closing point in that body's frame.
    pub at: [ExprId; 3],
    /// What it closes on.
    pub to: Parent,
    /// The point it is held on, in `to`'s frame.
    pub to_at: [ExprId; 3],
}

/// One side of a planar loop: the distance, across the common axis, between the two joints
/// a body (or the ground) carries on the loop.
#[derive(Clone, Debug, PartialEq)]
pub struct LoopSide {
    /// The body carrying the side, or `"ground"`.
    pub body: String,
    /// Its length squared (an expression in the parameters).
    pub squared: ExprId,
}

/// The closure rule of a planar loop of revolutes: a polygon with sides l₁ … l_s closes
/// (other than folded flat, where the dependent block is singular) only if its longest side
/// is shorter than the sum of the others, l_max < Σ l − l_max. For a four-bar this is the
/// triangle inequality of its two diagonals' triangles; Grashof's s + l ≤ p + q says in
/// addition whether a link turns fully, which the run handles (a dead point repartitions).
///
/// # Errors
/// [`MechanismError::LoopCannotClose`] naming the closure, the longest side's body and
/// length and the sum of the others; [`MechanismError::NonFiniteParameter`] for a side that
/// is not finite.
///
/// ```
/// use precess::mechanism::loops::check_loop_sides;
/// use precess::mechanism::MechanismError;
/// // Ground 3, crank 1, coupler 3, rocker 2.5 closes; a rocker of 8 cannot.
/// assert!(check_loop_sides("coupler", &[("ground", 3.0), ("crank", 1.0), ("coupler", 3.0), ("rocker", 2.5)]).is_ok());
/// let e = check_loop_sides("coupler", &[("ground", 3.0), ("crank", 1.0), ("coupler", 3.0), ("rocker", 8.0)]);
/// assert!(matches!(e, Err(MechanismError::LoopCannotClose { longest, others, .. }) if longest == 8.0 && others == 7.0));
/// ```
pub fn check_loop_sides(closure: &str, sides: &[(&str, f64)]) -> Result<(), MechanismError> {
    if let Some(&(body, value)) = sides.iter().find(|(_, l)| !l.is_finite()) {
        return Err(MechanismError::NonFiniteParameter {
            owner: format!("loop closed by `{closure}`"),
            quantity: format!("side of `{body}`"),
            value,
        });
    }
    let total: f64 = sides.iter().map(|s| s.1).sum();
    let Some(&(body, longest)) = sides.iter().max_by(|a, b| a.1.total_cmp(&b.1)) else {
        return Ok(());
    };
    let others = total - longest;
    if longest >= others {
        return Err(MechanismError::LoopCannotClose {
            closure: closure.to_owned(),
            body: body.to_owned(),
            longest,
            others,
        });
    }
    Ok(())
}
