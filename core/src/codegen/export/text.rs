//! An [`Exported`] scene as text and back: what the derive writes into the struct's
//! `impl Export` while it expands (one string literal, smaller than the C and the Python it
//! stands for), read back at run time to emit either.
//!
//! ```text
//! precess-export 1
//! name pendulum
//! state theta omega
//! inputs u0      only for a scene with inputs (the environment is [t, y, u, p])
//! parameters g l
//! function rhs 2 1 the state derivative
//! i 2            one instruction a line: c <bits>, i <place>, + - * / a b,
//! ...            n a (−a), r a (√a), p a <bits> (powf), s a, o a (sin, cos), f <name> a
//! outputs 1 7
//! ```
//!
//! Constants are their bits in hexadecimal, so the text round-trips every value exactly.

use std::fmt::Write;

use super::{ExportError, Exported, ExportedFunction};
use crate::codegen::program::{Op, Program, Slot};
use crate::sym::{Func, SymbolId};

/// The first line of every text, with the format's version.
const HEADER: &str = "precess-export 1";

impl Exported {
    /// The scene as text (see the module's docs).
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{HEADER}\nname {}", self.name);
        let _ = writeln!(s, "state {}", self.state.join(" ").trim_end());
        if !self.inputs.is_empty() {
            let _ = writeln!(s, "inputs {}", self.inputs.join(" "));
        }
        let _ = writeln!(s, "parameters {}", self.parameters.join(" ").trim_end());
        for f in &self.functions {
            let doc = f.doc.replace(['\n', '\r'], " ");
            let _ = writeln!(s, "function {} {} {} {doc}", f.name, f.rows, f.cols);
            for op in &f.program.ops {
                let _ = match *op {
                    Op::Const(c) => writeln!(s, "c {:x}", c.to_bits()),
                    Op::Input(k) => writeln!(s, "i {}", k.index()),
                    Op::Add(a, b) => writeln!(s, "+ {a} {b}"),
                    Op::Sub(a, b) => writeln!(s, "- {a} {b}"),
                    Op::Mul(a, b) => writeln!(s, "* {a} {b}"),
                    Op::Div(a, b) => writeln!(s, "/ {a} {b}"),
                    Op::Neg(a) => writeln!(s, "n {a}"),
                    Op::Sqrt(a) => writeln!(s, "r {a}"),
                    Op::Powf(a, r) => writeln!(s, "p {a} {:x}", r.to_bits()),
                    Op::Sin(a) => writeln!(s, "s {a}"),
                    Op::Cos(a) => writeln!(s, "o {a}"),
                    Op::Func(g, a) => writeln!(s, "f {} {a}", g.name()),
                };
            }
            let outputs: Vec<String> = f.program.outputs.iter().map(u32::to_string).collect();
            let _ = writeln!(s, "outputs {}", outputs.join(" "));
        }
        s
    }

    /// The scene [`Exported::to_text`] wrote.
    ///
    /// # Errors
    /// [`ExportError::Text`] with the line and the reason for anything else: an unknown
    /// instruction, an operand that is not an earlier instruction, an input past the
    /// environment, an output count that does not fill the function's shape, a repeated name.
    pub fn from_text(text: &str) -> Result<Exported, ExportError> {
        let mut rest = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.split_whitespace().collect::<Vec<_>>()))
            .peekable();
        let (n, header) = next_line(&mut rest, HEADER)?;
        if header.join(" ") != HEADER {
            return Err(malformed(n, format!("expected `{HEADER}`")));
        }
        let name = field(&mut rest, "name")?.concat();
        let state = field(&mut rest, "state")?;
        // Only a scene with inputs has the line.
        let inputs = match rest.peek() {
            Some((_, words)) if words.first() == Some(&"inputs") => field(&mut rest, "inputs")?,
            _ => Vec::new(),
        };
        let parameters = field(&mut rest, "parameters")?;
        let env = 1 + state.len() + inputs.len() + parameters.len();
        let mut exported = Exported {
            name,
            state,
            inputs,
            parameters,
            functions: Vec::new(),
        };
        while let Some((n, words)) = rest.next() {
            let [kw, fname, rows, cols, doc @ ..] = words.as_slice() else {
                return Err(malformed(
                    n,
                    "expected `function <name> <rows> <cols> <doc>`".into(),
                ));
            };
            if *kw != "function" {
                return Err(malformed(n, "expected `function …`".into()));
            }
            let (rows, cols) = (count(n, rows)?, count(n, cols)?);
            let mut ops: Vec<Op> = Vec::new();
            let outputs = loop {
                let (n, words) = rest
                    .next()
                    .ok_or_else(|| malformed(n, "the function has no `outputs` line".into()))?;
                if words.first() == Some(&"outputs") {
                    let outputs = words[1..]
                        .iter()
                        .map(|w| slot(n, w, ops.len()))
                        .collect::<Result<Vec<Slot>, _>>()?;
                    if rows.checked_mul(cols) != Some(outputs.len()) {
                        return Err(malformed(
                            n,
                            format!("{} outputs do not fill {rows} × {cols}", outputs.len()),
                        ));
                    }
                    break outputs;
                }
                ops.push(op(n, &words, ops.len(), env)?);
            };
            exported.functions.push(ExportedFunction {
                name: (*fname).to_owned(),
                doc: doc.join(" "),
                rows,
                cols,
                program: Program { ops, outputs },
            });
        }
        exported
            .check_names()
            .map_err(|e| malformed(0, e.to_string()))?;
        Ok(exported)
    }
}

/// The next line's number and words, or the error of a text that ends before `want`.
fn next_line<'a>(
    lines: &mut impl Iterator<Item = (usize, Vec<&'a str>)>,
    want: &str,
) -> Result<(usize, Vec<&'a str>), ExportError> {
    lines
        .next()
        .ok_or_else(|| malformed(0, format!("the text ends before `{want}`")))
}

/// The words after `key` on the next line, which must start with it.
fn field<'a>(
    lines: &mut impl Iterator<Item = (usize, Vec<&'a str>)>,
    key: &str,
) -> Result<Vec<String>, ExportError> {
    let (n, words) = next_line(lines, key)?;
    match words.split_first() {
        Some((&k, rest)) if k == key => Ok(rest.iter().map(|w| (*w).to_owned()).collect()),
        _ => Err(malformed(n, format!("expected `{key} …`"))),
    }
}

fn malformed(line: usize, reason: String) -> ExportError {
    ExportError::Text { line, reason }
}

fn count(n: usize, w: &str) -> Result<usize, ExportError> {
    w.parse()
        .map_err(|_| malformed(n, format!("`{w}` is not a count")))
}

/// An operand: an instruction before the `len`-th.
fn slot(n: usize, w: &str, len: usize) -> Result<Slot, ExportError> {
    match w.parse::<Slot>() {
        Ok(s) if (s as usize) < len => Ok(s),
        _ => Err(malformed(n, format!("`{w}` is not an earlier instruction"))),
    }
}

fn bits(n: usize, w: &str) -> Result<f64, ExportError> {
    u64::from_str_radix(w, 16)
        .map(f64::from_bits)
        .map_err(|_| malformed(n, format!("`{w}` is not a constant's bits")))
}

/// The instruction of one line, the `len`-th, in an environment of `env` values.
fn op(n: usize, words: &[&str], len: usize, env: usize) -> Result<Op, ExportError> {
    let s = |w: &str| slot(n, w, len);
    Ok(match *words {
        ["c", b] => Op::Const(bits(n, b)?),
        ["i", k] => match k.parse::<u32>() {
            Ok(k) if (k as usize) < env => Op::Input(SymbolId(k)),
            _ => {
                return Err(malformed(
                    n,
                    format!("`{k}` is not an input of the environment"),
                ));
            }
        },
        ["+", a, b] => Op::Add(s(a)?, s(b)?),
        ["-", a, b] => Op::Sub(s(a)?, s(b)?),
        ["*", a, b] => Op::Mul(s(a)?, s(b)?),
        ["/", a, b] => Op::Div(s(a)?, s(b)?),
        ["n", a] => Op::Neg(s(a)?),
        ["r", a] => Op::Sqrt(s(a)?),
        ["p", a, r] => Op::Powf(s(a)?, bits(n, r)?),
        ["s", a] => Op::Sin(s(a)?),
        ["o", a] => Op::Cos(s(a)?),
        ["f", name, a] => match Func::named(name) {
            Some(f) => Op::Func(f, s(a)?),
            None => return Err(malformed(n, format!("`{name}` is no registered function"))),
        },
        _ => {
            return Err(malformed(
                n,
                format!("`{}` is no instruction", words.join(" ")),
            ));
        }
    })
}
