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
        let mut lets = TokenStream::new();
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
                Op::Sin(a) | Op::Cos(a) => {
                    if let (Some(&s), Some(&c)) = (sines.get(&a), cosines.get(&a)) {
                        if !paired_done.contains(&a) {
                            paired_done.push(a);
                            let (s, c, arg) = (ident(s), ident(c), operand(a));
                            lets.extend(quote!(let (#s, #c): (f64, f64) = f64::sin_cos(#arg);));
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
            lets.extend(quote!(let #name: f64 = #rhs;));
        }
        let outputs = self.outputs.iter().map(|&s| operand(s)).collect();
        Emitted { lets, outputs }
    }
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

fn method(a: TokenStream, name: &str) -> TokenStream {
    let f = Ident::new(name, Span::call_site());
    quote!(f64::#f(#a))
}
