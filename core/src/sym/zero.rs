//! Deciding whether an expression is identically zero, fast when it is not.
//!
//! Expanding a large divisor only to learn that it is not zero is the costly way round. An
//! expression is first evaluated exactly in the integers modulo the prime p = 2⁶¹ − 1 at a
//! pseudo-random point (abbreviations through their definitions): a non-zero value proves
//! the expression non-zero, whatever its size. Only when the points tried give zero (three
//! of them) or cannot be used (a denominator or a square root without a value there, up to
//! 64 points) is the answer decided by expansion, which is exact.
//!
//! The point respects the relations the canonical form uses, so a zero of the engine's ring
//! evaluates to zero: sin u and cos u are (2t/(1 + t²), (1 − t²)/(1 + t²)) for a t drawn from
//! the value of u (odd in u, so sin(−u) = −sin u), and √v is a square root of v modulo p.
//! 1 + t² never vanishes because p ≡ 3 (mod 4).

use super::arena::{Arena, ExprId, Node};
use super::error::SymError;
use super::hash::IdMap;
use super::rational::Rational;

const P: u64 = (1 << 61) - 1;

/// The most points [`Arena::is_zero`] evaluates at before it expands.
const MAX_POINTS: u64 = 64;

/// The usable points at which an expression vanishing sends it to the expansion.
const ZERO_POINTS: u32 = 3;

fn add(a: u64, b: u64) -> u64 {
    (a + b) % P
}

fn mul(a: u64, b: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(P)) as u64
}

fn pow(mut a: u64, mut n: u64) -> u64 {
    let mut r = 1;
    while n > 0 {
        if n & 1 == 1 {
            r = mul(r, a);
        }
        a = mul(a, a);
        n >>= 1;
    }
    r
}

/// The inverse of a non-zero residue.
fn inv(a: u64) -> Option<u64> {
    (a != 0).then(|| pow(a, P - 2))
}

fn neg(a: u64) -> u64 {
    (P - a) % P
}

/// SplitMix64: a fixed, reproducible stream, so compilation stays deterministic.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

fn residue(i: i128) -> u64 {
    i.rem_euclid(i128::from(P)) as u64
}

/// The residue of r = n/d · 2^a · 5^b (`None` where a factor vanishes modulo P).
fn rational(r: Rational) -> Option<u64> {
    let (n, d, two, five) = r.scaled();
    let power = |base: u64, e: i32| {
        let p = pow(base, u64::from(e.unsigned_abs()));
        if e < 0 { inv(p) } else { Some(p) }
    };
    let ratio = mul(residue(n), inv(residue(d))?);
    Some(mul(mul(ratio, power(2, two)?), power(5, five)?))
}

/// (sin, cos) at an argument of value `v`, odd in `v`.
fn sin_cos(v: u64, seed: u64) -> (u64, u64) {
    let (flip, rep) = if v > P / 2 {
        (true, neg(v))
    } else {
        (false, v)
    };
    let mut t = mix(rep ^ mix(seed)) % P;
    if flip {
        t = neg(t);
    }
    let t2 = mul(t, t);
    let d = inv(add(1, t2)).unwrap_or(0);
    (mul(mul(2, t), d), mul(add(1, neg(t2)), d))
}

impl Arena {
    /// True if `e` is identically zero in the engine's ring (the trig-canonical polynomials
    /// in its symbols, abbreviations standing for their definitions).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let (s, c) = (a.sin(x), a.cos(x));
    /// let (s2, c2) = (a.mul(s, s), a.mul(c, c));
    /// let one = a.one();
    /// let sum = a.add(s2, c2);
    /// let z = a.sub(sum, one);
    /// assert_eq!(a.is_zero(z), Ok(true));
    /// assert_eq!(a.is_zero(s), Ok(false));
    /// ```
    ///
    /// # Errors
    /// [`SymError::ExpansionTooLarge`] if `e` vanishes at every point tried and is too large
    /// to expand; [`SymError::ForeignExpression`] for an id of another arena.
    pub fn is_zero(&mut self, e: ExprId) -> Result<bool, SymError> {
        self.check_owned(&[e])?;
        if e == self.zero() {
            return Ok(true);
        }
        if self.as_rational(e).is_some() || self.as_symbol(e).is_some() {
            return Ok(false);
        }
        // A square root is defined at a point only where its argument is a square modulo p,
        // half the residues: with k roots in `e`, one point in 2^k can be used. Points are
        // cheap (one pass over the graph) and expansion is not (a contact's 3 × 3
        // determinant under pivoting friction took seconds), so up to `MAX_POINTS` are
        // drawn; an expression that vanishes at `ZERO_POINTS` usable points is taken to the
        // exact expansion at once.
        let mut vanished = 0;
        for seed in 1..=MAX_POINTS {
            match self.modular_value(e, seed) {
                Some(0) => {
                    vanished += 1;
                    if vanished == ZERO_POINTS {
                        break;
                    }
                }
                Some(_) => return Ok(false),
                None => {}
            }
        }
        let x = self.try_expand(e)?;
        if x == self.zero() {
            return Ok(true);
        }
        let inlined = self.inline_abbreviations(x)?;
        if inlined == x {
            return Ok(false);
        }
        Ok(self.try_expand(inlined)? == self.zero())
    }

    /// The value of `e` modulo p at the point drawn from `seed`, `None` where it is not
    /// defined there.
    pub(crate) fn modular_value(&self, e: ExprId, seed: u64) -> Option<u64> {
        let mut values: IdMap<ExprId, u64> = IdMap::default();
        for id in self.walk(&[e], true, |_| true) {
            let v = |x: &ExprId| values.get(x).copied();
            let value = match self.node(id) {
                Node::Const(r) => rational(*r)?,
                Node::Sym(s) => match self.definitions.get(s) {
                    Some(d) => v(d)?,
                    None => mix(mix(seed) ^ s.index() as u64) % P,
                },
                Node::Add(t) => t.iter().try_fold(0, |acc, x| Some(add(acc, v(x)?)))?,
                Node::Mul(f) => f.iter().try_fold(1, |acc, x| Some(mul(acc, v(x)?)))?,
                Node::Pow(b, n) => {
                    let p = pow(v(b)?, n.unsigned_abs());
                    if *n < 0 { inv(p)? } else { p }
                }
                Node::Sqrt(u) => {
                    let x = v(u)?;
                    let r = pow(x, (P + 1) / 4);
                    if mul(r, r) != x {
                        return None;
                    }
                    r
                }
                // An opaque function of its base (as expansion treats it): a pseudo-random
                // value of the base's value and the exponent.
                Node::Powr(b, r) => {
                    let (n, d, two, five) = r.scaled();
                    let tag = mix((n as u64) ^ mix((d as u64) ^ mix((two ^ five << 16) as u64)));
                    mix(v(b)? ^ mix(seed ^ tag)) % P
                }
                Node::Sin(u) => sin_cos(v(u)?, seed).0,
                Node::Cos(u) => sin_cos(v(u)?, seed).1,
                // Opaque, as real powers are: a pseudo-random value of the argument's value
                // and the function.
                Node::Func(f, u) => {
                    let tag = mix(0x5052_494d ^ f.index() as u64);
                    mix(v(u)? ^ mix(seed ^ tag)) % P
                }
            };
            values.insert(id, value);
        }
        values.get(&e).copied()
    }
}
