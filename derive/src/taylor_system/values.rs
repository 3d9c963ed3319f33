//! A right-hand side of `taylor_system!` as written (a Rust expression) into the symbolic
//! engine: numbers exactly, state variables, the struct's fields and the time `t` as
//! symbols, `+ − × ÷` and unary `−`, and the functions the Taylor recurrences know (`sin`,
//! `cos`, `sqrt`, the engine's registered primitives such as `exp`, `powi` with an integer
//! literal, `powf` with a number literal, taken exactly as a rational), as methods
//! (`x.sin()`) or calls (`sin(x)`). A primitive registered in the engine
//! (`precess_core::sym::functions`) is known here by its name, with no change to this file.
//! Anything else is an error spanned on it.

use precess_core::sym::{Arena, ExprId, Func, Rational, parse_decimal};
use syn::{BinOp, Expr, Ident, Lit, UnOp};

use super::attr::TIME;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys::did_you_mean;
use crate::lang::values::number_literal;

/// What a right-hand side may use, listed in the errors.
fn allowed() -> String {
    let unary: String = unary_names().map(|f| format!("`{f}`, ")).collect();
    format!(
        "a right-hand side is built of numbers, state variables, the struct's f64 fields, the time `t`, `+ - * /`, unary `-`, and {unary}`powi`, `powf`"
    )
}

/// The functions of one argument: the built-in ones, then the engine's registry.
fn unary_names() -> impl Iterator<Item = &'static str> {
    ["sin", "cos", "sqrt"]
        .into_iter()
        .chain(Func::all().map(Func::name))
}

/// The built-in functions, with their argument counts besides the receiver.
const FUNCTIONS: &[(&str, usize)] = &[
    ("sin", 0),
    ("cos", 0),
    ("sqrt", 0),
    ("powi", 1),
    ("powf", 1),
];

/// The names a right-hand side reads and the symbols they stand for.
pub struct Names {
    /// The state variables, in state order.
    pub state: Vec<(Ident, ExprId)>,
    /// The struct's f64 fields.
    pub fields: Vec<(Ident, ExprId)>,
    /// The time, once a right-hand side reads `t`.
    pub time: Option<ExprId>,
}

/// Lowers right-hand sides into one arena, recording every error.
pub struct Lowerer<'a> {
    /// Where errors go.
    pub cx: &'a Ctxt,
    /// The arena the symbols live in.
    pub arena: &'a mut Arena,
    /// The names known.
    pub names: Names,
}

impl Lowerer<'_> {
    /// `e` as an expression of the engine, or `None` after recording why not.
    pub fn expr(&mut self, e: &Expr) -> Option<ExprId> {
        match e {
            Expr::Lit(l) => self.literal(&l.lit),
            Expr::Paren(p) => self.expr(&p.expr),
            Expr::Group(g) => self.expr(&g.expr),
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
                let v = self.expr(&u.expr)?;
                Some(self.arena.neg(v))
            }
            Expr::Binary(b) => {
                let (l, r) = (self.expr(&b.left), self.expr(&b.right));
                let (l, r) = (l?, r?);
                match b.op {
                    BinOp::Add(_) => Some(self.arena.add(l, r)),
                    BinOp::Sub(_) => Some(self.arena.sub(l, r)),
                    BinOp::Mul(_) => Some(self.arena.mul(l, r)),
                    BinOp::Div(_) => {
                        let v = self.arena_div(l, r);
                        self.checked(v, &b.right)
                    }
                    _ => {
                        self.cx
                            .error_spanned_by(b.op, format!("unsupported operator: {}", allowed()));
                        None
                    }
                }
            }
            Expr::Path(p) => match p.path.get_ident() {
                Some(ident) => self.name(ident),
                None => {
                    self.cx
                        .error_spanned_by(e, format!("unsupported name: {}", allowed()));
                    None
                }
            },
            Expr::MethodCall(m) => {
                let args: Vec<&Expr> = m.args.iter().collect();
                self.function(&m.method, &m.receiver, &args, e)
            }
            Expr::Call(c) => {
                let Expr::Path(p) = &*c.func else {
                    self.cx
                        .error_spanned_by(&c.func, format!("unsupported call: {}", allowed()));
                    return None;
                };
                let Some(function) = p.path.get_ident() else {
                    self.cx
                        .error_spanned_by(&c.func, format!("unsupported call: {}", allowed()));
                    return None;
                };
                let args: Vec<&Expr> = c.args.iter().collect();
                match args.split_first() {
                    Some((receiver, rest)) => self.function(function, receiver, rest, e),
                    None => self.function_error(function, 0, e),
                }
            }
            _ => {
                self.cx
                    .error_spanned_by(e, format!("unsupported expression: {}", allowed()));
                None
            }
        }
    }

    fn arena_div(&mut self, l: ExprId, r: ExprId) -> Result<ExprId, String> {
        self.arena
            .div(l, r)
            .map_err(|_| "division by a value that is identically zero".to_owned())
    }

    fn checked(&self, value: Result<ExprId, String>, at: &Expr) -> Option<ExprId> {
        value
            .map_err(|message| self.cx.error_spanned_by(at, message))
            .ok()
    }

    /// `function(receiver, args…)`, written as a method or a call (`whole`, for spans).
    fn function(
        &mut self,
        function: &Ident,
        receiver: &Expr,
        args: &[&Expr],
        whole: &Expr,
    ) -> Option<ExprId> {
        let name = function.to_string();
        if let Some(f) = Func::named(&name) {
            if !args.is_empty() {
                return self.function_error(function, args.len() + 1, whole);
            }
            let x = self.expr(receiver)?;
            let v = self.arena.apply(f, x).map_err(|e| e.to_string());
            return self.checked(v, whole);
        }
        let Some(&(_, count)) = FUNCTIONS.iter().find(|(f, _)| *f == name) else {
            let unary: String = unary_names().map(|f| format!("`{f}`, ")).collect();
            self.cx.error_spanned_by(
                function,
                format!(
                    "unsupported function `{name}`: the Taylor recurrences know {unary}`powi` (an integer power) and `powf` (a power with a number literal exponent){}",
                    did_you_mean(&name, unary_names().chain(["powi", "powf"]))
                ),
            );
            return None;
        };
        if args.len() != count {
            return self.function_error(function, args.len() + 1, whole);
        }
        let x = self.expr(receiver)?;
        match (name.as_str(), args.first()) {
            ("sin", _) => Some(self.arena.sin(x)),
            ("cos", _) => Some(self.arena.cos(x)),
            ("sqrt", _) => {
                let v = self.arena.sqrt(x).map_err(|e| e.to_string());
                self.checked(v, receiver)
            }
            ("powf", Some(exponent)) => {
                // The literal exactly (`1.5` is 3/2): an integer one is `powi`, any other a
                // real power of a base taken positive.
                let Some(r) = rational(exponent) else {
                    self.cx.error_spanned_by(
                        exponent,
                        "`powf` expects a number literal exponent (`x.powf(1.5)`, `x.powf(-0.25)`)",
                    );
                    return None;
                };
                let v = self.arena.powr(x, r).map_err(|e| e.to_string());
                self.checked(v, whole)
            }
            (_, Some(exponent)) => {
                let Some(n) = integer(exponent) else {
                    self.cx.error_spanned_by(
                        exponent,
                        "`powi` expects an integer literal exponent (`x.powi(3)`, `x.powi(-2)`)",
                    );
                    return None;
                };
                let v = self.arena.powi(x, n).map_err(|e| e.to_string());
                self.checked(v, whole)
            }
            _ => self.function_error(function, args.len() + 1, whole),
        }
    }

    fn function_error(&self, function: &Ident, given: usize, whole: &Expr) -> Option<ExprId> {
        let expected = FUNCTIONS
            .iter()
            .find(|(f, _)| function == f)
            .map_or(1, |(_, n)| n + 1);
        self.cx.error_spanned_by(
            whole,
            format!("`{function}` takes {expected} argument(s) counting the receiver, not {given}"),
        );
        None
    }

    /// A state variable, a field, or the time.
    fn name(&mut self, ident: &Ident) -> Option<ExprId> {
        let names = &self.names;
        if let Some((_, e)) = names
            .state
            .iter()
            .chain(&names.fields)
            .find(|(n, _)| n == ident)
        {
            return Some(*e);
        }
        if ident == TIME {
            // One time symbol per arena: every `t` is the same series.
            let t = self.arena.time();
            self.names.time = Some(t);
            return Some(t);
        }
        let known: Vec<String> = names
            .state
            .iter()
            .chain(&names.fields)
            .map(|(n, _)| n.to_string())
            .collect();
        self.cx.error_spanned_by(
            ident,
            format!(
                "unknown name `{ident}`: a right-hand side reads the state variables, the struct's f64 fields and the time `{TIME}`{}",
                did_you_mean(&ident.to_string(), known.iter().map(String::as_str))
            ),
        );
        None
    }

    /// A number literal, exactly (`0.51` is 51/100), finite in f64.
    fn literal(&mut self, lit: &Lit) -> Option<ExprId> {
        number_literal(self.cx, self.arena, lit, &allowed())
    }
}

/// A number literal exactly, possibly negated or parenthesised.
fn rational(e: &Expr) -> Option<Rational> {
    match e {
        Expr::Lit(l) => match &l.lit {
            Lit::Float(f) if f.suffix().is_empty() || f.suffix() == "f64" => {
                parse_decimal(f.base10_digits()).ok()
            }
            Lit::Int(i) if i.suffix().is_empty() || i.suffix() == "f64" => {
                parse_decimal(i.base10_digits()).ok()
            }
            _ => None,
        },
        Expr::Paren(p) => rational(&p.expr),
        Expr::Group(g) => rational(&g.expr),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Some(-rational(&u.expr)?),
        _ => None,
    }
}

/// An integer literal, possibly negated or parenthesised.
fn integer(e: &Expr) -> Option<i64> {
    match e {
        Expr::Lit(l) => match &l.lit {
            Lit::Int(i) if i.suffix().is_empty() || i.suffix() == "i32" => {
                i.base10_parse::<i64>().ok()
            }
            _ => None,
        },
        Expr::Paren(p) => integer(&p.expr),
        Expr::Group(g) => integer(&g.expr),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => integer(&u.expr)?.checked_neg(),
        _ => None,
    }
}
