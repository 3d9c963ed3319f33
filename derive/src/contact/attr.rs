//! Syntax of the `#[contact(...)]` list: `key = value` settings in the grammar of
//! `lang::syntax`, whose meaning `check.rs` decides. The surface and the law are values of
//! the call form `name(key = value, ...)` (`surface = sphere(radius = 0.02)`), read by the
//! checker, so a surface or law written where a setting belongs is told its form.

use syn::{Attribute, Ident};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::syntax::{Item, Parsed, parse_items};

/// What `#[contact]` expected where `name` stands alone: a setting.
fn expected(name: &Ident) -> String {
    if keys::SURFACES.iter().any(|(s, _, _)| name == s) {
        format!("expected `{} = {name}(...)`", keys::SURFACE)
    } else if keys::LAWS.iter().any(|(l, _)| name == l) {
        format!("expected `{} = {name}`", keys::LAW)
    } else {
        format!("expected `{name} = value`")
    }
}

/// The items of every `#[contact]` attribute (a bare `#[contact]` has none, and is then told
/// what it misses).
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<Item> {
    parse_items(cx, attrs, true, expected)
}
