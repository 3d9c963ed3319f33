//! Syntax of the `#[rigid(...)]` list: parts `name(key = value, ...)`, `pivot = [..]` and
//! `taylor = K`, parsed with syn into raw items whose meaning `check.rs` decides. (A custom
//! syn parser rather than `parse_nested_meta`, so an unknown part or key is reported and
//! skipped and every error in the list is collected.) `#[top]` lists are `key = value`
//! items too.

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, Token, parenthesized};

use crate::lang::ctxt::Ctxt;
use crate::lang::keys;

/// One entry of the list.
pub enum Item {
    /// `name(key = value, ...)`.
    Part {
        /// The part's name as written.
        name: Ident,
        /// Its keys in order.
        keys: Vec<KeyValue>,
    },
    /// `key = value` at the top level (only [`keys::PIVOT`] and [`keys::TAYLOR`] are
    /// meaningful).
    Setting(Box<KeyValue>),
}

/// `key = value`.
pub struct KeyValue {
    /// The key.
    pub key: Ident,
    /// The value.
    pub value: Expr,
}

impl Parse for KeyValue {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let key = Ident::parse_any(input)?;
        if !input.peek(Token![=]) {
            return Err(input.error(format!("expected `{key} = value`")));
        }
        input.parse::<Token![=]>()?;
        let value = input.parse()?;
        Ok(KeyValue { key, value })
    }
}

impl Parse for Item {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        // `box` is a keyword; parse_any accepts it as a part name.
        let name = Ident::parse_any(input)?;
        if input.peek(syn::token::Paren) {
            let content;
            parenthesized!(content in input);
            let keys = Punctuated::<KeyValue, Token![,]>::parse_terminated(&content)?;
            Ok(Item::Part {
                name,
                keys: keys.into_iter().collect(),
            })
        } else if input.peek(Token![=]) {
            input.parse::<Token![=]>()?;
            let value = input.parse()?;
            Ok(Item::Setting(Box::new(KeyValue { key: name, value })))
        } else {
            Err(syn::Error::new(
                name.span(),
                format!(
                    "expected a part `{name}(key = value, ...)`, `{} = [x, y, z]` or `{} = K`",
                    keys::PIVOT,
                    keys::TAYLOR
                ),
            ))
        }
    }
}

/// The items of a list of attributes.
pub struct Parsed<T> {
    /// The items of every attribute that parsed, in order.
    pub items: Vec<T>,
    /// False if an attribute was not valid syntax (its error is recorded): what the items
    /// leave out (a pivot, say) is then unknown rather than absent.
    pub complete: bool,
}

/// The items of every `#[rigid(...)]` attribute.
pub fn parse(cx: &Ctxt, attrs: &[&Attribute]) -> Parsed<Item> {
    parse_each(cx, attrs, |a| {
        a.parse_args_with(Punctuated::<Item, Token![,]>::parse_terminated)
    })
}

/// Parses each attribute with `parse`, recording syntax errors and going on with the rest.
pub fn parse_each<T>(
    cx: &Ctxt,
    attrs: &[&Attribute],
    parse: impl Fn(&Attribute) -> syn::Result<Punctuated<T, Token![,]>>,
) -> Parsed<T> {
    let mut parsed = Parsed {
        items: Vec::new(),
        complete: true,
    };
    for attr in attrs {
        match parse(attr) {
            Ok(list) => parsed.items.extend(list),
            Err(e) => {
                cx.syn_error(e);
                parsed.complete = false;
            }
        }
    }
    parsed
}
