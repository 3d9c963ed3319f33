//! The coefficient tables a primitive's recurrence reads and writes: series-major, the
//! order-k coefficient of series x at `x·st + k`, in `f64` or in double-double pairs.

use crate::exact::Dd;

/// A table of `f64` coefficients: `c[x·st + k]` is series `x` at order `k`.
pub(crate) struct F64Table<'a> {
    pub(crate) c: &'a mut [f64],
    pub(crate) st: usize,
}

impl F64Table<'_> {
    /// Series `x` at order `k`.
    #[inline]
    pub(crate) fn get(&self, x: u32, k: usize) -> f64 {
        self.c[x as usize * self.st + k]
    }

    /// Sets series `x` at order `k`.
    #[inline]
    pub(crate) fn set(&mut self, x: u32, k: usize, v: f64) {
        self.c[x as usize * self.st + k] = v;
    }

    /// The row of series `x`.
    #[inline]
    pub(crate) fn row(&self, x: u32) -> &[f64] {
        let i = x as usize * self.st;
        &self.c[i..i + self.st]
    }
}

/// A table of double-double coefficients stored series-major in `f64` pairs:
/// `w[2(x·st + k)]` and the next word are the hi and lo of series `x` at order `k`.
pub(crate) struct DdTable<'a> {
    pub(crate) w: &'a mut [f64],
    pub(crate) st: usize,
}

impl DdTable<'_> {
    /// The words a table of `series` series to order `st − 1` takes.
    pub(crate) fn len(series: usize, st: usize) -> usize {
        2 * series * st
    }

    /// Series `x` at order `k`.
    #[inline]
    pub(crate) fn get(&self, x: u32, k: usize) -> Dd {
        let i = 2 * (x as usize * self.st + k);
        Dd {
            hi: self.w[i],
            lo: self.w[i + 1],
        }
    }

    /// Sets series `x` at order `k`.
    #[inline]
    pub(crate) fn set(&mut self, x: u32, k: usize, v: Dd) {
        let i = 2 * (x as usize * self.st + k);
        self.w[i] = v.hi;
        self.w[i + 1] = v.lo;
    }

    /// `Σⱼ a_j b_{k−j}` for `j` in `from ..= to`.
    pub(crate) fn cauchy(&self, a: u32, b: u32, k: usize, from: usize, to: usize) -> Dd {
        Dd::dot((from..=to).map(|j| (self.get(a, j), self.get(b, k - j))))
    }
}
