//! Bodies as lattices of point masses, and their tensors summed directly: the independent
//! values the body tests compare the closed forms with. They live here rather than in the
//! test crates because the tests compile without optimisation and these sums run over
//! millions of particles: the closures a caller passes are `&dyn`, so that every loop is
//! compiled here, once, optimised.

use precess::nalgebra::{Matrix3, Vector3};

/// A weighted point mass.
pub type Particle = (f64, Vector3<f64>);

/// I = Σ m (r² E − x xᵀ) about `o`, summed directly.
pub fn tensor_about(ps: &[Particle], o: &Vector3<f64>) -> Matrix3<f64> {
    let mut t = Matrix3::zeros();
    for (m, x) in ps {
        let d = x - o;
        t += *m * (Matrix3::identity() * d.norm_squared() - d * d.transpose());
    }
    t
}

/// Total mass and centre of mass.
pub fn mass_center(ps: &[Particle]) -> (f64, Vector3<f64>) {
    let m: f64 = ps.iter().map(|p| p.0).sum();
    let s: Vector3<f64> = ps.iter().map(|p| p.1 * p.0).sum();
    (m, s / m)
}

/// Rescales the weights so they add up to `mass`.
pub fn normalise(mut ps: Vec<Particle>, mass: f64) -> Vec<Particle> {
    let total: f64 = ps.iter().map(|p| p.0).sum();
    for p in &mut ps {
        p.0 *= mass / total;
    }
    ps
}

/// Midpoints of `n` equal cells of [a, b].
pub fn mids(a: f64, b: f64, n: usize) -> impl Iterator<Item = f64> + Clone {
    let h = (b - a) / n as f64;
    (0..n).map(move |i| a + (i as f64 + 0.5) * h)
}

/// A uniform Cartesian lattice of the box [−a/2, a/2] × [−b/2, b/2] × [−c/2, c/2].
pub fn cuboid(m: f64, a: f64, b: f64, c: f64, n: usize) -> Vec<Particle> {
    let mut ps = Vec::new();
    for x in mids(-a / 2.0, a / 2.0, n) {
        for y in mids(-b / 2.0, b / 2.0, n) {
            for z in mids(-c / 2.0, c / 2.0, n) {
                ps.push((1.0, Vector3::new(x, y, z)));
            }
        }
    }
    normalise(ps, m)
}

/// A solid of revolution about z between z0 and z1, radius from `inner(z)` to `outer(z)`,
/// as a polar lattice weighted by r (the volume element r dr dθ dz).
pub fn revolution(
    m: f64,
    z0: f64,
    z1: f64,
    inner: &dyn Fn(f64) -> f64,
    outer: &dyn Fn(f64) -> f64,
    n: usize,
) -> Vec<Particle> {
    let mut ps = Vec::new();
    for z in mids(z0, z1, n) {
        let (r0, r1) = (inner(z), outer(z));
        for r in mids(r0, r1, n) {
            for t in mids(0.0, std::f64::consts::TAU, n) {
                ps.push((r * (r1 - r0), Vector3::new(r * t.cos(), r * t.sin(), z)));
            }
        }
    }
    normalise(ps, m)
}

/// A solid ellipsoid with semi-axes a, b, c: a ball lattice in spherical coordinates
/// (weight ρ² sin θ), stretched.
pub fn ellipsoid(m: f64, a: f64, b: f64, c: f64, n: usize) -> Vec<Particle> {
    let mut ps = Vec::new();
    for rho in mids(0.0, 1.0, n) {
        for th in mids(0.0, std::f64::consts::PI, n) {
            for ph in mids(0.0, std::f64::consts::TAU, n) {
                let u = Vector3::new(th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos());
                ps.push((
                    rho * rho * th.sin(),
                    Vector3::new(a * u.x, b * u.y, c * u.z) * rho,
                ));
            }
        }
    }
    normalise(ps, m)
}

/// A thin spherical shell: particles on the sphere, weight sin θ.
pub fn shell(m: f64, r: f64, n: usize) -> Vec<Particle> {
    let mut ps = Vec::new();
    for th in mids(0.0, std::f64::consts::PI, n) {
        for ph in mids(0.0, std::f64::consts::TAU, 2 * n) {
            let u = Vector3::new(th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos());
            ps.push((th.sin(), u * r));
        }
    }
    normalise(ps, m)
}

/// A thin disk (normal z): polar lattice in the plane, weight r.
pub fn disk(m: f64, radius: f64, n: usize) -> Vec<Particle> {
    let mut ps = Vec::new();
    for r in mids(0.0, radius, n) {
        for t in mids(0.0, std::f64::consts::TAU, n) {
            ps.push((r, Vector3::new(r * t.cos(), r * t.sin(), 0.0)));
        }
    }
    normalise(ps, m)
}

/// A thin ring (normal z).
pub fn ring(m: f64, r: f64, n: usize) -> Vec<Particle> {
    let ps = mids(0.0, std::f64::consts::TAU, n)
        .map(|t| (1.0, Vector3::new(r * t.cos(), r * t.sin(), 0.0)))
        .collect();
    normalise(ps, m)
}

/// A thin rod along z, centred.
pub fn rod(m: f64, l: f64, n: usize) -> Vec<Particle> {
    let ps = mids(-l / 2.0, l / 2.0, n)
        .map(|z| (1.0, Vector3::new(0.0, 0.0, z)))
        .collect();
    normalise(ps, m)
}

/// Moves every particle by `d`.
pub fn shifted(ps: &[Particle], d: Vector3<f64>) -> Vec<Particle> {
    ps.iter().map(|(m, x)| (*m, x + d)).collect()
}

/// Lays particles described with z as their axis along x (z → x, x → y, y → z: a proper
/// rotation).
pub fn z_to_x(ps: &[Particle]) -> Vec<Particle> {
    ps.iter()
        .map(|(m, x)| (*m, Vector3::new(x.z, x.x, x.y)))
        .collect()
}

/// Equal particles on a uniform cubic grid of the box [−h₀, h₀] × [−h₁, h₁] × [−h₂, h₂],
/// kept where `inside` holds: the plainest lattice.
pub fn cubic_lattice(
    m: f64,
    half: [f64; 3],
    n: usize,
    inside: &dyn Fn(Vector3<f64>) -> bool,
) -> Vec<Particle> {
    let mut ps = Vec::new();
    for x in mids(-half[0], half[0], n) {
        for y in mids(-half[1], half[1], n) {
            for z in mids(-half[2], half[2], n) {
                let p = Vector3::new(x, y, z);
                if inside(p) {
                    ps.push((1.0, p));
                }
            }
        }
    }
    normalise(ps, m)
}

/// The particles turned by `r` and then moved to `at`.
pub fn placed(ps: &[Particle], r: &Matrix3<f64>, at: &Vector3<f64>) -> Vec<Particle> {
    ps.iter().map(|(m, x)| (*m, r * x + at)).collect()
}
