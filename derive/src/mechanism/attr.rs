//! Syntax of `#[body(...)]` and `#[mechanism(...)]`, parsed with syn into raw items whose
//! meaning `check.rs` decides. A link list is its name, then `key = value` settings and
//! `group(...)` items: `parts(...)` holds `#[rigid]` parts, any other group `key = value`s.

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, Meta, Token, parenthesized};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::rigid::attr::{Item, KeyValue, Parsed, parse_each};

/// One entry of a `#[body(...)]` list.
pub enum LinkItem {
    /// A bare identifier: the link's name (first in the list).
    Name(Ident),
    /// `key = value`.
    Setting(Box<KeyValue>),
    /// `parts(part(..), ...)`.
    Parts {
        /// The `parts` keyword, for spans.
        keyword: Ident,
        /// The parts, as `#[rigid]` items.
        items: Vec<Item>,
    },
    /// `name(key = value, ...)`: a spring, or an unknown group.
    Group {
        /// The group's name as written.
        name: Ident,
        /// Its keys in order.
        keys: Vec<KeyValue>,
    },
}

impl Parse for LinkItem {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name = Ident::parse_any(input)?;
        if input.peek(syn::token::Paren) {
            let content;
            parenthesized!(content in input);
            if name == keys::PARTS_GROUP {
                let items = Punctuated::<Item, Token![,]>::parse_terminated(&content)?;
                Ok(LinkItem::Parts {
                    keyword: name,
                    items: items.into_iter().collect(),
                })
            } else {
                let list = Punctuated::<KeyValue, Token![,]>::parse_terminated(&content)?;
                Ok(LinkItem::Group {
                    name,
                    keys: list.into_iter().collect(),
                })
            }
        } else if input.peek(Token![=]) {
            input.parse::<Token![=]>()?;
            let value = input.parse()?;
            Ok(LinkItem::Setting(Box::new(KeyValue { key: name, value })))
        } else {
            Ok(LinkItem::Name(name))
        }
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

/// The items of every `#[mechanism(...)]` attribute (a bare `#[mechanism]` has none).
pub fn parse_settings(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<KeyValue> {
    parse_each(cx, attrs, |a| match &a.meta {
        Meta::Path(_) => Ok(Punctuated::new()),
        _ => a.parse_args_with(Punctuated::<KeyValue, Token![,]>::parse_terminated),
    })
}

/// Takes the `taylor = K` items out of the `#[mechanism(...)]` settings (so the other keys
/// are checked as before) and returns the first one's value; a repeat is an error on its key.
/// The value is judged by `crate::lang::taylor::check` once the links are known, since a user
/// function among the efforts rules the key out.
pub fn take_taylor(cx: &Ctxt, settings: &mut Parsed<KeyValue>) -> Option<Expr> {
    let mut value: Option<Expr> = None;
    settings.items.retain(|kv| {
        if kv.key != keys::TAYLOR {
            return true;
        }
        if value.is_some() {
            cx.error_spanned_by(&kv.key, format!("duplicate key `{}`", kv.key));
        } else {
            value = Some(kv.value.clone());
        }
        false
    });
    value
}
