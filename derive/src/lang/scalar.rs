//! Scalar values: literals (with units), fields, `PI` and `TAU`, arithmetic, `sqrt` and
//! `powi`, each with its dimension, checked against the dimension the key being read wants.
//!
//! Constants fold exactly: the arena's constants are rationals, so `0.1 + 0.2` is 3/10 and
//! `2 cm` is 1/50. π is irrational, so `PI` enters as the exact value of the f64
//! `std::f64::consts::PI`, the number the user's own Rust would compute with; everything
//! after is exact arithmetic on that value, rounded once when the code is generated (so
//! `2 * PI` is `TAU` to the bit). A symbolic π would need a node of its own in the engine,
//! and every printed equation of a literal body would carry it for no gain in the f64 result.

use precess_core::sym::ExprId;
use proc_macro2::{TokenStream, TokenTree};
use quote::ToTokens;
use syn::{BinOp, Expr, ExprMacro, Lit, UnOp};

use super::check::Checker;
use super::units::{Dim, UNITS_MACRO, parse_unit};
use super::values::{VALUES, path_ident};

/// The dimension a value has: `None` for a number without units or a field, which are SI in
/// whatever dimension the key wants (so every value written before units stays valid).
type Dimensioned = (ExprId, Option<Dim>);

/// The dimension the key being read wants, with the key's name for the errors.
#[derive(Clone, Copy)]
pub struct Expect {
    /// The dimension.
    pub dim: Dim,
    /// The key, as the user wrote it.
    pub key: &'static str,
    /// What the key takes, where the dimension's own name reads worse (a rotary spring's
    /// N m per rad has a torque's dimension).
    pub what: Option<&'static str>,
}

impl Checker<'_> {
    /// Reads values with `f` while expecting the dimension `dim` for the key `key`.
    pub(crate) fn expecting<T>(
        &mut self,
        dim: Dim,
        key: &'static str,
        f: impl FnOnce(&mut Self) -> T,
    ) -> T {
        self.expecting_as(dim, None, key, f)
    }

    /// [`Checker::expecting`], an error saying the key takes `what` (when given) rather
    /// than the dimension's own name.
    pub(crate) fn expecting_as<T>(
        &mut self,
        dim: Dim,
        what: Option<&'static str>,
        key: &'static str,
        f: impl FnOnce(&mut Self) -> T,
    ) -> T {
        let saved = self.expect.replace(Expect { dim, key, what });
        let out = f(self);
        self.expect = saved;
        out
    }

    /// A scalar value: a literal, an f64 field, or arithmetic on them; a value with units
    /// is checked against the dimension expected, if any.
    pub fn scalar(&mut self, e: &Expr) -> Option<ExprId> {
        let (v, d) = self.dimensioned(e)?;
        if let (Some(expect), Some(d)) = (self.expect, d)
            && !expect.dim.admits(d)
        {
            self.cx.error_spanned_by(
                e,
                format!(
                    "`{}` takes {}, but this value is {}",
                    expect.key,
                    expect
                        .what
                        .map_or_else(|| expect.dim.describe(), str::to_owned),
                    d.describe()
                ),
            );
            return None;
        }
        Some(v)
    }

    /// A value with its dimension.
    fn dimensioned(&mut self, e: &Expr) -> Option<Dimensioned> {
        match e {
            Expr::Lit(l) => {
                if let Lit::Float(_) | Lit::Int(_) = &l.lit {
                    self.unit_suffix(&l.lit)?;
                }
                Some((self.literal(&l.lit)?, None))
            }
            Expr::Paren(p) => self.dimensioned(&p.expr),
            Expr::Group(g) => self.dimensioned(&g.expr),
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
                let (v, d) = self.dimensioned(&u.expr)?;
                Some((self.arena.neg(v), d))
            }
            Expr::Binary(b) => self.binary(e, b),
            Expr::Call(call) if call.args.len() == 1 || call.args.len() == 2 => {
                let Some(f) = path_ident(&call.func).map(|f| f.to_string()) else {
                    return self.unsupported(e);
                };
                let args: Vec<&Expr> = call.args.iter().collect();
                self.function(e, &f, &args)
            }
            // `x.sqrt()`, `x.powi(2)`, as Rust writes them.
            Expr::MethodCall(m) => {
                let mut args = vec![&*m.receiver];
                args.extend(m.args.iter());
                self.function(e, &m.method.to_string(), &args)
            }
            Expr::Macro(m) if m.mac.path.is_ident(UNITS_MACRO) => self.with_unit(m),
            Expr::Path(p) => match p.path.get_ident() {
                Some(ident) if ident == "PI" || ident == "TAU" => self.pi(ident == "TAU"),
                Some(ident) => Some((self.field(ident)?, None)),
                None => {
                    let names: Vec<String> = p
                        .path
                        .segments
                        .iter()
                        .map(|s| s.ident.to_string())
                        .collect();
                    let names: Vec<&str> = names.iter().map(String::as_str).collect();
                    match names.as_slice() {
                        ["std" | "core", "f64", "consts", c @ ("PI" | "TAU")] => {
                            self.pi(*c == "TAU")
                        }
                        [.., "INFINITY" | "NEG_INFINITY" | "NAN"] => {
                            self.cx.error_spanned_by(
                                e,
                                format!("non-finite value: {VALUES}, and must be finite"),
                            );
                            None
                        }
                        _ => self.unsupported(e),
                    }
                }
            },
            _ => self.unsupported(e),
        }
    }

    fn unsupported(&mut self, e: &Expr) -> Option<Dimensioned> {
        self.cx
            .error_spanned_by(e, format!("unsupported value: {VALUES}"));
        None
    }

    /// π (or 2π) as the exact value of its f64, a pure number.
    fn pi(&mut self, tau: bool) -> Option<Dimensioned> {
        let x = if tau {
            std::f64::consts::TAU
        } else {
            std::f64::consts::PI
        };
        Some((self.arena.float(x).ok()?, None))
    }

    /// `a + b`, `a - b`, `a * b`, `a / b`, dimensions combined.
    fn binary(&mut self, e: &Expr, b: &syn::ExprBinary) -> Option<Dimensioned> {
        let (l, r) = (self.dimensioned(&b.left), self.dimensioned(&b.right));
        let ((l, dl), (r, dr)) = (l?, r?);
        let dims = |d: Option<Dim>| d.unwrap_or(Dim::NONE);
        match b.op {
            BinOp::Add(_) | BinOp::Sub(_) => {
                // Two values with units must agree; a plain number takes the other's.
                let mut sum = dl.or(dr);
                if let (Some(a), Some(c)) = (dl, dr) {
                    sum = a.sum(c);
                }
                if let (Some(a), Some(c), None) = (dl, dr, sum) {
                    self.cx.error_spanned_by(
                        e,
                        format!(
                            "cannot add or subtract {} and {}: both sides must have the same dimension",
                            a.describe(),
                            c.describe()
                        ),
                    );
                    return None;
                }
                let v = if matches!(b.op, BinOp::Add(_)) {
                    self.arena.add(l, r)
                } else {
                    self.arena.sub(l, r)
                };
                Some((v, sum))
            }
            BinOp::Mul(_) => {
                let d = match (dl, dr) {
                    (None, None) => None,
                    _ => Some(self.dim_or_error(e, dims(dl).times(dims(dr)))?),
                };
                Some((self.arena.mul(l, r), d))
            }
            BinOp::Div(_) => {
                let d = match (dl, dr) {
                    (None, None) => None,
                    _ => {
                        let inv = dims(dr).pow(-1);
                        Some(self.dim_or_error(e, inv.and_then(|i| dims(dl).times(i)))?)
                    }
                };
                // A divisor that is identically zero has no value anywhere.
                match self.arena.div(l, r) {
                    Ok(v) => Some((v, d)),
                    Err(_) => {
                        self.cx
                            .error_spanned_by(&b.right, "division by a value that is zero");
                        None
                    }
                }
            }
            _ => {
                let hint = if matches!(b.op, BinOp::BitXor(_)) {
                    ": `^` is Rust's exclusive or; write a power as `x.powi(2)`"
                } else {
                    ""
                };
                self.cx
                    .error_spanned_by(b.op, format!("unsupported operator: {VALUES}{hint}"));
                None
            }
        }
    }

    fn dim_or_error(&mut self, e: &Expr, d: Option<Dim>) -> Option<Dim> {
        if d.is_none() {
            self.cx
                .error_spanned_by(e, "the value's units have powers too large to track");
        }
        d
    }

    /// `sin`, `cos`, `sqrt` of a value, `powi` of a value and a whole power.
    fn function(&mut self, e: &Expr, f: &str, args: &[&Expr]) -> Option<Dimensioned> {
        match (f, args) {
            // The sine and cosine of an angle among the fields (a bicycle's steer axis tilted
            // by its head angle λ is [sin λ, 0, cos λ]) or of a constant one.
            ("sin" | "cos", [x]) => {
                let (x, d) = self.dimensioned(x)?;
                if let Some(d) = d.filter(|&d| !Dim::ANGLE.admits(d)) {
                    self.cx.error_spanned_by(
                        args[0],
                        format!(
                            "`{f}` takes an angle (a pure number, in rad or `deg`), but this value is {}",
                            d.describe()
                        ),
                    );
                    return None;
                }
                let v = if f == "sin" {
                    self.arena.sin(x)
                } else {
                    self.arena.cos(x)
                };
                Some((v, None))
            }
            ("sqrt", [x]) => {
                let (v, d) = self.dimensioned(x)?;
                let d = match d {
                    None => None,
                    Some(d) => {
                        let Some(root) = d.sqrt() else {
                            self.cx.error_spanned_by(
                                args[0],
                                format!(
                                    "the square root of {} has no unit: its powers are odd",
                                    d.describe()
                                ),
                            );
                            return None;
                        };
                        Some(root)
                    }
                };
                match self.arena.sqrt(v) {
                    Ok(r) => Some((r, d)),
                    Err(_) => {
                        self.cx.error_spanned_by(
                            args[0],
                            "the square root of a negative value: `sqrt` takes a value ≥ 0",
                        );
                        None
                    }
                }
            }
            ("powi", [x, n]) => {
                let power = match n {
                    Expr::Lit(syn::ExprLit {
                        lit: Lit::Int(i), ..
                    }) => i.base10_parse::<i64>().ok(),
                    Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => match &*u.expr {
                        Expr::Lit(syn::ExprLit {
                            lit: Lit::Int(i), ..
                        }) => i.base10_parse::<i64>().ok().map(|n| -n),
                        _ => None,
                    },
                    _ => None,
                };
                let Some(power) = power.filter(|p| p.abs() <= 64) else {
                    self.cx.error_spanned_by(
                        n,
                        "`powi` takes a whole power written as a number from -64 to 64, `x.powi(3)`",
                    );
                    return None;
                };
                let (v, d) = self.dimensioned(x)?;
                let d = match d {
                    None => None,
                    Some(d) => Some(self.dim_or_error(e, d.pow(power))?),
                };
                match self.arena.powi(v, power) {
                    Ok(p) => Some((p, d)),
                    Err(_) => {
                        self.cx.error_spanned_by(
                            e,
                            "a negative power of zero: the value has no finite value",
                        );
                        None
                    }
                }
            }
            _ => self.unsupported(e),
        }
    }

    /// `__units!((x) unit)`: `x` times the unit's size in SI, of the unit's dimension.
    fn with_unit(&mut self, m: &ExprMacro) -> Option<Dimensioned> {
        let tokens: Vec<TokenTree> = m.mac.tokens.clone().into_iter().collect();
        let (Some(TokenTree::Group(operand)), unit) = (tokens.first(), tokens.get(1..)) else {
            return self.unsupported(&Expr::Macro(m.clone()));
        };
        let unit = unit.unwrap_or_default();
        let operand: Expr = match syn::parse2(operand.stream()) {
            Ok(x) => x,
            Err(err) => {
                self.cx.syn_error(err);
                return None;
            }
        };
        let read = self.dimensioned(&operand);
        let (scale, unit_dim) = match parse_unit(unit) {
            Ok(u) => u,
            Err((tokens, msg)) => {
                self.cx.error_spanned_by(tokens, msg);
                return None;
            }
        };
        let (x, d) = read?;
        let dim = match d {
            None => unit_dim,
            Some(d) => self.dim_or_error(&operand, d.times(unit_dim))?,
        };
        let mut v = self.arena.constant(scale.ratio);
        if scale.pi != 0 {
            let pi = self.arena.float(std::f64::consts::PI).ok()?;
            let pi_k = self.arena.powi(pi, scale.pi.into()).ok()?;
            v = self.arena.mul(v, pi_k);
        }
        Some((self.arena.mul(x, v), Some(dim)))
    }

    /// A number written with a unit as its suffix, `2cm`: the unit must stand apart.
    fn unit_suffix(&mut self, lit: &Lit) -> Option<()> {
        let (digits, suffix) = match lit {
            Lit::Float(f) => (f.base10_digits(), f.suffix()),
            Lit::Int(i) => (i.base10_digits(), i.suffix()),
            _ => return Some(()),
        };
        let as_unit: TokenStream = suffix.parse().unwrap_or_default();
        let as_unit: Vec<TokenTree> = as_unit.into_iter().collect();
        if suffix.is_empty() || suffix == "f64" || parse_unit(&as_unit).is_err() {
            return Some(());
        }
        self.cx.error_spanned_by(
            lit.to_token_stream(),
            format!("unsupported suffix `{suffix}`: write the unit apart from the number, `{digits} {suffix}`"),
        );
        None
    }
}
