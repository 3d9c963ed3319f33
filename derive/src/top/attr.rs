//! Syntax of the `#[top(...)]` list: `key = value` items, whose meaning `check.rs` decides.
//! A bare `#[top]` is the empty list: a top under no declared torque.

use syn::Attribute;

use crate::lang::ctxt::Ctxt;
use crate::lang::syntax::{KeyValue, Parsed, parse_settings};

/// The items of every `#[top(...)]` attribute.
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<KeyValue> {
    parse_settings(cx, attrs)
}
