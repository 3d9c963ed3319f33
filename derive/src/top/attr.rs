//! Syntax of the `#[top(...)]` list: `key = value` settings and `rotor(key = value, ...)`
//! groups, in the grammar of `lang::syntax`, whose meaning `check.rs` decides. A bare
//! `#[top]` is the empty list: a top under no declared torque.

use syn::{Attribute, Ident};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::syntax::{Item, Parsed, parse_items};

/// What `#[top]` expected where `name` stands alone: a rotor's form, or a setting's.
fn expected(name: &Ident) -> String {
    let expected = if name == keys::ROTOR {
        crate::lang::rotor::form()
    } else if name == super::variational::VARIATIONAL {
        super::variational::form()
    } else {
        format!("`{name} = value`")
    };
    format!("expected {expected}")
}

/// The items of every `#[top(...)]` attribute (a bare `#[top]` has none).
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<Item> {
    parse_items(cx, attrs, true, expected)
}
