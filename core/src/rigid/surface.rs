//! Every surface that rolls — a body's on a table, a mechanism's wheel on the floor — and its
//! support map: the point of the surface whose outward normal is a given unit vector n, in
//! closed form, so the contact point is an expression of the attitude. One geometry for both
//! scenes, with one flatness limit ([`MIN_TILT`]).
//!
//! On a horizontal table the outward normal at the contact is the downward vertical, which in
//! body axes is n = −γ, γ = Rᵀ ẑ the "Poisson vector" (the space vertical seen from the body).
//! The contact point is then `s(−γ)`, the support point of the surface in that direction. A
//! mechanism's wheel takes the same map in ground axes, with n = −up and the wheel's axle
//! turned by the body's rotation ([`Surface::support_along`]): the map commutes with
//! rotations, s_{R·S}(R n) = R s_S(n).

use thiserror::Error;

use crate::sym::{Arena, ExprId, Node, SymError};

/// The smallest tilt (rad) of a disk rim's or torus's axis from the vertical — the angle of
/// the disk's plane to the table — at which its support point is trusted; a body on a table
/// (`ContactError::FlatDisk`) and a mechanism's wheel (`MechanismError::WheelFlat`) below it
/// are refused.
///
/// Why 1e-6: the rim's direction is (n − (n·a) a)/|n − (n·a) a|, a division by the sine of
/// the tilt, so the rounding of n's components (ε absolute) becomes ε/tilt relative in the
/// contact point and more in its rates. Measured on the thin rolling disk placed exactly in
/// the closed form's variables (tests/it/rolling_once), the body on a table's accelerations
/// stay within 1.2e-12 (relative to g/r + |ω|²) at a tilt of 1e-5, 5.6e-12 at 1e-6 and
/// 4.8e-11 at 1e-7, growing as 1/tilt: 1e-6 keeps them to about 1e-11, two orders inside the
/// tight tolerances the runs use. The same disk as a mechanism's wheel matches them where its
/// chart reaches flat at a lean of ±90°; where its tilt is an Euler angle near 0 the engine's
/// sin² = 1 − cos² costs it more (1/tilt³, measured in docs/mechanisms.md).
pub const MIN_TILT: f64 = 1e-6;

/// What the shared support map refuses.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SurfaceError {
    /// An ellipsoid has three axes: turning it onto one axis alone leaves it undefined.
    #[error(
        "the {surface} has no axis of symmetry to turn onto the axis given: only a sphere, a \
         disk rim, a torus and a paraboloid have one"
    )]
    NotAxisymmetric {
        /// The surface's name.
        surface: &'static str,
    },
    /// The arithmetic refused a root or a division.
    #[error(transparent)]
    Sym(#[from] SymError),
}

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
    /// fixed order: what a body on a table evaluates to check its parameters.
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
    /// (description axes). `n` is assumed a unit vector; on a table it is −γ.
    ///
    /// ```
    /// use precess_core::rigid::Surface;
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
        let z = [arena.zero(), arena.zero(), arena.one()];
        self.support_about(arena, n, &z)
    }

    /// The support point of the surface turned about its placement so that its axis of
    /// symmetry (description z) lies along the unit vector `axis`: a mechanism's wheel, whose
    /// axle is any direction of its body, or any body read in other axes. With a = `axis`:
    ///
    /// - sphere: s(n) = c + ρ n (`axis` plays no part);
    /// - disk rim: s(n) = c + ρ d/|d|, d = n − (n·a) a (|d| the sine of the angle between n
    ///   and a, which [`MIN_TILT`] bounds);
    /// - torus: the disk rim's point of radius R, plus r n;
    /// - paraboloid: s(n) = vertex − R d/(n·a) + R |d|²/(2 (n·a)²) a, for n·a < 0.
    ///
    /// With a = ẑ these are [`Surface::support`]'s formulas term for term.
    ///
    /// ```
    /// use precess_core::rigid::Surface;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (z, o) = (a.zero(), a.one());
    /// let r = a.parameter("r");
    /// // A wheel whose axle is y, standing upright: it touches the floor at −r ẑ.
    /// let wheel = Surface::DiskRim { center: [z; 3], radius: r };
    /// let down = [z, z, a.neg(o)];
    /// let p = wheel.support_along(&mut a, &down, &[z, o, z])?;
    /// assert_eq!(p, [z, z, a.neg(r)]);
    /// # Ok::<(), precess_core::rigid::SurfaceError>(())
    /// ```
    ///
    /// # Errors
    /// [`SurfaceError::NotAxisymmetric`] for an ellipsoid; [`SurfaceError::Sym`] from the
    /// arithmetic.
    pub fn support_along(
        &self,
        arena: &mut Arena,
        n: &[ExprId; 3],
        axis: &[ExprId; 3],
    ) -> Result<[ExprId; 3], SurfaceError> {
        if self.kind() == SurfaceKind::Ellipsoid {
            return Err(SurfaceError::NotAxisymmetric {
                surface: self.name(),
            });
        }
        Ok(self.support_about(arena, n, axis)?)
    }

    /// [`Surface::support_along`] for every surface but the ellipsoid, whose map here is
    /// the description axes' whatever `axis` ([`Surface::support`] passes ẑ).
    fn support_about(
        &self,
        arena: &mut Arena,
        n: &[ExprId; 3],
        axis: &[ExprId; 3],
    ) -> Result<[ExprId; 3], SymError> {
        match *self {
            Surface::Sphere { center, radius } => Ok(std::array::from_fn(|k| {
                let t = arena.mul(radius, n[k]);
                arena.add(center[k], t)
            })),
            Surface::Ellipsoid { center, semi_axes } => {
                ellipsoid_support(arena, center, semi_axes, n)
            }
            Surface::DiskRim { center, radius } => {
                let rim = Rim::new(arena, n, axis)?;
                Ok(std::array::from_fn(|k| {
                    let t = arena.mul(radius, rim.direction[k]);
                    arena.add(center[k], t)
                }))
            }
            Surface::Torus {
                center,
                radius,
                tube,
            } => {
                let rim = Rim::new(arena, n, axis)?;
                Ok(std::array::from_fn(|k| {
                    let a = arena.mul(radius, rim.direction[k]);
                    let b = arena.mul(tube, n[k]);
                    arena.sum(&[center[k], a, b])
                }))
            }
            Surface::Paraboloid {
                vertex,
                curvature_radius,
            } => {
                let along = dot(arena, n, axis);
                let d = across(arena, n, axis, along);
                let mr = arena.neg(curvature_radius);
                let mut out = [arena.zero(); 3];
                for k in 0..3 {
                    let t = arena.mul(mr, d[k]);
                    out[k] = arena.div(t, along)?;
                }
                let (x2, y2, z2) = (
                    arena.mul(out[0], out[0]),
                    arena.mul(out[1], out[1]),
                    arena.mul(out[2], out[2]),
                );
                let r2 = arena.sum(&[x2, y2, z2]);
                let two_r = arena.add(curvature_radius, curvature_radius);
                let rise = arena.div(r2, two_r)?;
                Ok(std::array::from_fn(|k| {
                    let up = arena.mul(rise, axis[k]);
                    arena.sum(&[vertex[k], out[k], up])
                }))
            }
        }
    }
}

/// The ellipsoid's support point, description axes: c₀ + D² n / √(nᵀ D² n).
fn ellipsoid_support(
    arena: &mut Arena,
    center: [ExprId; 3],
    semi_axes: [ExprId; 3],
    n: &[ExprId; 3],
) -> Result<[ExprId; 3], SymError> {
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

/// n·a.
fn dot(arena: &mut Arena, n: &[ExprId; 3], a: &[ExprId; 3]) -> ExprId {
    let terms: Vec<ExprId> = (0..3).map(|k| arena.mul(n[k], a[k])).collect();
    arena.sum(&terms)
}

/// n − (n·a) a, each component expanded (so that a wheel's components show their
/// cancellations, and a table's, in γ, stay as they are).
fn across(arena: &mut Arena, n: &[ExprId; 3], a: &[ExprId; 3], along: ExprId) -> [ExprId; 3] {
    std::array::from_fn(|k| {
        let t = arena.mul(along, a[k]);
        let d = arena.sub(n[k], t);
        arena.expand(d)
    })
}

/// The direction of a disk rim's point for an outward normal n, about the rim's unit axis a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rim {
    /// d/|d|, d = n − (n·a) a: the unit vector in the rim's plane nearest n.
    pub direction: [ExprId; 3],
    /// |d|, the sine of the angle between n and the axis: the disk's tilt from lying flat,
    /// which must stay above [`MIN_TILT`].
    pub tilt: ExprId,
}

impl Rim {
    /// The rim's direction for `n` about `axis` (both unit vectors). |d|² = Σ d_k² is
    /// expanded; when it is a monomial square (cos² φ for a wheel whose axle only leans by φ)
    /// the root is taken exactly, so that identities such as a wheel held on the floor by
    /// its joints show; otherwise it stays a square root. For a = ẑ, d = (n₁, n₂, 0) and
    /// |d| = √(n₁² + n₂²).
    ///
    /// # Errors
    /// [`SymError`] if the root or the division is refused.
    pub fn new(arena: &mut Arena, n: &[ExprId; 3], axis: &[ExprId; 3]) -> Result<Rim, SymError> {
        let along = dot(arena, n, axis);
        let d = across(arena, n, axis, along);
        let squares: Vec<ExprId> = d.iter().map(|&x| arena.mul(x, x)).collect();
        let q = arena.sum(&squares);
        let q = arena.expand(q);
        let tilt = match monomial_root(arena, q) {
            Some(r) => r,
            None => arena.sqrt(q)?,
        };
        let mut direction = [arena.zero(); 3];
        for k in 0..3 {
            direction[k] = arena.div(d[k], tilt)?;
        }
        Ok(Rim { direction, tilt })
    }
}

/// √e exactly when e is a monomial square c · Π b_i^(2k_i) with c a rational square, the
/// root taken with each base positive.
fn monomial_root(arena: &mut Arena, e: ExprId) -> Option<ExprId> {
    match arena.node(e).clone() {
        Node::Const(r) => r.sqrt_exact().map(|root| arena.constant(root)),
        Node::Pow(b, n) if n % 2 == 0 => arena.powi(b, n / 2).ok(),
        Node::Mul(factors) => {
            let roots: Option<Vec<ExprId>> =
                factors.iter().map(|&f| monomial_root(arena, f)).collect();
            roots.map(|r| arena.product(&r))
        }
        _ => None,
    }
}
