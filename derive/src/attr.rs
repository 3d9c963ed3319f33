//! Syntax of the `#[rigid(...)]` list: parts `name(key = value, ...)` and `pivot = [..]`,
//! parsed with syn into raw items whose meaning `check.rs` decides. (A custom syn parser
//! rather than `parse_nested_meta`, so an unknown part or key is reported and skipped and
//! every error in the list is collected.)

use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Expr, Ident, Token, parenthesized};

/// One entry of the list.
pub enum Item {
    /// `name(key = value, ...)`.
    Part {
        /// The part's name as written.
        name: Ident,
        /// Its keys in order.
        keys: Vec<KeyValue>,
    },
    /// `key = value` at the top level (only `pivot` is meaningful).
    Setting(KeyValue),
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
            Ok(Item::Setting(KeyValue { key: name, value }))
        } else {
            Err(syn::Error::new(
                name.span(),
                format!("expected a part `{name}(key = value, ...)` or `pivot = [x, y, z]`"),
            ))
        }
    }
}

/// The items of one `#[rigid(...)]` attribute.
pub fn parse(attr: &syn::Attribute) -> syn::Result<Vec<Item>> {
    let items = attr.parse_args_with(Punctuated::<Item, Token![,]>::parse_terminated)?;
    Ok(items.into_iter().collect())
}
