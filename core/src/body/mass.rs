//! Mass properties of a composite: total mass, centre of mass, and the inertia tensor about
//! the centre of mass and about the reference point, by the general parallel-axis theorem
//! I_O' = I_G + M (|d|² E − d dᵀ), d = G − O'.

use super::algebra::Algebra;
use super::error::BodyError;
use super::orientation::{rotate_tensor, rotate_vector, rotation_matrix};
use super::shape::{About, Description, Shape, closed_form};

/// A symmetric 3×3 tensor as rows.
pub type Tensor<V> = [[V; 3]; 3];

/// What a description amounts to, in the algebra it was computed in.
#[derive(Clone, PartialEq, Debug)]
pub struct MassProperties<V> {
    /// Total mass M.
    pub mass: V,
    /// Centre of mass G in the description frame.
    pub center: [V; 3],
    /// The reference point: the pivot if one is declared, else G.
    pub reference: [V; 3],
    /// Inertia tensor about the reference point, description axes.
    pub inertia: Tensor<V>,
    /// Inertia tensor about G, description axes.
    pub inertia_cm: Tensor<V>,
}

impl<V: Copy> MassProperties<V> {
    /// Checks that every quantity has a finite value, `value` giving each entry's `f64`.
    ///
    /// # Errors
    /// [`BodyError::Overflow`] for the first entry that is not finite, naming its quantity
    /// (total mass, centre of mass, either inertia tensor) and carrying its value.
    pub(crate) fn check_finite(&self, mut value: impl FnMut(V) -> f64) -> Result<(), BodyError> {
        let quantities: [(&'static str, Vec<V>); 4] = [
            ("total mass", vec![self.mass]),
            ("centre of mass", self.center.to_vec()),
            (
                "inertia tensor about the centre of mass",
                self.inertia_cm.iter().flatten().copied().collect(),
            ),
            (
                "inertia tensor about the reference point",
                self.inertia.iter().flatten().copied().collect(),
            ),
        ];
        for (quantity, entries) in quantities {
            for entry in entries {
                let value = value(entry);
                if !value.is_finite() {
                    return Err(BodyError::Overflow { quantity, value });
                }
            }
        }
        Ok(())
    }
}

/// `m (|d|² E − d dᵀ)`: the inertia of a point mass `m` at `d`.
pub fn point_tensor<A: Algebra>(al: &mut A, m: A::Value, d: [A::Value; 3]) -> Tensor<A::Value> {
    let sq = [al.square(d[0]), al.square(d[1]), al.square(d[2])];
    let zero = al.ratio(0, 1);
    let mut t = [[zero; 3]; 3];
    for i in 0..3 {
        let s = al.plus(sq[(i + 1) % 3], sq[(i + 2) % 3]);
        t[i][i] = al.times(m, s);
        for j in (i + 1)..3 {
            let p = al.times(d[i], d[j]);
            let mp = al.times(m, p);
            let neg = al.minus(zero, mp);
            t[i][j] = neg;
            t[j][i] = neg;
        }
    }
    t
}

/// `a ∘ b` entry by entry, `op` the algebra's `plus` or `minus`.
fn tensor_zip<A: Algebra>(
    al: &mut A,
    a: &Tensor<A::Value>,
    b: &Tensor<A::Value>,
    op: fn(&mut A, A::Value, A::Value) -> A::Value,
) -> Tensor<A::Value> {
    let mut out = *a;
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = op(al, a[i][j], b[i][j]);
        }
    }
    out
}

fn vsub<A: Algebra>(al: &mut A, a: [A::Value; 3], b: [A::Value; 3]) -> [A::Value; 3] {
    [
        al.minus(a[0], b[0]),
        al.minus(a[1], b[1]),
        al.minus(a[2], b[2]),
    ]
}

/// One part reduced to its mass, centre of mass and inertia about that centre.
struct Reduced<V> {
    mass: V,
    center: [V; 3],
    inertia: Tensor<V>,
}

/// Mass properties of `d`, computed in the algebra `al`.
///
/// Each part's tensor about its own centre of mass, turned into description axes by its
/// rotation R as R I Rᵀ, is shifted to the reference point by the general parallel-axis
/// theorem and summed.
///
/// # Errors
/// [`BodyError::NoParts`] for an empty description, [`BodyError::PivotRequired`] for an
/// explicit tensor given about a pivot that is not declared, [`BodyError::ZeroRotationAxis`]
/// for an axis–angle whose axis is (identically) zero, [`BodyError::ZeroTotalMass`]
/// when the masses add up to (identically) zero.
pub fn mass_properties<A: Algebra>(
    al: &mut A,
    d: &Description<A::Value>,
) -> Result<MassProperties<A::Value>, BodyError> {
    if d.parts.is_empty() {
        return Err(BodyError::NoParts);
    }
    let zero = al.ratio(0, 1);
    let mut reduced = Vec::with_capacity(d.parts.len());
    for (index, part) in d.parts.iter().enumerate() {
        let mass = *part.shape.mass();
        // R maps the part's axes to description axes; without one they coincide.
        let rotation = match &part.orientation {
            Some(o) => Some(rotation_matrix(al, o).ok_or(BodyError::ZeroRotationAxis {
                part: index,
                kind: part.shape.kind(),
                axis: [0.0; 3],
            })?),
            None => None,
        };
        let turn = |al: &mut A, t: Tensor<A::Value>| match &rotation {
            Some(r) => rotate_tensor(al, r, &t),
            None => t,
        };
        let (center, inertia) = match (&part.shape, closed_form(al, &part.shape)) {
            (_, Some((diag, offset))) => {
                let mut center = part.at;
                if let Some((axis, off)) = offset {
                    // The centre's offset from `at`, along the axis in part axes, turned.
                    let mut d = [zero; 3];
                    d[axis.index()] = off;
                    let d = match &rotation {
                        Some(r) => rotate_vector(al, r, &d),
                        None => d,
                    };
                    center = std::array::from_fn(|k| al.plus(center[k], d[k]));
                }
                let mut t = [[zero; 3]; 3];
                for i in 0..3 {
                    t[i][i] = diag[i];
                }
                (center, turn(al, t))
            }
            (Shape::Explicit { inertia, about, .. }, None) => {
                // A tensor about any point turns as R I Rᵀ: turn first, then shift in
                // description axes.
                let inertia = turn(al, *inertia);
                match about {
                    About::Center => (part.at, inertia),
                    About::Pivot => {
                        let pivot = d.pivot.ok_or(BodyError::PivotRequired { part: index })?;
                        // I_G = I_P − m (|g|² E − g gᵀ), g = G − P.
                        let g = vsub(al, part.at, pivot);
                        let shift = point_tensor(al, mass, g);
                        (part.at, tensor_zip(al, &inertia, &shift, A::minus))
                    }
                }
            }
            (_, None) => return Err(BodyError::NoParts),
        };
        reduced.push(Reduced {
            mass,
            center,
            inertia,
        });
    }
    let masses: Vec<A::Value> = reduced.iter().map(|r| r.mass).collect();
    let mass = al.total(&masses);
    let mut center = [zero; 3];
    for (k, c) in center.iter_mut().enumerate() {
        let moments: Vec<A::Value> = reduced
            .iter()
            .map(|r| al.times(r.mass, r.center[k]))
            .collect();
        let s = al.total(&moments);
        *c = al.divide(s, mass).ok_or(BodyError::ZeroTotalMass)?;
    }
    let about = |al: &mut A, o: [A::Value; 3]| {
        let mut acc = [[zero; 3]; 3];
        for r in &reduced {
            let dv = vsub(al, r.center, o);
            let shift = point_tensor(al, r.mass, dv);
            let part = tensor_zip(al, &r.inertia, &shift, A::plus);
            acc = tensor_zip(al, &acc, &part, A::plus);
        }
        acc
    };
    let inertia_cm = about(al, center);
    let (reference, inertia) = match d.pivot {
        Some(p) => (p, about(al, p)),
        None => (center, inertia_cm),
    };
    Ok(MassProperties {
        mass,
        center,
        reference,
        inertia,
        inertia_cm,
    })
}
