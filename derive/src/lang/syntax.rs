//! The grammar every attribute list shares, parsed with syn into raw items whose meaning
//! each attribute's `check.rs` decides: `key = value` settings and `name(key = value, ...)`
//! groups (a part, a force at a point, a spring). A custom syn parser rather than
//! `parse_nested_meta`, so an unknown part or key is reported by the checker and skipped, and
//! every error in the list is collected.

use proc_macro2::TokenTree;
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream, discouraged::Speculative};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, Meta, Token, parenthesized};

use super::ctxt::Ctxt;
use super::keys;
use super::units;

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
        let value = parse_value(input)?;
        Ok(KeyValue { key, value })
    }
}

/// A value: an expression, with units attached (`2 cm` becomes an expression syn reads,
/// see `units.rs`). A value without units is parsed as written, with syn's own errors.
pub fn parse_value(input: ParseStream) -> syn::Result<Expr> {
    let fork = input.fork();
    let mut tokens = Vec::new();
    // A value ends at the next comma of its list: commas inside it sit in groups.
    while !fork.is_empty() && !fork.peek(Token![,]) {
        tokens.push(fork.parse::<TokenTree>()?);
    }
    match units::attach(tokens) {
        Some(rewritten) => {
            input.advance_to(&fork);
            syn::parse2(rewritten)
        }
        None => input.parse(),
    }
}

/// One entry of a list that holds groups and settings.
pub enum Item {
    /// `name(key = value, ...)`.
    Group {
        /// The group's name as written.
        name: Ident,
        /// Its keys in order.
        keys: Vec<KeyValue>,
    },
    /// `key = value`.
    Setting(Box<KeyValue>),
}

/// The error for a name followed by neither `(` nor `=`: what the attribute expected there,
/// given the name as written.
pub type Expected = fn(&Ident) -> String;

impl Item {
    /// One item, with `expected` as the error for a name that starts neither form.
    pub fn parse_or(input: ParseStream, expected: Expected) -> syn::Result<Self> {
        // `box` is a keyword; parse_any accepts it as a part name.
        let name = Ident::parse_any(input)?;
        if input.peek(syn::token::Paren) {
            let content;
            parenthesized!(content in input);
            let keys = Punctuated::<KeyValue, Token![,]>::parse_terminated(&content)?;
            Ok(Item::Group {
                name,
                keys: keys.into_iter().collect(),
            })
        } else if input.peek(Token![=]) {
            input.parse::<Token![=]>()?;
            let value = parse_value(input)?;
            Ok(Item::Setting(Box::new(KeyValue { key: name, value })))
        } else {
            Err(syn::Error::new(name.span(), expected(&name)))
        }
    }

    /// A comma-separated list of items, as [`Item::parse_or`] reads each.
    pub fn parse_list(input: ParseStream, expected: Expected) -> syn::Result<Vec<Item>> {
        // As `Punctuated::parse_terminated`, which takes no closure: a trailing comma allowed.
        let mut items = Vec::new();
        while !input.is_empty() {
            items.push(Item::parse_or(input, expected)?);
            if input.is_empty() {
                break;
            }
            input.parse::<Token![,]>()?;
        }
        Ok(items)
    }
}

/// The `key = value` settings of `settings` the attribute's own check reads, in order: each
/// key's first only, a repeat an error on its key (two gravities would be ambiguous), with
/// `in_what` naming the attribute (`` `#[top]` ``); `taylor` is left to `TaylorKey`.
pub fn distinct<'a>(
    cx: &'a Ctxt,
    settings: impl IntoIterator<Item = &'a KeyValue>,
    in_what: &'a str,
) -> impl Iterator<Item = &'a KeyValue> {
    let mut seen: Vec<&Ident> = Vec::new();
    settings.into_iter().filter(move |kv| {
        if kv.key == keys::TAYLOR {
            return false;
        }
        if seen.contains(&&kv.key) {
            cx.error_spanned_by(&kv.key, format!("duplicate key `{}` in {in_what}", kv.key));
            return false;
        }
        seen.push(&kv.key);
        true
    })
}

/// The items of a list of attributes.
pub struct Parsed<T> {
    /// The items of every attribute that parsed, in order.
    pub items: Vec<T>,
    /// False if an attribute was not valid syntax (its error is recorded): what the items
    /// leave out (a pivot, say) is then unknown rather than absent.
    pub complete: bool,
}

/// The items of every attribute of `attrs`, groups and settings. With `bare`, an attribute
/// without a list (`#[free]`) is the empty list: every key of it is optional.
pub fn parse_items(
    cx: &Ctxt,
    attrs: &[&Attribute],
    bare: bool,
    expected: Expected,
) -> Parsed<Item> {
    parse_each(cx, attrs, |a| match &a.meta {
        Meta::Path(_) if bare => Ok(Vec::new()),
        _ => a.parse_args_with(|input: ParseStream| Item::parse_list(input, expected)),
    })
}

/// Parses each attribute with `parse`, recording syntax errors and going on with the rest.
fn parse_each<T>(
    cx: &Ctxt,
    attrs: &[&Attribute],
    parse: impl Fn(&Attribute) -> syn::Result<Vec<T>>,
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
