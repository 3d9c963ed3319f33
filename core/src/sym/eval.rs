//! Direct floating-point evaluation of an expression (the reference the code generator's
//! interpreter and the tests compare against).

use super::arena::{Arena, ExprId, Node};

impl Arena {
    /// The value of `e` with symbol `s` set to `env[s.index()]`.
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
        let mut values = vec![f64::NAN; e.index() + 1];
        for id in self.reachable(e) {
            values[id.index()] = self.eval_node(id, &values, env);
        }
        values[e.index()]
    }

    /// The ids `e` depends on (itself included), children before parents.
    pub fn reachable(&self, e: ExprId) -> Vec<ExprId> {
        let mut seen = vec![false; e.index() + 1];
        seen[e.index()] = true;
        // Ids are topologically ordered, so a reverse sweep marks every dependency.
        for i in (0..=e.index()).rev() {
            if !seen[i] {
                continue;
            }
            match &self.nodes_slice()[i] {
                Node::Const(_) | Node::Sym(_) => {}
                Node::Add(c) | Node::Mul(c) => c.iter().for_each(|x| seen[x.index()] = true),
                Node::Pow(b, _) => seen[b.index()] = true,
                Node::Sqrt(u) | Node::Sin(u) | Node::Cos(u) => seen[u.index()] = true,
            }
        }
        (0..=e.index())
            .filter(|&i| seen[i])
            .map(|i| ExprId(i as u32))
            .collect()
    }

    fn eval_node(&self, id: ExprId, values: &[f64], env: &[f64]) -> f64 {
        let v = |x: &ExprId| values[x.index()];
        match self.node(id) {
            Node::Const(r) => r.to_f64(),
            Node::Sym(s) => env.get(s.index()).copied().unwrap_or(f64::NAN),
            Node::Add(c) => c.iter().map(v).sum(),
            Node::Mul(c) => c.iter().map(v).product(),
            Node::Pow(b, n) => match i32::try_from(*n) {
                Ok(n) => v(b).powi(n),
                Err(_) => v(b).powf(*n as f64),
            },
            Node::Sqrt(u) => v(u).sqrt(),
            Node::Sin(u) => v(u).sin(),
            Node::Cos(u) => v(u).cos(),
        }
    }
}
