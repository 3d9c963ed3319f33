//! The stub impls emitted next to the errors of `#[derive(Mechanism)]`, so code using the
//! struct (its `MechanismDynamics` methods, its coordinate consts, a solver over it) does not
//! add a cascade of "not implemented" and "no associated item" errors to the real ones.
//!
//! The coordinate count the errors may hide is read from the `q = ...` keys as written: the
//! stubs implement `MechanismDynamics<N>` and `System<2N>` for that N, or, when no coordinate
//! could be read, for every N (the uses then fix it).

use proc_macro2::TokenStream;
use quote::quote;
use syn::parse::Parse;
use syn::punctuated::Punctuated;
use syn::{DeriveInput, Expr, Ident, Token};

use super::attr::LinkItem;
use super::joint::path_ident;
use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::stub::hidden_const;
use crate::lang::syntax::KeyValue;

/// The stubs for `input`; nothing for a generic type (its one error is that it is generic).
pub fn stub(input: &DeriveInput) -> TokenStream {
    if !input.generics.params.is_empty() {
        return TokenStream::new();
    }
    let p = Private;
    let ident = &input.ident;
    let coordinates = written_coordinates(input);
    let rolling = rolls(input);
    // Each name once as a const (case aside, as the consts are named), N counting every one
    // written: a duplicate is its own error, and the uses are sized for what was written. A
    // rolling stub has `STATE` and `SPEEDS` of its own (a coordinate so named is an error).
    let mut named: Vec<String> = if rolling {
        vec!["STATE".to_owned(), "SPEEDS".to_owned()]
    } else {
        Vec::new()
    };
    let unique = coordinates.iter().enumerate().filter(|(_, c)| {
        let upper = c.to_string().to_uppercase();
        let new = !named.contains(&upper);
        named.push(upper);
        new
    });
    let consts = unique.map(|(k, c)| hidden_const(&c.to_string(), c.span(), k));
    let stub = quote!(::core::unimplemented!(
        "the #[derive(Mechanism)] description has errors"
    ));
    if rolling {
        return rolling_stub(
            ident,
            coordinates.len(),
            written_speeds(input),
            consts,
            &stub,
        );
    }
    let n = coordinates.len();
    let (dynamics_generics, system_generics, n, s) = if n == 0 {
        (
            quote!(<const __N: usize>),
            quote!(<const __S: usize>),
            quote!(__N),
            quote!(__S),
        )
    } else {
        let s = 2 * n;
        (
            TokenStream::new(),
            TokenStream::new(),
            quote!(#n),
            quote!(#s),
        )
    };
    quote! {
        #[automatically_derived]
        impl #ident {
            #(#consts)*
        }

        #[automatically_derived]
        impl #dynamics_generics #p::MechanismDynamics<#n> for #ident {
            const COORDINATES: [&'static str; #n] = [""; #n];
            const ROUTE: &'static str = "";
            fn accelerations(&self, _: f64, _: &[f64; #n], _: &[f64; #n]) -> ::core::result::Result<[f64; #n], #p::MechanismError> { #stub }
            fn accelerations_unchecked(&self, _: f64, _: &[f64; #n], _: &[f64; #n]) -> [f64; #n] { #stub }
            fn kinetic(&self, _: &[f64; #n], _: &[f64; #n]) -> f64 { #stub }
            fn potential(&self, _: &[f64; #n]) -> f64 { #stub }
            fn power(&self, _: f64, _: &[f64; #n], _: &[f64; #n]) -> f64 { #stub }
            fn conserved_momenta(&self, _: &[f64; #n], _: &[f64; #n]) -> [::core::option::Option<f64>; #n] { #stub }
        }

        #[automatically_derived]
        impl #system_generics #p::System<#s> for #ident {
            fn rhs(&self, _: f64, _: &[f64; #s], _: &mut [f64; #s]) { #stub }
        }
    }
}

/// The coordinate names the `q = ...` keys of the `#[body(...)]` attributes write, in order,
/// whatever else is wrong with the attributes.
fn written_coordinates(input: &DeriveInput) -> Vec<Ident> {
    let mut names: Vec<Ident> = Vec::new();
    for list in lists::<LinkItem>(input, keys::LINK) {
        for item in list {
            let Some(kv) = item.setting() else {
                continue;
            };
            if kv.key != keys::COORDINATES {
                continue;
            }
            let written: Vec<&Expr> = match &kv.value {
                Expr::Array(a) => a.elems.iter().collect(),
                other => vec![other],
            };
            names.extend(written.into_iter().filter_map(path_ident).cloned());
        }
    }
    names
}

/// True if a `#[body(...)]` declares `rolls = ..`: the mechanism's impl is then
/// `RollingDynamics`, not `MechanismDynamics`.
fn rolls(input: &DeriveInput) -> bool {
    lists::<LinkItem>(input, keys::LINK).any(|list| {
        list.iter()
            .any(|item| item.setting().is_some_and(|kv| kv.key == keys::ROLLS))
    })
}

/// The number of names in `speeds = [..]` of `#[mechanism(...)]`, if written.
fn written_speeds(input: &DeriveInput) -> Option<usize> {
    lists::<KeyValue>(input, keys::MECHANISM)
        .flatten()
        .find(|kv| kv.key == keys::SPEEDS)
        .and_then(|kv| match kv.value {
            Expr::Array(a) => Some(a.elems.len()),
            _ => None,
        })
}

/// The stubs of a rolling mechanism: the coordinate consts, `STATE` and
/// `RollingDynamics<N, N − K, K>` for the N coordinates and K speeds written (every M and K
/// when the speeds could not be read, or name more than the coordinates).
fn rolling_stub(
    ident: &Ident,
    n: usize,
    speeds: Option<usize>,
    consts: impl Iterator<Item = TokenStream>,
    stub: &TokenStream,
) -> TokenStream {
    let p = Private;
    let written = speeds.filter(|&k| k <= n).unwrap_or(0);
    let (generics, m, k, state) = match speeds.filter(|&k| k <= n) {
        Some(k) => {
            let m = n - k;
            let state = n + k;
            (TokenStream::new(), quote!(#m), quote!(#k), quote!(#state))
        }
        None => (
            quote!(<const __M: usize, const __K: usize>),
            quote!(__M),
            quote!(__K),
            quote!(#n),
        ),
    };
    quote! {
        #[automatically_derived]
        impl #ident {
            #(#consts)*
            #[doc(hidden)]
            pub const STATE: usize = #state;
            #[doc(hidden)]
            pub const SPEEDS: [usize; #written] = [0; #written];
        }

        #[automatically_derived]
        impl #generics #p::RollingDynamics<#n, #m, #k> for #ident {
            fn partition(&self) -> #p::Partition<#m, #k> { #stub }
            fn coordinate_names(&self) -> [&'static str; #n] { #stub }
            fn mass_forcing(&self, _: f64, _: &[f64; #n], _: &[f64; #n]) -> (#p::SMatrix<f64, #n, #n>, #p::SVector<f64, #n>) { #stub }
            fn constraint_rows(&self, _: &[f64; #n], _: &[f64; #n]) -> (#p::SMatrix<f64, #m, #n>, #p::SVector<f64, #m>) { #stub }
            fn holonomic_rows(&self) -> [bool; #m] { #stub }
            fn heights(&self, _: &[f64; #n]) -> [f64; #m] { #stub }
            fn lowest_tilt(&self, _: &[f64; #n]) -> (usize, f64) { #stub }
            fn energy(&self, _: &[f64; #n], _: &[f64; #n]) -> f64 { #stub }
            fn contact_speed(&self, _: &[f64; #n], _: &[f64; #n]) -> f64 { #stub }
        }
    }
}

/// The item lists of the `#[attribute(...)]` attributes that parse as lists of `T`, read
/// apart from the checks so the stubs stand whatever else is wrong.
fn lists<'a, T: Parse>(
    input: &'a DeriveInput,
    attribute: &'a str,
) -> impl Iterator<Item = Vec<T>> + 'a {
    input
        .attrs
        .iter()
        .filter(move |a| a.path().is_ident(attribute))
        .filter_map(|a| {
            a.parse_args_with(Punctuated::<T, Token![,]>::parse_terminated)
                .ok()
        })
        .map(|list| list.into_iter().collect())
}
