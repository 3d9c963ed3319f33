//! The contact surfaces a body may touch the table with, and their support maps: the point of
//! the surface whose outward normal is a given unit vector n, in closed form, so the contact
//! point is an expression of the attitude.
//!
//! On a horizontal table the outward normal at the contact is the downward vertical, which in
//! body axes is n = −γ, γ = Rᵀ ẑ the "Poisson vector" (the space vertical seen from the body).
//! The contact point is then `s(−γ)`, the support point of the surface in that direction.

use crate::sym::{Arena, ExprId, SymError};

/// A convex contact surface fixed in the body, in description axes. Every surface has its
/// symmetry (or principal) axes along the description axes; its placement is `center`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface {
    /// A sphere of radius ρ about `center`: s(n) = c + ρ n (the tippe top, Routh's sphere,
    /// the Chaplygin ball).
    Sphere {
        /// The sphere's centre.
        center: [ExprId; 3],
        /// Its radius ρ > 0.
        radius: ExprId,
    },
    /// An ellipsoid of semi-axes (a, b, c) along the description axes about `center`:
    /// s(n) = c₀ + D² n / √(nᵀ D² n), D = diag(a, b, c) (the rattleback).
    Ellipsoid {
        /// The ellipsoid's centre.
        center: [ExprId; 3],
        /// Its semi-axes along description x, y, z, each > 0.
        semi_axes: [ExprId; 3],
    },
    /// The sharp rim of a disk of radius ρ about `center`, its axis along description z:
    /// s(n) = c + ρ (n − (n·e₃) e₃) / √(1 − (n·e₃)²), undefined when the disk lies flat
    /// (the rolling disk, Euler's disk).
    DiskRim {
        /// The disk's centre.
        center: [ExprId; 3],
        /// Its radius ρ > 0.
        radius: ExprId,
    },
    /// The outer half of a torus about description z: the rim of radius R (to the tube's
    /// centre line) thickened by a tube of radius r ≤ R: the disk rim's support point plus r n
    /// (a coin with a rounded edge, a wheel with a tyre).
    Torus {
        /// The torus's centre.
        center: [ExprId; 3],
        /// The radius R of the tube's centre line, > 0.
        radius: ExprId,
        /// The tube radius r, 0 < r ≤ R.
        tube: ExprId,
    },
    /// A paraboloid bowl `z = z₀ + (x² + y²)/(2 R)` about description z through its vertex
    /// `vertex`, R its radius of curvature at the vertex: for an outward normal n with n₃ < 0,
    /// s(n) = vertex + (−R n₁/n₃, −R n₂/n₃, R (n₁² + n₂²)/(2 n₃²)).
    Paraboloid {
        /// The vertex, the lowest point when the axis is vertical.
        vertex: [ExprId; 3],
        /// The radius of curvature R > 0 at the vertex.
        curvature_radius: ExprId,
    },
}

/// The kind of a [`Surface`], without its dimensions: what decides which attitudes its
/// support map can place.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceKind {
    /// [`Surface::Sphere`].
    Sphere,
    /// [`Surface::Ellipsoid`].
    Ellipsoid,
    /// [`Surface::DiskRim`]: singular when the disk lies flat.
    DiskRim,
    /// [`Surface::Torus`]: singular when the torus lies flat.
    Torus,
    /// [`Surface::Paraboloid`]: only while the bowl faces the table (n₃ < 0).
    Paraboloid,
}

impl SurfaceKind {
    /// The surface's name in the attribute language.
    pub fn name(self) -> &'static str {
        match self {
            SurfaceKind::Sphere => "sphere",
            SurfaceKind::Ellipsoid => "ellipsoid",
            SurfaceKind::DiskRim => "disk_rim",
            SurfaceKind::Torus => "torus",
            SurfaceKind::Paraboloid => "paraboloid",
        }
    }
}

impl Surface {
    /// The surface's name in the attribute language.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// The surface's kind.
    pub fn kind(&self) -> SurfaceKind {
        match self {
            Surface::Sphere { .. } => SurfaceKind::Sphere,
            Surface::Ellipsoid { .. } => SurfaceKind::Ellipsoid,
            Surface::DiskRim { .. } => SurfaceKind::DiskRim,
            Surface::Torus { .. } => SurfaceKind::Torus,
            Surface::Paraboloid { .. } => SurfaceKind::Paraboloid,
        }
    }

    /// The surface's placement (centre or vertex) and its lengths, with their names, in a
    /// fixed order: what [`super::ContactModel`] evaluates to check the parameters.
    pub fn dimensions(&self) -> ([ExprId; 3], Vec<(&'static str, ExprId)>) {
        match *self {
            Surface::Sphere { center, radius } | Surface::DiskRim { center, radius } => {
                (center, vec![("radius", radius)])
            }
            Surface::Ellipsoid { center, semi_axes } => (
                center,
                vec![
                    ("semi-axis a", semi_axes[0]),
                    ("semi-axis b", semi_axes[1]),
                    ("semi-axis c", semi_axes[2]),
                ],
            ),
            Surface::Torus {
                center,
                radius,
                tube,
            } => (center, vec![("radius", radius), ("tube", tube)]),
            Surface::Paraboloid {
                vertex,
                curvature_radius,
            } => (vertex, vec![("curvature radius", curvature_radius)]),
        }
    }

    /// The support point s(n): the point of the surface whose outward unit normal is `n`
    /// (body axes). `n` is assumed a unit vector; on a table it is −γ.
    ///
    /// ```
    /// use precess_core::contact::Surface;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (z, o) = (a.zero(), a.one());
    /// let r = a.parameter("r");
    /// // A sphere about the origin touches a table below it at −r ẑ.
    /// let s = Surface::Sphere { center: [z; 3], radius: r };
    /// let down = [z, z, a.neg(o)];
    /// let p = s.support(&mut a, &down)?;
    /// assert_eq!(p, [z, z, a.neg(r)]);
    /// # Ok::<(), precess_core::sym::SymError>(())
    /// ```
    ///
    /// # Errors
    /// [`SymError`] from the arithmetic (a square root or division the arena refuses).
    pub fn support(&self, arena: &mut Arena, n: &[ExprId; 3]) -> Result<[ExprId; 3], SymError> {
        match *self {
            Surface::Sphere { center, radius } => Ok(std::array::from_fn(|k| {
                let t = arena.mul(radius, n[k]);
                arena.add(center[k], t)
            })),
            Surface::Ellipsoid { center, semi_axes } => {
                let d2n: [ExprId; 3] = std::array::from_fn(|k| {
                    let a2 = arena.mul(semi_axes[k], semi_axes[k]);
                    arena.mul(a2, n[k])
                });
                let terms: Vec<ExprId> = (0..3).map(|k| arena.mul(d2n[k], n[k])).collect();
                let quad = arena.sum(&terms);
                let norm = arena.sqrt(quad)?;
                let mut out = [arena.zero(); 3];
                for k in 0..3 {
                    let t = arena.div(d2n[k], norm)?;
                    out[k] = arena.add(center[k], t);
                }
                Ok(out)
            }
            Surface::DiskRim { center, radius } => {
                let rim = rim_direction(arena, n)?;
                Ok(std::array::from_fn(|k| {
                    let t = arena.mul(radius, rim[k]);
                    arena.add(center[k], t)
                }))
            }
            Surface::Torus {
                center,
                radius,
                tube,
            } => {
                let rim = rim_direction(arena, n)?;
                Ok(std::array::from_fn(|k| {
                    let a = arena.mul(radius, rim[k]);
                    let b = arena.mul(tube, n[k]);
                    arena.sum(&[center[k], a, b])
                }))
            }
            Surface::Paraboloid {
                vertex,
                curvature_radius,
            } => {
                let mr = arena.neg(curvature_radius);
                let x = arena.mul(mr, n[0]);
                let x = arena.div(x, n[2])?;
                let y = arena.mul(mr, n[1]);
                let y = arena.div(y, n[2])?;
                let (x2, y2) = (arena.mul(x, x), arena.mul(y, y));
                let r2 = arena.add(x2, y2);
                let two_r = arena.add(curvature_radius, curvature_radius);
                let z = arena.div(r2, two_r)?;
                Ok([
                    arena.add(vertex[0], x),
                    arena.add(vertex[1], y),
                    arena.add(vertex[2], z),
                ])
            }
        }
    }
}

/// The unit vector in the disk's plane (⊥ e₃) nearest n: (n − (n·e₃) e₃)/√(n₁² + n₂²).
fn rim_direction(arena: &mut Arena, n: &[ExprId; 3]) -> Result<[ExprId; 3], SymError> {
    let (x2, y2) = (arena.mul(n[0], n[0]), arena.mul(n[1], n[1]));
    let q = arena.add(x2, y2);
    let norm = arena.sqrt(q)?;
    Ok([arena.div(n[0], norm)?, arena.div(n[1], norm)?, arena.zero()])
}
