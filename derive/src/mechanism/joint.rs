//! A body's joint: its kind, axes, location and name, with the rules literal axes meet now.

use precess_core::mechanism::{
    JointKind, MechanismError, PARALLEL_SINE, check_axis, check_universal_axes,
};
use precess_core::rigid::AngleSequence;
use precess_core::sym::ExprId;
use syn::{Expr, Ident};

use crate::lang::check::Checker;
use crate::lang::keys;
use crate::lang::units::Dim;

/// A joint as read.
pub(super) struct JointSpec {
    /// `None`: named after its link.
    pub(super) name: Option<Ident>,
    /// Where it sits in the parent's frame.
    pub(super) at: [ExprId; 3],
    /// Its kind and axes.
    pub(super) kind: JointKind,
    /// The kind as written (`free`, …), for errors about where the joint may go.
    pub(super) kind_ident: Ident,
}

impl Checker<'_> {
    /// `kind(name = .., axis = .., at = ..)`.
    pub(super) fn joint(&mut self, e: &Expr) -> Option<JointSpec> {
        const EXPECTED: &str = "expected a joint `revolute(axis = x, at = [x, y, z])`, `prismatic(axis = ..)`, `universal(axes = [x, y])`, `spherical(sequence = zxz)` or `free(sequence = zxz)`";
        let (kind_ident, args): (&Ident, Vec<&Expr>) = match e {
            Expr::Call(c) => match path_ident(&c.func) {
                Some(i) => (i, c.args.iter().collect()),
                None => {
                    self.cx.error_spanned_by(e, EXPECTED);
                    return None;
                }
            },
            Expr::Path(_) => match path_ident(e) {
                Some(i) => (i, Vec::new()),
                None => {
                    self.cx.error_spanned_by(e, EXPECTED);
                    return None;
                }
            },
            _ => {
                self.cx.error_spanned_by(e, EXPECTED);
                return None;
            }
        };
        let kind_name = kind_ident.to_string();
        let allowed: &[&str] = match kind_name.as_str() {
            "revolute" | "prismatic" => &[keys::NAME, keys::AXIS, keys::AT],
            "universal" => &[keys::NAME, keys::AXES, keys::AT],
            "spherical" | "free" => &[keys::NAME, keys::SEQUENCE, keys::AT],
            _ => {
                self.cx.error_spanned_by(
                    kind_ident,
                    format!(
                        "unknown joint `{kind_name}`: expected one of {}{}",
                        keys::JOINT_KINDS.join(", "),
                        keys::did_you_mean(&kind_name, keys::JOINT_KINDS.iter().copied())
                    ),
                );
                return None;
            }
        };
        let mut given: Vec<(&Ident, &Expr)> = Vec::new();
        let mut ok = true;
        for arg in args {
            let Expr::Assign(a) = arg else {
                self.cx.error_spanned_by(
                    arg,
                    format!(
                        "expected `key = value` in `{kind_name}(...)`: its keys are {}",
                        allowed.join(", ")
                    ),
                );
                ok = false;
                continue;
            };
            let Some(key) = path_ident(&a.left) else {
                self.cx.error_spanned_by(
                    &a.left,
                    format!("expected a key of `{kind_name}`: {}", allowed.join(", ")),
                );
                ok = false;
                continue;
            };
            let place = format!("for `{kind_name}`");
            if keys::known_key(self.cx, key, &place, allowed).is_none() {
                ok = false;
                continue;
            }
            if given.iter().any(|(g, _)| *g == key) {
                self.cx
                    .error_spanned_by(key, format!("duplicate key `{key}` in `{kind_name}`"));
                ok = false;
                continue;
            }
            given.push((key, &a.right));
        }
        let value = |k: &str| given.iter().find(|(g, _)| *g == k).map(|(_, v)| *v);
        let name = match value(keys::NAME) {
            Some(v) => match path_ident(v) {
                Some(i) => Some(i.clone()),
                None => {
                    self.cx
                        .error_spanned_by(v, "expected the joint's name, such as `shoulder`");
                    None
                }
            },
            None => None,
        };
        let at = match value(keys::AT) {
            Some(v) => self.expecting(Dim::LENGTH, keys::AT, |ck| ck.vector(v)),
            None => Some([self.arena.zero(); 3]),
        };
        let kind = match kind_name.as_str() {
            "revolute" | "prismatic" => {
                let axis = match value(keys::AXIS) {
                    Some(v) => self.joint_axis(v),
                    None => {
                        self.cx.error_spanned_by(kind_ident, format!("`{kind_name}` needs its `{}`: `x`, `y`, `z` or `[x, y, z]` in the parent's frame", keys::AXIS));
                        None
                    }
                };
                axis.map(|axis| {
                    if kind_name == "revolute" {
                        JointKind::Revolute { axis }
                    } else {
                        JointKind::Prismatic { axis }
                    }
                })
            }
            "universal" => match value(keys::AXES) {
                Some(Expr::Array(a)) if a.elems.len() == 2 => {
                    let first = a.elems.first().and_then(|x| self.joint_axis(x));
                    let second = a.elems.last().and_then(|x| self.joint_axis(x));
                    let axes = [first?, second?];
                    if let (Some(outer), Some(inner)) =
                        (self.literal_axis(&axes[0]), self.literal_axis(&axes[1]))
                        && let Err(MechanismError::ParallelAxes { sine, .. }) =
                            check_universal_axes("", outer, inner)
                    {
                        self.cx.error_spanned_by(a, format!(
                            "the universal joint's axes are parallel (the sine of the angle between them is {sine:e}, below √ε ≈ {PARALLEL_SINE:.1e}), so its two coordinates would turn about one line: give axes at an angle, such as `[x, y]`"
                        ));
                        return None;
                    }
                    Some(JointKind::Universal { axes })
                }
                Some(v) => {
                    self.cx.error_spanned_by(v, "expected the two axes of the universal joint, `[outer, inner]`, such as `[x, y]`");
                    None
                }
                None => {
                    self.cx.error_spanned_by(
                        kind_ident,
                        format!(
                            "`universal` needs its `{}`: `[outer, inner]`, such as `[x, y]`",
                            keys::AXES
                        ),
                    );
                    None
                }
            },
            _ => match value(keys::SEQUENCE) {
                None => Some(angles(&kind_name, AngleSequence::Zxz)),
                Some(v) => match path_ident(v).map(|i| i.to_string()).as_deref() {
                    Some("zxz") => Some(angles(&kind_name, AngleSequence::Zxz)),
                    Some("zyx") => Some(angles(&kind_name, AngleSequence::Zyx)),
                    _ => {
                        self.cx.error_spanned_by(
                            v,
                            format!(
                                "`{}` expects `zxz` (φ, θ, ψ) or `zyx` (yaw, pitch, roll)",
                                keys::SEQUENCE
                            ),
                        );
                        None
                    }
                },
            },
        };
        if !ok {
            return None;
        }
        if name.is_none() && value(keys::NAME).is_some() {
            return None;
        }
        Some(JointSpec {
            name,
            at: at?,
            kind: kind?,
            kind_ident: kind_ident.clone(),
        })
    }

    /// `x`, `y`, `z` (or negated) or `[x, y, z]`; a literal axis of zero length has no
    /// direction.
    pub(super) fn joint_axis(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        let (inner, negated) = match e {
            Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => (&*u.expr, true),
            _ => (e, false),
        };
        if let Some(i) = path_ident(inner) {
            let k = match i.to_string().as_str() {
                "x" => 0,
                "y" => 1,
                "z" => 2,
                _ => {
                    // Not an axis name: a field, and the scalar's error says so.
                    self.cx.error_spanned_by(
                        e,
                        "expected an axis `x`, `y`, `z` (or `-x`, …) or a vector `[x, y, z]`",
                    );
                    return None;
                }
            };
            let (z, one) = (self.arena.zero(), self.arena.one());
            let one = if negated { self.arena.neg(one) } else { one };
            let mut axis = [z; 3];
            axis[k] = one;
            return Some(axis);
        }
        if !matches!(e, Expr::Array(_)) {
            self.cx.error_spanned_by(
                e,
                "expected an axis `x`, `y`, `z` (or `-x`, …) or a vector `[x, y, z]`",
            );
            return None;
        }
        let axis = self.expecting_as(
            Dim::NONE,
            Some("a direction, pure numbers (its length does not matter)"),
            keys::AXIS,
            |ck| ck.vector(e),
        )?;
        let zero = self.arena.zero();
        if axis.iter().all(|&c| self.arena.expand(c) == zero) {
            self.cx.error_spanned_by(
                e,
                "the axis has zero length and so no direction: give a non-zero axis such as [0.0, 0.0, 1.0]",
            );
            return None;
        }
        // The run-time rule for axes of fields, applied to the literal's value.
        if let Some(value) = self.literal_axis(&axis)
            && let Err(MechanismError::ZeroAxis {
                squared_length: Some(squared),
                ..
            }) = check_axis("", "axis", value)
        {
            self.cx.error_spanned_by(
                e,
                format!("the axis's squared length {squared:e} is outside f64's normal positive numbers, so the engine cannot normalise it: scale the axis to a length near 1"),
            );
            return None;
        }
        Some(axis)
    }

    /// The value of an axis whose components are all literals.
    fn literal_axis(&self, axis: &[ExprId; 3]) -> Option<[f64; 3]> {
        let mut out = [0.0; 3];
        for (o, &c) in out.iter_mut().zip(axis) {
            *o = self.arena.as_rational(c)?.to_f64();
        }
        Some(out)
    }
}

/// A spherical joint, or a free one (`kind_name` is one of the two), turning by `sequence`.
fn angles(kind_name: &str, sequence: AngleSequence) -> JointKind {
    if kind_name == "free" {
        JointKind::Free { sequence }
    } else {
        JointKind::Spherical { sequence }
    }
}

/// The single identifier a path expression is, if it is one.
pub(super) fn path_ident(e: &Expr) -> Option<&Ident> {
    match e {
        Expr::Path(p) if p.qself.is_none() => p.path.get_ident(),
        _ => None,
    }
}
