//! A borrowed view of the derive input: the struct, its fields and its `#[rigid]`
//! attributes, keeping the original tokens for spans.

use syn::{Attribute, Data, DeriveInput, Fields, Ident, Type};

use crate::ctxt::Ctxt;

/// The struct the derive applies to.
pub struct Input<'a> {
    /// Its name.
    pub ident: &'a Ident,
    /// Its named fields (none for a unit struct).
    pub fields: Vec<Field<'a>>,
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
    /// True if the type is written `f64`.
    pub fn is_f64(&self) -> bool {
        matches!(self.ty, Type::Path(p) if p.qself.is_none() && p.path.is_ident("f64"))
    }
}

const SUPPORTED: &str =
    "`RigidBody` can be derived only for a struct with named f64 fields (or no fields)";

impl<'a> Input<'a> {
    /// The view of `input`, or `None` after recording why the derive does not apply.
    pub fn from_syn(cx: &mut Ctxt, input: &'a DeriveInput) -> Option<Input<'a>> {
        // A generic struct has no single set of field values to describe a body with.
        if !input.generics.params.is_empty() || input.generics.where_clause.is_some() {
            cx.error(
                &input.generics,
                format!("{SUPPORTED}; generic structs are not supported"),
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
                    cx.error(
                        unnamed,
                        format!("{SUPPORTED}; tuple structs are not supported: name the fields"),
                    );
                    return None;
                }
            },
            Data::Enum(e) => {
                cx.error(
                    e.enum_token,
                    format!("{SUPPORTED}; enums are not supported"),
                );
                return None;
            }
            Data::Union(u) => {
                cx.error(
                    u.union_token,
                    format!("{SUPPORTED}; unions are not supported"),
                );
                return None;
            }
        };
        let named = |name: &str| {
            input
                .attrs
                .iter()
                .filter(|a| a.path().is_ident(name))
                .collect()
        };
        Some(Input {
            ident: &input.ident,
            fields,
            rigid: named("rigid"),
            top: named("top"),
        })
    }

    /// The field named `name`.
    pub fn field(&self, name: &Ident) -> Option<&Field<'a>> {
        self.fields.iter().find(|f| f.ident == name)
    }
}
