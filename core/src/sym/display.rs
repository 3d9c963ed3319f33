//! Plain-text rendering, for error messages and debugging.

use super::arena::{Arena, ExprId, Node};

/// What is left to write: a node in a context, or text.
enum Piece {
    /// A node, parenthesised when its precedence is below the context's
    /// (0 = sum context, 1 = product context, 2 = power base, 3 = atom).
    Node(ExprId, u8),
    Text(String),
}

impl Arena {
    /// `e` as plain text, e.g. `2*x*sin(theta) + 1/3`. Written from an explicit stack, so
    /// any depth of nesting prints.
    pub fn display(&self, e: ExprId) -> String {
        let mut out = String::new();
        let mut stack = vec![Piece::Node(e, 0)];
        while let Some(piece) = stack.pop() {
            let (e, outer) = match piece {
                Piece::Text(t) => {
                    out.push_str(&t);
                    continue;
                }
                Piece::Node(e, outer) => (e, outer),
            };
            let (prec, parts) = self.plain_parts(e);
            let open = prec < outer;
            if open {
                stack.push(Piece::Text(")".to_owned()));
            }
            stack.extend(parts.into_iter().rev());
            if open {
                stack.push(Piece::Text("(".to_owned()));
            }
        }
        out
    }

    /// The precedence of `e` and the pieces that write it.
    fn plain_parts(&self, e: ExprId) -> (u8, Vec<Piece>) {
        let text = |s: String| vec![Piece::Text(s)];
        let joined = |list: &[ExprId], sep: &str, ctx: u8| {
            let mut v = Vec::with_capacity(2 * list.len());
            for (i, &x) in list.iter().enumerate() {
                if i > 0 {
                    v.push(Piece::Text(sep.to_owned()));
                }
                v.push(Piece::Node(x, ctx));
            }
            v
        };
        let call = |f: &str, u: ExprId| {
            vec![
                Piece::Text(format!("{f}(")),
                Piece::Node(u, 0),
                Piece::Text(")".to_owned()),
            ]
        };
        match self.node(e) {
            Node::Const(r) => (
                if r.is_integer() && !r.is_negative() {
                    3
                } else {
                    1
                },
                text(r.to_string()),
            ),
            Node::Sym(s) => (3, text(self.symbol(*s).name.clone())),
            Node::Add(terms) => (0, joined(terms, " + ", 1)),
            Node::Mul(f) => (1, joined(f, "*", 2)),
            Node::Pow(b, n) => (2, vec![Piece::Node(*b, 3), Piece::Text(format!("^{n}"))]),
            Node::Powr(b, r) => (2, vec![Piece::Node(*b, 3), Piece::Text(format!("^({r})"))]),
            Node::Sqrt(u) => (3, call("sqrt", *u)),
            Node::Sin(u) => (3, call("sin", *u)),
            Node::Cos(u) => (3, call("cos", *u)),
            Node::Func(f, u) => (3, call(f.name(), *u)),
        }
    }
}
