//! Spatial algebra written as pairs of symbolic 3-vectors: motions (ω, v), forces (n, f) and
//! articulated inertias as 3×3 blocks, each entry an unexpanded expression so products with
//! exact zeros (an axis along x, a centre on an axis) vanish in the canonical constructors.

// Index loops over 3×3 blocks read as the matrix algebra they implement.
#![allow(clippy::needless_range_loop)]

use super::bind::Binder;
use crate::sym::mat3::{self, Mat3};
use crate::sym::{Arena, ExprId};

/// A 3-vector of expressions.
pub(crate) type V3 = [ExprId; 3];

pub(crate) fn add3(a: &mut Arena, x: &V3, y: &V3) -> V3 {
    [a.add(x[0], y[0]), a.add(x[1], y[1]), a.add(x[2], y[2])]
}

pub(crate) fn sub3(a: &mut Arena, x: &V3, y: &V3) -> V3 {
    [a.sub(x[0], y[0]), a.sub(x[1], y[1]), a.sub(x[2], y[2])]
}

pub(crate) fn scale3(a: &mut Arena, s: ExprId, x: &V3) -> V3 {
    [a.mul(s, x[0]), a.mul(s, x[1]), a.mul(s, x[2])]
}

pub(crate) fn neg3(a: &mut Arena, x: &V3) -> V3 {
    [a.neg(x[0]), a.neg(x[1]), a.neg(x[2])]
}

/// `mᵀ v`.
pub(crate) fn mat_t_vec(a: &mut Arena, m: &Mat3, v: &V3) -> V3 {
    mat3::mat_vec(a, &mat3::transpose(m), v)
}

/// A motion (ω, v) or a force (n, f): angular part first.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pair {
    pub ang: V3,
    pub lin: V3,
}

impl Pair {
    pub(crate) fn zero(a: &Arena) -> Pair {
        Pair {
            ang: [a.zero(); 3],
            lin: [a.zero(); 3],
        }
    }

    pub(crate) fn add(&self, a: &mut Arena, o: &Pair) -> Pair {
        Pair {
            ang: add3(a, &self.ang, &o.ang),
            lin: add3(a, &self.lin, &o.lin),
        }
    }

    /// Every entry bound to its symbol (see `bind.rs`), so the next link holds it as one atom.
    pub(crate) fn bound(&self, a: &mut Arena, binder: &mut Binder) -> Pair {
        Pair {
            ang: binder.bind3(a, &self.ang),
            lin: binder.bind3(a, &self.lin),
        }
    }
}

/// A symmetric spatial inertia `[[A, B], [Bᵀ, C]]` acting on motions (ω, v):
/// n = A ω + B v, f = Bᵀ ω + C v. A and C are kept symmetric entry by entry.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Inertia {
    pub a: Mat3,
    pub b: Mat3,
    pub c: Mat3,
}

/// The 3×3 matrix `[x]×` with `[x]× y = x × y`.
pub(crate) fn cross_matrix(a: &mut Arena, x: &V3) -> Mat3 {
    let z = a.zero();
    let n = neg3(a, x);
    [[z, n[2], x[1]], [x[2], z, n[0]], [n[1], x[0], z]]
}

/// The symmetric part of a matrix known to be symmetric: the upper triangle mirrored, so
/// equal entries are equal ids.
fn mirror(m: &mut Mat3) {
    for i in 0..3 {
        for j in 0..i {
            m[i][j] = m[j][i];
        }
    }
}

/// `x yᵀ` summed over pairs, entries of the upper triangle only when `symmetric`.
fn outer(a: &mut Arena, x: &V3, y: &V3, symmetric: bool) -> Mat3 {
    let mut m = [[a.zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            if !symmetric || j >= i {
                m[i][j] = a.mul(x[i], y[j]);
            }
        }
    }
    if symmetric {
        mirror(&mut m);
    }
    m
}

fn mat_add(a: &mut Arena, x: &Mat3, y: &Mat3, symmetric: bool) -> Mat3 {
    let mut m = [[a.zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            if !symmetric || j >= i {
                m[i][j] = a.add(x[i][j], y[i][j]);
            }
        }
    }
    if symmetric {
        mirror(&mut m);
    }
    m
}

fn mat_sub(a: &mut Arena, x: &Mat3, y: &Mat3, symmetric: bool) -> Mat3 {
    let mut m = [[a.zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            if !symmetric || j >= i {
                m[i][j] = a.sub(x[i][j], y[i][j]);
            }
        }
    }
    if symmetric {
        mirror(&mut m);
    }
    m
}

/// `r m rᵀ` (symmetric result) or `r m rᵀ` for a general `m`.
fn rotate(a: &mut Arena, r: &Mat3, m: &Mat3, symmetric: bool) -> Mat3 {
    let rm = mat3::mat_mul(a, r, m);
    let mut out = [[a.zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            if !symmetric || j >= i {
                let terms: Vec<ExprId> = (0..3).map(|k| a.mul(rm[i][k], r[j][k])).collect();
                out[i][j] = a.sum(&terms);
            }
        }
    }
    if symmetric {
        mirror(&mut out);
    }
    out
}

impl Inertia {
    /// Every entry bound to its symbol (see `bind.rs`), so the next link holds it as one atom.
    pub(crate) fn bound(&self, a: &mut Arena, binder: &mut Binder) -> Inertia {
        let mut out = *self;
        for (o, m) in [
            (&mut out.a, &self.a),
            (&mut out.b, &self.b),
            (&mut out.c, &self.c),
        ] {
            for (orow, mrow) in o.iter_mut().zip(m) {
                for (oe, &me) in orow.iter_mut().zip(mrow) {
                    *oe = binder.bind(a, me);
                }
            }
        }
        out
    }

    /// The rigid-body inertia about a frame's origin: mass m, first moment h = m c, rotational
    /// inertia I_O about the origin: `[[I_O, [h]×], [[h]×ᵀ, m 1]]`.
    pub(crate) fn rigid(a: &mut Arena, m: ExprId, h: &V3, inertia_origin: &Mat3) -> Inertia {
        let z = a.zero();
        Inertia {
            a: *inertia_origin,
            b: cross_matrix(a, h),
            c: [[m, z, z], [z, m, z], [z, z, m]],
        }
    }

    pub(crate) fn zero(a: &Arena) -> Inertia {
        let z = [[a.zero(); 3]; 3];
        Inertia { a: z, b: z, c: z }
    }

    /// `I x` for a motion x.
    pub(crate) fn apply(&self, a: &mut Arena, x: &Pair) -> Pair {
        let aw = mat3::mat_vec(a, &self.a, &x.ang);
        let bv = mat3::mat_vec(a, &self.b, &x.lin);
        let btw = mat_t_vec(a, &self.b, &x.ang);
        let cv = mat3::mat_vec(a, &self.c, &x.lin);
        Pair {
            ang: add3(a, &aw, &bv),
            lin: add3(a, &btw, &cv),
        }
    }

    pub(crate) fn add(&self, a: &mut Arena, o: &Inertia) -> Inertia {
        Inertia {
            a: mat_add(a, &self.a, &o.a, true),
            b: mat_add(a, &self.b, &o.b, false),
            c: mat_add(a, &self.c, &o.c, true),
        }
    }

    /// `I − w uᵀ` for the force pair u = I S and w = u / D (a symmetric rank-one update).
    pub(crate) fn minus_outer(&self, a: &mut Arena, w: &Pair, u: &Pair) -> Inertia {
        let wa = outer(a, &w.ang, &u.ang, true);
        let wb = outer(a, &w.ang, &u.lin, false);
        let wc = outer(a, &w.lin, &u.lin, true);
        Inertia {
            a: mat_sub(a, &self.a, &wa, true),
            b: mat_sub(a, &self.b, &wb, false),
            c: mat_sub(a, &self.c, &wc, true),
        }
    }

    /// The same inertia seen from the parent frame: its blocks turned by `r` (child → parent
    /// axes, `None` for none), then moved from the child's origin to the parent's, the child
    /// origin sitting at `p` in the parent frame:
    /// A' = A − B[p] + [p]Bᵀ − [p]C[p], B' = B + [p]C, C' = C.
    pub(crate) fn seen_from_parent(
        &self,
        a: &mut Arena,
        binder: &mut Binder,
        r: Option<&Turn>,
        p: &V3,
    ) -> Inertia {
        let (ra, rb, rc) = match r {
            Some(r) => {
                let turned = match r.about {
                    Some(ref about) => Inertia {
                        a: about.rotate(a, binder, &self.a, true),
                        b: about.rotate(a, binder, &self.b, false),
                        c: about.rotate(a, binder, &self.c, true),
                    },
                    None => Inertia {
                        a: rotate(a, &r.matrix, &self.a, true),
                        b: rotate(a, &r.matrix, &self.b, false),
                        c: rotate(a, &r.matrix, &self.c, true),
                    },
                };
                // Bound before the shift, so the shift's rational lengths multiply one atom
                // per entry instead of being distributed over each entry's rotated terms.
                let turned = turned.bound(a, binder);
                (turned.a, turned.b, turned.c)
            }
            None => (self.a, self.b, self.c),
        };
        let px = cross_matrix(a, p);
        let pc = mat3::mat_mul(a, &px, &rc);
        let b_new = mat_add(a, &rb, &pc, false);
        // A − B[p] + [p]Bᵀ − [p]C[p] = A + [p]Bᵀ + ([p]Bᵀ)ᵀ − [p]C[p], upper triangle only.
        let pbt = mat3::mat_mul(a, &px, &mat3::transpose(&rb));
        let pcp = mat3::mat_mul(a, &pc, &px);
        let mut a_new = [[a.zero(); 3]; 3];
        for i in 0..3 {
            for j in i..3 {
                let s = a.sum(&[ra[i][j], pbt[i][j], pbt[j][i]]);
                a_new[i][j] = a.sub(s, pcp[i][j]);
            }
        }
        mirror(&mut a_new);
        Inertia {
            a: a_new,
            b: b_new,
            c: rc,
        }
    }
}

/// A force (n, f) at the child's origin in child axes, seen at the parent's origin in parent
/// axes: f' = r f, n' = r n + p × f'.
pub(crate) fn force_to_parent(
    a: &mut Arena,
    binder: &mut Binder,
    r: Option<&Turn>,
    p: &V3,
    x: &Pair,
) -> Pair {
    let (n, f) = match r {
        Some(r) => {
            let turned = Pair {
                ang: mat3::mat_vec(a, &r.matrix, &x.ang),
                lin: mat3::mat_vec(a, &r.matrix, &x.lin),
            };
            let turned = turned.bound(a, binder);
            (turned.ang, turned.lin)
        }
        None => (x.ang, x.lin),
    };
    let pf = mat3::cross(a, p, &f);
    Pair {
        ang: add3(a, &n, &pf),
        lin: f,
    }
}

/// A motion (ω, v) at the parent's origin in parent axes, seen at the child's origin in child
/// axes: ω' = rᵀ ω, v' = rᵀ (v + ω × p).
pub(crate) fn motion_to_child(a: &mut Arena, r: Option<&Turn>, p: &V3, x: &Pair) -> Pair {
    let wp = mat3::cross(a, &x.ang, p);
    let v = add3(a, &x.lin, &wp);
    match r {
        Some(r) => Pair {
            ang: mat_t_vec(a, &r.matrix, &x.ang),
            lin: mat_t_vec(a, &r.matrix, &v),
        },
        None => Pair { ang: x.ang, lin: v },
    }
}

/// The spatial motion cross product `x ×ₘ y = (ω × ω_y, ω × v_y + v × ω_y)`.
pub(crate) fn cross_motion(a: &mut Arena, x: &Pair, y: &Pair) -> Pair {
    let ang = mat3::cross(a, &x.ang, &y.ang);
    let l1 = mat3::cross(a, &x.ang, &y.lin);
    let l2 = mat3::cross(a, &x.lin, &y.ang);
    Pair {
        ang,
        lin: add3(a, &l1, &l2),
    }
}

/// `x · y` of a force and a motion (or of two pairs), both parts.
pub(crate) fn dot_pair(a: &mut Arena, x: &Pair, y: &Pair) -> ExprId {
    let d1 = mat3::dot(a, &x.ang, &y.ang);
    let d2 = mat3::dot(a, &x.lin, &y.lin);
    a.add(d1, d2)
}

/// The rotation by angle q (sine s, cosine c) about the unit axis k, child → parent axes:
/// `c 1 + s [k]× + (1 − c) k kᵀ`.
pub(crate) fn axis_rotation(a: &mut Arena, k: &V3, s: ExprId, c: ExprId) -> Mat3 {
    let one = a.one();
    let one_minus_c = a.sub(one, c);
    let kx = cross_matrix(a, k);
    let mut r = [[a.zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let diag = if i == j { c } else { a.zero() };
            let skew = a.mul(s, kx[i][j]);
            let kk = a.product(&[one_minus_c, k[i], k[j]]);
            r[i][j] = a.sum(&[diag, skew, kk]);
        }
    }
    r
}

/// k if `axis` is exactly the k-th coordinate axis e_k.
pub(crate) fn unit_axis(a: &Arena, axis: &V3) -> Option<usize> {
    let (zero, one) = (a.zero(), a.one());
    (0..3).find(|&k| {
        axis.iter()
            .enumerate()
            .all(|(m, &e)| e == if m == k { one } else { zero })
    })
}

/// A joint's rotation (child → parent axes) and, when its axis is a coordinate axis, the
/// bound scalars of the cheap form of `r m rᵀ` ([`AxisTurn`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Turn {
    pub matrix: Mat3,
    pub about: Option<AxisTurn>,
}

/// A rotation by q about coordinate axis k, with the products of sin q = s and cos q = c that
/// turning a 3×3 block needs, each bound once per joint.
///
/// With (k, i, j) cyclic, `r m rᵀ` leaves m_kk, turns row k and column k as plane vectors,
/// and changes the i–j block by
/// m′_ii = m_ii − t, m′_jj = m_jj + t, m′_ij = m_ij + u, m′_ji = m_ji + u, where
/// Δ = m_ii − m_jj, ρ = m_ij + m_ji, t = s² Δ + s c ρ, u = s c Δ − s² ρ
/// (12 operations for the block instead of 4 rows of 2×2 products; 10 when m is symmetric).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AxisTurn {
    k: usize,
    s: ExprId,
    c: ExprId,
    ss: ExprId,
    sc: ExprId,
    two_ss: ExprId,
    two_sc: ExprId,
}

impl Turn {
    /// The rotation by q (sine s, cosine c) about the unit axis `axis`.
    pub(crate) fn new(a: &mut Arena, binder: &mut Binder, axis: &V3, s: ExprId, c: ExprId) -> Turn {
        let matrix = axis_rotation(a, axis, s, c);
        let about = unit_axis(a, axis).map(|k| {
            let ss = a.mul(s, s);
            let ss = binder.bind(a, ss);
            let sc = a.mul(s, c);
            let sc = binder.bind(a, sc);
            let two = a.integer(2);
            let two_ss = a.mul(two, ss);
            let two_ss = binder.bind(a, two_ss);
            let two_sc = a.mul(two, sc);
            let two_sc = binder.bind(a, two_sc);
            AxisTurn {
                k,
                s,
                c,
                ss,
                sc,
                two_ss,
                two_sc,
            }
        });
        Turn { matrix, about }
    }
}

impl AxisTurn {
    /// `r m rᵀ`, symmetric when `symmetric` (then only m's upper triangle is read).
    fn rotate(&self, a: &mut Arena, binder: &mut Binder, m: &Mat3, symmetric: bool) -> Mat3 {
        let (k, i, j) = (self.k, (self.k + 1) % 3, (self.k + 2) % 3);
        let (s, c) = (self.s, self.c);
        let mut m = *m;
        if symmetric {
            mirror(&mut m);
        }
        let mut out = m;
        // Row k and column k: plane rotations of (m_ki, m_kj) and (m_ik, m_jk).
        let plane = |a: &mut Arena, x: ExprId, y: ExprId| {
            let cx = a.mul(c, x);
            let sy = a.mul(s, y);
            let sx = a.mul(s, x);
            let cy = a.mul(c, y);
            (a.sub(cx, sy), a.add(sx, cy))
        };
        let (ki, kj) = plane(a, m[k][i], m[k][j]);
        out[k][i] = ki;
        out[k][j] = kj;
        if symmetric {
            out[i][k] = ki;
            out[j][k] = kj;
        } else {
            let (ik, jk) = plane(a, m[i][k], m[j][k]);
            out[i][k] = ik;
            out[j][k] = jk;
        }
        let delta = a.sub(m[i][i], m[j][j]);
        let (t, u) = if symmetric {
            let t1 = a.mul(self.ss, delta);
            let t2 = a.mul(self.two_sc, m[i][j]);
            let u1 = a.mul(self.sc, delta);
            let u2 = a.mul(self.two_ss, m[i][j]);
            (a.add(t1, t2), a.sub(u1, u2))
        } else {
            let rho = a.add(m[i][j], m[j][i]);
            let t1 = a.mul(self.ss, delta);
            let t2 = a.mul(self.sc, rho);
            let u1 = a.mul(self.sc, delta);
            let u2 = a.mul(self.ss, rho);
            (a.add(t1, t2), a.sub(u1, u2))
        };
        let (t, u) = (binder.bind(a, t), binder.bind(a, u));
        out[i][i] = a.sub(m[i][i], t);
        out[j][j] = a.add(m[j][j], t);
        out[i][j] = a.add(m[i][j], u);
        out[j][i] = if symmetric {
            out[i][j]
        } else {
            a.add(m[j][i], u)
        };
        out
    }
}
