//! The one map from the arena's symbols to the Rust that reads them (`self.m`, `omega[0]`,
//! `state[3]`, …), and the lowering of expressions through it.
//!
//! Symbols are identities: a field is found by the id its parameter got when the checker
//! read it, an input or a coordinate by the id the engine handed out, never by a name. A
//! symbol the map does not know is a bug of the macro; it is reported as a compile error on
//! the struct rather than emitted as a value.

use precess_core::codegen::{Emitted, Op, Program};
use precess_core::sym::{Arena, ExprId, SymbolId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Ident, LitStr};

use crate::lang::ctxt::Ctxt;

/// The Rust expression of each symbol generated code reads.
#[derive(Clone, Default)]
pub struct SymbolTokens {
    entries: Vec<(SymbolId, TokenStream)>,
}

impl SymbolTokens {
    /// Reads `symbol` as `tokens`.
    pub fn insert(&mut self, symbol: SymbolId, tokens: TokenStream) {
        self.entries.push((symbol, tokens));
    }

    /// Reads the symbol `e` is as `tokens`. Every expression passed here is a bare symbol
    /// the engine made; were one not, lowering would report it as unknown.
    pub fn insert_expr(&mut self, arena: &Arena, e: ExprId, tokens: TokenStream) {
        if let Some(s) = arena.as_symbol(e) {
            self.insert(s, tokens);
        }
    }

    /// The Rust that reads `s`, if the map knows it.
    pub fn get(&self, s: SymbolId) -> Option<TokenStream> {
        self.entries
            .iter()
            .find(|(k, _)| *k == s)
            .map(|(_, t)| t.clone())
    }

    /// Lowers `outputs` to straight-line Rust reading the symbols through this map. A symbol
    /// it does not know is recorded in `cx` as an internal error spanned on `ident` (the
    /// derive then emits its errors and stub impls, never this code).
    fn lower(&self, cx: &Ctxt, ident: &Ident, arena: &Arena, outputs: &[ExprId]) -> Emitted {
        let program = Program::lower(arena, outputs);
        // A constant is exact in the engine but rounds to ±inf as an f64 when the values
        // combine past f64's range (1.8e308 − (−1.8e308), say): the code would compute
        // with an infinity, so the derive refuses it.
        if let Some(x) = program.ops().iter().find_map(|op| match op {
            Op::Const(x) if !x.is_finite() => Some(*x),
            _ => None,
        }) {
            cx.error_spanned_by(
                ident,
                format!(
                    "a constant of the body's equations rounds to {x} in f64: its values combine past f64's range (about 1.8e308); use other units"
                ),
            );
        }
        program.to_tokens(&mut |s| match self.get(s) {
            Some(tokens) => tokens,
            None => {
                let symbol = arena.symbol(s);
                cx.error_spanned_by(
                    ident,
                    format!(
                        "internal error of the derive: the generated code reads the symbol `{}` ({:?}), which has no value; please report this",
                        symbol.name, symbol.kind
                    ),
                );
                // Never compiled: the error above replaces the whole expansion.
                quote!(0.0)
            }
        })
    }
}

/// Lowering of one impl's methods: the symbols every method reads (the fields, say), and
/// where an unknown symbol is reported.
pub struct Lowering<'a> {
    cx: &'a Ctxt,
    ident: &'a Ident,
    symbols: SymbolTokens,
}

impl<'a> Lowering<'a> {
    /// Lowers with `symbols`, reporting into `cx` on the struct `ident`.
    pub fn new(cx: &'a Ctxt, ident: &'a Ident, symbols: SymbolTokens) -> Self {
        Lowering { cx, ident, symbols }
    }

    /// The struct the code is lowered for.
    pub fn ident(&self) -> &'a Ident {
        self.ident
    }

    /// `outputs` as straight-line Rust reading the common symbols.
    pub fn lower(&self, arena: &Arena, outputs: &[ExprId]) -> Emitted {
        self.symbols.lower(self.cx, self.ident, arena, outputs)
    }

    /// `outputs` as straight-line Rust reading the common symbols and, for one method,
    /// each expression of `reads` (a bare symbol) as its tokens.
    pub fn lower_reading(
        &self,
        arena: &Arena,
        outputs: &[ExprId],
        reads: &[(ExprId, TokenStream)],
    ) -> Emitted {
        let mut symbols = self.symbols.clone();
        for (e, tokens) in reads {
            symbols.insert_expr(arena, *e, tokens.clone());
        }
        symbols.lower(self.cx, self.ident, arena, outputs)
    }

    /// `outputs` as straight-line Rust reading entry k of the state array `y` for the k-th
    /// expression of `state` (the free body's and the contact's methods over their ODE state).
    pub fn lower_state(&self, arena: &Arena, outputs: &[ExprId], state: &[ExprId]) -> Emitted {
        let reads: Vec<(ExprId, TokenStream)> = state
            .iter()
            .enumerate()
            .map(|(k, &e)| (e, quote!(y[#k])))
            .collect();
        self.lower_reading(arena, outputs, &reads)
    }
}

/// The statements some outputs need bound first, given the outputs.
pub type Prelude<'a> = dyn Fn(&Arena, &[ExprId]) -> TokenStream + 'a;

/// Lowers one method's outputs over a scene's ODE state array `y` (a free body's, a
/// contact's), after the statements `prelude` binds for them.
pub struct StateMethod<'a> {
    /// How the fields and the rest are read.
    pub low: &'a Lowering<'a>,
    /// The state's symbols, entry k read from `y[k]`.
    pub state: &'a [ExprId],
    /// The statements the outputs need first (a free body's user calls), if any.
    pub prelude: Option<&'a Prelude<'a>>,
}

impl StateMethod<'_> {
    /// `{ prelude; lets; build(outputs) }`.
    pub fn body(
        &self,
        arena: &Arena,
        outputs: &[ExprId],
        build: impl FnOnce(&[TokenStream]) -> TokenStream,
    ) -> TokenStream {
        let pre = self.prelude.map(|f| f(arena, outputs)).unwrap_or_default();
        let Emitted { lets, outputs } = self.low.lower_state(arena, outputs, self.state);
        let out = build(&outputs);
        quote!({ #pre #lets #out })
    }
}

/// The struct fields read as the arena's parameters, in the order first used.
#[derive(Default)]
pub struct FieldParameters {
    fields: Vec<(SymbolId, Ident)>,
}

impl FieldParameters {
    /// Records that `field` is read as the parameter `symbol` (once).
    pub fn insert(&mut self, symbol: SymbolId, field: &Ident) {
        if !self.fields.iter().any(|(s, _)| *s == symbol) {
            self.fields.push((symbol, field.clone()));
        }
    }

    /// True if no field is read: the body is made of literals.
    pub fn is_empty(&self) -> bool {
        self.fields.is_empty()
    }

    /// The fields read, in the order first used.
    pub fn fields(&self) -> impl Iterator<Item = &Ident> + '_ {
        self.fields.iter().map(|(_, f)| f)
    }

    /// Statements refusing each field read that is NaN or ±∞, by name, before any rule reads
    /// it (a NaN would pass some rules unnoticed: an inertia entry cancelled in a sum):
    /// `error(name, value)` is the scene's error, an expression, for the field `name` (a
    /// string literal) of value `value`.
    pub fn finite_checks(
        &self,
        error: impl Fn(&LitStr, &TokenStream) -> TokenStream,
    ) -> TokenStream {
        self.fields()
            .map(|f| {
                let name = LitStr::new(&f.to_string(), f.span());
                let value = quote!(self.#f);
                let error = error(&name, &value);
                quote! {
                    if !#value.is_finite() {
                        return ::core::result::Result::Err(#error);
                    }
                }
            })
            .collect()
    }

    /// The map reading each field as `self.field`.
    pub fn tokens(&self) -> SymbolTokens {
        let mut map = SymbolTokens::default();
        for (s, field) in &self.fields {
            map.insert(*s, quote!(self.#field));
        }
        map
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A symbol the map does not know is a spanned internal error, never a value: the old
    /// fallback emitted `f64::NAN` and the body silently computed NaN.
    #[test]
    fn an_unknown_symbol_is_an_error_on_the_struct() {
        let mut arena = Arena::new();
        let m = arena.parameter("m");
        let stray = arena.input("omega_1");
        let sum = arena.add(m, stray);
        let mut map = SymbolTokens::default();
        map.insert_expr(&arena, m, quote!(self.m));
        let ident: Ident = syn::parse_quote!(Spinner);
        let cx = Ctxt::new();
        let code = map.lower(&cx, &ident, &arena, &[sum]);
        let text = format!("{} {:?}", code.lets, code.outputs);
        assert!(!text.contains("NAN"), "{text}");
        let errors = cx.check().expect_err("the stray input is reported");
        assert_eq!(errors.len(), 1);
        let message = errors[0].to_string();
        assert!(
            message.contains("internal error") && message.contains("omega_1"),
            "{message}"
        );
        // Known symbols alone lower without an error.
        let cx = Ctxt::new();
        let code = map.lower(&cx, &ident, &arena, &[m]);
        assert!(cx.check().is_ok());
        assert!(code.lets.to_string().contains("self . m"));
    }
}
