//! Plain-text rendering, for error messages and debugging.

use super::arena::{Arena, ExprId, Node};

impl Arena {
    /// `e` as plain text, e.g. `2*x*sin(theta) + 1/3`.
    pub fn display(&self, e: ExprId) -> String {
        let mut out = String::new();
        self.write_plain(e, 0, &mut out);
        out
    }

    /// Writes `e` with parentheses when its precedence is below `outer`
    /// (0 = sum context, 1 = product context, 2 = power base).
    fn write_plain(&self, e: ExprId, outer: u8, out: &mut String) {
        let (prec, text) = match self.node(e) {
            Node::Const(r) => (
                if r.is_integer() && !r.is_negative() {
                    3
                } else {
                    1
                },
                r.to_string(),
            ),
            Node::Sym(s) => (3, self.symbol(*s).name.clone()),
            Node::Add(terms) => {
                let mut s = String::new();
                for (i, &t) in terms.iter().enumerate() {
                    if i > 0 {
                        s.push_str(" + ");
                    }
                    self.write_plain(t, 1, &mut s);
                }
                (0, s)
            }
            Node::Mul(f) => {
                let mut s = String::new();
                for (i, &x) in f.iter().enumerate() {
                    if i > 0 {
                        s.push('*');
                    }
                    self.write_plain(x, 2, &mut s);
                }
                (1, s)
            }
            Node::Pow(b, n) => {
                let mut s = String::new();
                self.write_plain(*b, 3, &mut s);
                s.push_str(&format!("^{n}"));
                (2, s)
            }
            Node::Sqrt(u) => (3, format!("sqrt({})", self.display(*u))),
            Node::Sin(u) => (3, format!("sin({})", self.display(*u))),
            Node::Cos(u) => (3, format!("cos({})", self.display(*u))),
        };
        if prec < outer {
            out.push('(');
            out.push_str(&text);
            out.push(')');
        } else {
            out.push_str(&text);
        }
    }
}
