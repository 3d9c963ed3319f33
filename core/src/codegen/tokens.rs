//! Emission of a [`Program`] as Rust tokens: one `let` per instruction, `sin_cos` for paired
//! sines and cosines, constants inlined as literals.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use super::program::{Op, Program, Slot};
use crate::sym::{IdMap, SymbolId};

/// Rust code for a program: statements to splice into a function body, then one expression
/// per output (an identifier bound by the statements, or a literal).
#[derive(Clone, Debug)]
pub struct Emitted {
    /// `let` statements, in order.
    pub lets: TokenStream,
    /// One expression per output of the program.
    pub outputs: Vec<TokenStream>,
}

fn ident(slot: Slot) -> Ident {
    Ident::new(&format!("__p{slot}"), Span::call_site())
}

/// A literal for a constant, parenthesised when negative so it binds as one operand.
pub fn f64_literal(x: f64) -> TokenStream {
    if !x.is_finite() {
        // Unreachable from exact rationals; kept total rather than panicking in a macro.
        let bits = x.to_bits();
        return quote!(f64::from_bits(#bits));
    }
    let lit = Literal::f64_suffixed(x.abs());
    if x.is_sign_negative() && x != 0.0 {
        quote!((-#lit))
    } else {
        quote!(#lit)
    }
}

impl Program {
    /// Emits the program. `input` gives the Rust expression of each symbol the program reads
    /// (e.g. `self.m` or `q[1]`); each is read once into a local.
    ///
    /// ```
    /// use precess_core::{codegen::Program, sym::Arena};
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let e = a.powi(x, 3).unwrap();
    /// let p = Program::lower(&a, &[e]);
    /// let code = p.to_tokens(&mut |_| quote::quote!(x));
    /// let text = code.lets.to_string();
    /// assert!(text.contains("__p1 * __p0"));
    /// ```
    pub fn to_tokens(&self, input: &mut dyn FnMut(SymbolId) -> TokenStream) -> Emitted {
        let operand = |s: Slot| -> TokenStream {
            match self.ops[s as usize] {
                Op::Const(c) => f64_literal(c),
                _ => {
                    let id = ident(s);
                    quote!(#id)
                }
            }
        };
        // Arguments whose sine and cosine are both needed, with the slot of each.
        let mut sines: IdMap<Slot, Slot> = IdMap::default();
        let mut cosines: IdMap<Slot, Slot> = IdMap::default();
        for (i, op) in self.ops.iter().enumerate() {
            match *op {
                Op::Sin(a) => _ = sines.insert(a, i as Slot),
                Op::Cos(a) => _ = cosines.insert(a, i as Slot),
                _ => {}
            }
        }
        let mut stmts: Vec<Statement> = Vec::with_capacity(self.ops.len());
        let mut paired_done: Vec<Slot> = Vec::new();
        for (i, op) in self.ops.iter().enumerate() {
            let slot = i as Slot;
            let name = ident(slot);
            let rhs = match *op {
                Op::Const(_) => continue,
                Op::Input(s) => input(s),
                Op::Add(a, b) => binary(operand(a), quote!(+), operand(b)),
                Op::Sub(a, b) => binary(operand(a), quote!(-), operand(b)),
                Op::Mul(a, b) => binary(operand(a), quote!(*), operand(b)),
                Op::Div(a, b) => binary(operand(a), quote!(/), operand(b)),
                Op::Neg(a) => {
                    let a = operand(a);
                    quote!(-#a)
                }
                Op::Sqrt(a) => method(operand(a), "sqrt"),
                Op::Powf(a, r) => {
                    let (a, r) = (operand(a), f64_literal(r));
                    quote!(f64::powf(#a, #r))
                }
                Op::Func(f, a) => f.call_tokens(operand(a)),
                Op::Sin(a) | Op::Cos(a) => {
                    if let (Some(&s), Some(&c)) = (sines.get(&a), cosines.get(&a)) {
                        if !paired_done.contains(&a) {
                            paired_done.push(a);
                            let (si, ci, arg) = (ident(s), ident(c), operand(a));
                            stmts.push(Statement {
                                defines: vec![s, c],
                                uses: vec![a],
                                tokens: quote!(let (#si, #ci): (f64, f64) = f64::sin_cos(#arg);),
                            });
                        }
                        continue;
                    }
                    let f = if matches!(op, Op::Sin(_)) {
                        "sin"
                    } else {
                        "cos"
                    };
                    method(operand(a), f)
                }
            };
            stmts.push(Statement {
                defines: vec![slot],
                uses: operands(op),
                tokens: quote!(let #name: f64 = #rhs;),
            });
        }
        let lets = chunked(stmts, &self.outputs);
        let outputs = self.outputs.iter().map(|&s| operand(s)).collect();
        Emitted { lets, outputs }
    }
}

/// One `let` of the emitted code, with the slots it binds and reads.
struct Statement {
    defines: Vec<Slot>,
    uses: Vec<Slot>,
    tokens: TokenStream,
}

/// How many `let`s share one block (see [`chunked`]).
const LETS_PER_BLOCK: usize = 128;

/// The operand slots an instruction reads.
fn operands(op: &Op) -> Vec<Slot> {
    match *op {
        Op::Const(_) | Op::Input(_) => Vec::new(),
        Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => vec![a, b],
        Op::Neg(a) | Op::Sqrt(a) | Op::Powf(a, _) | Op::Sin(a) | Op::Cos(a) | Op::Func(_, a) => {
            vec![a]
        }
    }
}

/// The statements, grouped: every `let` opens a scope nested in the previous one, and with
/// tens of thousands in one function rustc's debug-info writer recurses past its stack. So
/// past [`LETS_PER_BLOCK`] statements each group becomes a block that returns the slots
/// later groups read, `let (a, b,): (f64, f64,) = { …; (a, b,) };`, which keeps the nesting
/// depth near `n / LETS_PER_BLOCK + LETS_PER_BLOCK`. The computation is the same.
fn chunked(stmts: Vec<Statement>, outputs: &[Slot]) -> TokenStream {
    if stmts.len() <= LETS_PER_BLOCK {
        return stmts.into_iter().map(|s| s.tokens).collect();
    }
    // The last group that reads each slot (outputs are read after all of them).
    let mut last_read: IdMap<Slot, usize> = IdMap::default();
    for (i, st) in stmts.iter().enumerate() {
        for &u in &st.uses {
            last_read.insert(u, i / LETS_PER_BLOCK);
        }
    }
    for &o in outputs {
        last_read.insert(o, usize::MAX);
    }
    let mut out = TokenStream::new();
    for (group, chunk) in stmts.chunks(LETS_PER_BLOCK).enumerate() {
        let exported: Vec<Ident> = chunk
            .iter()
            .flat_map(|st| st.defines.iter())
            .filter(|s| last_read.get(s).is_some_and(|&g| g > group))
            .map(|&s| ident(s))
            .collect();
        let body: TokenStream = chunk.iter().map(|st| st.tokens.clone()).collect();
        if exported.is_empty() {
            out.extend(quote!({ #body }));
        } else {
            let types = exported.iter().map(|_| quote!(f64));
            out.extend(quote!(let (#(#exported,)*): (#(#types,)*) = { #body (#(#exported,)*) };));
        }
    }
    out
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

fn method(a: TokenStream, name: &str) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    quote!(f64::#f(#a))
}
