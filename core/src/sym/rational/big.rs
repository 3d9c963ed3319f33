//! A minimal unsigned big integer: just what exact comparison and correct rounding of
//! rationals need (products, powers of five, shifts, comparison, subtraction).
//!
//! Limbs are little-endian `u64`s with no high zero limb, so equal values are equal vectors
//! and the bit length is read off the top limb.

use std::cmp::Ordering;

/// The largest power of five that fits a limb: 5²⁷ < 2⁶⁴.
const FIVE_27: u64 = 7_450_580_596_923_828_125;

#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Big(Vec<u64>);

impl Big {
    pub(super) fn from_u128(x: u128) -> Big {
        let mut b = Big(vec![x as u64, (x >> 64) as u64]);
        b.trim();
        b
    }

    fn trim(&mut self) {
        while self.0.last() == Some(&0) {
            self.0.pop();
        }
    }

    pub(super) fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// Number of significant bits (0 for zero).
    pub(super) fn bit_len(&self) -> u64 {
        match self.0.last() {
            Some(&top) => 64 * self.0.len() as u64 - u64::from(top.leading_zeros()),
            None => 0,
        }
    }

    pub(super) fn mul_small(&mut self, m: u64) {
        let mut carry: u128 = 0;
        for limb in &mut self.0 {
            let t = u128::from(*limb) * u128::from(m) + carry;
            *limb = t as u64;
            carry = t >> 64;
        }
        if carry != 0 {
            self.0.push(carry as u64);
        }
        self.trim();
    }

    /// `self · other`, schoolbook.
    pub(super) fn mul(&self, other: &Big) -> Big {
        let mut out = vec![0u64; self.0.len() + other.0.len()];
        for (i, &a) in self.0.iter().enumerate() {
            let mut carry: u128 = 0;
            for (j, &b) in other.0.iter().enumerate() {
                let t = u128::from(a) * u128::from(b) + u128::from(out[i + j]) + carry;
                out[i + j] = t as u64;
                carry = t >> 64;
            }
            // The slot above this row is still untouched by it, so the carry fits.
            out[i + other.0.len()] = carry as u64;
        }
        let mut b = Big(out);
        b.trim();
        b
    }

    /// `self · 5^k`.
    pub(super) fn mul_pow5(&mut self, mut k: u64) {
        while k >= 27 {
            self.mul_small(FIVE_27);
            k -= 27;
        }
        if k > 0 {
            self.mul_small(5u64.pow(k as u32));
        }
    }

    /// `self · 2^bits`.
    pub(super) fn shl(&mut self, bits: u64) {
        if self.is_zero() {
            return;
        }
        let (limbs, rem) = ((bits / 64) as usize, (bits % 64) as u32);
        if rem > 0 {
            let mut carry = 0u64;
            for limb in &mut self.0 {
                let next = *limb >> (64 - rem);
                *limb = (*limb << rem) | carry;
                carry = next;
            }
            if carry != 0 {
                self.0.push(carry);
            }
        }
        self.0.splice(0..0, std::iter::repeat_n(0, limbs));
    }

    /// `⌊self / 2⌋`.
    pub(super) fn shr1(&mut self) {
        let mut carry = 0u64;
        for limb in self.0.iter_mut().rev() {
            let next = *limb << 63;
            *limb = (*limb >> 1) | carry;
            carry = next;
        }
        self.trim();
    }

    /// `self − other`; the caller guarantees `self ≥ other`.
    pub(super) fn sub_assign(&mut self, other: &Big) {
        let mut borrow = false;
        for (i, limb) in self.0.iter_mut().enumerate() {
            let b = other.0.get(i).copied().unwrap_or(0);
            let (d, o1) = limb.overflowing_sub(b);
            let (d, o2) = d.overflowing_sub(u64::from(borrow));
            *limb = d;
            borrow = o1 || o2;
        }
        self.trim();
    }
}

impl PartialOrd for Big {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Big {
    fn cmp(&self, other: &Self) -> Ordering {
        // Trimmed limbs: more limbs is larger; otherwise compare from the top.
        self.0
            .len()
            .cmp(&other.0.len())
            .then_with(|| self.0.iter().rev().cmp(other.0.iter().rev()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_matches_u128() {
        let (a, b) = (0xDEAD_BEEF_1234_5678_9ABC_u128, 0x1_0000_0001_u128);
        let mut p = Big::from_u128(a).mul(&Big::from_u128(b));
        assert_eq!(p, Big::from_u128(a * b));
        p.sub_assign(&Big::from_u128(a));
        assert_eq!(p, Big::from_u128(a * b - a));
        let mut f = Big::from_u128(3);
        f.mul_pow5(40);
        assert_eq!(f, Big::from_u128(3 * 5u128.pow(40)));
        let mut s = Big::from_u128(5);
        s.shl(70);
        assert_eq!(s.bit_len(), 73);
        s.shr1();
        assert_eq!(s, Big::from_u128(5 << 69));
        assert!(Big::from_u128(u128::MAX) > s);
        s.shl(200);
        assert!(Big::from_u128(u128::MAX) < s);
        assert_eq!(Big::from_u128(0).bit_len(), 0);
    }
}
