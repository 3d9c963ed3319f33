//! Syntax of the `#[top(...)]` list: `key = value` items, whose meaning `check.rs` decides.

use syn::punctuated::Punctuated;
use syn::{Attribute, Token};

use crate::ctxt::Ctxt;
use crate::rigid::attr::{KeyValue, Parsed, parse_each};

/// The items of every `#[top(...)]` attribute.
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<KeyValue> {
    parse_each(cx, attrs, |a| {
        a.parse_args_with(Punctuated::<KeyValue, Token![,]>::parse_terminated)
    })
}
