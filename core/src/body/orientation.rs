//! Parts at any orientation: a rotation given as an axis and an angle, as a matrix, or as a
//! sequence of elementary rotations, and what it does to a part.
//!
//! A part is first laid out in its own axes at `at` (a cylinder along its `axis`, a box with
//! its edges along x, y, z), then turned about `at` by the rotation R, which maps the part's
//! axes to description axes. Its tensor about its own centre becomes R I Rᵀ and the offset of
//! that centre from `at` (the cone's h/4 along its axis) becomes R d; the parallel-axis shift
//! to the reference point then follows as for any part.
//!
//! Everything here is written over an [`Algebra`], so the run-time builder (`f64`) and the
//! derive macro (symbolic, where an angle may be a field) share one implementation.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::algebra::{Algebra, Numeric};
use super::mass::Tensor;
use super::shape::Axis;

/// How a part is turned: the rotation R from the part's own axes to description axes.
///
/// Angles are in radians and turn right-handedly (counter-clockwise seen from the tip of the
/// axis). Every form gives the same kind of R, so `x(α)`, `axis_angle([1, 0, 0], α)` and the
/// matrix `[[1, 0, 0], [0, cos α, −sin α], [0, sin α, cos α]]` are one rotation.
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::Vector3;
/// use precess_core::body::{Axis, Orientation};
/// let a = Orientation::axis_angle([0.0, 0.0, 2.0], 0.5).to_matrix().unwrap();
/// let b = Orientation::sequence([(Axis::Z, 0.5)]).to_matrix().unwrap();
/// assert_relative_eq!(a, b, epsilon = 1e-16);
/// // A quarter turn about z takes x to y.
/// let r = Orientation::axis_angle([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2).to_matrix().unwrap();
/// assert_relative_eq!(r * Vector3::x(), Vector3::y(), epsilon = 1e-16);
/// ```
#[derive(Clone, PartialEq, Debug)]
pub enum Orientation<T> {
    /// A turn by `angle` about `axis` (any non-zero length), by Rodrigues' formula
    /// R = cos α E + sin α \[u\]× + (1 − cos α) u uᵀ with u = axis / |axis|.
    AxisAngle {
        /// The axis of the turn; only its direction matters.
        axis: [T; 3],
        /// The angle of the turn, radians.
        angle: T,
    },
    /// R itself, as rows: column k is the part's axis k in description coordinates. It must
    /// be a rotation: orthonormal to 1e-9 and det R = +1 (not a reflection). It is used as
    /// the nearest rotation (the orthogonal factor of its polar decomposition), so a matrix
    /// rounded to a few digits turns the part without stretching its moments; one that is a
    /// rotation to rounding (from angles, a quaternion, a `Rotation3`) is used as given.
    Matrix([[T; 3]; 3]),
    /// Elementary rotations composed as R = R_a1(α1) R_a2(α2) …: turn about a1 by α1, then
    /// about the turned a2 by α2, and so on (the convention of Euler angles, so `[(Z, φ),
    /// (X, θ), (Z, ψ)]` is the top's R = Rz(φ) Rx(θ) Rz(ψ)). Empty is the identity.
    Sequence(Vec<(Axis, T)>),
}

impl<T> Orientation<T> {
    /// The same orientation with every value mapped through `f`.
    pub fn map<U>(&self, f: &mut impl FnMut(&T) -> U) -> Orientation<U> {
        let v3 = |v: &[T; 3], f: &mut dyn FnMut(&T) -> U| [f(&v[0]), f(&v[1]), f(&v[2])];
        match self {
            Orientation::AxisAngle { axis, angle } => Orientation::AxisAngle {
                axis: v3(axis, f),
                angle: f(angle),
            },
            Orientation::Matrix(rows) => {
                Orientation::Matrix([v3(&rows[0], f), v3(&rows[1], f), v3(&rows[2], f)])
            }
            Orientation::Sequence(turns) => {
                Orientation::Sequence(turns.iter().map(|(axis, a)| (*axis, f(a))).collect())
            }
        }
    }

    /// Every value it holds, in order.
    pub fn values(&self) -> Vec<&T> {
        match self {
            Orientation::AxisAngle { axis, angle } => axis.iter().chain([angle]).collect(),
            Orientation::Matrix(rows) => rows.iter().flatten().collect(),
            Orientation::Sequence(turns) => turns.iter().map(|(_, a)| a).collect(),
        }
    }
}

impl Orientation<f64> {
    /// A turn by `angle` (radians) about `axis`, which need not be a unit vector.
    pub fn axis_angle(axis: impl Into<Vector3<f64>>, angle: f64) -> Orientation<f64> {
        let axis = axis.into();
        Orientation::AxisAngle {
            axis: [axis.x, axis.y, axis.z],
            angle,
        }
    }

    /// Elementary turns composed as R = R_a1(α1) R_a2(α2) … (see [`Orientation::Sequence`]).
    pub fn sequence(turns: impl IntoIterator<Item = (Axis, f64)>) -> Orientation<f64> {
        Orientation::Sequence(turns.into_iter().collect())
    }

    /// The rotation matrix R (part axes → description axes); `None` for an axis–angle whose
    /// axis is zero. A [`Orientation::Matrix`] is returned as the rotation nearest to it
    /// (meaningful for one within the tolerance, which the body's validation checks).
    pub fn to_matrix(&self) -> Option<Matrix3<f64>> {
        rotation_matrix(&mut Numeric, self).map(|t| Matrix3::from_fn(|i, j| t[i][j]))
    }
}

impl From<Matrix3<f64>> for Orientation<f64> {
    /// The matrix as R (checked when the body is validated).
    fn from(m: Matrix3<f64>) -> Orientation<f64> {
        Orientation::Matrix(std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)])))
    }
}

impl From<[[f64; 3]; 3]> for Orientation<f64> {
    /// The rows of R (checked when the body is validated).
    fn from(rows: [[f64; 3]; 3]) -> Orientation<f64> {
        Orientation::Matrix(rows)
    }
}

impl From<Rotation3<f64>> for Orientation<f64> {
    fn from(r: Rotation3<f64>) -> Orientation<f64> {
        Orientation::from(*r.matrix())
    }
}

impl From<UnitQuaternion<f64>> for Orientation<f64> {
    fn from(q: UnitQuaternion<f64>) -> Orientation<f64> {
        Orientation::from(q.to_rotation_matrix())
    }
}

/// The rotation matrix R of `o` as rows, in the algebra `al`; `None` when an axis–angle's
/// axis is (identically) zero, so that it has no direction.
pub fn rotation_matrix<A: Algebra>(
    al: &mut A,
    o: &Orientation<A::Value>,
) -> Option<Tensor<A::Value>> {
    match o {
        // Within the tolerance of a rotation is not a rotation: R I Rᵀ would scale the
        // moments by |R|² (1 + 8e-10 at the tolerance's edge).
        Orientation::Matrix(rows) => Some(al.orthonormalise(rows)),
        Orientation::AxisAngle { axis, angle } => axis_angle(al, axis, *angle),
        Orientation::Sequence(turns) => {
            let mut r = identity(al);
            for &(axis, angle) in turns {
                let turn = elementary(al, axis, angle);
                r = product(al, &r, &turn);
            }
            Some(r)
        }
    }
}

/// Rodrigues' formula with the axis k left unnormalised: u uᵀ = k kᵀ / |k|² needs no root,
/// and only the sin α [u]× term divides by |k|.
fn axis_angle<A: Algebra>(
    al: &mut A,
    k: &[A::Value; 3],
    angle: A::Value,
) -> Option<Tensor<A::Value>> {
    let squares = [al.square(k[0]), al.square(k[1]), al.square(k[2])];
    let norm2 = al.total(&squares);
    let norm = al.sqrt(norm2)?;
    let (c, s) = (al.cos(angle), al.sin(angle));
    let one = al.ratio(1, 1);
    let versine = al.minus(one, c);
    let w = al.divide(versine, norm2)?;
    let zero = al.ratio(0, 1);
    let mut u = [zero; 3];
    for (ui, &ki) in u.iter_mut().zip(k) {
        let t = al.times(s, ki);
        *ui = al.divide(t, norm)?;
    }
    let mut r = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let kk = al.times(k[i], k[j]);
            let sym = al.times(w, kk);
            r[i][j] = if i == j { al.plus(c, sym) } else { sym };
        }
    }
    // + sin α [u]×, with [u]× = [[0, −u3, u2], [u3, 0, −u1], [−u2, u1, 0]].
    for (i, j, l) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
        r[i][j] = al.minus(r[i][j], u[l]);
        r[j][i] = al.plus(r[j][i], u[l]);
    }
    Some(r)
}

/// The turn by `angle` about a coordinate axis.
fn elementary<A: Algebra>(al: &mut A, axis: Axis, angle: A::Value) -> Tensor<A::Value> {
    let (c, s) = (al.cos(angle), al.sin(angle));
    let zero = al.ratio(0, 1);
    let neg_s = al.minus(zero, s);
    let mut r = identity(al);
    // The plane of the turn, in right-handed order: (y, z) about x, (z, x) about y, (x, y)
    // about z.
    let (a, b) = match axis {
        Axis::X => (1, 2),
        Axis::Y => (2, 0),
        Axis::Z => (0, 1),
    };
    r[a][a] = c;
    r[b][b] = c;
    r[a][b] = neg_s;
    r[b][a] = s;
    r
}

fn identity<A: Algebra>(al: &mut A) -> Tensor<A::Value> {
    let (zero, one) = (al.ratio(0, 1), al.ratio(1, 1));
    let mut r = [[zero; 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        row[i] = one;
    }
    r
}

/// `a b`.
fn product<A: Algebra>(al: &mut A, a: &Tensor<A::Value>, b: &Tensor<A::Value>) -> Tensor<A::Value> {
    let zero = al.ratio(0, 1);
    let mut out = [[zero; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, entry) in row.iter_mut().enumerate() {
            let terms: Vec<A::Value> = (0..3).map(|k| al.times(a[i][k], b[k][j])).collect();
            *entry = al.total(&terms);
        }
    }
    out
}

/// R T Rᵀ, the tensor `t` given in part axes expressed in description axes. Each entry is
/// computed once for i ≤ j and mirrored, so the result is exactly symmetric in `f64` too.
pub fn rotate_tensor<A: Algebra>(
    al: &mut A,
    r: &Tensor<A::Value>,
    t: &Tensor<A::Value>,
) -> Tensor<A::Value> {
    let rt = product(al, r, t);
    let mut out = *t;
    for i in 0..3 {
        for j in i..3 {
            let terms: Vec<A::Value> = (0..3).map(|l| al.times(rt[i][l], r[j][l])).collect();
            let e = al.total(&terms);
            out[i][j] = e;
            out[j][i] = e;
        }
    }
    out
}

/// R v.
pub fn rotate_vector<A: Algebra>(
    al: &mut A,
    r: &Tensor<A::Value>,
    v: &[A::Value; 3],
) -> [A::Value; 3] {
    std::array::from_fn(|i| {
        let terms: Vec<A::Value> = (0..3).map(|k| al.times(r[i][k], v[k])).collect();
        al.total(&terms)
    })
}
