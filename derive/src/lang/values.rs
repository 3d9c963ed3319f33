//! Values of the attribute language: literals read exactly, f64 fields as parameters,
//! arithmetic on them, vectors, tensors, axes. Part of the checker, so every error lands in
//! the same context with the same wording.

use precess_core::body::{About, Axis, Orientation, check_orientation};
use precess_core::sym::{Arena, ExprId, SymError, parse_decimal};
use quote::ToTokens;
use syn::{Expr, Ident, Lit, UnOp};

use super::check::Checker;
use super::ctxt::Ctxt;
use super::dim::Dim;
use super::keys;
use super::parts::rotation_message;

pub(crate) const VALUES: &str = "values are number literals (with units, `2 cm`), names of the struct's f64 fields, `PI`, `TAU`, or `+ - * /`, parentheses, `sqrt`, `powi` on them";

impl Checker<'_> {
    /// `x`, `y` or `z`.
    pub(crate) fn axis(&mut self, e: &Expr) -> Option<(Axis, bool)> {
        // `-z` reverses the axis: it matters only for the cone, whose apex it points to.
        let (inner, reversed) = match e {
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => (&*u.expr, true),
            _ => (e, false),
        };
        match path_ident(inner).map(|i| i.to_string()).as_deref() {
            Some("x") => Some((Axis::X, reversed)),
            Some("y") => Some((Axis::Y, reversed)),
            Some("z") => Some((Axis::Z, reversed)),
            _ => {
                self.cx.error_spanned_by(
                    e,
                    "expected `x`, `y` or `z` (or `-x`, `-y`, `-z`) for `axis`",
                );
                None
            }
        }
    }

    /// Reads a rotation's axis or entries: pure numbers, which no angle unit may be written
    /// into, though the rotation's angles may be (`y(30 deg)`).
    fn direction<T>(&mut self, f: impl FnOnce(&mut Self) -> T) -> T {
        self.expecting_as(
            Dim::NONE,
            Some("a pure number (an axis's components or a rotation's entries)"),
            keys::ROTATE,
            f,
        )
    }

    /// `axis_angle([x, y, z], angle)`, `matrix([[..], [..], [..]])`, or elementary turns
    /// named by their axes, `zxz(φ, θ, ψ)`, `y(α)`. A rotation whose values are literals is
    /// checked now, and its error spanned on the axis or the matrix.
    pub(crate) fn orientation(
        &mut self,
        e: &Expr,
        kind: &'static str,
    ) -> Option<Orientation<ExprId>> {
        const ROTATE: &str = "expected `axis_angle([x, y, z], angle)`, `matrix([[..], [..], [..]])` (rows of the rotation) or up to three turns about the part's axes such as `zxz(phi, theta, psi)` or `y(angle)` for `rotate` (angles in radians)";
        let call = match e {
            Expr::Call(call) => call,
            _ => {
                self.cx.error_spanned_by(e, ROTATE);
                return None;
            }
        };
        let Some(name) = path_ident(&call.func).map(|i| i.to_string()) else {
            self.cx.error_spanned_by(e, ROTATE);
            return None;
        };
        let args: Vec<&Expr> = call.args.iter().collect();
        match (name.as_str(), args.as_slice()) {
            ("axis_angle", [axis, angle]) => {
                let (k, a) = (self.direction(|ck| ck.vector(axis)), self.scalar(angle));
                let (k, a) = (k?, a?);
                // The axis is checked on its own, so a literal zero axis is refused even
                // when the angle is a field.
                let zero = self.arena.zero();
                let axis_only = Orientation::AxisAngle {
                    axis: k,
                    angle: zero,
                };
                self.literal_rotation(&axis_only, kind, axis)
                    .then_some(Orientation::AxisAngle { axis: k, angle: a })
            }
            ("axis_angle", _) => {
                self.cx.error_spanned_by(e, "`axis_angle` takes an axis and an angle in radians: `axis_angle([x, y, z], angle)`");
                None
            }
            ("matrix", [rows]) => {
                let Expr::Array(a) = rows else {
                    self.cx.error_spanned_by(rows, "expected the rows of the rotation, `[[Rxx, Rxy, Rxz], [Ryx, Ryy, Ryz], [Rzx, Rzy, Rzz]]`");
                    return None;
                };
                if a.elems.len() != 3 {
                    self.cx.error_spanned_by(rows, "expected the three rows of the rotation, `[[Rxx, Rxy, Rxz], [Ryx, Ryy, Ryz], [Rzx, Rzy, Rzz]]`");
                    return None;
                }
                let r: Vec<Option<[ExprId; 3]>> = a
                    .elems
                    .iter()
                    .map(|row| self.direction(|ck| ck.vector(row)))
                    .collect();
                let o = Orientation::Matrix([r[0]?, r[1]?, r[2]?]);
                self.literal_rotation(&o, kind, rows).then_some(o)
            }
            ("matrix", _) => {
                self.cx.error_spanned_by(e, "`matrix` takes the rows of the rotation: `matrix([[Rxx, Rxy, Rxz], [Ryx, Ryy, Ryz], [Rzx, Rzy, Rzz]])`");
                None
            }
            (turns, _)
                if (1..=3).contains(&turns.len()) && turns.chars().all(|c| "xyz".contains(c)) =>
            {
                if args.len() != turns.len() {
                    let n = turns.len();
                    let axes: Vec<String> = turns.chars().map(String::from).collect();
                    let msg = format!(
                        "`{turns}(..)` turns about {} in turn, so it takes {n} {}, got {}",
                        axes.join(", then "),
                        if n == 1 { "angle" } else { "angles" },
                        args.len()
                    );
                    if args.is_empty() {
                        self.cx.error_spanned_by(e, msg);
                    } else {
                        self.cx.error_spanned_by(&call.args, msg);
                    }
                    return None;
                }
                let angles: Vec<Option<ExprId>> = args.iter().map(|a| self.scalar(a)).collect();
                let mut sequence = Vec::with_capacity(angles.len());
                for (c, angle) in turns.chars().zip(angles) {
                    let axis = match c {
                        'x' => Axis::X,
                        'y' => Axis::Y,
                        _ => Axis::Z,
                    };
                    sequence.push((axis, angle?));
                }
                Some(Orientation::Sequence(sequence))
            }
            _ => {
                self.cx.error_spanned_by(e, ROTATE);
                None
            }
        }
    }

    /// Checks a rotation whose values are all literals, with its error spanned on `tokens`;
    /// false if it is not a rotation (one with fields is checked by `validate()`).
    fn literal_rotation(
        &mut self,
        o: &Orientation<ExprId>,
        kind: &'static str,
        tokens: &Expr,
    ) -> bool {
        let mut constant = true;
        let numeric = o.map(&mut |&e| {
            constant &= self.arena.free_symbols(e).is_empty();
            self.arena.eval(e, &[])
        });
        if !constant {
            return true;
        }
        match check_orientation(0, kind, &numeric) {
            Ok(()) => true,
            Err(err) => {
                self.cx.error_spanned_by(tokens, rotation_message(&err));
                false
            }
        }
    }

    /// `center` or `pivot`.
    pub(crate) fn about(&mut self, e: &Expr) -> Option<About> {
        match path_ident(e).map(|i| i.to_string()).as_deref() {
            Some("center") => Some(About::Center),
            Some("pivot") => Some(About::Pivot),
            _ => {
                self.cx
                    .error_spanned_by(e, "expected `center` or `pivot` for `about`");
                None
            }
        }
    }

    /// `diag(a, b, c)` or `[[..], [..], [..]]`.
    pub(crate) fn tensor(&mut self, e: &Expr) -> Option<[[ExprId; 3]; 3]> {
        const TENSOR: &str = "expected `diag(I1, I2, I3)` or a full matrix `[[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]]`";
        match e {
            Expr::Call(call)
                if path_ident(&call.func).is_some_and(|i| i == "diag") && call.args.len() == 3 =>
            {
                let d: Vec<Option<ExprId>> = call.args.iter().map(|a| self.scalar(a)).collect();
                let z = self.arena.zero();
                Some([[d[0]?, z, z], [z, d[1]?, z], [z, z, d[2]?]])
            }
            Expr::Array(rows) if rows.elems.len() == 3 => {
                let r: Vec<Option<[ExprId; 3]>> =
                    rows.elems.iter().map(|row| self.vector(row)).collect();
                Some([r[0]?, r[1]?, r[2]?])
            }
            _ => {
                self.cx.error_spanned_by(e, TENSOR);
                None
            }
        }
    }

    /// `[x, y, z]`.
    pub fn vector(&mut self, e: &Expr) -> Option<[ExprId; 3]> {
        match e {
            Expr::Array(a) if a.elems.len() == 3 => {
                let v: Vec<Option<ExprId>> = a.elems.iter().map(|x| self.scalar(x)).collect();
                Some([v[0]?, v[1]?, v[2]?])
            }
            _ => {
                self.cx
                    .error_spanned_by(e, "expected a vector of three values `[x, y, z]`");
                None
            }
        }
    }

    /// A number literal, exactly (`0.03` is 3/100).
    pub(crate) fn literal(&mut self, lit: &Lit) -> Option<ExprId> {
        number_literal(self.cx, self.arena, lit, VALUES)
    }

    /// A field name: it must exist and be an f64 (the body's parameters are f64).
    pub(crate) fn field(&mut self, ident: &Ident) -> Option<ExprId> {
        let name = ident.to_string();
        let Some(field) = self.input.field(ident) else {
            let available: Vec<String> = self
                .input
                .fields
                .iter()
                .filter(|f| f.is_f64())
                .map(|f| format!("`{}`", f.ident))
                .collect();
            let list = if available.is_empty() {
                "it has none".to_owned()
            } else {
                format!("its f64 fields are {}", available.join(", "))
            };
            self.cx.error_spanned_by(
                ident,
                format!(
                    "no field `{name}` in `{}`: {VALUES}; {list}",
                    self.input.ident
                ),
            );
            return None;
        };
        if !field.is_f64() {
            // As written: token streams print paths as `a :: b`.
            let ty = field.ty.to_token_stream().to_string().replace(" :: ", "::");
            let ty = ty
                .strip_prefix(":: ")
                .map_or(ty.clone(), |t| format!("::{t}"));
            self.cx.error_spanned_by(
                ident,
                format!("field `{name}` has type `{ty}`: only f64 fields can be used as values"),
            );
            return None;
        }
        let parameter = self.arena.parameter(&name);
        if let Some(symbol) = self.arena.as_symbol(parameter) {
            self.parameters.insert(symbol, ident);
        }
        Some(parameter)
    }
}

/// The single identifier a path expression is, if it is one.
pub(crate) fn path_ident(e: &Expr) -> Option<&Ident> {
    match e {
        Expr::Path(p) if p.qself.is_none() => p.path.get_ident(),
        _ => None,
    }
}

/// A number literal, exactly (`0.03` is 3/100), finite and not flushed to zero in f64; a
/// spanned error otherwise, ending with `allowed` (what the caller's values may be).
pub(crate) fn number_literal(
    cx: &Ctxt,
    arena: &mut Arena,
    lit: &Lit,
    allowed: &str,
) -> Option<ExprId> {
    let (digits, suffix) = match lit {
        Lit::Float(f) => (f.base10_digits().to_owned(), f.suffix().to_owned()),
        Lit::Int(i) => (i.base10_digits().to_owned(), i.suffix().to_owned()),
        _ => {
            cx.error_spanned_by(lit, format!("expected a number: {allowed}"));
            return None;
        }
    };
    // Values are f64: another suffix would silently change the type the user wrote.
    if !suffix.is_empty() && suffix != "f64" {
        cx.error_spanned_by(
            lit,
            format!("unsupported suffix `{suffix}`: write a plain number or an `f64` one"),
        );
        return None;
    }
    match parse_decimal(&digits) {
        // Exact, but the generated code and the checks use the f64 it rounds to.
        Ok(r) if !r.to_f64().is_finite() => {
            cx.error_spanned_by(
                lit,
                format!("`{digits}` overflows f64: the largest finite f64 is about 1.8e308"),
            );
            None
        }
        Ok(r) if r.to_f64() == 0.0 && !r.is_zero() => {
            cx.error_spanned_by(
                lit,
                format!(
                    "`{digits}` underflows f64 to zero: the smallest positive f64 is about 4.9e-324"
                ),
            );
            None
        }
        Ok(r) => Some(arena.constant(r)),
        Err(SymError::LiteralOutOfRange { .. }) => {
            cx.error_spanned_by(lit, "literal out of range: values have at most 38 significant digits and lie within f64's range (about 4.9e-324 to 1.8e308)");
            None
        }
        Err(_) => {
            cx.error_spanned_by(lit, format!("expected a decimal number: {allowed}"));
            None
        }
    }
}
