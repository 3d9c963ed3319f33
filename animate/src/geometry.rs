//! Triangle soups of the solids, in each solid's own axes (symmetry axis along local z).
//!
//! A soup is a list of triangles with no shared vertices and no normals: glTF viewers draw a
//! primitive without normals flat-shaded (the specification asks them to compute flat normals),
//! which is what a faceted solid should look like, and it keeps the file small. Triangles are
//! wound counter-clockwise seen from outside. Each soup is split in two halves, so that a
//! solid turning about its symmetry axis shows its turn (see [`Halves`]).

/// A point in a solid's own axes.
pub(crate) type P3 = [f64; 3];

/// A triangle, counter-clockwise seen from outside.
pub(crate) type Tri = [P3; 3];

/// Facets around a circle (cylinders, disks, cones, the sphere's longitudes).
pub(crate) const SEGMENTS: usize = 32;

/// Bands from pole to pole on a sphere.
const BANDS: usize = 16;

/// The two halves of a solid, drawn in two colours: for spheres and ellipsoids the halves
/// z ≥ 0 and z < 0 (so a top turning over shows it), for solids of revolution about z the
/// halves x ≥ 0 and x < 0 (so their spin shows), each triangle by its centroid.
#[derive(Default, Debug, Clone)]
pub(crate) struct Halves {
    /// The half drawn in the part's own colour.
    pub first: Vec<Tri>,
    /// The half drawn in the complementary colour.
    pub second: Vec<Tri>,
}

/// Which coordinate splits a soup into its halves.
#[derive(Clone, Copy)]
pub(crate) enum Split {
    /// By the sign of z (spheres, ellipsoids).
    Z,
    /// By the sign of x (solids of revolution about z, boxes).
    X,
}

impl Halves {
    /// `soup` split by the sign of the `split` coordinate of each centroid.
    pub(crate) fn split(soup: Vec<Tri>, split: Split) -> Halves {
        let k = match split {
            Split::Z => 2,
            Split::X => 0,
        };
        let (first, second) = soup
            .into_iter()
            .partition(|t: &Tri| t[0][k] + t[1][k] + t[2][k] >= 0.0);
        Halves { first, second }
    }
}

/// A point on the unit circle at facet `i` of [`SEGMENTS`].
fn circle(i: usize) -> (f64, f64) {
    let a = std::f64::consts::TAU * (i % SEGMENTS) as f64 / SEGMENTS as f64;
    (a.cos(), a.sin())
}

/// The ellipsoid x²/a² + y²/b² + z²/c² = 1 (a sphere when the three are equal).
pub(crate) fn ellipsoid(semi: [f64; 3]) -> Vec<Tri> {
    let point = |band: usize, i: usize| {
        let polar = std::f64::consts::PI * band as f64 / BANDS as f64;
        let (c, s) = circle(i);
        [
            semi[0] * polar.sin() * c,
            semi[1] * polar.sin() * s,
            semi[2] * polar.cos(),
        ]
    };
    let mut out = Vec::with_capacity(2 * BANDS * SEGMENTS);
    for band in 0..BANDS {
        for i in 0..SEGMENTS {
            let (a, b) = (point(band, i), point(band, i + 1));
            let (c, d) = (point(band + 1, i), point(band + 1, i + 1));
            // The poles' degenerate triangles are left out.
            if band > 0 {
                out.push([a, c, b]);
            }
            if band + 1 < BANDS {
                out.push([b, c, d]);
            }
        }
    }
    out
}

/// A tube about z from z = z0 to z = z1 between radii `inner` (0 for a solid cylinder) and
/// `outer`, with its end faces.
pub(crate) fn tube(inner: f64, outer: f64, z0: f64, z1: f64) -> Vec<Tri> {
    let mut out = Vec::with_capacity(8 * SEGMENTS);
    for i in 0..SEGMENTS {
        let (c0, s0) = circle(i);
        let (c1, s1) = circle(i + 1);
        let at = |r: f64, c: f64, s: f64, z: f64| [r * c, r * s, z];
        let (a, b) = (at(outer, c0, s0, z0), at(outer, c1, s1, z0));
        let (c, d) = (at(outer, c0, s0, z1), at(outer, c1, s1, z1));
        out.push([a, b, d]);
        out.push([a, d, c]);
        let (ia, ib) = (at(inner, c0, s0, z0), at(inner, c1, s1, z0));
        let (ic, id) = (at(inner, c0, s0, z1), at(inner, c1, s1, z1));
        // The end faces: a fan to the axis for a solid, a ring of quads for a tube.
        out.push([c, d, id]);
        out.push([a, ib, b]);
        if inner > 0.0 {
            out.push([c, id, ic]);
            out.push([a, ia, ib]);
            // The inner wall faces the axis.
            out.push([ia, id, ib]);
            out.push([ia, ic, id]);
        }
    }
    out
}

/// A cone about z, its base of radius `radius` at z = 0 and its apex at z = `height` (at
/// z = −`height` when negative).
pub(crate) fn cone(radius: f64, height: f64) -> Vec<Tri> {
    let apex = [0.0, 0.0, height];
    let centre = [0.0, 0.0, 0.0];
    let mut out = Vec::with_capacity(2 * SEGMENTS);
    for i in 0..SEGMENTS {
        let (c0, s0) = circle(i);
        let (c1, s1) = circle(i + 1);
        let a = [radius * c0, radius * s0, 0.0];
        let b = [radius * c1, radius * s1, 0.0];
        if height >= 0.0 {
            out.push([a, b, apex]);
            out.push([a, centre, b]);
        } else {
            out.push([a, apex, b]);
            out.push([a, b, centre]);
        }
    }
    out
}

/// A torus about z: the circle of radius `radius` (the tube's centre line) thickened by a tube
/// of radius `tube`.
pub(crate) fn torus(radius: f64, tube: f64) -> Vec<Tri> {
    let point = |i: usize, j: usize| {
        let (c, s) = circle(i);
        let (cj, sj) = circle(j);
        let r = radius + tube * cj;
        [r * c, r * s, tube * sj]
    };
    let mut out = Vec::with_capacity(2 * SEGMENTS * SEGMENTS / 2);
    // Half as many facets around the tube as around the axis.
    for i in 0..SEGMENTS {
        for j in (0..SEGMENTS).step_by(2) {
            let (a, b) = (point(i, j), point(i + 1, j));
            let (c, d) = (point(i, j + 2), point(i + 1, j + 2));
            out.push([a, b, d]);
            out.push([a, d, c]);
        }
    }
    out
}

/// A box of edges `size` centred on the origin.
pub(crate) fn cuboid(size: [f64; 3]) -> Vec<Tri> {
    let h = [size[0] / 2.0, size[1] / 2.0, size[2] / 2.0];
    let v = |x: f64, y: f64, z: f64| [x * h[0], y * h[1], z * h[2]];
    let mut out = Vec::with_capacity(12);
    // Each face: its outward axis k, the sign s, and two in-plane axes ordered so that
    // (u, w, k) is right-handed for s = +1.
    for (k, u, w) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
        for s in [1.0, -1.0] {
            let corner = |a: f64, b: f64| {
                let mut p = [0.0; 3];
                p[k] = s;
                p[u] = a;
                p[w] = b * s;
                v(p[0], p[1], p[2])
            };
            let (p00, p10, p11, p01) = (
                corner(-1.0, -1.0),
                corner(1.0, -1.0),
                corner(1.0, 1.0),
                corner(-1.0, 1.0),
            );
            out.push([p00, p10, p11]);
            out.push([p00, p11, p01]);
        }
    }
    out
}

/// A paraboloid bowl z = (x² + y²)/(2 ρ) about z up to the height `depth`.
pub(crate) fn paraboloid(curvature_radius: f64, depth: f64) -> Vec<Tri> {
    let rim = (2.0 * curvature_radius * depth).sqrt();
    let point = |ring: usize, i: usize| {
        let r = rim * ring as f64 / 8.0;
        let (c, s) = circle(i);
        [r * c, r * s, r * r / (2.0 * curvature_radius)]
    };
    let mut out = Vec::new();
    for ring in 0..8 {
        for i in 0..SEGMENTS {
            let (a, b) = (point(ring, i), point(ring, i + 1));
            let (c, d) = (point(ring + 1, i), point(ring + 1, i + 1));
            if ring > 0 {
                out.push([a, b, d]);
            }
            out.push([a, d, c]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The signed volume of a closed soup, Σ a·(b × c)/6 (the divergence theorem): positive
    /// for outward winding, and close to the solid's volume.
    fn volume(soup: &[Tri]) -> f64 {
        soup.iter()
            .map(|[a, b, c]| {
                let cross = [
                    b[1] * c[2] - b[2] * c[1],
                    b[2] * c[0] - b[0] * c[2],
                    b[0] * c[1] - b[1] * c[0],
                ];
                (a[0] * cross[0] + a[1] * cross[1] + a[2] * cross[2]) / 6.0
            })
            .sum()
    }

    #[test]
    fn closed_solids_are_wound_outwards_with_their_volumes() {
        use std::f64::consts::PI;
        // Polyhedra inscribed in the solids: the volumes approach from below, within the
        // faceting's few per cent (a 32-gon holds 0.64 % less area than its circle).
        let cases: [(&str, Vec<Tri>, f64); 5] = [
            (
                "ellipsoid",
                ellipsoid([1.0, 2.0, 3.0]),
                4.0 / 3.0 * PI * 6.0,
            ),
            ("cylinder", tube(0.0, 1.0, -1.0, 1.0), PI * 2.0),
            ("tube", tube(0.5, 1.0, 0.0, 2.0), PI * 0.75 * 2.0),
            ("cone", cone(1.0, 3.0), PI),
            ("cuboid", cuboid([1.0, 2.0, 3.0]), 6.0),
        ];
        for (name, soup, exact) in cases {
            let v = volume(&soup);
            assert!(
                v > 0.0 && v <= exact * (1.0 + 1e-12),
                "{name}: {v} vs {exact}"
            );
            assert!(v > 0.97 * exact, "{name}: {v} vs {exact}");
        }
        let reversed = volume(&cone(1.0, -3.0));
        assert!((reversed - PI).abs() < 0.03 * PI, "{reversed}");
        // Pappus: V = 2π R · π r².
        let t = volume(&torus(2.0, 0.5));
        let exact = 2.0 * PI * 2.0 * PI * 0.25;
        assert!(t > 0.9 * exact && t < exact, "{t} vs {exact}");
    }

    #[test]
    fn halves_split_by_the_centroid() {
        let h = Halves::split(ellipsoid([1.0; 3]), Split::Z);
        assert_eq!(h.first.len(), h.second.len());
        assert!(h.first.iter().flatten().all(|p| p[2] >= -1e-12));
        assert!(h.second.iter().flatten().all(|p| p[2] <= 1e-12));
    }
}
