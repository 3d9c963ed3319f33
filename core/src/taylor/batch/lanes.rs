//! [`Lanes<L>`]: `L` doubles stepped as one value, each lane on its own, with the arithmetic
//! the emitted recurrences use. Every operation is a loop over the lanes of a fixed length,
//! which the compiler turns into packed instructions (`mulpd`, `vmulpd ymm`, …), and each
//! lane's result is the scalar operation's on that lane: no reassociation, no fused
//! multiply-add (Rust contracts none), so a lane rounds as a scalar run does.

use core::ops::{Add, Div, Mul, Neg, Sub};

/// `L` doubles, one per trajectory, operated on lane by lane.
///
/// ```
/// use precess_core::taylor::batch::Lanes;
/// let a = Lanes([1.0, 2.0, 3.0, 4.0]);
/// let b = 2.0 * a + Lanes::splat(0.5);
/// assert_eq!(b, Lanes([2.5, 4.5, 6.5, 8.5]));
/// assert_eq!(b.0[3], 8.5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanes<const L: usize>(pub [f64; L]);

impl<const L: usize> Default for Lanes<L> {
    fn default() -> Self {
        Self::splat(0.0)
    }
}

impl<const L: usize> From<f64> for Lanes<L> {
    #[inline(always)]
    fn from(v: f64) -> Self {
        Self::splat(v)
    }
}

impl<const L: usize> Lanes<L> {
    /// The same value in every lane.
    #[inline(always)]
    pub const fn splat(v: f64) -> Self {
        Self([v; L])
    }

    /// `f` applied lane by lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Self(self.0.map(f))
    }

    /// √ of each lane (a packed `sqrtpd`: the square root is correctly rounded, so the same
    /// as `f64::sqrt`).
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }

    /// Each lane to the power `r` (`f64::powf`, one call per lane).
    #[inline(always)]
    pub fn powf(self, r: f64) -> Self {
        self.map(|v| v.powf(r))
    }

    /// The sine of each lane (`f64::sin`, one call per lane).
    #[inline(always)]
    pub fn sin(self) -> Self {
        self.map(f64::sin)
    }

    /// The cosine of each lane (`f64::cos`, one call per lane).
    #[inline(always)]
    pub fn cos(self) -> Self {
        self.map(f64::cos)
    }

    /// Sine and cosine of each lane (`f64::sin_cos`, one call per lane).
    #[inline(always)]
    pub fn sin_cos(self) -> (Self, Self) {
        let (mut s, mut c) = ([0.0; L], [0.0; L]);
        for ((si, ci), v) in s.iter_mut().zip(c.iter_mut()).zip(self.0) {
            (*si, *ci) = v.sin_cos();
        }
        (Self(s), Self(c))
    }
}

/// `Lanes ∘ Lanes`, `Lanes ∘ f64` and `f64 ∘ Lanes` for one operator, lane by lane; the
/// scalar is the same in every lane and keeps its side, so `2.0 * a` rounds as `2.0 * aᵢ`.
macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const L: usize> $trait for Lanes<L> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                let mut out = self.0;
                for (o, r) in out.iter_mut().zip(rhs.0) {
                    *o = *o $op r;
                }
                Self(out)
            }
        }

        impl<const L: usize> $trait<f64> for Lanes<L> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: f64) -> Self {
                let mut out = self.0;
                for o in &mut out {
                    *o = *o $op rhs;
                }
                Self(out)
            }
        }

        impl<const L: usize> $trait<Lanes<L>> for f64 {
            type Output = Lanes<L>;
            #[inline(always)]
            fn $method(self, rhs: Lanes<L>) -> Lanes<L> {
                let mut out = rhs.0;
                for o in &mut out {
                    *o = self $op *o;
                }
                Lanes(out)
            }
        }
    };
}

// `*o = *o − r` is written out, not `*o −= r`, so that the three forms read alike and
// `f64 ∘ Lanes` visibly keeps the scalar on the left.
#[allow(clippy::assign_op_pattern)]
mod ops {
    use super::{Add, Div, Lanes, Mul, Sub};
    lane_op!(Add, add, +);
    lane_op!(Sub, sub, -);
    lane_op!(Mul, mul, *);
    lane_op!(Div, div, /);
}

impl<const L: usize> Neg for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|v| -v)
    }
}

impl<const L: usize> core::ops::AddAssign for Lanes<L> {
    #[inline(always)]
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}
