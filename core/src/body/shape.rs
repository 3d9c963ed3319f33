//! The parts a body is made of, and each part's inertia about its own centre of mass in
//! closed form.
//!
//! Every closed form is the textbook one (uniform density, SI units). Axisymmetric parts
//! are written with their symmetry axis along local z and then laid along the part's
//! [`Axis`]; the others are given directly in description axes.

use super::algebra::Algebra;
use super::orientation::Orientation;

/// A coordinate axis of the description frame.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum Axis {
    /// The x axis.
    X,
    /// The y axis.
    Y,
    /// The z axis (the default for axisymmetric parts).
    #[default]
    Z,
}

impl Axis {
    /// 0, 1 or 2.
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }
}

/// The point an explicit tensor is given about.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub enum About {
    /// The part's own centre of mass (its `at`).
    #[default]
    Center,
    /// The body's pivot (which the description must then declare).
    Pivot,
}

/// A uniform solid, or an explicit mass distribution, with its dimensions.
///
/// Lengths are full lengths (a cylinder's `length` is end to end); radii are radii.
#[derive(Clone, PartialEq, Debug)]
pub enum Shape<T> {
    /// A point mass: zero inertia about itself.
    Particle {
        /// Mass.
        mass: T,
    },
    /// Solid sphere: I = 2/5 m r².
    Sphere {
        /// Mass.
        mass: T,
        /// Radius.
        radius: T,
    },
    /// Thin spherical shell: I = 2/3 m r².
    Shell {
        /// Mass.
        mass: T,
        /// Radius.
        radius: T,
    },
    /// Solid box with edges `size = [a, b, c]` along x, y, z: Ixx = m (b² + c²)/12, cyclic.
    Cuboid {
        /// Mass.
        mass: T,
        /// Full edge lengths along x, y, z.
        size: [T; 3],
    },
    /// Solid cylinder: I_axis = ½ m r², I_transverse = m (3 r² + L²)/12.
    Cylinder {
        /// Mass.
        mass: T,
        /// Radius.
        radius: T,
        /// Length along the axis.
        length: T,
        /// Symmetry axis.
        axis: Axis,
    },
    /// Thick-walled tube: I_axis = ½ m (a² + b²), I_transverse = m (3 (a² + b²) + L²)/12.
    Tube {
        /// Mass.
        mass: T,
        /// Inner radius a (0 ≤ a < b).
        inner: T,
        /// Outer radius b.
        outer: T,
        /// Length along the axis.
        length: T,
        /// Symmetry axis.
        axis: Axis,
    },
    /// Thin disk: I_axis = ½ m r², I_transverse = ¼ m r².
    Disk {
        /// Mass.
        mass: T,
        /// Radius.
        radius: T,
        /// Normal to the disk.
        axis: Axis,
    },
    /// Thin ring (hoop): I_axis = m r², I_transverse = ½ m r².
    Ring {
        /// Mass.
        mass: T,
        /// Radius.
        radius: T,
        /// Normal to the ring's plane.
        axis: Axis,
    },
    /// Thin rod: I_axis = 0, I_transverse = m L²/12.
    Rod {
        /// Mass.
        mass: T,
        /// Length.
        length: T,
        /// Direction of the rod.
        axis: Axis,
    },
    /// Solid cone, its base centred on `at` and its apex at `at ± height · axis` (+ unless
    /// `reversed`); centre of mass at `at ± height/4 · axis`. About it: I_axis = 3/10 m r²,
    /// I_transverse = 3/20 m r² + 3/80 m h².
    Cone {
        /// Mass.
        mass: T,
        /// Radius of the base.
        radius: T,
        /// Height from base to apex.
        height: T,
        /// The symmetry axis.
        axis: Axis,
        /// True if the apex lies towards −axis from the base (`axis = -z` in the attribute).
        reversed: bool,
    },
    /// Solid ellipsoid with semi-axes `[a, b, c]` along x, y, z: Ixx = m (b² + c²)/5, cyclic.
    Ellipsoid {
        /// Mass.
        mass: T,
        /// Semi-axes along x, y, z.
        semi_axes: [T; 3],
    },
    /// A body given by its mass, its centre of mass (`at`) and its inertia tensor.
    Explicit {
        /// Mass.
        mass: T,
        /// The symmetric inertia tensor, in description axes.
        inertia: [[T; 3]; 3],
        /// The point the tensor is taken about.
        about: About,
    },
}

/// One part of a body: a shape placed at `at` (its centre; for a cone, the centre of its
/// base), laid out in its own axes and, if `orientation` is given, turned about `at`.
#[derive(Clone, PartialEq, Debug)]
pub struct Part<T> {
    /// The shape and its dimensions, in the part's own axes.
    pub shape: Shape<T>,
    /// Where it sits in the description frame.
    pub at: [T; 3],
    /// The rotation from the part's axes to description axes, about `at`; `None` keeps the
    /// part's axes along the description axes.
    pub orientation: Option<Orientation<T>>,
}

impl<T> Part<T> {
    /// `shape` at `at`, its axes along the description axes.
    pub fn new(shape: Shape<T>, at: [T; 3]) -> Part<T> {
        Part {
            shape,
            at,
            orientation: None,
        }
    }

    /// The same part turned by `orientation` about `at` (replacing any earlier turn).
    pub fn rotated(self, orientation: Orientation<T>) -> Part<T> {
        Part {
            orientation: Some(orientation),
            ..self
        }
    }
}

/// A whole body: its parts and an optional pivot (a fixed point of the motion).
#[derive(Clone, PartialEq, Debug)]
pub struct Description<T> {
    /// The parts, in the order given.
    pub parts: Vec<Part<T>>,
    /// The pivot, if the body turns about a fixed point.
    pub pivot: Option<[T; 3]>,
}

impl<T> Shape<T> {
    /// The part's name as the attribute language spells it.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Particle { .. } => "particle",
            Shape::Sphere { .. } => "sphere",
            Shape::Shell { .. } => "shell",
            Shape::Cuboid { .. } => "cuboid",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Tube { .. } => "tube",
            Shape::Disk { .. } => "disk",
            Shape::Ring { .. } => "ring",
            Shape::Rod { .. } => "rod",
            Shape::Cone { .. } => "cone",
            Shape::Ellipsoid { .. } => "ellipsoid",
            Shape::Explicit { .. } => "body",
        }
    }

    /// The mass.
    pub fn mass(&self) -> &T {
        match self {
            Shape::Particle { mass }
            | Shape::Sphere { mass, .. }
            | Shape::Shell { mass, .. }
            | Shape::Cuboid { mass, .. }
            | Shape::Cylinder { mass, .. }
            | Shape::Tube { mass, .. }
            | Shape::Disk { mass, .. }
            | Shape::Ring { mass, .. }
            | Shape::Rod { mass, .. }
            | Shape::Cone { mass, .. }
            | Shape::Ellipsoid { mass, .. }
            | Shape::Explicit { mass, .. } => mass,
        }
    }

    /// The dimensions that must be positive, each with its key (the inner radius of a tube,
    /// which may be zero, is not listed).
    pub fn dimensions(&self) -> Vec<(&'static str, &T)> {
        match self {
            Shape::Particle { .. } | Shape::Explicit { .. } => vec![],
            Shape::Sphere { radius, .. }
            | Shape::Shell { radius, .. }
            | Shape::Disk { radius, .. }
            | Shape::Ring { radius, .. } => vec![("radius", radius)],
            Shape::Cuboid { size, .. } => size.iter().map(|s| ("size", s)).collect(),
            Shape::Ellipsoid { semi_axes, .. } => {
                semi_axes.iter().map(|s| ("semi_axes", s)).collect()
            }
            Shape::Cylinder { radius, length, .. } => vec![("radius", radius), ("length", length)],
            Shape::Tube { outer, length, .. } => vec![("outer", outer), ("length", length)],
            Shape::Rod { length, .. } => vec![("length", length)],
            Shape::Cone { radius, height, .. } => vec![("radius", radius), ("height", height)],
        }
    }

    /// The same shape with every value mapped through `f`.
    pub fn map<U>(&self, f: &mut impl FnMut(&T) -> U) -> Shape<U> {
        let v3 = |v: &[T; 3], f: &mut dyn FnMut(&T) -> U| [f(&v[0]), f(&v[1]), f(&v[2])];
        match self {
            Shape::Particle { mass } => Shape::Particle { mass: f(mass) },
            Shape::Sphere { mass, radius } => Shape::Sphere {
                mass: f(mass),
                radius: f(radius),
            },
            Shape::Shell { mass, radius } => Shape::Shell {
                mass: f(mass),
                radius: f(radius),
            },
            Shape::Cuboid { mass, size } => Shape::Cuboid {
                mass: f(mass),
                size: v3(size, f),
            },
            Shape::Cylinder {
                mass,
                radius,
                length,
                axis,
            } => Shape::Cylinder {
                mass: f(mass),
                radius: f(radius),
                length: f(length),
                axis: *axis,
            },
            Shape::Tube {
                mass,
                inner,
                outer,
                length,
                axis,
            } => Shape::Tube {
                mass: f(mass),
                inner: f(inner),
                outer: f(outer),
                length: f(length),
                axis: *axis,
            },
            Shape::Disk { mass, radius, axis } => Shape::Disk {
                mass: f(mass),
                radius: f(radius),
                axis: *axis,
            },
            Shape::Ring { mass, radius, axis } => Shape::Ring {
                mass: f(mass),
                radius: f(radius),
                axis: *axis,
            },
            Shape::Rod { mass, length, axis } => Shape::Rod {
                mass: f(mass),
                length: f(length),
                axis: *axis,
            },
            Shape::Cone {
                mass,
                radius,
                height,
                axis,
                reversed,
            } => Shape::Cone {
                mass: f(mass),
                radius: f(radius),
                height: f(height),
                axis: *axis,
                reversed: *reversed,
            },
            Shape::Ellipsoid { mass, semi_axes } => Shape::Ellipsoid {
                mass: f(mass),
                semi_axes: v3(semi_axes, f),
            },
            Shape::Explicit {
                mass,
                inertia,
                about,
            } => Shape::Explicit {
                mass: f(mass),
                inertia: [v3(&inertia[0], f), v3(&inertia[1], f), v3(&inertia[2], f)],
                about: *about,
            },
        }
    }
}

impl<T> Description<T> {
    /// The same description with every value mapped through `f`.
    pub fn map<U>(&self, f: &mut impl FnMut(&T) -> U) -> Description<U> {
        let v3 = |v: &[T; 3], f: &mut dyn FnMut(&T) -> U| [f(&v[0]), f(&v[1]), f(&v[2])];
        Description {
            parts: self
                .parts
                .iter()
                .map(|p| Part {
                    shape: p.shape.map(f),
                    at: v3(&p.at, f),
                    orientation: p.orientation.as_ref().map(|o| o.map(f)),
                })
                .collect(),
            pivot: self.pivot.as_ref().map(|p| v3(p, f)),
        }
    }
}

/// A shape's diagonal tensor about its centre of mass, and that centre's offset from `at`
/// along an axis (the cone's h/4), both in the part's own axes.
pub type ClosedForm<V> = ([V; 3], Option<(Axis, V)>);

/// Lays an axisymmetric tensor (transverse `t`, axial `a`) along `axis`.
fn along<V: Copy>(axis: Axis, t: V, a: V) -> [V; 3] {
    let mut d = [t; 3];
    d[axis.index()] = a;
    d
}

/// The diagonal of a non-explicit shape's inertia tensor about its own centre of mass, in
/// the part's own axes (description axes unless the part is rotated), and the offset of that centre from `at` along the shape's axis
/// (non-zero only for the cone). `None` for [`Shape::Explicit`].
pub fn closed_form<A: Algebra>(
    al: &mut A,
    shape: &Shape<A::Value>,
) -> Option<ClosedForm<A::Value>> {
    let zero = al.ratio(0, 1);
    Some(match *shape {
        Shape::Particle { .. } => ([zero; 3], None),
        Shape::Sphere { mass, radius } | Shape::Shell { mass, radius } => {
            let k = if matches!(shape, Shape::Sphere { .. }) {
                (2, 5)
            } else {
                (2, 3)
            };
            let mr2 = sq_times(al, mass, radius);
            ([al.scaled(k.0, k.1, mr2); 3], None)
        }
        Shape::Cuboid { mass, size } => (box_like(al, mass, size, 12), None),
        Shape::Ellipsoid { mass, semi_axes } => (box_like(al, mass, semi_axes, 5), None),
        Shape::Cylinder {
            mass,
            radius,
            length,
            axis,
        } => {
            let mr2 = sq_times(al, mass, radius);
            let ml2 = sq_times(al, mass, length);
            (revolution(al, axis, mr2, ml2, CYLINDER), None)
        }
        Shape::Tube {
            mass,
            inner,
            outer,
            length,
            axis,
        } => {
            let a2 = sq_times(al, mass, inner);
            let b2 = sq_times(al, mass, outer);
            let ml2 = sq_times(al, mass, length);
            let s = al.plus(a2, b2);
            (revolution(al, axis, s, ml2, CYLINDER), None)
        }
        Shape::Disk { mass, radius, axis } => {
            let mr2 = sq_times(al, mass, radius);
            let (a, t) = (al.scaled(1, 2, mr2), al.scaled(1, 4, mr2));
            (along(axis, t, a), None)
        }
        Shape::Ring { mass, radius, axis } => {
            let mr2 = sq_times(al, mass, radius);
            (along(axis, al.scaled(1, 2, mr2), mr2), None)
        }
        Shape::Rod { mass, length, axis } => {
            let ml2 = sq_times(al, mass, length);
            (along(axis, al.scaled(1, 12, ml2), zero), None)
        }
        Shape::Cone {
            mass,
            radius,
            height,
            axis,
            reversed,
        } => {
            let mr2 = sq_times(al, mass, radius);
            let mh2 = sq_times(al, mass, height);
            let diagonal = revolution(al, axis, mr2, mh2, CONE);
            let offset = al.scaled(if reversed { -1 } else { 1 }, 4, height);
            (diagonal, Some((axis, offset)))
        }
        Shape::Explicit { .. } => return None,
    })
}

/// The fractions (α, β, γ) of a solid of revolution: I_axis = α S and
/// I_transverse = β S + γ m L², with S its radial measure and L its length along the axis.
type Fractions = [(i64, i64); 3];

/// A solid cylinder (S = m r²) or a thick tube (S = m (a² + b²)): ½, ¼, 1/12.
const CYLINDER: Fractions = [(1, 2), (1, 4), (1, 12)];

/// A solid cone about its centre of mass (S = m r², L the height): 3/10, 3/20, 3/80.
const CONE: Fractions = [(3, 10), (3, 20), (3, 80)];

/// The diagonal of a solid of revolution along `axis` from its radial measure `s` and
/// `ml2 = m L²` (see [`Fractions`]).
fn revolution<A: Algebra>(
    al: &mut A,
    axis: Axis,
    s: A::Value,
    ml2: A::Value,
    [(a_num, a_den), (t_num, t_den), (l_num, l_den)]: Fractions,
) -> [A::Value; 3] {
    let a = al.scaled(a_num, a_den, s);
    let t1 = al.scaled(t_num, t_den, s);
    let t2 = al.scaled(l_num, l_den, ml2);
    along(axis, al.plus(t1, t2), a)
}

/// `m · x²`.
fn sq_times<A: Algebra>(al: &mut A, m: A::Value, x: A::Value) -> A::Value {
    let x2 = al.square(x);
    al.times(m, x2)
}

/// `m (b² + c²)/k`, cyclic, with `s = [a, b, c]` (a box for k = 12 with full edges, an
/// ellipsoid for k = 5 with semi-axes).
fn box_like<A: Algebra>(al: &mut A, m: A::Value, s: [A::Value; 3], k: i64) -> [A::Value; 3] {
    let sq = [al.square(s[0]), al.square(s[1]), al.square(s[2])];
    let mut out = sq;
    for i in 0..3 {
        let sum = al.plus(sq[(i + 1) % 3], sq[(i + 2) % 3]);
        let msum = al.times(m, sum);
        out[i] = al.scaled(1, k, msum);
    }
    out
}

impl<T> Default for Description<T> {
    fn default() -> Self {
        Description {
            parts: Vec::new(),
            pivot: None,
        }
    }
}
