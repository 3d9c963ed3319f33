//! Syntax of the `#[free(...)]` list: `key = value` settings and force parts
//! `name(key = value, ...)`, whose meaning `check.rs` decides. A bare `#[free]` declares a
//! torque-free body.

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Ident, Meta, Token, parenthesized};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::rigid::attr::{KeyValue, Parsed, parse_each};

/// One entry of the list.
pub enum FreeItem {
    /// `key = value`.
    Setting(Box<KeyValue>),
    /// `name(key = value, ...)`: a force at a point.
    Force {
        /// The part's name as written.
        name: Ident,
        /// Its keys in order.
        keys: Vec<KeyValue>,
    },
}

impl Parse for FreeItem {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name = Ident::parse_any(input)?;
        if input.peek(syn::token::Paren) {
            let content;
            parenthesized!(content in input);
            let keys = Punctuated::<KeyValue, Token![,]>::parse_terminated(&content)?;
            Ok(FreeItem::Force {
                name,
                keys: keys.into_iter().collect(),
            })
        } else if input.peek(Token![=]) {
            input.parse::<Token![=]>()?;
            let value = input.parse()?;
            Ok(FreeItem::Setting(Box::new(KeyValue { key: name, value })))
        } else {
            let expected = if keys::FREE_FORCES.iter().any(|&f| name == f) {
                format!(
                    "`{name}({} = [x, y, z], {} = [x, y, z])`",
                    keys::FORCE,
                    keys::FORCE_AT
                )
            } else {
                format!("`{name} = value`")
            };
            Err(syn::Error::new(name.span(), format!("expected {expected}")))
        }
    }
}

/// The items of every `#[free]` attribute (a bare `#[free]` has none).
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<FreeItem> {
    parse_each(cx, attrs, |a| match &a.meta {
        Meta::Path(_) => Ok(Punctuated::new()),
        _ => a.parse_args_with(Punctuated::<FreeItem, Token![,]>::parse_terminated),
    })
}
