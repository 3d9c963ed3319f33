//! The exponential, everything about it: `exp 0 = 1`, `exp′ = exp`, `\exp`, `f64::exp`,
//! and the Taylor recurrence of X = exp U from X′ = U′ X:
//! x_0 = exp u_0, x_k = (1/k) Σⱼ₌₁ᵏ j u_j x_{k−j}.
//!
//! The weights j u_j are the derivative's coefficients d_j, kept in the companion series
//! `out + 1` (made once per order, read by every later order's sum), so the sum is a plain
//! dot product: the interior Σⱼ₌₁ᵏ⁻¹ d_j x_{k−j} reads lower orders only, and the boundary
//! d_k x_0 comes last, as in the sine–cosine pair.

use proc_macro2::TokenStream;
use quote::quote;

use super::{DdTable, F64Table, Func, Primitive, SeriesCode, SeriesNames};
use crate::exact::Dd;
use crate::sym::series::dot_reversed;
use crate::sym::{Arena, ExprId, SymError};

/// The exponential.
pub(super) struct Exp;

/// The exponential's handle, for [`Arena::apply`].
///
/// ```
/// use precess_core::sym::{Arena, functions::EXP};
/// let mut a = Arena::new();
/// let x = a.parameter("x");
/// let e = a.apply(EXP, x).unwrap();
/// assert_eq!(a.display(e), "exp(x)");
/// assert_eq!(a.eval(e, &[1.0]), std::f64::consts::E);
/// let zero = a.zero();
/// assert_eq!(a.apply(EXP, zero), Ok(a.one())); // exp 0 = 1
/// ```
pub const EXP: Func = Func(&Exp);

impl Primitive for Exp {
    fn name(&self) -> &'static str {
        "exp"
    }

    fn latex(&self) -> &'static str {
        "\\exp"
    }

    fn value(&self, x: f64) -> f64 {
        x.exp()
    }

    fn value_dd(&self, x: Dd) -> Dd {
        x.exp()
    }

    fn exact(&self, arena: &mut Arena, u: ExprId) -> Result<Option<ExprId>, SymError> {
        // exp 0 = 1 is the one rational value: e^r is irrational for every other rational.
        Ok((u == arena.zero()).then(|| arena.one()))
    }

    fn derivative(&self, _arena: &mut Arena, _u: ExprId, value: ExprId) -> ExprId {
        value
    }

    fn companions(&self) -> u32 {
        1
    }

    fn flops(&self, k: usize) -> usize {
        // The order-0 call, then per order: d_k (1), the sum of k terms (2k), the scaling (1).
        if k == 0 { 1 } else { 2 * k + 2 }
    }

    fn series(&self, c: &mut F64Table<'_>, arg: u32, out: u32, k: usize) {
        let d = out + 1;
        if k == 0 {
            let v = c.get(arg, 0).exp();
            c.set(out, 0, v);
            c.set(d, 0, 0.0);
            return;
        }
        let dk = k as f64 * c.get(arg, k);
        c.set(d, k, dk);
        let inv = 1.0 / k as f64;
        let interior = dot_reversed(&c.row(d)[1..k], &c.row(out)[1..k]);
        let v = (interior + dk * c.get(out, 0)) * inv;
        c.set(out, k, v);
    }

    fn series_dd(&self, c: &mut DdTable<'_>, arg: u32, out: u32, k: usize) {
        let d = out + 1;
        if k == 0 {
            let v = c.get(arg, 0).exp();
            c.set(out, 0, v);
            c.set(d, 0, Dd::default());
            return;
        }
        c.set(d, k, c.get(arg, k) * Dd::from(k as f64));
        let v = c.cauchy(d, out, k, 1, k).div_f64(k as f64);
        c.set(out, k, v);
    }

    fn series_code(&self, n: &SeriesNames) -> SeriesCode {
        let (o, v, i, dot) = (&n.out, &n.value, &n.interior, &n.dot);
        let (a0, ak) = (&n.arg_zero, &n.arg_k);
        let Some(d) = n.companions.first() else {
            // The emitter names one row per companion; without it there is nothing to run.
            return SeriesCode {
                zero: TokenStream::new(),
                interior: TokenStream::new(),
                order_k: TokenStream::new(),
            };
        };
        let call = EXP.call_tokens(quote!(#a0));
        SeriesCode {
            zero: quote! {
                let #v: f64 = #call;
                #o[0] = #v;
            },
            interior: quote!(let #i: f64 = #dot(&#d[1..__k], &#o[1..__k]);),
            order_k: quote! {
                let __dk: f64 = (__k as f64) * #ak;
                #d[__k] = __dk;
                let #v: f64 = (#i + __dk * #o[0]) * (1.0 / (__k as f64));
                #o[__k] = #v;
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x = exp(a τ) has the coefficients aᵏ/k!: the recurrence of exp U with U = a τ.
    #[test]
    fn coefficients_of_exp_of_a_line_are_powers_over_factorials() {
        let (st, a) = (16, -0.7f64);
        let mut w = vec![0.0; 3 * st];
        let mut c = F64Table { c: &mut w, st };
        c.set(0, 1, a);
        for k in 0..st {
            Exp.series(&mut c, 0, 1, k);
        }
        let mut want = 1.0;
        for k in 0..st {
            if k > 0 {
                want *= a / k as f64;
            }
            let got = c.get(1, k);
            assert!(
                (got - want).abs() <= 1e-15 * want.abs(),
                "order {k}: {got} vs {want}"
            );
        }
    }

    /// In double-double, exp(τ) at τ = 1 summed from its coefficients 1/k! to order 30
    /// gives e to 30 digits: 2.718281828459045235360287471352662 (the known digits).
    #[test]
    fn double_double_series_sums_to_e() {
        let st = 31;
        let mut w = vec![0.0; DdTable::len(3, st)];
        let mut c = DdTable { w: &mut w, st };
        c.set(0, 1, Dd::from(1.0));
        for k in 0..st {
            Exp.series_dd(&mut c, 0, 1, k);
        }
        let mut sum = Dd::default();
        for k in (0..st).rev() {
            sum = sum + c.get(1, k);
        }
        // e = 2.718281828459045 + 1.4456468917292502e-16 (hi, lo of the double-double).
        let e_lo = 1.445_646_891_729_250_2e-16;
        assert_eq!(sum.hi, std::f64::consts::E);
        assert!((sum.lo - e_lo).abs() < 1e-30, "lo {:e}", sum.lo);
    }
}
