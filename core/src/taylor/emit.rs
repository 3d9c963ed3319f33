//! Emission of a [`Tape`] as Rust: the body of [`super::TaylorSystem::coefficients`]
//! specialised to one right-hand side, which the derive macros splice into
//! `impl TaylorSystem<N>` for a scene that asks (`taylor = K`).
//!
//! The series live in the caller's workspace, `Vec<[f64; K + 1]>` (one row per series, `K`
//! a constant), bound row by row with one slice pattern so that every index is checked
//! against a length the compiler knows; nothing is zeroed or allocated per call (the rows
//! are sized once, on the first call). The scalars are `let`s computed once (literals
//! inlined, so the compiler folds them); order 0 (the values themselves: `sin_cos`, `sqrt`,
//! quotients) is straight-line code before the loop, and the loop over the orders k ≥ 1 runs
//! each step's recurrence, its sums through [`super::kernels`], in two phases: first the
//! interior of every sum (the terms that read lower orders only), then the steps in program
//! order with the terms that read order k (docs/taylor.md, "The order of the sums").

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

use super::tape::{ScalarOp, SeriesOp, Tape, Value};

mod fused;
mod step;
use crate::codegen::f64_literal;
use crate::sym::SymbolId;

fn series(x: u32) -> Ident {
    Ident::new(&format!("__x{x}"), Span::call_site())
}

/// How the emitted sums reach [`super::kernels`]: inlined into the loop over the orders, or
/// through [`super::kernels::outlined`] for tapes past [`OUTLINE_KERNELS_FROM_SUMS`] sums.
#[derive(Clone, Copy)]
struct Sums {
    /// Cauchy products split into interior and boundary ([`Tape::split_products`]).
    split: bool,
    /// The kernels called through their never-inlined twins.
    outlined: bool,
    /// The code steps `__L` trajectories at once: every value is a `Lanes<__L>`
    /// (`super::batch`), the sums go through `super::batch::kernels`.
    lanes: bool,
    /// The plain dot-product interiors of an order are summed in loops of at most this
    /// many sums ([`fused`]); 0: each through its kernel call.
    fused: usize,
}

impl Sums {
    /// The path generated code reaches a kernel by: the facade's hidden module, the one
    /// path all generated code names precess through.
    fn kernel(self, name: &str) -> TokenStream {
        let f = Ident::new(name, Span::call_site());
        if self.lanes {
            quote!(::precess::__private::lane_kernels::#f)
        } else if self.outlined {
            quote!(::precess::__private::kernels::outlined::#f)
        } else {
            quote!(::precess::__private::kernels::#f)
        }
    }

    /// The type of a value: `f64`, or `Lanes<__L>` in the lanes.
    fn num(self) -> TokenStream {
        if self.lanes {
            quote!(::precess::__private::Lanes<__L>)
        } else {
            quote!(f64)
        }
    }

    /// `e` as a value: itself, or in the lanes a `Lanes<__L>` made of it (an `f64` literal
    /// splat to every lane, a `Lanes` kept).
    fn value(self, e: TokenStream) -> TokenStream {
        if self.lanes {
            let num = self.num();
            quote!(<#num>::from(#e))
        } else {
            e
        }
    }
}

/// The emitted code of a tape, with its size for the price reports.
#[derive(Clone, Debug)]
pub struct TaylorTokens {
    /// The body of `fn coefficients(&self, ws: &mut Self::Workspace, t: f64, y: &[f64; N],
    /// order: usize, coeffs: &mut [[f64; N]])`: it reads those five names.
    pub body: TokenStream,
    /// The type of `TaylorSystem::Workspace` the body expects (`Vec<[f64; K + 1]>`).
    pub workspace: TokenStream,
    /// The number of series rows the workspace holds (the tape's series less those the code
    /// keeps in `let`s).
    pub series: usize,
}

impl TaylorTokens {
    /// The number of tokens of the body (a delimited group counts its two delimiters): the
    /// size the compiler parses, for the price reports.
    pub fn token_count(&self) -> usize {
        fn count(ts: TokenStream) -> usize {
            ts.into_iter()
                .map(|t| match t {
                    proc_macro2::TokenTree::Group(g) => 2 + count(g.stream()),
                    _ => 1,
                })
                .sum()
        }
        count(self.body.clone())
    }
}

impl Tape {
    /// The code [`Tape::to_tokens`] emits up to `max_order`, with every scalar symbol read
    /// as one field access: its size is the scene's (for the price reports).
    pub fn emitted(&self, max_order: usize) -> TaylorTokens {
        self.to_tokens(max_order, &mut |_| quote!(self.p))
    }

    /// Emits the coefficients' body up to the compile-time order bound `max_order`; `symbol`
    /// gives the Rust expression of each symbol read as a scalar (e.g. `self.m`).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::Tape;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let rhs = a.mul(x, x); // x' = x²
    /// let tape = Tape::new(&a, &[x], None, &[rhs]).unwrap();
    /// let code = tape.to_tokens(20, &mut |_| quote::quote!(0.0));
    /// assert!(code.body.to_string().contains("20usize"));
    /// assert_eq!(code.series, 1); // x; x² is read once, at its own order: a `let`
    /// ```
    pub fn to_tokens(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
    ) -> TaylorTokens {
        self.emit(max_order, symbol, self.scalar_sums(), false)
    }

    /// How the scalar code (a system's or an event's) sums its dot products.
    fn scalar_sums(&self) -> Sums {
        Sums {
            split: self.split_products(),
            outlined: self.sum_count() >= OUTLINE_KERNELS_FROM_SUMS,
            lanes: false,
            fused: if self.split_products() {
                FUSED_SCALAR
            } else {
                0
            },
        }
    }

    /// The coefficients of an event function g (the tape's one output) along the series of
    /// the state, as compiled code: the body of
    /// [`EventSeries::coefficients_into`](super::EventSeries::coefficients_into), which reads
    /// `ws`, `t: f64`, `y: &[f64; N]`, `rows: &[[f64; N]]` and `out: &mut [f64]`. The
    /// recurrences are [`Tape::to_tokens`]'s (the same steps, sums and order of additions),
    /// with the state's series read from the jet: at order k, the state's row k is loaded
    /// from `rows[k − 1]` before the steps run, and g's coefficient of order k is written to
    /// `out[k]`, k = 0 … p, p = min(`out.len()` − 1, `rows.len()`, `max_order`). So the
    /// compiled coefficients are those of the interpreted
    /// [`TaylorEvent`](super::TaylorEvent) of the same expression bit for bit (the
    /// interpreter walks the same steps in the same order, one order at a time).
    ///
    /// `None` unless the tape has exactly one output (g).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::Tape;
    /// let mut a = Arena::new();
    /// let (x, v) = (a.coordinate("x"), a.coordinate("v"));
    /// let g = a.mul(x, v); // g = x v, over the state (x, v)
    /// let program = precess_core::codegen::Program::lower(&a, &[g]);
    /// let state = [a.as_symbol(x).unwrap(), a.as_symbol(v).unwrap()];
    /// let tape = Tape::from_program(&program, &state, None);
    /// let code = tape.to_event_tokens(20, &mut |_| quote::quote!(0.0)).unwrap();
    /// let body = code.body.to_string();
    /// assert!(body.contains("rows [__k - 1]"), "{body}");
    /// assert!(body.contains("out [__k]"), "{body}");
    /// ```
    pub fn to_event_tokens(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
    ) -> Option<TaylorTokens> {
        if self.outputs.len() != 1 {
            return None;
        }
        Some(self.emit(max_order, symbol, self.scalar_sums(), true))
    }

    /// The recurrences of [`Tape::to_tokens`] on `L` trajectories at once: every value a
    /// [`Lanes<__L>`](super::batch::Lanes), `__L` a const generic the caller's `impl` declares,
    /// the sums through [`super::batch::kernels`]; each lane's operations are the scalar
    /// code's in the same order, so a lane's coefficients are a scalar call's bit for bit.
    /// `symbol` gives each scalar symbol as an expression of type `Lanes<__L>`. The body reads
    /// `ws`, `t: Lanes<__L>`, `y: &[Lanes<__L>; N]`, `order` and `coeffs: &mut [[Lanes<__L>;
    /// N]]`.
    ///
    /// `None` for a tape with a primitive function ([`SeriesOp::Func`], whose emitted code is
    /// written for `f64`) or with `OUTLINE_KERNELS_FROM_SUMS` (512) sums or more (the lanes
    /// multiply a body the compiler already struggles with): such a scene keeps its scalar
    /// recurrences only.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// use precess_core::taylor::Tape;
    /// let mut a = Arena::new();
    /// let x = a.coordinate("x");
    /// let rhs = a.mul(x, x); // x' = x²
    /// let tape = Tape::new(&a, &[x], None, &[rhs]).unwrap();
    /// let code = tape.to_lane_tokens(20, &mut |_| quote::quote!(0.0)).unwrap();
    /// assert!(code.workspace.to_string().contains("Lanes < __L >"));
    /// ```
    pub fn to_lane_tokens(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
    ) -> Option<TaylorTokens> {
        let has_func = self
            .steps
            .iter()
            .any(|st| matches!(st.op, SeriesOp::Func(..)))
            || self
                .scalars
                .iter()
                .any(|op| matches!(op, ScalarOp::Func(..)));
        if has_func || self.sum_count() >= OUTLINE_KERNELS_FROM_SUMS {
            return None;
        }
        let sums = Sums {
            split: self.split_products(),
            outlined: false,
            lanes: true,
            fused: if self.split_products() {
                FUSED_LANES
            } else {
                0
            },
        };
        Some(self.emit(max_order, symbol, sums, false))
    }

    /// The code of [`Tape::to_tokens`] and of the lanes ([`Tape::to_lane_tokens`]), or with
    /// `event` of an event function's coefficients ([`Tape::to_event_tokens`]).
    fn emit(
        &self,
        max_order: usize,
        symbol: &mut dyn FnMut(SymbolId) -> TokenStream,
        sums: Sums,
        event: bool,
    ) -> TaylorTokens {
        let scalar_operand = |i: u32| -> TokenStream {
            match self.scalars.get(i as usize) {
                Some(ScalarOp::Const(c)) => f64_literal(*c),
                _ => {
                    let id = Ident::new(&format!("__s{i}"), Span::call_site());
                    quote!(#id)
                }
            }
        };
        let mut scalars = TokenStream::new();
        let num = sums.num();
        let zero = sums.value(quote!(0.0f64));
        for (i, op) in self.scalars.iter().enumerate() {
            let s = scalar_operand;
            let rhs = match *op {
                ScalarOp::Const(_) => continue,
                ScalarOp::Symbol(sym) => symbol(sym),
                ScalarOp::Add(a, b) => binary(s(a), quote!(+), s(b)),
                ScalarOp::Sub(a, b) => binary(s(a), quote!(-), s(b)),
                ScalarOp::Mul(a, b) => binary(s(a), quote!(*), s(b)),
                ScalarOp::Div(a, b) => binary(s(a), quote!(/), s(b)),
                ScalarOp::Neg(a) => {
                    let a = s(a);
                    quote!(-#a)
                }
                ScalarOp::Sqrt(a) => method(s(a), "sqrt", sums),
                ScalarOp::Powf(a, r) => {
                    let (a, r, num) = (sums.value(s(a)), f64_literal(r), sums.num());
                    quote!(<#num>::powf(#a, #r))
                }
                ScalarOp::Sin(a) => method(s(a), "sin", sums),
                ScalarOp::Cos(a) => method(s(a), "cos", sums),
                ScalarOp::Func(f, a) => f.call_tokens(s(a)),
            };
            let id = Ident::new(&format!("__s{i}"), Span::call_site());
            let (rhs, num) = (sums.value(rhs), sums.num());
            scalars.extend(quote!(let #id: #num = #rhs;));
        }
        let layout = &self.layout();
        let code = step::StepCode {
            layout,
            sums,
            scalar: scalar_operand,
        };
        // Only the series that are not `let`s get a row: fewer rows, a smaller workspace.
        let with_row: Vec<u32> = (0..self.series_count)
            .filter(|&x| !layout.is_local(x))
            .collect();
        let rows = with_row.len();
        let bindings = with_row.iter().map(|&x| series(x));
        // The workspace's rows sized once and bound by name, in the system's code and an
        // event's alike.
        let workspace_rows = quote! {
            if ws.len() != #rows {
                ws.clear();
                ws.resize(#rows, [#zero; __K + 1]);
            }
            let [#(#bindings),*] = &mut ws[..] else {
                return;
            };
        };
        let load = (0..self.dimension).map(|i| {
            let id = series(i as u32);
            quote!(#id[0] = y[#i];)
        });
        // A workspace of the same type may have served another system: the time's row is
        // the only one read beyond what this call writes, so it is written whole.
        let time = self.time.map(|ti| {
            let id = series(ti);
            let one = sums.value(quote!(1.0f64));
            quote!(*#id = [#zero; __K + 1]; #id[0] = t; #id[1] = #one;)
        });
        let first = self.steps.iter().map(|st| code.order_zero(st.out, st.op));
        // Each order in two phases: first the interiors of the sums (they read lower orders
        // only, so their chains of additions depend neither on one another nor on this
        // order's other values), then every step in program order, adding the terms that
        // read order k to its interior, from the `let`s of the values just made. What
        // remains between one order and the next is the short chain of those terms.
        let dots: Vec<fused::Dot> = if sums.fused > 0 {
            self.steps
                .iter()
                .flat_map(|st| fused::dots(st.out, st.op, sums.split))
                .collect()
        } else {
            Vec::new()
        };
        let fused_dots = fused::block(&dots, sums, sums.fused);
        let interiors = self.steps.iter().map(|st| code.interior(st.out, st.op));
        let steps = self.steps.iter().map(|st| code.order_k(st.out, st.op));
        // f's order-k coefficient into the state's order k + 1: at order 0 as it is, at
        // order k ≥ 1 divided by k + 1 (`__inv`); a scalar output has order 0 only.
        let output = |order_zero: bool| {
            let zero = &zero;
            let f = self.outputs.iter().enumerate().map(move |(i, out)| {
                let state = series(i as u32);
                match (*out, order_zero) {
                    (Value::Series(x), true) => {
                        let v = layout.current(x, quote!(0));
                        quote!(#state[1] = #v;)
                    }
                    (Value::Series(x), false) => {
                        let v = layout.current(x, quote!(__k));
                        quote!(#state[__k + 1] = #v * __inv;)
                    }
                    (Value::Scalar(x), true) => {
                        let v = sums.value(scalar_operand(x));
                        quote!(#state[1] = #v;)
                    }
                    (Value::Scalar(_), false) => quote!(#state[__k + 1] = #zero;),
                }
            });
            quote!(#(#f)*)
        };
        let (outputs_zero, outputs_k) = (output(true), output(false));
        let next = |k: TokenStream| {
            let ids = (0..self.dimension).map(|i| {
                let id = series(i as u32);
                quote!(#id[#k + 1])
            });
            quote!([#(#ids),*])
        };
        let (next_zero, next_k) = (next(quote!(0)), next(quote!(__k)));
        if event {
            // g's coefficient of order k into `out[k]`; the state's row k from the jet.
            let g = |order_zero: bool| match (self.outputs.first(), order_zero) {
                (Some(&Value::Series(x)), true) => layout.current(x, quote!(0)),
                (Some(&Value::Series(x)), false) => layout.current(x, quote!(__k)),
                (Some(&Value::Scalar(x)), true) => scalar_operand(x),
                _ => quote!(0.0f64),
            };
            let (g_zero, g_k) = (g(true), g(false));
            let load_k = (0..self.dimension).map(|i| {
                let id = series(i as u32);
                quote!(#id[__k] = rows[__k - 1][#i];)
            });
            let body = quote! {
                const __K: usize = #max_order;
                let ::core::option::Option::Some(__top) = out.len().checked_sub(1) else {
                    return;
                };
                let __p: usize = if __top < __K { __top } else { __K };
                let __p: usize = if __p < rows.len() { __p } else { rows.len() };
                #workspace_rows
                #scalars
                #(#load)*
                #time
                #(#first)*
                out[0] = #g_zero;
                for __k in 1..=__p {
                    #(#load_k)*
                    #fused_dots
                    #(#interiors)*
                    #(#steps)*
                    out[__k] = #g_k;
                }
            };
            return TaylorTokens {
                body,
                workspace: quote!(::std::vec::Vec<[#num; #max_order + 1]>),
                series: rows,
            };
        }
        let order_body = quote! {
            #fused_dots
            #(#interiors)*
            #(#steps)*
            let __inv: f64 = 1.0 / ((__k + 1) as f64);
            #outputs_k
            coeffs[__k + 1] = #next_k;
        };
        // Unrolling the orders (each with its k a constant, so that every sum has a fixed
        // length and no remainder loop) was measured slower: B5 at order 13 0.12 → 0.14 µs,
        // the heavy top 1.3 → 1.7 µs, the free body 1.3 → 2.1 µs (the code grows K-fold).
        let orders = quote! {
            for __k in 1..__n {
                #order_body
            }
        };
        let body = quote! {
            const __K: usize = #max_order;
            let ::core::option::Option::Some(__top) = coeffs.len().checked_sub(1) else {
                return;
            };
            let __n: usize = if order < __K { order } else { __K };
            let __n: usize = if __n < __top { __n } else { __top };
            #workspace_rows
            #scalars
            #(#load)*
            #time
            coeffs[0] = *y;
            if __n == 0 {
                return;
            }
            #(#first)*
            #outputs_zero
            coeffs[1] = #next_zero;
            #orders
        };
        TaylorTokens {
            body,
            workspace: quote!(::std::vec::Vec<[#num; #max_order + 1]>),
            series: rows,
        }
    }
}

/// The most sums (products, squares, quotients, roots, sine–cosine pairs) a tape may have
/// for its Cauchy products to be split into interior and boundary terms. Measured
/// (`cargo bench --bench taylor_coefficients`): the split takes B5 (3 sums), the heavy top
/// (12) and the free body (15) from 0.36 to 0.27 µs, 1.8 to 1.3 µs and 1.45 to 1.3 µs at
/// order 20, and slowed the general top (88) and the three-link chain by up to a quarter
/// (their many independent sums already keep the processor busy, and the split's code is a
/// third larger); the bound lies between.
const SPLIT_PRODUCTS_MAX_SUMS: usize = 32;

/// The number of sums from which the emitted code calls the kernels through
/// [`super::kernels::outlined`] rather than inlining each: LLVM's time to optimise one loop
/// body grows faster than its size, and a 10-link chain's (some 2 000 sums, 4 000 kernel
/// calls, inlined) took 111 s of a release build (`scripts/build_cost.py --n 10 --taylor 20
/// --profile release`, docs/mechanisms.md). The scenes of the benches have at most a few
/// hundred sums and keep their inlined kernels.
const OUTLINE_KERNELS_FROM_SUMS: usize = 512;

/// The most dot-product interiors one fused loop sums in the scalar code ([`fused`]): more
/// accumulators than the registers hold spill, and the spilled chains wait on the stack. The
/// generated heavy top in angles (`#[top(taylor = 20)]`, 1e-10, 1 000 runs) took 0.18 s
/// before the loops, 0.23–0.29 s with all its sums in one loop and 0.17–0.18 s with 8 a
/// loop; the Euler–Poisson top (8 sums) 0.22 s, 0.19 s and 0.19 s.
const FUSED_SCALAR: usize = 8;

/// The most dot-product interiors one fused loop sums in the lanes ([`fused`]), where they
/// are fused at all (`batch::kernels::fuse_sums`): a lane value takes up to two registers.
const FUSED_LANES: usize = 4;

impl Tape {
    /// Whether the emitted Cauchy products sum their interior first and the boundary
    /// `a_0 b_k + a_k b_0` last (as [`super::kernels::cauchy`]), or left to right in one
    /// loop over `j = 0 … k`: the first for small tapes, whose orders are a few short
    /// dependency chains, the second for large ones ([`SPLIT_PRODUCTS_MAX_SUMS`]).
    fn split_products(&self) -> bool {
        self.sum_count() <= SPLIT_PRODUCTS_MAX_SUMS
    }

    /// The number of steps whose recurrence has a sum over the orders.
    fn sum_count(&self) -> usize {
        self.steps
            .iter()
            .filter(|st| {
                matches!(
                    st.op,
                    SeriesOp::Mul(..)
                        | SeriesOp::Square(_)
                        | SeriesOp::Div(..)
                        | SeriesOp::ScalarDiv(..)
                        | SeriesOp::Sqrt(_)
                        | SeriesOp::Powf(..)
                        | SeriesOp::SinCos(_)
                        | SeriesOp::Func(..)
                )
            })
            .count()
    }

    /// The series that need no row: made by a step whose recurrence does not read its own
    /// lower orders, and read once, at the current order only (by a sum, a scaling, the
    /// numerator of a quotient, a root's or a sine's argument, or an output). Such a
    /// series is a `let` at each order, e.g. the product in `−0.51 y₁ y₂`.
    fn layout(&self) -> Layout {
        let n = self.series_count as usize;
        let mut reads = vec![0u32; n];
        let mut ranged = vec![false; n];
        let mut count = |x: u32, whole: bool| {
            if let Some(r) = reads.get_mut(x as usize) {
                *r += 1;
            }
            if whole && let Some(r) = ranged.get_mut(x as usize) {
                *r = true;
            }
        };
        for st in &self.steps {
            match st.op {
                SeriesOp::Add(a, b) | SeriesOp::Sub(a, b) => {
                    count(a, false);
                    count(b, false);
                }
                SeriesOp::AddScalar(a, _)
                | SeriesOp::SubScalar(a, _)
                | SeriesOp::ScalarSub(_, a)
                | SeriesOp::Neg(a)
                | SeriesOp::Scale(a, _)
                | SeriesOp::DivScalar(a, _)
                | SeriesOp::Sqrt(a)
                | SeriesOp::SinCos(a) => count(a, false),
                SeriesOp::Div(a, b) => {
                    count(a, false);
                    count(b, true);
                }
                SeriesOp::Mul(a, b) => {
                    count(a, true);
                    count(b, true);
                }
                SeriesOp::Square(a) | SeriesOp::ScalarDiv(_, a) | SeriesOp::Powf(a, _) => {
                    count(a, true)
                }
                SeriesOp::Func(_, a) => count(a, false),
            }
        }
        for out in &self.outputs {
            if let Value::Series(x) = *out {
                count(x, false);
            }
        }
        let mut local = vec![false; n];
        let mut produced = vec![false; n];
        for st in &self.steps {
            for x in [
                Some(st.out),
                matches!(st.op, SeriesOp::SinCos(_)).then_some(st.out + 1),
            ]
            .into_iter()
            .flatten()
            {
                if let Some(p) = produced.get_mut(x as usize) {
                    *p = true;
                }
            }
            let own_history = matches!(
                st.op,
                SeriesOp::Div(..)
                    | SeriesOp::ScalarDiv(..)
                    | SeriesOp::Sqrt(_)
                    | SeriesOp::Powf(..)
                    | SeriesOp::SinCos(_)
                    | SeriesOp::Func(..)
            );
            let x = st.out as usize;
            if !own_history && reads.get(x) == Some(&1) && ranged.get(x) == Some(&false) {
                local[x] = true;
            }
        }
        Layout { local, produced }
    }
}

/// Where each series' coefficients live in the emitted code.
struct Layout {
    /// The series with no row (a `let` at each order; see [`Tape::layout`]).
    local: Vec<bool>,
    /// The series a step makes (sine–cosine pairs both), which have a `let __vX` holding the
    /// current order's value once their step has run: later steps read it there, not back
    /// from the row just written.
    produced: Vec<bool>,
}

impl Layout {
    fn is_local(&self, x: u32) -> bool {
        self.local.get(x as usize).copied().unwrap_or(false)
    }

    /// Series `x` at the current order `k`, in a step after the one that makes it: its
    /// `let`, or its row's entry for the state and the time (written at the order before).
    fn current(&self, x: u32, k: TokenStream) -> TokenStream {
        if self.produced.get(x as usize).copied().unwrap_or(false) {
            let v = value(x);
            quote!(#v)
        } else {
            let id = series(x);
            quote!(#id[#k])
        }
    }
}

/// The `let` holding a made series' value at the current order.
fn value(x: u32) -> Ident {
    Ident::new(&format!("__v{x}"), Span::call_site())
}

/// The `let` holding the interior of step `out`'s sum at the current order (`tag` tells a
/// sine's from a cosine's).
fn interior_id(out: u32, tag: &str) -> Ident {
    Ident::new(&format!("__i{tag}{out}"), Span::call_site())
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

fn method(a: TokenStream, name: &str, sums: Sums) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    if sums.lanes {
        let (a, num) = (sums.value(a), sums.num());
        quote!(<#num>::#f(#a))
    } else {
        quote!(f64::#f(#a))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Arena;

    /// The tape of x' = Σᵢ₌₁ⁿ xⁱ⁺¹·x (n products of a growing power): n + (n − 1) sums.
    fn products(n: usize) -> Tape {
        let mut a = Arena::new();
        let x = a.coordinate("x");
        let mut power = x;
        let mut terms = Vec::new();
        for _ in 0..n {
            power = a.mul(power, x);
            let shifted = a.add(power, x);
            terms.push(a.mul(shifted, x));
        }
        let rhs = a.sum(&terms);
        Tape::new(&a, &[x], None, &[rhs]).unwrap()
    }

    #[test]
    fn large_tapes_call_the_outlined_kernels_and_small_ones_inline_them() {
        let small = products(4);
        assert!(small.sum_count() < OUTLINE_KERNELS_FROM_SUMS);
        let code = small.to_tokens(20, &mut |_| quote!(0.0)).body.to_string();
        // Its products' interiors are fused loops (`fused`), its squares' inlined calls.
        assert!(
            code.contains("__private :: kernels :: square_interior"),
            "{code}"
        );
        assert!(!code.contains("outlined"));
        let large = products(OUTLINE_KERNELS_FROM_SUMS);
        assert!(large.sum_count() >= OUTLINE_KERNELS_FROM_SUMS);
        let code = large.to_tokens(20, &mut |_| quote!(0.0)).body.to_string();
        assert!(code.contains("kernels :: outlined :: dot_reversed"));
        assert!(!code.contains("kernels :: dot_reversed"));
    }

    #[test]
    fn an_orders_dot_products_are_summed_in_one_loop() {
        // x' = Σ (xⁱ⁺¹ + x)·x for i ≤ 4: four products whose interiors have the same length
        // at every order, so one loop of each kind (short, paired) sums them all, and no
        // product calls `dot_reversed` (callgrind: a call's set-up cost as much as its terms).
        let code = products(4)
            .to_tokens(20, &mut |_| quote!(0.0))
            .body
            .to_string();
        assert_eq!(code.matches("for __j in 1 .. __k").count(), 1, "{code}");
        assert_eq!(code.matches("for __p in 0 ..").count(), 1, "{code}");
        assert!(!code.contains("dot_reversed"), "{code}");
        // The lanes fuse only where a lane value fits the registers, and call the kernel
        // otherwise.
        let lanes = products(4)
            .to_lane_tokens(20, &mut |_| quote!(0.0))
            .unwrap()
            .body
            .to_string();
        assert!(lanes.contains("fuse_sums (__L)"), "{lanes}");
        // In loops of at most `FUSED_LANES` sums: more than the scalar code's one.
        let loops = lanes.matches("for __j in 1 .. __k").count();
        assert!(
            (2..=FUSED_SCALAR / FUSED_LANES).contains(&loops),
            "{loops} loops"
        );
        assert!(lanes.contains("lane_kernels :: dot_reversed"));
    }
}
