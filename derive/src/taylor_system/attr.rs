//! Syntax of `taylor_system!`: a struct item, then statements each ended by `;`:
//! `state [x, y, …]`, `taylor = K`, one `d/dt x = expression` per state variable, and any
//! number of `event Name = expression` (an event function, emitted as a type whose Taylor
//! coefficients are compiled recurrences). What they mean (names, counts, the order's
//! range) is decided in `check.rs`.

use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Expr, Ident, ItemStruct, Token, bracketed};

/// The words of the macro's language.
pub const STATE: &str = "state";
/// `event Name = g;`: an event function compiled beside the system.
pub const EVENT: &str = "event";
/// The time, readable in the right-hand sides.
pub const TIME: &str = "t";
/// `d` of `d/dt x = …`.
const D: &str = "d";
/// `dt` of `d/dt x = …`.
const DT: &str = "dt";

/// The whole input.
pub struct SystemInput {
    /// The struct as written (its fields are the parameters).
    pub item: ItemStruct,
    /// The statements in order.
    pub statements: Vec<Statement>,
}

/// One statement.
pub enum Statement {
    /// `state [x, y, …]`.
    State {
        /// The `state` keyword, for spans.
        keyword: Ident,
        /// The state variables in order.
        names: Vec<Ident>,
    },
    /// `taylor = K`.
    Taylor {
        /// The `taylor` keyword, for spans.
        keyword: Ident,
        /// The order as written.
        value: Expr,
    },
    /// `event Name = expression`.
    Event {
        /// The name of the type emitted.
        name: Ident,
        /// g(t, y).
        value: Expr,
    },
    /// `d/dt x = expression`.
    Equation {
        /// The variable differentiated.
        name: Ident,
        /// Its right-hand side.
        value: Expr,
    },
}

impl Parse for SystemInput {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let item: ItemStruct = input.parse()?;
        let mut statements = Vec::new();
        while !input.is_empty() {
            statements.push(input.parse()?);
        }
        Ok(SystemInput { item, statements })
    }
}

impl Parse for Statement {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let expected = || {
            format!(
                "expected `{STATE} [x, y, …];`, `{} = K;`, an equation `{D}/{DT} x = …;` or `{EVENT} Name = …;`",
                crate::lang::keys::TAYLOR
            )
        };
        let keyword: Ident = input
            .parse()
            .map_err(|e| syn::Error::new(e.span(), expected()))?;
        let statement = if keyword == STATE {
            let content;
            bracketed!(content in input);
            let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
            Statement::State {
                keyword,
                names: names.into_iter().collect(),
            }
        } else if keyword == crate::lang::keys::TAYLOR {
            input.parse::<Token![=]>()?;
            Statement::Taylor {
                keyword,
                value: input.parse()?,
            }
        } else if keyword == EVENT && input.peek(Ident) {
            let name = input.parse()?;
            input.parse::<Token![=]>()?;
            Statement::Event {
                name,
                value: input.parse()?,
            }
        } else if keyword == D && input.peek(Token![/]) {
            input.parse::<Token![/]>()?;
            let dt: Ident = input.parse()?;
            if dt != DT {
                return Err(syn::Error::new(
                    dt.span(),
                    format!("expected `{DT}`: an equation reads `{D}/{DT} x = …;`"),
                ));
            }
            let name = input.parse()?;
            input.parse::<Token![=]>()?;
            Statement::Equation {
                name,
                value: input.parse()?,
            }
        } else {
            return Err(syn::Error::new(keyword.span(), expected()));
        };
        input.parse::<Token![;]>()?;
        Ok(statement)
    }
}
