//! A borrowed view of the struct a derive applies to: its name, its fields and its
//! attributes (the `#[rigid]` and `#[top]` ones at hand, which more than one attribute's
//! checks read), keeping the original tokens for spans.

use quote::ToTokens;
use syn::{Attribute, Data, DeriveInput, Fields, Ident, Type, Visibility};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;

/// The struct the derive applies to.
pub struct Input<'a> {
    /// Its name.
    pub ident: &'a Ident,
    /// Its visibility, which the types generated beside it take.
    pub vis: &'a Visibility,
    /// Its named fields (none for a unit struct).
    pub fields: Vec<Field<'a>>,
    /// All its attributes.
    attrs: &'a [Attribute],
    /// The `#[rigid(...)]` attributes, in order.
    pub rigid: Vec<&'a Attribute>,
    /// The `#[top(...)]` attributes, in order.
    pub top: Vec<&'a Attribute>,
}

/// A named field.
pub struct Field<'a> {
    /// Its name.
    pub ident: &'a Ident,
    /// Its type as written.
    pub ty: &'a Type,
}

impl Field<'_> {
    /// True if the type is written `f64` or as the primitive's path
    /// (`core::primitive::f64`, `::std::primitive::f64`, …).
    pub fn is_f64(&self) -> bool {
        let Type::Path(p) = self.ty else {
            return false;
        };
        let segments: Vec<String> = p
            .path
            .segments
            .iter()
            .filter(|s| s.arguments.is_none())
            .map(|s| s.ident.to_string())
            .collect();
        if p.qself.is_some() || segments.len() != p.path.segments.len() {
            return false;
        }
        // A bare `f64` cannot be a path from the crate root, and the primitive module lives
        // only in `core` and `std`: any other `f64` is a user's type of that name.
        match segments.as_slice() {
            [f] => p.path.leading_colon.is_none() && f == "f64",
            [krate, module, f] => {
                (krate == "core" || krate == "std") && module == "primitive" && f == "f64"
            }
            _ => false,
        }
    }
}

impl<'a> Input<'a> {
    /// The view of `input` for the derive named `derive` (its name in the errors).
    pub fn for_derive(cx: &Ctxt, input: &'a DeriveInput, derive: &str) -> Option<Input<'a>> {
        let supported = format!(
            "`{derive}` can be derived only for a struct with named f64 fields (or no fields)"
        );
        // A generic struct has no single set of field values to describe a body with.
        if !input.generics.params.is_empty() {
            cx.error_spanned_by(
                &input.generics,
                format!("{supported}; generic structs are not supported"),
            );
            return None;
        }
        // Spanned on the clause itself: `Generics` without parameters prints no tokens.
        if let Some(clause) = &input.generics.where_clause {
            cx.error_spanned_by(
                clause,
                format!("{supported}; where clauses are not supported: remove it"),
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
                        format!("{supported}; tuple structs are not supported: name the fields"),
                    );
                    return None;
                }
            },
            Data::Enum(e) => {
                cx.error_spanned_by(
                    e.enum_token,
                    format!("{supported}; enums are not supported"),
                );
                return None;
            }
            Data::Union(u) => {
                cx.error_spanned_by(
                    u.union_token,
                    format!("{supported}; unions are not supported"),
                );
                return None;
            }
        };
        let mut ast = Input {
            ident: &input.ident,
            vis: &input.vis,
            fields,
            attrs: &input.attrs,
            rigid: Vec::new(),
            top: Vec::new(),
        };
        ast.rigid = ast.attributes(keys::RIGID);
        ast.top = ast.attributes(keys::TOP);
        Some(ast)
    }

    /// The struct's attributes named `name` (`#[free]`, `#[body]`, …), in order.
    pub fn attributes(&self, name: &str) -> Vec<&'a Attribute> {
        self.attrs
            .iter()
            .filter(|a| a.path().is_ident(name))
            .collect()
    }

    /// The field named `name`.
    pub fn field(&self, name: &Ident) -> Option<&Field<'a>> {
        self.fields.iter().find(|f| f.ident == name)
    }

    /// Every `#[rigid]` attribute's tokens, to span an error on the whole description.
    pub fn rigid_tokens(&self) -> proc_macro2::TokenStream {
        self.rigid.iter().map(|a| a.to_token_stream()).collect()
    }
}
