//! The mechanism's side of the `variational(tangents = m, sensitivities = [field, …])` group
//! of `#[mechanism]`, whose keys, checks and emission are the engine's
//! (`lang::variational`, shared with `#[top]`): `#[mechanism(...)]` holds settings and this
//! one group; the state is (q, q̇) in the coordinates' order, n = 2·dof; a user effort
//! function is refused (its derivatives are unknown), and so are rolling bodies, whose
//! equations are not one `MechanismDerivation` (`VariationalEquations::from_mechanism` takes
//! only that). The generated type checks the fields as the mechanism does.

use precess_core::mechanism::MechanismDerivation;
use precess_core::sym::Arena;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

use super::check::CheckedMechanism;
use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::symbols::FieldParameters;
use crate::lang::syntax::{Item, KeyValue, Parsed};
use crate::lang::variational::{Scene, Target, VARIATIONAL, VariationalKey, form};

/// A `name(key = value, ...)` group of `#[mechanism(...)]`.
pub type Group = (Ident, Vec<KeyValue>);

/// The expected form of a `#[mechanism(...)]` item, for a name followed by neither `=` nor
/// `(`.
fn expected(name: &Ident) -> String {
    format!(
        "expected `{name} = value`, or {}, the generated variational equations",
        form()
    )
}

/// The items of every `#[mechanism(...)]`: its `key = value` settings, and its groups, of
/// which only `variational(...)` is known (an unknown one, or a second, is an error on its
/// name and is dropped).
pub fn parse(cx: &Ctxt, attrs: &[&syn::Attribute]) -> (Parsed<KeyValue>, Option<Group>) {
    let items = crate::lang::syntax::parse_items(cx, attrs, true, expected);
    let mut settings = Parsed {
        items: Vec::new(),
        complete: items.complete,
    };
    let mut group: Option<Group> = None;
    for item in items.items {
        match item {
            Item::Setting(kv) => settings.items.push(*kv),
            Item::Group { name, .. } if name != VARIATIONAL => cx.error_spanned_by(
                &name,
                format!(
                    "unknown group `{name}(...)` in `#[{}]`: the only group is {}, the generated variational equations; settings are written `key = value`",
                    keys::MECHANISM,
                    form()
                ),
            ),
            Item::Group { name, .. } if group.is_some() => cx.error_spanned_by(
                &name,
                format!(
                    "duplicate group `{name}(...)` in `#[{}]`: one set of variational equations per mechanism",
                    keys::MECHANISM
                ),
            ),
            Item::Group { name, keys } => group = Some((name, keys)),
        }
    }
    (settings, group)
}

/// Checks the group against the checked mechanism: `None` after recording the errors.
pub fn check(
    ck: &Checker,
    (name, keys): &Group,
    checked: &CheckedMechanism,
) -> Option<VariationalKey> {
    if checked.rolling.is_some() {
        ck.cx.error_spanned_by(
            name,
            format!(
                "`{VARIATIONAL}(...)` is not supported for a mechanism with rolling bodies: its equations are finished by a projection onto the rolling constraints at each evaluation, not one right-hand side the derive can differentiate; remove `{VARIATIONAL}(...)`"
            ),
        );
        return None;
    }
    let scene = Scene {
        whose: "the mechanism's",
        n: 2 * checked.coordinates.len(),
        user: (!checked.efforts.is_empty()).then_some(keys::EFFORT),
    };
    crate::lang::variational::check(ck, name, keys, &scene)
}

/// The generated type for the state (q, q̇) and right-hand side (q̇, q̈) of `derivation`,
/// reading the fields as the other methods do.
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    parameters: &FieldParameters,
    derivation: &MechanismDerivation,
    key: &VariationalKey,
) -> TokenStream {
    let (state, rhs) = derivation.first_order_system();
    let (p, dof) = (Private, state.len() / 2);
    let target = Target {
        attribute: keys::MECHANISM,
        field: format_ident!("mechanism"),
        chart: "in its coordinates",
        check_doc: " The mechanism's checks of its fields, before any step.",
        check: quote!(#p::MechanismDynamics::<#dof>::check_parameters(self.mechanism)
            .map_err(#p::MechanismError::into_ode_error)),
    };
    let symbols = parameters.tokens();
    crate::lang::variational::expand(cx, ident, arena, &symbols, (&state, &rhs), key, &target)
}
