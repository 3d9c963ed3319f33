//! Syntax of `#[body(...)]`, in the grammar of `lang::syntax` (`#[mechanism(...)]` is a list of
//! settings and one group, read by `variational::parse`), whose meaning `check.rs` decides. A
//! link list is its name, then `key = value` settings and `group(...)` items: `parts(...)`
//! holds parts of `lang::parts`, any other group `key = value`s.

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Ident, Meta, Token, parenthesized};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::syntax::{Item, KeyValue};

/// One entry of a `#[body(...)]` list.
pub enum LinkItem {
    /// A bare identifier: the link's name (first in the list).
    Name(Ident),
    /// `parts(part(..), ...)`.
    Parts {
        /// The `parts` keyword, for spans.
        keyword: Ident,
        /// The parts, as `#[rigid]` items.
        items: Vec<Item>,
    },
    /// `key = value`, or `name(key = value, ...)` (a spring, or an unknown group).
    Item(Item),
}

impl LinkItem {
    /// The `key = value` setting this item is, if it is one.
    pub fn setting(&self) -> Option<&KeyValue> {
        match self {
            LinkItem::Item(Item::Setting(kv)) => Some(kv),
            _ => None,
        }
    }
}

impl Parse for LinkItem {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        // A name alone (neither a group nor a setting follows) is the body's name.
        if !input.peek2(syn::token::Paren) && !input.peek2(Token![=]) {
            return Ok(LinkItem::Name(Ident::parse_any(input)?));
        }
        let fork = input.fork();
        if Ident::parse_any(&fork).is_ok_and(|name| name == keys::PARTS_GROUP)
            && fork.peek(syn::token::Paren)
        {
            let keyword = Ident::parse_any(input)?;
            let content;
            parenthesized!(content in input);
            let items = crate::lang::parts::parse_parts(&content)?;
            return Ok(LinkItem::Parts { keyword, items });
        }
        // Unreachable message: a name followed by `(` or `=` starts an item.
        Item::parse_or(input, |name| format!("expected `{name} = value`")).map(LinkItem::Item)
    }
}

/// One `#[body(...)]` attribute's items, with the attribute for spans.
pub struct LinkAttr<'a> {
    /// The attribute.
    pub attr: &'a Attribute,
    /// Its items in order.
    pub items: Vec<LinkItem>,
}

/// Every `#[body(...)]` that parsed, and whether all did.
pub struct Links<'a> {
    /// The links that parsed, in order.
    pub links: Vec<LinkAttr<'a>>,
    /// False if one was not valid syntax (its error is recorded).
    pub complete: bool,
}

/// The items of every `#[body(...)]` attribute, each kept apart (one link each).
pub fn parse_links<'a>(cx: &Ctxt, attrs: &[&'a Attribute]) -> Links<'a> {
    let mut links = Links {
        links: Vec::new(),
        complete: true,
    };
    for &attr in attrs {
        let parsed = match &attr.meta {
            Meta::List(_) => {
                attr.parse_args_with(Punctuated::<LinkItem, Token![,]>::parse_terminated)
            }
            _ => Err(syn::Error::new_spanned(
                attr,
                format!(
                    "expected `#[{}(name, {} = ..., {} = kind(...), {} = name, {}(...))]`",
                    keys::LINK,
                    keys::PARENT,
                    keys::JOINT,
                    keys::COORDINATES,
                    keys::PARTS_GROUP
                ),
            )),
        };
        match parsed {
            Ok(list) => links.links.push(LinkAttr {
                attr,
                items: list.into_iter().collect(),
            }),
            Err(e) => {
                cx.syn_error(e);
                links.complete = false;
            }
        }
    }
    links
}
