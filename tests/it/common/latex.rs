//! A reader for the LaTeX the paper form writes (`codegen::paper_latex`), evaluating as it
//! parses: sums, implicit products, `\frac`, `\left( … \right)`, powers `^{n}`, `\sin`,
//! `\cos`, `\sqrt`, `\cdot`, numbers, and symbols (`x`, `I_{1}`, `\theta`, `\dot{\phi}`,
//! `\tau_{2}`) looked up by their LaTeX. Written for the tests, independently of the printer.

use std::collections::HashMap;

/// The value of the LaTeX expression `s`, its symbols read from `vars`.
///
/// # Errors
/// A message naming what could not be read.
pub fn evaluate(s: &str, vars: &HashMap<String, f64>) -> Result<f64, String> {
    let mut r = Reader { s, pos: 0, vars };
    let v = r.expr()?;
    r.space();
    if r.pos == s.len() {
        Ok(v)
    } else {
        Err(format!("unread text at {}: {}", r.pos, &s[r.pos..]))
    }
}

struct Reader<'a> {
    s: &'a str,
    pos: usize,
    vars: &'a HashMap<String, f64>,
}

impl Reader<'_> {
    fn rest(&self) -> &str {
        &self.s[self.pos..]
    }

    fn space(&mut self) {
        while self.rest().starts_with(' ') {
            self.pos += 1;
        }
    }

    fn eat(&mut self, t: &str) -> bool {
        if self.rest().starts_with(t) {
            self.pos += t.len();
            true
        } else {
            false
        }
    }

    fn expect(&mut self, t: &str) -> Result<(), String> {
        if self.eat(t) {
            Ok(())
        } else {
            Err(format!("expected {t} at {}: {}", self.pos, self.rest()))
        }
    }

    fn expr(&mut self) -> Result<f64, String> {
        self.space();
        let negative = self.eat("-");
        let first = self.term()?;
        let mut acc = if negative { -first } else { first };
        loop {
            self.space();
            if self.eat("+") {
                acc += self.term()?;
            } else if self.eat("-") {
                acc -= self.term()?;
            } else {
                return Ok(acc);
            }
        }
    }

    fn term(&mut self) -> Result<f64, String> {
        let mut acc = self.factor()?;
        loop {
            self.space();
            let r = self.rest();
            if r.is_empty()
                || r.starts_with('+')
                || r.starts_with('-')
                || r.starts_with('}')
                || r.starts_with("\\right")
            {
                return Ok(acc);
            }
            self.eat("\\cdot");
            acc *= self.factor()?;
        }
    }

    fn factor(&mut self) -> Result<f64, String> {
        let base = self.atom()?;
        if self.eat("^{") {
            let n = self.expr()?;
            self.expect("}")?;
            return Ok(base.powf(n));
        }
        Ok(base)
    }

    fn braced(&mut self) -> Result<f64, String> {
        self.expect("{")?;
        let v = self.expr()?;
        self.expect("}")?;
        Ok(v)
    }

    fn atom(&mut self) -> Result<f64, String> {
        self.space();
        if self.eat("\\frac") {
            let n = self.braced()?;
            let d = self.braced()?;
            return Ok(n / d);
        }
        if self.eat("\\left(") {
            let v = self.expr()?;
            self.expect("\\right)")?;
            return Ok(v);
        }
        if self.eat("\\sqrt") {
            return Ok(self.braced()?.sqrt());
        }
        for (name, f) in [("\\sin", f64::sin as fn(f64) -> f64), ("\\cos", f64::cos)] {
            if self.eat(name) {
                let power = if self.eat("^{") {
                    let n = self.expr()?;
                    self.expect("}")?;
                    n
                } else {
                    1.0
                };
                let arg = self.atom()?;
                return Ok(f(arg).powf(power));
            }
        }
        if self.rest().starts_with('{') {
            return self.braced();
        }
        if self.rest().starts_with(|c: char| c.is_ascii_digit()) {
            let digits: String = self
                .rest()
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect();
            self.pos += digits.len();
            return digits.parse().map_err(|e| format!("{e}: {digits}"));
        }
        let (name, end) = read_symbol(self.s, self.pos)
            .ok_or_else(|| format!("no symbol at {}: {}", self.pos, self.rest()))?;
        self.pos = end;
        self.vars
            .get(&name)
            .copied()
            .ok_or_else(|| format!("unknown symbol {name}"))
    }
}

/// The symbol starting at `pos` (`x`, `I_{1}`, `\theta`, `\dot{\phi}`) and where it ends.
pub fn read_symbol(s: &str, pos: usize) -> Option<(String, usize)> {
    let rest = &s[pos..];
    let mut end = pos;
    if rest.starts_with("\\dot{") || rest.starts_with("\\ddot{") {
        let open = rest.find('{')?;
        end = pos + open + matching_brace(&rest[open..])? + 1;
    } else if let Some(command) = rest.strip_prefix('\\') {
        let letters = command
            .chars()
            .take_while(char::is_ascii_alphabetic)
            .count();
        if letters == 0 {
            return None;
        }
        end += 1 + letters;
    } else if rest.starts_with(|c: char| c.is_ascii_alphabetic()) {
        end += 1;
    } else {
        return None;
    }
    if s[end..].starts_with("_{") {
        end += 1 + matching_brace(&s[end + 1..])? + 1;
    }
    Some((s[pos..end].to_owned(), end))
}

/// The index of the brace closing the one `s` starts with.
fn matching_brace(s: &str) -> Option<usize> {
    let mut depth = 0;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// The terms of a sum at the top level (outside braces and parentheses).
pub fn top_level_terms(s: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start, mut i) = (0i32, 0, 0);
    while i < s.len() {
        let rest = &s[i..];
        if depth == 0 && i > start && (rest.starts_with(" + ") || rest.starts_with(" - ")) {
            out.push(&s[start..i]);
            start = i + 3;
        }
        if rest.starts_with('{') || rest.starts_with("\\left") {
            depth += 1;
        } else if rest.starts_with('}') || rest.starts_with("\\right") {
            depth -= 1;
        }
        i += rest.chars().next().map_or(1, char::len_utf8);
    }
    out.push(&s[start..]);
    out
}

/// The symbols of a term outside its parentheses (inside a fraction's braces too).
pub fn top_level_symbols(term: &str) -> Vec<String> {
    let mut outside = String::new();
    let mut depth = 0;
    let mut i = 0;
    while i < term.len() {
        let rest = &term[i..];
        if rest.starts_with("\\left(") {
            depth += 1;
            i += 6;
        } else if rest.starts_with("\\right)") {
            depth -= 1;
            i += 7;
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            if depth == 0 {
                outside.push(c);
            }
            i += c.len_utf8();
        }
    }
    read_symbols(&outside)
}

/// Every symbol in `s`, the commands for functions and structure left out.
pub fn read_symbols(s: &str) -> Vec<String> {
    const STRUCTURE: [&str; 8] = [
        "\\frac", "\\sin", "\\cos", "\\sqrt", "\\left", "\\right", "\\cdot", "\\quad",
    ];
    let mut out = Vec::new();
    let mut i = 0;
    while i < s.len() {
        match read_symbol(s, i) {
            Some((name, end)) => {
                if !STRUCTURE.contains(&name.as_str()) {
                    out.push(name);
                }
                i = end;
            }
            None => i += s[i..].chars().next().map_or(1, char::len_utf8),
        }
    }
    out
}
