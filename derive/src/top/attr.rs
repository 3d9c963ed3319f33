//! Syntax of the `#[top(...)]` list: `key = value` items, whose meaning `check.rs` decides.
//! A bare `#[top]` is the empty list: a top under no declared torque.

use syn::punctuated::Punctuated;
use syn::{Attribute, Meta, Token};

use crate::lang::ctxt::Ctxt;
use crate::rigid::attr::{KeyValue, Parsed, parse_each};

/// The items of every `#[top(...)]` attribute.
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<KeyValue> {
    parse_each(cx, attrs, |a| match &a.meta {
        // Every key is optional, so no list at all is the torque-free top.
        Meta::Path(_) => Ok(Punctuated::new()),
        _ => a.parse_args_with(Punctuated::<KeyValue, Token![,]>::parse_terminated),
    })
}
