//! The symbolic body the derive macro builds: mass properties as expressions in the struct's
//! fields (constants for a body of literals), the principal frame decided at compile time
//! where it can be, and Euler's equations specialised to the body.

use nalgebra::Vector3;

use super::error::BodyError;
use super::mass::{MassProperties, mass_properties};
use super::principal::{Principal, principal_frame};
use super::shape::Description;
use super::validate::matrix;
use crate::sym::{Arena, ExprId};

/// How the principal frame of a symbolic body is known.
#[derive(Clone, Debug, PartialEq)]
pub enum Frame {
    /// The tensor is symbolically diagonal: the description axes are principal, and these
    /// are the moments (constants for a body of literals).
    Diagonal([ExprId; 3]),
    /// A constant tensor that is not diagonal, decomposed now.
    Constant(Principal),
    /// A tensor depending on parameters and not symbolically diagonal: decomposed at run
    /// time.
    Runtime,
}

/// A body described symbolically, with what the macro needs to emit.
///
/// Literal values fold to exact rationals, so a body of literals has constant moments and
/// coefficients; a symmetric body's vanishing coefficient removes its term.
///
/// ```
/// use approx::assert_relative_eq;
/// use precess_core::body::{Axis, Description, Frame, Part, Shape, SymbolicBody};
/// use precess_core::sym::{Arena, Rational};
/// let mut a = Arena::new();
/// let (m, r, l) = (a.number("2").unwrap(), a.number("0.1").unwrap(), a.number("0.4").unwrap());
/// let z = a.zero();
/// let cylinder = Shape::Cylinder { mass: m, radius: r, length: l, axis: Axis::Z };
/// let d = Description { parts: vec![Part { shape: cylinder, at: [z, z, z] }], pivot: None };
/// let body = SymbolicBody::new(&mut a, &d).unwrap();
/// let Frame::Diagonal(moments) = body.frame else { panic!("a cylinder is diagonal") };
/// // I3 = ½ m r² = 1/100 exactly.
/// assert_eq!(a.as_rational(moments[2]), Rational::new(1, 100));
/// let w = [a.parameter("w1"), a.parameter("w2"), a.parameter("w3")];
/// let g = [a.parameter("g1"), a.parameter("g2"), a.parameter("g3")];
/// let rhs = body.euler_rhs(&mut a, w, g).unwrap().unwrap();
/// // ω̇3 = G3 / I3: no ω1 ω2 term, and the reciprocal is the constant 100.
/// let env = [9.0, 9.0, 9.0, 0.0, 0.0, 0.5];
/// assert_relative_eq!(a.eval(rhs[2], &env), 50.0);
/// ```
#[derive(Clone, Debug)]
pub struct SymbolicBody {
    /// Mass properties as expressions.
    pub props: MassProperties<ExprId>,
    /// The principal frame.
    pub frame: Frame,
    /// True if nothing depends on a parameter.
    pub constant: bool,
}

impl SymbolicBody {
    /// Computes the mass properties of `d` in `arena` and decides the principal frame.
    ///
    /// Literal bodies should be validated first ([`evaluate`] then
    /// [`Description::validate`]); this checks only what holds for every parameter value.
    ///
    /// # Errors
    /// As [`mass_properties`], and [`BodyError::ZeroPrincipalMoment`] if a moment is
    /// identically zero.
    pub fn new(arena: &mut Arena, d: &Description<ExprId>) -> Result<SymbolicBody, BodyError> {
        let props = mass_properties(arena, d)?;
        let props = abbreviated(arena, props);
        let t = props.inertia;
        let constant = t
            .iter()
            .flatten()
            .chain(props.center.iter())
            .chain([&props.mass])
            .all(|&e| arena.free_symbols(e).is_empty());
        let diagonal = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .all(|&(i, j)| arena.expand(t[i][j]) == arena.zero());
        let frame = if diagonal {
            let moments = [t[0][0], t[1][1], t[2][2]];
            if moments.iter().any(|&m| arena.expand(m) == arena.zero()) {
                let v = moments.map(|m| arena.eval(m, &[]));
                return Err(BodyError::ZeroPrincipalMoment { moments: v });
            }
            Frame::Diagonal(moments)
        } else if constant {
            let numeric = t.map(|row| row.map(|e| arena.eval(e, &[])));
            Frame::Constant(principal_frame(&matrix(&numeric)))
        } else {
            Frame::Runtime
        };
        Ok(SymbolicBody {
            props,
            frame,
            constant,
        })
    }

    /// Euler's equations ω̇ = (k1 ω2 ω3 + G1/I1, …) with kᵢ = (I_j − I_k)/I_i, as expressions
    /// in `omega`, `torque` and the parameters; `None` for a [`Frame::Runtime`] body. For a
    /// constant body every coefficient is a constant (no division is left), and a
    /// coefficient that vanishes (a symmetric body) removes its term.
    ///
    /// # Errors
    /// [`BodyError::ZeroPrincipalMoment`] if a moment is identically zero.
    pub fn euler_rhs(
        &self,
        arena: &mut Arena,
        omega: [ExprId; 3],
        torque: [ExprId; 3],
    ) -> Result<Option<[ExprId; 3]>, BodyError> {
        let moments: [ExprId; 3] = match &self.frame {
            Frame::Runtime => return Ok(None),
            Frame::Diagonal(m) => *m,
            Frame::Constant(p) => {
                let m: Vector3<f64> = p.moments;
                let mut out = [arena.zero(); 3];
                for (o, &v) in out.iter_mut().zip(m.iter()) {
                    *o = arena.float(v).map_err(|_| zero_moment(&m))?;
                }
                out
            }
        };
        let mut rhs = [arena.zero(); 3];
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let diff = arena.sub(moments[j], moments[k]);
            let diff = if arena.is_zero(diff).unwrap_or(false) {
                arena.zero()
            } else {
                diff
            };
            let mut coefficient = arena
                .div(diff, moments[i])
                .map_err(|_| BodyError::ZeroPrincipalMoment { moments: [0.0; 3] })?;
            let mut inverse = arena
                .recip(moments[i])
                .map_err(|_| BodyError::ZeroPrincipalMoment { moments: [0.0; 3] })?;
            if self.constant {
                // Fold to one correctly rounded constant each: no division at run time.
                coefficient = self.fold(arena, coefficient)?;
                inverse = self.fold(arena, inverse)?;
            }
            let gyro = arena.product(&[coefficient, omega[j], omega[k]]);
            let drive = arena.mul(inverse, torque[i]);
            rhs[i] = arena.add(gyro, drive);
        }
        Ok(Some(rhs))
    }

    fn fold(&self, arena: &mut Arena, e: ExprId) -> Result<ExprId, BodyError> {
        if arena.as_rational(e).is_some() {
            return Ok(e);
        }
        let v = arena.eval(e, &[]);
        arena
            .float(v)
            .map_err(|_| BodyError::ZeroPrincipalMoment { moments: [0.0; 3] })
    }
}

/// The mass properties with each compound entry named once ([`Arena::abbreviate`]): a body
/// of N field-valued parts has entries of O(N) terms, and a derivation over them (a top's
/// determinant and adjugate) would otherwise grow as a power of N. Values are unchanged.
fn abbreviated(arena: &mut Arena, p: MassProperties<ExprId>) -> MassProperties<ExprId> {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let name = |arena: &mut Arena, n: String, e: ExprId| arena.abbreviate(&n, e).unwrap_or(e);
    let tensor = |arena: &mut Arena, prefix: &str, t: [[ExprId; 3]; 3]| {
        let mut out = t;
        for i in 0..3 {
            for j in i..3 {
                let e = name(arena, format!("{prefix}_{}{}", AXES[i], AXES[j]), t[i][j]);
                out[i][j] = e;
                out[j][i] = e;
            }
        }
        out
    };
    let inertia = tensor(arena, "I", p.inertia);
    let inertia_cm = tensor(arena, "Icm", p.inertia_cm);
    let center = std::array::from_fn(|k| name(arena, format!("c_{}", AXES[k]), p.center[k]));
    let reference = std::array::from_fn(|k| name(arena, format!("c_{}", AXES[k]), p.reference[k]));
    MassProperties {
        mass: name(arena, "M".to_owned(), p.mass),
        center,
        reference,
        inertia,
        inertia_cm,
    }
}

fn zero_moment(m: &Vector3<f64>) -> BodyError {
    BodyError::ZeroPrincipalMoment {
        moments: [m[0], m[1], m[2]],
    }
}

/// The numeric description behind a constant symbolic one (`None` if a value depends on a
/// parameter).
pub fn evaluate(arena: &Arena, d: &Description<ExprId>) -> Option<Description<f64>> {
    let mut constant = true;
    let numeric = d.map(&mut |&e| {
        constant &= arena.free_symbols(e).is_empty();
        arena.eval(e, &[])
    });
    constant.then_some(numeric)
}
