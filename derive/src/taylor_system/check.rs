//! Meaning of `taylor_system!`'s statements: the struct's fields are its f64 parameters
//! (none named `t`, the time); one `state [...]` of distinct new names; one `taylor = K`;
//! exactly one equation per state variable; events of distinct names, none the struct's.
//! Every error is recorded, spanned on the
//! offending tokens, before giving up.

use syn::{Expr, Fields, Ident};

use super::attr::{EVENT, STATE, Statement, SystemInput, TIME};
use crate::lang::ast::Field;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys::{self, did_you_mean};
use crate::lang::taylor::TaylorKey;

/// The checked system.
pub struct CheckedSystem<'a> {
    /// The state variables in order.
    pub state: Vec<&'a Ident>,
    /// The struct's fields (all f64), the parameters.
    pub fields: Vec<&'a Ident>,
    /// The maximum Taylor order.
    pub order: usize,
    /// The right-hand side of each state variable, in state order.
    pub equations: Vec<&'a Expr>,
    /// The event functions, `(name, g)`, as written.
    pub events: Vec<(&'a Ident, &'a Expr)>,
}

/// Checks the input; `None` after recording every error found.
pub fn check<'a>(cx: &Ctxt, input: &'a SystemInput) -> Option<CheckedSystem<'a>> {
    let errors_before = cx.error_count();
    let item = &input.item;
    if !item.generics.params.is_empty() || item.generics.where_clause.is_some() {
        cx.error_spanned_by(
            &item.generics,
            "a `taylor_system!` struct cannot be generic: its fields are f64 parameters",
        );
    }
    let fields = fields(cx, &item.fields);
    let mut state: Option<(&Ident, &[Ident])> = None;
    let mut equations: Vec<(&Ident, &Expr)> = Vec::new();
    let mut events: Vec<(&Ident, &Expr)> = Vec::new();
    for statement in &input.statements {
        match statement {
            Statement::State { keyword, names } => {
                if state.is_some() {
                    cx.error_spanned_by(
                        keyword,
                        format!("duplicate `{STATE}`: declare the state once"),
                    );
                } else {
                    state = Some((keyword, names));
                }
            }
            // Read by `TaylorKey` below.
            Statement::Taylor { .. } => {}
            Statement::Equation { name, value } => equations.push((name, value)),
            Statement::Event { name, value } => {
                // Each event is a type beside the system's struct: two of one name, or one
                // named as the struct, would be two items of one name.
                if events.iter().any(|(n, _)| *n == name) {
                    cx.error_spanned_by(
                        name,
                        format!("a second `{EVENT} {name}`: name each event once"),
                    );
                } else if *name == item.ident {
                    cx.error_spanned_by(
                        name,
                        format!(
                            "`{EVENT} {name}` is named as the system's struct: an event is a type of its own"
                        ),
                    );
                } else {
                    events.push((name, value));
                }
            }
        }
    }
    let orders = input.statements.iter().filter_map(|s| match s {
        Statement::Taylor { keyword, value } => Some((keyword, value)),
        _ => None,
    });
    let taylor = TaylorKey::find(cx, orders, "`taylor_system!`");
    let Some((keyword, names)) = state else {
        cx.error_spanned_by(
            &item.ident,
            format!("missing the state: add `{STATE} [x, y, …];` after the struct"),
        );
        return None;
    };
    let state = state_names(cx, keyword, names, &fields);
    let order = if taylor.is_given() {
        taylor.order(cx, &[])
    } else {
        cx.error_spanned_by(
            &item.ident,
            format!(
                "missing the maximum Taylor order: add `{} = 20;` (about 20 reaches double precision)",
                keys::TAYLOR
            ),
        );
        None
    };
    let mut by_state: Vec<Option<&Expr>> = vec![None; state.len()];
    for (name, value) in equations {
        let Some(i) = state.iter().position(|s| *s == name) else {
            if names.contains(name) {
                // A state variable already refused above.
                continue;
            }
            let known = state.iter().map(|s| s.to_string()).collect::<Vec<_>>();
            cx.error_spanned_by(
                name,
                format!(
                    "`{name}` is not a state variable (the state is [{}]){}",
                    known.join(", "),
                    did_you_mean(&name.to_string(), known.iter().map(String::as_str))
                ),
            );
            continue;
        };
        if by_state[i].is_some() {
            cx.error_spanned_by(
                name,
                format!("a second equation for `{name}`: write one `d/dt {name} = …;`"),
            );
        } else {
            by_state[i] = Some(value);
        }
    }
    for (name, value) in state.iter().zip(&by_state) {
        if value.is_none() {
            cx.error_spanned_by(
                name,
                format!("no equation for the state variable `{name}`: add `d/dt {name} = …;`"),
            );
        }
    }
    if cx.error_count() > errors_before {
        return None;
    }
    Some(CheckedSystem {
        state,
        fields,
        order: order?,
        equations: by_state.into_iter().collect::<Option<_>>()?,
        events,
    })
}

/// The fields' names: each must be named and of type `f64` (a unit struct has none).
fn fields<'a>(cx: &Ctxt, fields: &'a Fields) -> Vec<&'a Ident> {
    match fields {
        Fields::Unit => Vec::new(),
        Fields::Unnamed(u) => {
            cx.error_spanned_by(
                u,
                "a `taylor_system!` struct has named f64 fields (its parameters) or none",
            );
            Vec::new()
        }
        Fields::Named(named) => named
            .named
            .iter()
            .filter_map(|f| {
                let ident = f.ident.as_ref()?;
                // The same paths as `#[rigid]`'s fields: `f64` and the primitive's path
                // (`core::primitive::f64`, `::std::primitive::f64`, …).
                if !(Field { ident, ty: &f.ty }).is_f64() {
                    cx.error_spanned_by(
                        &f.ty,
                        "a field of a `taylor_system!` struct is a parameter: its type must be `f64`",
                    );
                }
                // `t` in a right-hand side is the time: a parameter of that name could
                // never be read, and would silently shadow the time if it were.
                if ident == TIME {
                    cx.error_spanned_by(
                        ident,
                        format!("`{TIME}` is the time in a right-hand side: name the field otherwise"),
                    );
                    return None;
                }
                Some(ident)
            })
            .collect(),
    }
}

/// The state variables: at least one, distinct, neither a field nor the time. Returns the
/// valid ones, so an error here is not repeated as a missing equation.
fn state_names<'a>(
    cx: &Ctxt,
    keyword: &Ident,
    names: &'a [Ident],
    fields: &[&Ident],
) -> Vec<&'a Ident> {
    if names.is_empty() {
        cx.error_spanned_by(
            keyword,
            "the state needs at least one variable: `state [x, …];`",
        );
    }
    let mut valid: Vec<&Ident> = Vec::new();
    for (i, name) in names.iter().enumerate() {
        if names.iter().take(i).any(|n| n == name) {
            cx.error_spanned_by(name, format!("`{name}` appears twice in the state"));
        } else if fields.contains(&name) {
            cx.error_spanned_by(
                name,
                format!("`{name}` is both a state variable and a field of the struct"),
            );
        } else if name == TIME {
            cx.error_spanned_by(
                name,
                format!("`{TIME}` is the time: name the state variable otherwise"),
            );
        } else {
            valid.push(name);
        }
    }
    valid
}
