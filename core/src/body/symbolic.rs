//! The symbolic body the derive macro builds: mass properties as expressions in the struct's
//! fields (constants for a body of literals), the principal frame decided at compile time
//! where it can be, and Euler's equations specialised to the body.

use nalgebra::Vector3;

use super::error::BodyError;
use super::mass::{MassProperties, mass_properties};
use super::principal::{Principal, principal_frame};
use super::shape::Description;
use super::validate::matrix;
use crate::sym::mat3::{adjugate_times, cross, determinant, mat_vec};
use crate::sym::{Arena, ExprId, Node, SymError};

/// How the principal frame of a symbolic body is known.
#[derive(Clone, Debug, PartialEq)]
pub enum Frame {
    /// The tensor is symbolically diagonal: the description axes are principal, and these
    /// are the moments (constants for a body of literals).
    Diagonal([ExprId; 3]),
    /// A constant tensor that is not diagonal, decomposed now.
    Constant(Principal),
    /// A tensor depending on parameters and not symbolically diagonal: the generated code
    /// decomposes it when called, from the parameters' values then.
    DecomposedAtRunTime,
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
/// let d = Description { parts: vec![Part::new(cylinder, [z, z, z])], pivot: None };
/// let body = SymbolicBody::new(&mut a, &d).unwrap();
/// let Frame::Diagonal(moments) = body.frame else { panic!("a cylinder is diagonal") };
/// // I3 = ½ m r² = 1/100 exactly.
/// assert_eq!(a.as_rational(moments[2]), Rational::new(1, 100));
/// let w = [a.parameter("w1"), a.parameter("w2"), a.parameter("w3")];
/// let g = [a.parameter("g1"), a.parameter("g2"), a.parameter("g3")];
/// let rhs = body.euler_rhs_principal(&mut a, w, g).unwrap().unwrap();
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
    /// As [`mass_properties`]; for a body of literals, [`BodyError::Overflow`] if a mass
    /// property rounds past the largest `f64` and [`BodyError::ZeroPrincipalMoment`] if a
    /// moment is zero; for a body with parameters, [`BodyError::IdenticallyZeroMoment`] if a
    /// moment is zero whatever their values.
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
        let props = if constant {
            // Every mass property of a body of literals must be a finite `f64` once rounded.
            props.check_finite(|e| arena.eval(e, &[]))?;
            constants_folded(arena, props)?
        } else {
            props
        };
        let diagonal = [(0, 1), (0, 2), (1, 2)]
            .iter()
            .all(|&(i, j)| arena.expand(t[i][j]) == arena.zero());
        let frame = if diagonal {
            let moments = [t[0][0], t[1][1], t[2][2]];
            if let Some(i) = (0..3).find(|&i| arena.expand(moments[i]) == arena.zero()) {
                return Err(zero_moment(arena, constant, &moments, i));
            }
            Frame::Diagonal(moments)
        } else if constant {
            let numeric = t.map(|row| row.map(|e| arena.eval(e, &[])));
            Frame::Constant(principal_frame(&matrix(&numeric)))
        } else {
            Frame::DecomposedAtRunTime
        };
        Ok(SymbolicBody {
            props,
            frame,
            constant,
        })
    }

    /// Euler's equations ω̇ = (k1 ω2 ω3 + G1/I1, …) with kᵢ = (I_j − I_k)/I_i, as expressions
    /// in `omega`, `torque` and the parameters; `None` for a [`Frame::DecomposedAtRunTime`]
    /// body. For a constant body every coefficient is a constant (no division is left), and a
    /// coefficient that vanishes (a symmetric body) removes its term.
    ///
    /// # Errors
    /// [`BodyError::ZeroPrincipalMoment`] (literals) or [`BodyError::IdenticallyZeroMoment`]
    /// (parameters) if a moment is zero; [`BodyError::Overflow`] if a moment or coefficient
    /// of a constant body is not a finite `f64`.
    pub fn euler_rhs_principal(
        &self,
        arena: &mut Arena,
        omega: [ExprId; 3],
        torque: [ExprId; 3],
    ) -> Result<Option<[ExprId; 3]>, BodyError> {
        let moments: [ExprId; 3] = match &self.frame {
            Frame::DecomposedAtRunTime => return Ok(None),
            Frame::Diagonal(m) => *m,
            Frame::Constant(p) => {
                let m: Vector3<f64> = p.moments;
                let mut out = [arena.zero(); 3];
                for (o, &value) in out.iter_mut().zip(m.iter()) {
                    *o = arena.float(value).map_err(|_| BodyError::Overflow {
                        quantity: "principal moments",
                        value,
                    })?;
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
            let (Ok(coefficient), Ok(inverse)) =
                (arena.div(diff, moments[i]), arena.recip(moments[i]))
            else {
                return Err(zero_moment(arena, self.constant, &moments, i));
            };
            let (mut coefficient, mut inverse) = (coefficient, inverse);
            if self.constant {
                // Fold to one constant each: no division at run time.
                coefficient = fold(arena, coefficient, "coefficients of Euler's equations")?;
                inverse = fold(arena, inverse, "inverse principal moments")?;
            }
            let gyro = arena.product(&[coefficient, omega[j], omega[k]]);
            let drive = arena.mul(inverse, torque[i]);
            rhs[i] = arena.add(gyro, drive);
        }
        Ok(Some(rhs))
    }

    /// Euler's equations in the description axes, for any tensor and with no principal
    /// frame: I ω̇ = G − ω × (I ω), I the inertia tensor about the reference point, ω and
    /// the torque G in description axes, solved by the adjugate,
    ///
    /// ω̇ = adj(I) (G − ω × (I ω)) · (1 / det I),
    ///
    /// one division by det I shared by the three rows. The determinant and the adjugate's
    /// entries, polynomials in the tensor's entries alone, are expanded (what cancels
    /// exactly is gone, a zero product of inertia removes its terms); the products with ω
    /// are not. This is what a body whose principal frame is found only at run time
    /// ([`Frame::DecomposedAtRunTime`]) has as straight-line expressions, since its
    /// principal moments and rotation are an eigen-decomposition.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::body::{About, Description, Part, Shape, SymbolicBody};
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let [ixx, iyy, izz, ixy] = ["ixx", "iyy", "izz", "ixy"].map(|n| a.parameter(n));
    /// let (z, m) = (a.zero(), a.one());
    /// let tensor = [[ixx, ixy, z], [ixy, iyy, z], [z, z, izz]];
    /// let shape = Shape::Explicit { mass: m, inertia: tensor, about: About::Center };
    /// let d = Description { parts: vec![Part::new(shape, [z, z, z])], pivot: None };
    /// let body = SymbolicBody::new(&mut a, &d).unwrap();
    /// let w = [a.input("w1"), a.input("w2"), a.input("w3")];
    /// let rhs = body.euler_rhs_description(&mut a, w, [z; 3]).unwrap();
    /// let env = |w: [f64; 3]| [2.0, 3.0, 4.0, 0.5, w[0], w[1], w[2]];
    /// // ω along z, a principal axis: I ω = (0, 0, I_zz) ∥ ω, so ω̇ = 0.
    /// assert_eq!(a.eval(rhs[2], &env([0.0, 0.0, 1.0])), 0.0);
    /// // ω = (1, 0, 1): I ω = (I_xx, I_xy, I_zz), G = −ω × I ω = (I_xy, I_zz − I_xx, −I_xy),
    /// // and the x–y block of I⁻¹ is [[I_yy, −I_xy], [−I_xy, I_xx]] / (I_xx I_yy − I_xy²).
    /// let (det, g) = (2.0 * 3.0 - 0.25, [0.5, 4.0 - 2.0, -0.5]);
    /// let got = [0, 1, 2].map(|i| a.eval(rhs[i], &env([1.0, 0.0, 1.0])));
    /// assert_relative_eq!(got[0], (3.0 * g[0] - 0.5 * g[1]) / det, epsilon = 1e-15);
    /// assert_relative_eq!(got[1], (2.0 * g[1] - 0.5 * g[0]) / det, epsilon = 1e-15);
    /// assert_relative_eq!(got[2], g[2] / 4.0, epsilon = 1e-15);
    /// ```
    ///
    /// # Errors
    /// [`SymError::DivisionByZero`] if det I is zero whatever the parameters (no valid body
    /// has such a tensor), [`SymError::ExpansionTooLarge`] if deciding it would expand past
    /// the term limit.
    pub fn euler_rhs_description(
        &self,
        arena: &mut Arena,
        omega: [ExprId; 3],
        torque: [ExprId; 3],
    ) -> Result<[ExprId; 3], SymError> {
        let tensor = self.props.inertia;
        let rows: Vec<Vec<ExprId>> = tensor.iter().map(|r| r.to_vec()).collect();
        let momentum = mat_vec(arena, &tensor, &omega);
        let gyro = cross(arena, &omega, &momentum);
        let g: [ExprId; 3] = std::array::from_fn(|k| arena.sub(torque[k], gyro[k]));
        let det = determinant(arena, &rows);
        let det = arena.expand(det);
        let inv_det = arena.recip(det)?;
        let num = adjugate_times(arena, &rows, &g);
        Ok(std::array::from_fn(|i| arena.mul(num[i], inv_det)))
    }
}

/// The mass properties with each compound entry named once ([`Arena::abbreviate`]): a body
/// of N field-valued parts has entries of O(N) terms, and a derivation over them (a top's
/// determinant and adjugate) would otherwise grow as a power of N. Values are unchanged.
fn abbreviated(arena: &mut Arena, p: MassProperties<ExprId>) -> MassProperties<ExprId> {
    const AXES: [&str; 3] = ["x", "y", "z"];
    // A body of literals stays constant (its checks and folding need the values); only
    // entries that hold parameters are named.
    let name = |arena: &mut Arena, n: String, e: ExprId| {
        if arena.free_symbols(e).is_empty() {
            return e;
        }
        arena.abbreviate(&n, e).unwrap_or(e)
    };
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

/// A body of literals with every mass property one constant. Literal values are rationals,
/// so only a rotated part leaves irrational constants (sin 0.5, √2): each such entry is
/// expanded, which keeps what cancels exactly (a cylinder turned about its own axis stays
/// diagonal, its moments exact), and otherwise rounded once. Left as expressions, they would
/// be carried through a top's whole derivation.
fn constants_folded(
    arena: &mut Arena,
    p: MassProperties<ExprId>,
) -> Result<MassProperties<ExprId>, BodyError> {
    let one = |arena: &mut Arena, e: ExprId| -> Result<ExprId, BodyError> {
        if arena.as_rational(e).is_some() {
            return Ok(e);
        }
        // Without a turn, a constant that is not one rational is an exact product that left
        // 128 bits: it is rounded as the emitted code always rounded it.
        let turned = arena
            .reachable(e)
            .iter()
            .any(|&id| matches!(arena.node(id), Node::Sin(_) | Node::Cos(_) | Node::Sqrt(_)));
        if !turned {
            return Ok(e);
        }
        let x = arena.expand(e);
        if arena.as_rational(x).is_some() {
            return Ok(x);
        }
        fold(arena, x, "mass properties")
    };
    let tensor = |arena: &mut Arena, t: [[ExprId; 3]; 3]| -> Result<_, BodyError> {
        let mut out = t;
        for i in 0..3 {
            for j in i..3 {
                let e = one(arena, t[i][j])?;
                out[i][j] = e;
                out[j][i] = e;
            }
        }
        Ok(out)
    };
    let inertia = tensor(arena, p.inertia)?;
    let inertia_cm = tensor(arena, p.inertia_cm)?;
    let vector = |arena: &mut Arena, v: [ExprId; 3]| -> Result<[ExprId; 3], BodyError> {
        Ok([one(arena, v[0])?, one(arena, v[1])?, one(arena, v[2])?])
    };
    let center = vector(arena, p.center)?;
    let reference = vector(arena, p.reference)?;
    Ok(MassProperties {
        mass: p.mass,
        center,
        reference,
        inertia,
        inertia_cm,
    })
}

/// A constant expression as one constant: itself if it folded exactly (then rounded once
/// when emitted), else its value, rounded at each step where the exact folding overflowed.
fn fold(arena: &mut Arena, e: ExprId, quantity: &'static str) -> Result<ExprId, BodyError> {
    if arena.as_rational(e).is_some() {
        return Ok(e);
    }
    let value = arena.eval(e, &[]);
    arena
        .float(value)
        .map_err(|_| BodyError::Overflow { quantity, value })
}

/// The error for the zero moment about description axis `i`: with its values for a body of
/// literals, by axis for one with parameters (whose moments have no value here).
fn zero_moment(arena: &Arena, constant: bool, moments: &[ExprId; 3], i: usize) -> BodyError {
    if constant {
        let mut v = moments.map(|m| arena.eval(m, &[]));
        v.sort_by(f64::total_cmp);
        BodyError::ZeroPrincipalMoment { moments: v }
    } else {
        BodyError::IdenticallyZeroMoment {
            axis: ["x", "y", "z"][i % 3],
        }
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
