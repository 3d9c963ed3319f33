//! Root isolation of a polynomial on [0, 1] with a guarantee: the Bernstein form with a
//! rigorous bound on the rounding of each coefficient, Descartes' rule of signs on it, and
//! de Casteljau bisection (the Vincent–Collins–Akritas method in Bernstein form, as heyoka
//! isolates the roots of an event's Taylor polynomial).
//!
//! q(s) = Σₖ aₖ sᵏ on [0, 1] has the Bernstein coefficients bᵢ = Σ_{k≤i} C(i,k)/C(n,k) aₖ,
//! q = Σᵢ bᵢ C(n,i) sⁱ(1 − s)ⁿ⁻ⁱ. Descartes' rule for this form: the number of roots of q in
//! (0, 1) is at most the number v of sign changes of b₀ … bₙ, and has its parity. So v = 0
//! proves the piece rootless and v = 1 proves exactly one root inside, with q(0) = b₀ and
//! q(1) = bₙ of opposite signs. Otherwise the piece is halved (de Casteljau at ½ gives both
//! halves' coefficients) until every piece is one or the other.
//!
//! Rounding cannot fake a proof: each coefficient carries a bound eᵢ ≥ |bᵢ − b̂ᵢ| on the
//! error of the computed b̂ᵢ (the conversion and every halving, under the standard model of
//! floating-point arithmetic, round-to-nearest, no underflow), and a sign counts only where
//! |b̂ᵢ| > eᵢ. A piece with a coefficient of uncertain sign is halved again; one that is
//! still undecided after [`MAX_DEPTH`] halvings (2⁻⁵⁰ of the step: a multiple root, a cluster
//! of roots, or a polynomial within its rounding of 0) is reported as such, an
//! [`Piece::Unresolved`] piece, for the caller to judge by the signs at its ends. A piece whose
//! every coefficient is of uncertain sign is reported at once, whatever its width (q is
//! indistinguishable from 0 there). At most [`MAX_PIECES`] pieces are examined per call;
//! past that (never met on a polynomial whose roots are not within rounding of each other)
//! what is left is reported as unresolved pieces.

/// Halvings of [0, 1], at most: a piece is never shorter than 2⁻⁵⁰, about 4 ulps of the
/// step's start for a step as long as its start time.
pub(crate) const MAX_DEPTH: u32 = 50;

/// Pieces examined per call, at most (each costs n²/2 additions for degree n).
pub(crate) const MAX_PIECES: usize = 1024;

/// The unit roundoff 2⁻⁵³ with a margin for the rounding of the bounds themselves.
const U: f64 = 1.01 * f64::EPSILON / 2.0;

/// A piece [lo, hi] of [0, 1] that the isolation reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Piece {
    /// Exactly one root of q in the open piece, none at its ends, and q has opposite signs
    /// at the ends.
    Isolated(f64, f64),
    /// Undecided: roots closer than the piece, a multiple root, or q within its rounding of
    /// 0; the sign of q may change here any number of times that the ends' signs allow.
    Unresolved(f64, f64),
}

impl Piece {
    /// The piece's ends.
    pub(crate) fn ends(self) -> (f64, f64) {
        match self {
            Piece::Isolated(lo, hi) | Piece::Unresolved(lo, hi) => (lo, hi),
        }
    }
}

/// Scratch of [`isolate`], kept across calls so that isolating allocates nothing once the
/// buffers have grown to the degree.
#[derive(Debug, Clone, Default)]
pub(crate) struct Isolator {
    /// The pieces still to examine: (lo, hi, depth); their coefficients and bounds are in
    /// `pool`, 2(n + 1) values each, in the same order.
    stack: Vec<(f64, f64, u32)>,
    pool: Vec<f64>,
    /// The piece being examined, and the two halves.
    work: Vec<f64>,
    left: Vec<f64>,
    right: Vec<f64>,
    /// 1/C(n, k) for the degree n of the last call (rebuilt when the degree changes).
    inv: Vec<f64>,
}

/// The Bernstein coefficients of Σ aₖ sᵏ on [0, 1] into `b[..=n]` and the bounds of their
/// rounding into `e[..=n]` (n = a.len() − 1), with `rel` the relative error already carried
/// by each aₖ in units of [`U`] (the caller's scaling of the coefficients), and `inv` the
/// table 1/C(n, k).
///
/// bᵢ = Σ_{k≤i} C(i, k) dₖ with dₖ = aₖ/C(n, k) is the binomial transform of d, computed
/// by n passes of neighbouring sums (pass j adds entry i − 1 to entry i for i > j, from the
/// top down, Pascal's rule C(i, k) = C(i − 1, k) + C(i − 1, k − 1)): n²/2 additions, no
/// division, the additions of one pass independent of each other. The same passes on |dₖ|
/// give mᵢ = Σₖ C(i, k)|dₖ|. Each term of bᵢ goes through at most n additions after its
/// product, so |bᵢ − b̂ᵢ| ≤ γ·mᵢ with γ = (n + 4 + rel)·2⁻⁵³ covering the additions, the
/// product and `rel` (which includes the rounding of 1/C(n, k)).
fn bernstein(a: &[f64], rel: f64, inv: &[f64], b: &mut [f64], e: &mut [f64]) {
    let n = a.len() - 1;
    for ((bk, ek), (&ak, &ik)) in b.iter_mut().zip(e.iter_mut()).zip(a.iter().zip(inv)) {
        *bk = ak * ik;
        *ek = bk.abs();
    }
    for j in 0..n {
        for i in (j + 1..=n).rev() {
            b[i] += b[i - 1];
            e[i] += e[i - 1];
        }
    }
    let factor = (n as f64 + 4.0 + rel) * U;
    for ei in e.iter_mut().take(n + 1) {
        *ei *= factor;
    }
}

/// 1/C(n, k), k = 0 … n, into `inv`, from C(n, k) = C(n, k − 1)(n − k + 1)/k: entry k
/// carries at most 2k + 1 roundings, which [`Isolator::isolate`] adds to `rel`.
fn inverse_binomials(n: usize, inv: &mut Vec<f64>) {
    inv.clear();
    let mut c = 1.0f64;
    inv.push(1.0);
    for k in 1..=n {
        c = c * (n + 1 - k) as f64 / k as f64;
        inv.push(1.0 / c);
    }
}

/// Signs that count: +1, −1, or 0 where |b| ≤ e. Returns (variations, uncertain, all
/// uncertain).
fn signs(b: &[f64], e: &[f64]) -> (usize, bool, bool) {
    let (mut last, mut v, mut uncertain, mut all) = (0i8, 0, false, true);
    for (&bi, &ei) in b.iter().zip(e) {
        let s = if bi > ei {
            1
        } else if bi < -ei {
            -1
        } else {
            uncertain = true;
            continue;
        };
        all = false;
        if last != 0 && s != last {
            v += 1;
        }
        last = s;
    }
    (v, uncertain, all)
}

/// Halves a piece: the coefficients and bounds of [lo, mid] and [mid, hi] from those of
/// [lo, hi] (`w` = b then e, each n + 1 long; `w` is overwritten).
fn halve(w: &mut [f64], left: &mut [f64], right: &mut [f64]) {
    let m = w.len() / 2 - 1;
    let (b, e) = w.split_at_mut(m + 1);
    let (lb, le) = left.split_at_mut(m + 1);
    let (rb, re) = right.split_at_mut(m + 1);
    (lb[0], le[0], rb[m], re[m]) = (b[0], e[0], b[m], e[m]);
    for r in 1..=m {
        for i in 0..=m - r {
            // (x + y)/2 rounds once (the halving is exact); the bound averages and adds it.
            b[i] = 0.5 * (b[i] + b[i + 1]);
            e[i] = 0.5 * (e[i] + e[i + 1]) + U * b[i].abs();
        }
        (lb[r], le[r], rb[m - r], re[m - r]) = (b[0], e[0], b[m - r], e[m - r]);
    }
}

impl Isolator {
    /// Appends to `out`, in ascending order, the pieces of [0, 1] outside which
    /// q(s) = Σ aₖ sᵏ has no root (proved on its Bernstein form, rounding bounded), each
    /// isolated or unresolved (see the module's docs); `rel` is the relative error each
    /// aₖ already carries, in units of 2⁻⁵³. The pieces are disjoint and touch only at
    /// their ends; a root at 0 or 1 lies in a piece that ends there.
    pub(crate) fn isolate(&mut self, a: &[f64], rel: f64, out: &mut Vec<Piece>) {
        let Some(n) = a.len().checked_sub(1) else {
            return;
        };
        let w = 2 * (n + 1);
        for v in [&mut self.work, &mut self.left, &mut self.right] {
            v.clear();
            v.resize(w, 0.0);
        }
        self.stack.clear();
        self.pool.clear();
        self.pool.resize(w, 0.0);
        if self.inv.len() != n + 1 {
            inverse_binomials(n, &mut self.inv);
        }
        {
            let (b, e) = self.pool.split_at_mut(n + 1);
            // 1/C(n, k) carries up to 2k + 1 ≤ 2n + 1 roundings of its own.
            bernstein(a, rel + 2.0 * n as f64 + 1.0, &self.inv, b, e);
        }
        self.stack.push((0.0, 1.0, 0));
        let (first, mut examined) = (out.len(), 0);
        while let Some((lo, hi, depth)) = self.stack.pop() {
            let base = self.pool.len() - w;
            self.work.copy_from_slice(&self.pool[base..]);
            self.pool.truncate(base);
            examined += 1;
            let (b, e) = self.work.split_at(n + 1);
            let (v, uncertain, all) = signs(b, e);
            if !uncertain && v == 0 {
                continue;
            }
            if !uncertain && v == 1 {
                out.push(Piece::Isolated(lo, hi));
                continue;
            }
            let mid = 0.5 * (lo + hi);
            if all || depth >= MAX_DEPTH || examined >= MAX_PIECES || !(lo < mid && mid < hi) {
                // Undecided pieces that touch are one: the pieces around a multiple root,
                // or around a root on a halving point, are each within rounding of 0.
                let ours = out.len() > first;
                match out.last_mut() {
                    Some(Piece::Unresolved(_, end)) if ours && *end == lo => {
                        *end = hi;
                    }
                    _ => out.push(Piece::Unresolved(lo, hi)),
                }
                continue;
            }
            halve(&mut self.work, &mut self.left, &mut self.right);
            // The right half below the left on the stack: the left is examined first, so
            // that the pieces come out ascending.
            self.pool.extend_from_slice(&self.right);
            self.stack.push((mid, hi, depth + 1));
            self.pool.extend_from_slice(&self.left);
            self.stack.push((lo, mid, depth + 1));
        }
        // Pieces left when the budget ran out were reported as unresolved one by one above,
        // so `out` is ascending and complete.
    }
}

#[cfg(test)]
mod tests;
