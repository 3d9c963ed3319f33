//! Direct floating-point evaluation of an expression (the reference the code generator's
//! interpreter and the tests compare against).

use super::arena::{Arena, ExprId, Node};
use super::hash::IdMap;

impl Arena {
    /// The value of `e` with symbol `s` set to `env[s.index()]`; an abbreviation takes the
    /// value of its definition.
    ///
    /// Missing entries read as NaN, so an unbound symbol cannot pass for a number.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let e = a.mul(x, x);
    /// assert_eq!(a.eval(e, &[3.0]), 9.0);
    /// ```
    pub fn eval(&self, e: ExprId, env: &[f64]) -> f64 {
        let order = self.walk(&[e], true, |_| true);
        let mut values: IdMap<ExprId, f64> = IdMap::default();
        values.reserve(order.len());
        for id in order {
            let v = self.eval_node(id, &values, env);
            values.insert(id, v);
        }
        values.get(&e).copied().unwrap_or(f64::NAN)
    }

    fn eval_node(&self, id: ExprId, values: &IdMap<ExprId, f64>, env: &[f64]) -> f64 {
        let v = |x: &ExprId| values.get(x).copied().unwrap_or(f64::NAN);
        match self.node(id) {
            Node::Const(r) => r.to_f64(),
            Node::Sym(s) => match self.definitions.get(s) {
                Some(d) => v(d),
                None => env.get(s.index()).copied().unwrap_or(f64::NAN),
            },
            Node::Add(c) => c.iter().map(v).sum(),
            Node::Mul(c) => c.iter().map(v).product(),
            Node::Pow(b, n) => match i32::try_from(*n) {
                Ok(n) => v(b).powi(n),
                Err(_) => v(b).powf(*n as f64),
            },
            Node::Powr(b, r) => v(b).powf(r.to_f64()),
            Node::Sqrt(u) => v(u).sqrt(),
            Node::Sin(u) => v(u).sin(),
            Node::Cos(u) => v(u).cos(),
            Node::Func(f, u) => f.value(v(u)),
        }
    }
}
