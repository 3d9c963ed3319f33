//! Syntax of the `#[rigid(...)]` list: parts `name(key = value, ...)`, `pivot = [..]` and
//! `taylor = K`, in the grammar of `lang::syntax`; what they mean is `check.rs`'s to decide.

use syn::{Attribute, Ident};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::syntax::{Item, Parsed, parse_items};

/// What `#[rigid]` expected where `name` stands alone.
fn expected(name: &Ident) -> String {
    format!(
        "expected a part `{name}(key = value, ...)`, `{} = [x, y, z]` or `{} = K`",
        keys::PIVOT,
        keys::TAYLOR
    )
}

/// The items of every `#[rigid(...)]` attribute.
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<Item> {
    parse_items(cx, attrs, false, expected)
}
