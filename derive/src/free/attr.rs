//! Syntax of the `#[free(...)]` list: `key = value` settings and force parts
//! `name(key = value, ...)`, in the grammar of `lang::syntax`, whose meaning `check.rs`
//! decides. A bare `#[free]` declares a torque-free body.

use syn::{Attribute, Ident};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::syntax::{Item, Parsed, parse_items};

/// What `#[free]` expected where `name` stands alone: a force part's form, or a setting's.
fn expected(name: &Ident) -> String {
    let expected = if keys::FREE_FORCES.iter().any(|&f| name == f) {
        format!(
            "`{name}({} = [x, y, z], {} = [x, y, z])`",
            keys::FORCE,
            keys::FORCE_AT
        )
    } else if name == keys::ROTOR {
        crate::lang::rotor::form()
    } else {
        format!("`{name} = value`")
    };
    format!("expected {expected}")
}

/// The items of every `#[free]` attribute (a bare `#[free]` has none).
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<Item> {
    parse_items(cx, attrs, true, expected)
}
