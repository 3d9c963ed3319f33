//! `#[derive(Mechanism)]`: a tree of rigid bodies described by `#[body(...)]` attributes
//! (each a body in the `#[rigid]` part language, joined to its parent by a named joint) and
//! `#[mechanism(...)]` settings, in the phases every attribute of the derive has: `attr`
//! (syntax), `check` (meaning and the tree's rules), `expand` (the `MechanismDynamics` impl).

pub mod attr;
pub mod check;
pub mod expand;
mod joint;
mod loads;
mod tree;

use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use syn::{Data, DeriveInput, Fields};

use crate::ctxt::Ctxt;
use crate::keys;
use crate::rigid::ast::{Field, Input};
use crate::rigid::check::Checker;
use crate::symbols::FieldParameters;

const SUPPORTED: &str =
    "`Mechanism` can be derived only for a struct with named f64 fields (or no fields)";

/// The whole derive: the impls, or every error.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let cx = Ctxt::new();
    let expanded = expand(&cx, input);
    match cx.check() {
        Ok(()) => expanded.unwrap_or_else(|| {
            syn::Error::new_spanned(
                &input.ident,
                "internal error of the derive: it stopped without an error; please report this",
            )
            .to_compile_error()
        }),
        // No stub impls: `MechanismDynamics<N>` needs the coordinate count the errors may
        // hide, and a wrong N would add errors of its own.
        Err(errors) => errors.iter().map(syn::Error::to_compile_error).collect(),
    }
}

/// Every phase: syntax and meaning of all attributes, then the expansion.
fn expand(cx: &Ctxt, input: &DeriveInput) -> Option<TokenStream> {
    let ast = view(cx, input)?;
    let attrs = |name: &str| -> Vec<&syn::Attribute> {
        input
            .attrs
            .iter()
            .filter(|a| a.path().is_ident(name))
            .collect()
    };
    let settings = attr::parse_settings(cx, &attrs(keys::MECHANISM));
    let links = attr::parse_links(cx, &attrs(keys::LINK));
    let mut arena = Arena::new();
    let mut parameters = FieldParameters::default();
    let mut ck = Checker::new(cx, &ast, &mut arena, &mut parameters);
    let checked = check::check(&mut ck, &settings, &links)?;
    expand::expand(cx, &input.ident, &mut arena, &parameters, &checked)
}

/// The struct as the value checker sees it: its name and named fields.
fn view<'a>(cx: &Ctxt, input: &'a DeriveInput) -> Option<Input<'a>> {
    if !input.generics.params.is_empty() {
        cx.error_spanned_by(
            &input.generics,
            format!("{SUPPORTED}; generic structs are not supported"),
        );
        return None;
    }
    if let Some(clause) = &input.generics.where_clause {
        cx.error_spanned_by(
            clause,
            format!("{SUPPORTED}; where clauses are not supported: remove it"),
        );
        return None;
    }
    let fields = match &input.data {
        Data::Struct(s) => match &s.fields {
            Fields::Named(named) => named
                .named
                .iter()
                .filter_map(|f| {
                    Some(Field {
                        ident: f.ident.as_ref()?,
                        ty: &f.ty,
                    })
                })
                .collect(),
            Fields::Unit => Vec::new(),
            Fields::Unnamed(unnamed) => {
                cx.error_spanned_by(
                    unnamed,
                    format!("{SUPPORTED}; tuple structs are not supported: name the fields"),
                );
                return None;
            }
        },
        Data::Enum(e) => {
            cx.error_spanned_by(
                e.enum_token,
                format!("{SUPPORTED}; enums are not supported"),
            );
            return None;
        }
        Data::Union(u) => {
            cx.error_spanned_by(
                u.union_token,
                format!("{SUPPORTED}; unions are not supported"),
            );
            return None;
        }
    };
    Some(Input {
        ident: &input.ident,
        fields,
        rigid: Vec::new(),
        top: Vec::new(),
    })
}
