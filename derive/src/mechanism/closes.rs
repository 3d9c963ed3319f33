//! `closes = other(at = [..], to = [..])` on a body: the point `at` of this body (its frame)
//! is held on the point `to` of `other` (its frame; `ground` for the ground's), closing a
//! kinematic loop. Read here; the target is resolved once every body is known
//! ([`resolve`]), and the loop's rows are the engine's (`MechanismScene::derive_loops`).

use precess_core::mechanism::Parent;
use precess_core::mechanism::loops::LoopClosure;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use super::check::LinkSpec;
use super::joint::path_ident;
use crate::lang::check::Checker;
use crate::lang::keys;
use crate::lang::units::Dim;

pub use keys::CLOSES;
/// The point on the other body.
const TO: &str = "to";

/// A closure as read, with its tokens for errors.
#[derive(Clone)]
pub struct ClosesSpec {
    /// The `closes` key.
    pub key: Ident,
    /// The whole value `other(...)`, where errors about the loop point.
    pub value: Expr,
    /// The body (or `ground`) it closes on.
    pub target: Ident,
    /// The point of the closing body, its frame.
    pub at: [ExprId; 3],
    /// The point of the target, its frame.
    pub to: [ExprId; 3],
}

/// The expected form, for errors.
fn expected() -> String {
    format!(
        "expected `{CLOSES} = other(at = [x, y, z], {TO} = [x, y, z])`: the point `at` of this body held on the point `{TO}` of body `other` (or of `{}`), each in its own body's frame",
        keys::GROUND
    )
}

impl Checker<'_> {
    /// `other(at = .., to = ..)`; both points default to the frames' origins.
    pub(super) fn closes(&mut self, key: &Ident, e: &Expr) -> Option<ClosesSpec> {
        let (target, args): (&Ident, Vec<&Expr>) = match e {
            Expr::Call(c) => match path_ident(&c.func) {
                Some(i) => (i, c.args.iter().collect()),
                None => {
                    self.cx.error_spanned_by(e, expected());
                    return None;
                }
            },
            Expr::Path(_) => match path_ident(e) {
                Some(i) => (i, Vec::new()),
                None => {
                    self.cx.error_spanned_by(e, expected());
                    return None;
                }
            },
            _ => {
                self.cx.error_spanned_by(e, expected());
                return None;
            }
        };
        let zero = [self.arena.zero(); 3];
        let (mut at, mut to) = (Some(zero), Some(zero));
        let mut seen: Vec<String> = Vec::new();
        for arg in args {
            let Expr::Assign(a) = arg else {
                self.cx.error_spanned_by(arg, expected());
                return None;
            };
            let Some(name) = path_ident(&a.left) else {
                self.cx.error_spanned_by(&a.left, expected());
                return None;
            };
            let place = format!("for `{CLOSES}`");
            let word = keys::known_key(self.cx, name, &place, &[keys::AT, TO])?;
            if seen.iter().any(|s| s == word) {
                self.cx
                    .error_spanned_by(name, format!("duplicate key `{name}` in `{CLOSES}`"));
                return None;
            }
            seen.push(word.to_owned());
            let point = self.expecting(Dim::LENGTH, word, |ck| ck.vector(&a.right));
            if word == keys::AT {
                at = point;
            } else {
                to = point;
            }
        }
        Some(ClosesSpec {
            key: key.clone(),
            value: e.clone(),
            target: target.clone(),
            at: at?,
            to: to?,
        })
    }
}

/// Each closure with its target resolved to a body index (or the ground), in the order of
/// the bodies; an unknown target is an error spanned on it, with a suggestion.
pub(super) fn resolve(ck: &Checker, specs: &[LinkSpec]) -> Option<Vec<(LoopClosure, ClosesSpec)>> {
    let names: Vec<String> = specs.iter().map(|s| s.name.to_string()).collect();
    let mut out = Vec::new();
    let mut ok = true;
    for (body, spec) in specs.iter().enumerate() {
        let Some(closes) = &spec.closes else {
            continue;
        };
        let target = closes.target.to_string();
        let to = if target == keys::GROUND {
            Parent::Ground
        } else if let Some(b) = names.iter().position(|n| *n == target) {
            if b == body {
                ck.cx.error_spanned_by(
                    &closes.target,
                    format!(
                        "body `{target}` cannot close a loop on itself: name another body or `{}`",
                        keys::GROUND
                    ),
                );
                ok = false;
                continue;
            }
            Parent::Body(b)
        } else {
            ck.cx.error_spanned_by(
                &closes.target,
                format!(
                    "unknown body `{target}` in `{CLOSES}`: a loop closes on `{}` or another body ({}){}",
                    keys::GROUND,
                    names.join(", "),
                    keys::did_you_mean(&target, names.iter().map(String::as_str))
                ),
            );
            ok = false;
            continue;
        };
        out.push((
            LoopClosure {
                name: spec.name.to_string(),
                body,
                at: closes.at,
                to,
                to_at: closes.to,
            },
            closes.clone(),
        ));
    }
    ok.then_some(out)
}
