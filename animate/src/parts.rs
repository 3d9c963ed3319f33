//! A body's declared parts (and a contact surface) as coloured triangles in description axes.

use precess_core::body::{About, Axis, Part, Shape};
use precess_core::nalgebra::{Matrix3, SymmetricEigen, Vector3};

use crate::error::AnimateError;
use crate::geometry::{self, Halves, Split, Tri};

/// An RGB colour, each channel in [0, 1].
pub type Rgb = [f32; 3];

/// The colours given to a body's parts in turn: orange, green, purple, red, teal, yellow.
pub const PALETTE: [Rgb; 6] = [
    [0.95, 0.55, 0.10],
    [0.20, 0.65, 0.25],
    [0.55, 0.30, 0.80],
    [0.85, 0.15, 0.20],
    [0.10, 0.60, 0.60],
    [0.90, 0.80, 0.15],
];

/// The colour of the opposite hue, the same lightness and saturation (RGB reflected about the
/// mean of its largest and smallest channels): the second half of every part.
pub fn complement(c: Rgb) -> Rgb {
    let (hi, lo) = (c[0].max(c[1]).max(c[2]), c[0].min(c[1]).min(c[2]));
    [hi + lo - c[0], hi + lo - c[1], hi + lo - c[2]]
}

/// Triangles of one colour, in description axes.
#[derive(Debug, Clone)]
pub struct Group {
    /// The colour.
    pub colour: Rgb,
    /// The triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[[f64; 3]; 3]>,
}

/// How large to draw what has no size: particles (spheres) and rods (thin cylinders), as
/// fractions of the body's size.
const MARKER: f64 = 0.04;

/// The groups of a body's `parts`, part `k` in [`PALETTE`]`[k % 6]` and its complement;
/// `pivot` is where `about = pivot` tensors are taken. `size` sets the radius of particles and
/// the thickness of rods; [`body_size`] gives one.
///
/// # Errors
/// [`AnimateError::BadPart`] for a part whose values draw nothing (not finite, a mass or
/// length not positive, a tensor with no positive moments), naming the part.
pub fn part_groups(
    parts: &[Part<f64>],
    pivot: Option<[f64; 3]>,
    size: f64,
) -> Result<Vec<Group>, AnimateError> {
    let mut out = Vec::with_capacity(2 * parts.len());
    for (k, part) in parts.iter().enumerate() {
        let bad = |why: &'static str| AnimateError::BadPart {
            index: k,
            kind: part.shape.kind(),
            why,
        };
        let (halves, turn) = solid(part, pivot, size).map_err(bad)?;
        let frame = match &part.orientation {
            Some(o) => o
                .to_matrix()
                .ok_or_else(|| bad("its orientation has no axis"))?,
            None => Matrix3::identity(),
        } * turn;
        let place = |t: Vec<Tri>| -> Vec<Tri> {
            let at = Vector3::from(part.at);
            t.into_iter()
                .map(|tri| tri.map(|p| (at + frame * Vector3::from(p)).into()))
                .collect()
        };
        let colour = PALETTE[k % PALETTE.len()];
        out.push(Group {
            colour,
            triangles: place(halves.first),
        });
        out.push(Group {
            colour: complement(colour),
            triangles: place(halves.second),
        });
    }
    Ok(out)
}

/// The radius within which a body's parts lie about `centre`, counting each part's extent
/// (particles none): what [`part_groups`] scales its markers by. At least 1 mm.
pub fn body_size(parts: &[Part<f64>], centre: [f64; 3]) -> f64 {
    let c = Vector3::from(centre);
    parts
        .iter()
        .map(|p| (Vector3::from(p.at) - c).norm() + extent(&p.shape))
        .fold(1e-3, f64::max)
}

/// The half-diagonal of the box around a shape (0 for particles and explicit bodies).
fn extent(shape: &Shape<f64>) -> f64 {
    match shape {
        Shape::Particle { .. } | Shape::Explicit { .. } => 0.0,
        Shape::Sphere { radius, .. }
        | Shape::Shell { radius, .. }
        | Shape::Disk { radius, .. }
        | Shape::Ring { radius, .. } => *radius,
        Shape::Cuboid { size, .. } => Vector3::from(*size).norm() / 2.0,
        Shape::Ellipsoid { semi_axes, .. } => semi_axes.iter().fold(0.0, |a: f64, b| a.max(*b)),
        Shape::Cylinder { radius, length, .. } => radius.hypot(length / 2.0),
        Shape::Tube { outer, length, .. } => outer.hypot(length / 2.0),
        Shape::Rod { length, .. } => length / 2.0,
        Shape::Cone { radius, height, .. } => radius.max(*height),
    }
}

/// The rotation that lays local z along `axis` (a cyclic permutation, right-handed).
fn along(axis: Axis) -> Matrix3<f64> {
    match axis {
        Axis::Z => Matrix3::identity(),
        // local (x, y, z) → description (y, z, x) and (z, x, y).
        Axis::X => Matrix3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0),
        Axis::Y => Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0),
    }
}

/// A part's solid in its own axes, and the turn from those to the part's axes.
fn solid(
    part: &Part<f64>,
    pivot: Option<[f64; 3]>,
    size: f64,
) -> Result<(Halves, Matrix3<f64>), &'static str> {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    let check = |vs: &[f64]| {
        if vs.iter().all(|v| positive(*v)) {
            Ok(())
        } else {
            Err("a mass or a length is not a positive number")
        }
    };
    let marker = MARKER * size;
    let round = |soup| Halves::split(soup, Split::Z);
    let spin = |soup| Halves::split(soup, Split::X);
    let id = Matrix3::identity();
    Ok(match &part.shape {
        Shape::Particle { mass } => {
            check(&[*mass])?;
            (round(geometry::ellipsoid([marker; 3])), id)
        }
        Shape::Sphere { radius, mass } | Shape::Shell { radius, mass } => {
            check(&[*radius, *mass])?;
            (round(geometry::ellipsoid([*radius; 3])), id)
        }
        Shape::Ellipsoid { semi_axes, mass } => {
            check(&[semi_axes[0], semi_axes[1], semi_axes[2], *mass])?;
            (round(geometry::ellipsoid(*semi_axes)), id)
        }
        Shape::Cuboid { size, mass } => {
            check(&[size[0], size[1], size[2], *mass])?;
            (spin(geometry::cuboid(*size)), id)
        }
        Shape::Cylinder {
            radius,
            length,
            axis,
            mass,
        } => {
            check(&[*radius, *length, *mass])?;
            let soup = geometry::tube(0.0, *radius, -length / 2.0, length / 2.0);
            (spin(soup), along(*axis))
        }
        Shape::Tube {
            inner,
            outer,
            length,
            axis,
            mass,
        } => {
            check(&[*outer, *length, *mass])?;
            if !(inner.is_finite() && *inner >= 0.0 && inner < outer) {
                return Err("a tube's inner radius is not in [0, outer)");
            }
            let soup = geometry::tube(*inner, *outer, -length / 2.0, length / 2.0);
            (spin(soup), along(*axis))
        }
        // A thin disk is drawn 1/25 of its radius thick, a ring as a torus of tube r/20.
        Shape::Disk { radius, axis, mass } => {
            check(&[*radius, *mass])?;
            let h = radius / 50.0;
            (spin(geometry::tube(0.0, *radius, -h, h)), along(*axis))
        }
        Shape::Ring { radius, axis, mass } => {
            check(&[*radius, *mass])?;
            (spin(geometry::torus(*radius, radius / 20.0)), along(*axis))
        }
        Shape::Rod { length, axis, mass } => {
            check(&[*length, *mass])?;
            let r = (marker / 2.0).min(length / 20.0);
            let soup = geometry::tube(0.0, r, -length / 2.0, length / 2.0);
            (spin(soup), along(*axis))
        }
        Shape::Cone {
            radius,
            height,
            axis,
            reversed,
            mass,
        } => {
            check(&[*radius, *height, *mass])?;
            let h = if *reversed { -height } else { *height };
            (spin(geometry::cone(*radius, h)), along(*axis))
        }
        Shape::Explicit {
            mass,
            inertia,
            about,
        } => {
            check(&[*mass])?;
            let (semi, frame) = inertia_ellipsoid(*mass, inertia, *about, part.at, pivot)?;
            (round(geometry::ellipsoid(semi)), frame)
        }
    })
}

/// The uniform solid ellipsoid of mass M with the same inertia about its centre as the
/// tensor: semi-axes aᵢ² = 5 (Iⱼ + Iₖ − Iᵢ) / (2 M) along the principal axes (the ellipsoid's
/// Iᵢ = M (aⱼ² + aₖ²)/5 solved), the principal frame right-handed. A tensor about the pivot
/// is first moved to the centre: I_G = I_O − M (|d|² E − d dᵀ), d = G − O.
fn inertia_ellipsoid(
    mass: f64,
    inertia: &[[f64; 3]; 3],
    about: About,
    at: [f64; 3],
    pivot: Option<[f64; 3]>,
) -> Result<([f64; 3], Matrix3<f64>), &'static str> {
    let mut i = Matrix3::from_fn(|r, c| inertia[r][c]);
    if about == About::Pivot {
        let o = pivot.ok_or("its tensor is about a pivot the body does not declare")?;
        let d = Vector3::from(at) - Vector3::from(o);
        i -= (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * mass;
    }
    if i.iter().any(|v| !v.is_finite()) {
        return Err("its inertia is not finite");
    }
    let eig = SymmetricEigen::new(i);
    let m = eig.eigenvalues;
    let mut frame = eig.eigenvectors;
    if frame.determinant() < 0.0 {
        frame.column_mut(2).neg_mut();
    }
    let trace = m.sum();
    // A NaN trace was refused above (the tensor is finite); a sum of moments ≤ 0 draws nothing.
    if trace <= 0.0 {
        return Err("its inertia has no positive moment");
    }
    // A moment at the triangle inequality's edge gives a flat ellipsoid: drawn 1 % thick.
    let floor = 1e-4 * trace;
    let semi = [0, 1, 2].map(|k| (5.0 * (trace - 2.0 * m[k]).max(floor) / (2.0 * mass)).sqrt());
    Ok((semi, frame))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn the_inertia_ellipsoid_has_the_tensor_s_moments() {
        // A box's tensor, turned: its ellipsoid of the same mass has Iᵢ = M (aⱼ² + aₖ²)/5.
        let (m, a, b, c) = (2.0, 0.3, 0.2, 0.1);
        let diag = [
            m * (b * b + c * c) / 12.0,
            m * (a * a + c * c) / 12.0,
            m * (a * a + b * b) / 12.0,
        ];
        let r = precess_core::nalgebra::Rotation3::from_euler_angles(0.3, -0.2, 1.1);
        let t = r.matrix() * Matrix3::from_diagonal(&Vector3::from(diag)) * r.matrix().transpose();
        let tensor = [0, 1, 2].map(|i| [0, 1, 2].map(|j| t[(i, j)]));
        let (semi, frame) = inertia_ellipsoid(m, &tensor, About::Center, [0.0; 3], None).unwrap();
        let s2 = semi.map(|s| s * s);
        let moments = [0, 1, 2].map(|k| m * (s2[(k + 1) % 3] + s2[(k + 2) % 3]) / 5.0);
        let back = frame * Matrix3::from_diagonal(&Vector3::from(moments)) * frame.transpose();
        assert_relative_eq!(back, t, epsilon = 1e-14);
        assert_relative_eq!(frame.determinant(), 1.0, epsilon = 1e-12);
    }

    #[test]
    fn a_tensor_about_the_pivot_is_moved_to_the_centre() {
        // A point-like sphere's 2/5 m r² about its centre, given about a pivot 1 m below.
        let (m, i0) = (3.0, 0.01);
        let tensor = [[i0 + m, 0.0, 0.0], [0.0, i0 + m, 0.0], [0.0, 0.0, i0]];
        let (semi, _) =
            inertia_ellipsoid(m, &tensor, About::Pivot, [0.0, 0.0, 1.0], Some([0.0; 3])).unwrap();
        let r = (5.0 * i0 / (2.0 * m)).sqrt();
        for s in semi {
            assert_relative_eq!(s, r, max_relative = 1e-12);
        }
        let none = inertia_ellipsoid(m, &tensor, About::Pivot, [0.0; 3], None);
        assert!(none.is_err());
    }

    #[test]
    fn the_complement_is_the_opposite_hue() {
        assert_eq!(complement([1.0, 0.5, 0.0]), [0.0, 0.5, 1.0]);
        let grey = [0.3, 0.3, 0.3];
        assert_eq!(complement(grey), grey);
    }

    #[test]
    fn bad_parts_are_named() {
        let part = Part::new(
            Shape::Sphere {
                mass: 1.0,
                radius: -1.0,
            },
            [0.0; 3],
        );
        let ok = Part::new(Shape::Particle { mass: 1.0 }, [0.0; 3]);
        match part_groups(&[ok, part], None, 1.0) {
            Err(AnimateError::BadPart { index, kind, .. }) => {
                assert_eq!((index, kind), (1, "sphere"));
            }
            other => panic!("{other:?}"),
        }
    }
}
