//! Expansion of `#[contact]`: the `ContactDynamics` impl.

use proc_macro2::TokenStream;

use super::check::ContactSettings;
use crate::lang::expansion::Expansion;
use crate::rigid::check::CheckedBody;

/// `impl ContactDynamics for …`, or `None` after recording why it could not be derived.
pub fn expand(
    _ex: &mut Expansion,
    _checked: &CheckedBody,
    _settings: &ContactSettings,
) -> Option<TokenStream> {
    Some(TokenStream::new())
}
