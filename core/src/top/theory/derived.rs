//! The heavy-top theory of a derived top: I1, I3 about the pivot and M g l read from the
//! top's own mass properties and gravity, after checking that the closed forms apply
//! (symmetric about the description z axis, centre of mass on it, gravity alone, no rotor).

use super::error::TheoryError;
use super::heavy::{HeavyTopTheory, SYMMETRY_TOLERANCE};
use crate::top::dynamics::TopDynamics;
use crate::top::error::TopError;

/// [`TopDynamics::theory`]: the checks in the order a user would fix them.
pub(crate) fn derived_theory<T: TopDynamics<N> + ?Sized, const N: usize>(
    top: &T,
) -> Result<HeavyTopTheory, TopError> {
    top.check_all()?;
    if let Some(declared) = T::BEYOND_GRAVITY {
        return Err(TheoryError::OtherTorque { declared }.into());
    }
    if T::ROTORS > 0 {
        return Err(TheoryError::Rotor { rotors: T::ROTORS }.into());
    }
    let i = top.inertia();
    let scale = i[(0, 0)].max(i[(1, 1)]).max(i[(2, 2)]);
    let (ixy, ixz, iyz) = (i[(0, 1)], i[(0, 2)], i[(1, 2)]);
    let relative = ixy.abs().max(ixz.abs()).max(iyz.abs()) / scale;
    if relative > SYMMETRY_TOLERANCE {
        return Err(TheoryError::ProductsOfInertia {
            ixy,
            ixz,
            iyz,
            relative,
            limit: SYMMETRY_TOLERANCE,
        }
        .into());
    }
    let (i1, i2, i3) = (i[(0, 0)], i[(1, 1)], i[(2, 2)]);
    let relative = (i1 - i2).abs() / i1.max(i2);
    if relative > SYMMETRY_TOLERANCE {
        return Err(TheoryError::NotSymmetric {
            i1,
            i2,
            relative,
            limit: SYMMETRY_TOLERANCE,
        }
        .into());
    }
    let lever = top.center_of_mass() - top.reference_point();
    let off = lever.x.hypot(lever.y);
    let relative = off / lever.norm();
    if off > 0.0 && relative > SYMMETRY_TOLERANCE {
        return Err(TheoryError::CentreOffAxis {
            x: lever.x,
            y: lever.y,
            relative,
            limit: SYMMETRY_TOLERANCE,
        }
        .into());
    }
    // Undeclared gravity is none; `check_all` has refused a negative or NaN one. A centre
    // on the pivot makes M g l zero too: both are the torque-free top.
    let g = top.top_parameters().gravity.unwrap_or(0.0);
    let mgl = top.mass() * g * lever.z;
    Ok(HeavyTopTheory::new(0.5 * (i1 + i2), i3, mgl)?)
}
