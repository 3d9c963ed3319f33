//! Lowering an expression graph to a straight-line program with shared subexpressions.
//!
//! Hash-consing already shares equal subtrees; lowering adds value numbering at the level of
//! binary instructions, so `a·b` appearing inside two different products is computed once.
//! Negative coefficients become subtractions, negative powers divisions, and integer powers
//! square-and-multiply chains: the instruction list is what the emitted Rust executes.

use crate::sym::{Arena, ExprId, Func, IdMap, Node, Rational, SymbolId};

/// Index of an instruction's result in a [`Program`].
pub type Slot = u32;

/// One straight-line instruction.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Op {
    /// A constant.
    Const(f64),
    /// The value of a symbol, read from the environment.
    Input(SymbolId),
    /// `a + b`.
    Add(Slot, Slot),
    /// `a − b`.
    Sub(Slot, Slot),
    /// `a · b`.
    Mul(Slot, Slot),
    /// `a / b`.
    Div(Slot, Slot),
    /// `−a`.
    Neg(Slot),
    /// `√a`.
    Sqrt(Slot),
    /// `a^r` for a non-integer constant `r` (`f64::powf`, NaN for a negative `a`).
    Powf(Slot, f64),
    /// `sin a`.
    Sin(Slot),
    /// `cos a`.
    Cos(Slot),
    /// `f(a)` for a registered primitive `f` ([`crate::sym::functions`]).
    Func(Func, Slot),
}

/// Hashable identity of an instruction (constants by their bits) for value numbering.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Const(u64),
    Input(SymbolId),
    Bin(u8, Slot, Slot),
    Un(u8, Slot),
    Powf(Slot, u64),
    Func(Func, Slot),
}

impl Op {
    fn key(self) -> Key {
        // Commutative operands are ordered so a·b and b·a number alike.
        let ord = |a: Slot, b: Slot| (a.min(b), a.max(b));
        match self {
            Op::Const(x) => Key::Const(x.to_bits()),
            Op::Input(s) => Key::Input(s),
            Op::Add(a, b) => {
                let (a, b) = ord(a, b);
                Key::Bin(0, a, b)
            }
            Op::Mul(a, b) => {
                let (a, b) = ord(a, b);
                Key::Bin(1, a, b)
            }
            Op::Sub(a, b) => Key::Bin(2, a, b),
            Op::Div(a, b) => Key::Bin(3, a, b),
            Op::Neg(a) => Key::Un(0, a),
            Op::Sqrt(a) => Key::Un(1, a),
            Op::Powf(a, r) => Key::Powf(a, r.to_bits()),
            Op::Sin(a) => Key::Un(2, a),
            Op::Cos(a) => Key::Un(3, a),
            Op::Func(f, a) => Key::Func(f, a),
        }
    }
}

/// A straight-line program computing several outputs from symbol values.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub(crate) ops: Vec<Op>,
    pub(crate) outputs: Vec<Slot>,
}

struct Lowering<'a> {
    arena: &'a Arena,
    ops: Vec<Op>,
    numbered: IdMap<Key, Slot>,
    by_node: IdMap<ExprId, Slot>,
    /// Negative powers used by more than one product: their reciprocal is computed once
    /// and multiplied in, instead of dividing in every product.
    shared_reciprocals: IdMap<(ExprId, i64), ()>,
}

/// How deep the greedy factoring of one sum may nest (each level pulls out one base).
const MAX_HORNER_DEPTH: usize = 64;

/// The nodes [`Lowering::node`] is asked for when lowering `outputs`, children before
/// parents: the bases of the factors of products and of the terms of sums, the bases of
/// powers, the arguments of functions, the definitions of abbreviations.
fn lowering_order(arena: &Arena, outputs: &[ExprId]) -> Vec<ExprId> {
    let base = |x: ExprId| match arena.node(x) {
        Node::Pow(b, _) => *b,
        _ => x,
    };
    let factors_of = |t: ExprId, out: &mut Vec<ExprId>| match arena.node(t) {
        Node::Const(_) => {}
        Node::Mul(f) => out.extend(
            f.iter()
                .filter(|&&x| !matches!(arena.node(x), Node::Const(_)))
                .map(|&x| base(x)),
        ),
        _ => out.push(base(t)),
    };
    let mut seen: IdMap<ExprId, ()> = IdMap::default();
    let mut order = Vec::new();
    let mut stack: Vec<ExprId> = outputs.to_vec();
    let mut next = Vec::new();
    while let Some(e) = stack.pop() {
        if seen.insert(e, ()).is_some() {
            continue;
        }
        order.push(e);
        next.clear();
        match arena.node(e) {
            Node::Const(_) => {}
            Node::Sym(s) => next.extend(arena.definition(*s)),
            Node::Add(terms) => terms.iter().for_each(|&t| factors_of(t, &mut next)),
            Node::Mul(_) => factors_of(e, &mut next),
            Node::Pow(b, _) | Node::Powr(b, _) => next.push(*b),
            Node::Sqrt(u) | Node::Sin(u) | Node::Cos(u) | Node::Func(_, u) => next.push(*u),
        }
        stack.extend(next.iter().filter(|x| !seen.contains_key(x)));
    }
    order.sort_unstable_by_key(|e| e.index());
    order
}

/// A term of a sum: its rational coefficient and its factors `(base, exponent)`.
type Term = (Rational, Vec<(ExprId, i64)>);

/// The negative powers that appear as a factor of two or more products reachable from
/// `outputs`.
fn shared_reciprocals(arena: &Arena, outputs: &[ExprId]) -> IdMap<(ExprId, i64), ()> {
    let mut uses: IdMap<(ExprId, i64), u32> = IdMap::default();
    for e in arena.walk(outputs, true, |_| true) {
        if let Node::Mul(c) = arena.node(e) {
            for &f in c.iter() {
                if let Node::Pow(b, n) = arena.node(f)
                    && *n < 0
                {
                    *uses.entry((*b, *n)).or_default() += 1;
                }
            }
        }
    }
    uses.into_iter()
        .filter(|&(_, n)| n >= 2)
        .map(|(e, _)| (e, ()))
        .collect()
}

impl Program {
    /// Lowers `outputs` (evaluated together, sharing every common subexpression).
    ///
    /// ```
    /// use precess_core::{codegen::Program, sym::Arena};
    /// let mut a = Arena::new();
    /// let x = a.parameter("x");
    /// let y = a.parameter("y");
    /// let xy = a.mul(x, y);
    /// let e1 = a.sin(xy);
    /// let e2 = a.cos(xy);
    /// let p = Program::lower(&a, &[e1, e2]);
    /// assert_eq!(p.op_count().muls, 1); // x·y once for both outputs
    /// let v = p.eval(&[0.5, 2.0]);
    /// assert_eq!(v, vec![1f64.sin(), 1f64.cos()]);
    /// ```
    pub fn lower(arena: &Arena, outputs: &[ExprId]) -> Program {
        let mut l = Lowering {
            arena,
            ops: Vec::new(),
            numbered: IdMap::default(),
            by_node: IdMap::default(),
            shared_reciprocals: shared_reciprocals(arena, outputs),
        };
        // Lower every node the outputs need, children first, so that `node` finds each
        // child done and never recurses deeper than one level.
        for e in lowering_order(arena, outputs) {
            l.node(e);
        }
        let outputs = outputs.iter().map(|&e| l.node(e)).collect();
        Program {
            ops: l.ops,
            outputs,
        }
    }

    /// The instructions, in execution order.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// The slot of each output.
    pub fn outputs(&self) -> &[Slot] {
        &self.outputs
    }

    /// The symbols the program reads, in symbol order.
    pub fn inputs(&self) -> Vec<SymbolId> {
        let mut v: Vec<SymbolId> = self
            .ops
            .iter()
            .filter_map(|op| match op {
                Op::Input(s) => Some(*s),
                _ => None,
            })
            .collect();
        v.sort();
        v.dedup();
        v
    }
}

impl Lowering<'_> {
    fn emit(&mut self, op: Op) -> Slot {
        let key = op.key();
        if let Some(&s) = self.numbered.get(&key) {
            return s;
        }
        let s = self.ops.len() as Slot;
        self.ops.push(op);
        self.numbered.insert(key, s);
        s
    }

    fn constant(&mut self, r: Rational) -> Slot {
        self.emit(Op::Const(r.to_f64()))
    }

    fn node(&mut self, e: ExprId) -> Slot {
        if let Some(&s) = self.by_node.get(&e) {
            return s;
        }
        let s = match self.arena.node(e) {
            Node::Const(r) => self.constant(*r),
            Node::Sym(sym) => match self.arena.definition(*sym) {
                // An abbreviation is computed from its definition.
                Some(d) => self.node(d),
                None => self.emit(Op::Input(*sym)),
            },
            Node::Add(terms) => self.sum(terms),
            Node::Mul(_) => {
                let (c, factors) = self.term_of(e);
                let mag = self.product(c.abs_value(), &factors);
                if c.is_negative() {
                    self.emit(Op::Neg(mag))
                } else {
                    mag
                }
            }
            Node::Pow(b, n) => {
                let base = self.node(*b);
                self.power_of(base, *n)
            }
            Node::Sqrt(u) => {
                let u = self.node(*u);
                self.emit(Op::Sqrt(u))
            }
            Node::Powr(b, r) => {
                let b = self.node(*b);
                self.emit(Op::Powf(b, r.to_f64()))
            }
            Node::Sin(u) => {
                let u = self.node(*u);
                self.emit(Op::Sin(u))
            }
            Node::Cos(u) => {
                let u = self.node(*u);
                self.emit(Op::Cos(u))
            }
            Node::Func(f, u) => {
                let u = self.node(*u);
                self.emit(Op::Func(*f, u))
            }
        };
        self.by_node.insert(e, s);
        s
    }

    /// A leading rational coefficient and the remaining factors.
    fn coefficient<'f>(&self, factors: &'f [ExprId]) -> (Rational, &'f [ExprId]) {
        match self.arena.node(factors[0]) {
            Node::Const(r) => (*r, &factors[1..]),
            _ => (Rational::ONE, factors),
        }
    }

    /// Square-and-multiply; value numbering shares the squares between powers of one base.
    fn positive_power(&mut self, base: Slot, n: u64) -> Slot {
        if n == 1 {
            return base;
        }
        let half = self.positive_power(base, n / 2);
        let sq = self.emit(Op::Mul(half, half));
        if n % 2 == 1 {
            self.emit(Op::Mul(sq, base))
        } else {
            sq
        }
    }

    /// `c · Π bᵢ^nᵢ` with `c ≥ 0`: numerator factors multiplied, negative powers gathered
    /// into one denominator, so a quotient costs a single division.
    fn product(&mut self, c: Rational, factors: &[(ExprId, i64)]) -> Slot {
        let mut num: Option<Slot> = None;
        let mut den: Option<Slot> = None;
        for &(b, n) in factors {
            let base = self.node(b);
            let (target, slot) = if n < 0 && !self.shared_reciprocals.contains_key(&(b, n)) {
                (&mut den, self.positive_power(base, n.unsigned_abs()))
            } else {
                (&mut num, self.power_of(base, n))
            };
            *target = Some(match *target {
                Some(acc) => self.emit(Op::Mul(acc, slot)),
                None => slot,
            });
        }
        let num = match (num, c.is_one()) {
            (Some(n), true) => n,
            (Some(n), false) => {
                let k = self.constant(c);
                self.emit(Op::Mul(k, n))
            }
            (None, _) => self.constant(c),
        };
        match den {
            Some(d) => self.emit(Op::Div(num, d)),
            None => num,
        }
    }

    /// `base^n` for a lowered base and a non-zero n.
    fn power_of(&mut self, base: Slot, n: i64) -> Slot {
        let pos = self.positive_power(base, n.unsigned_abs());
        if n < 0 {
            let one = self.constant(Rational::ONE);
            self.emit(Op::Div(one, pos))
        } else {
            pos
        }
    }

    /// A term as its coefficient and its factors `(base, exponent)`.
    fn term_of(&self, t: ExprId) -> Term {
        let base_exp = |x: ExprId| match self.arena.node(x) {
            Node::Pow(b, n) => (*b, *n),
            _ => (x, 1),
        };
        match self.arena.node(t) {
            Node::Mul(f) => {
                let (c, rest) = self.coefficient(f);
                (c, rest.iter().map(|&x| base_exp(x)).collect())
            }
            Node::Const(r) => (*r, Vec::new()),
            _ => (Rational::ONE, vec![base_exp(t)]),
        }
    }

    /// A sum, factored greedily (multivariate Horner): the base that divides most terms is
    /// pulled out, `a·x + b·x + c = x·(a + b) + c`, recursively. Negative terms become
    /// subtractions.
    fn sum(&mut self, terms: &[ExprId]) -> Slot {
        let terms: Vec<Term> = terms.iter().map(|&t| self.term_of(t)).collect();
        let parts = self.horner(terms, 0);
        self.signed_sum(parts)
    }

    /// The sum of `terms` as signed parts `(negative, magnitude)`. Past [`MAX_HORNER_DEPTH`]
    /// nested factorings the rest is summed flat, which bounds the recursion.
    fn horner(&mut self, terms: Vec<Term>, depth: usize) -> Vec<(bool, Slot)> {
        let mut counts: Vec<(ExprId, usize)> = Vec::new();
        for (_, f) in &terms {
            for &(b, n) in f {
                if n > 0 {
                    match counts.iter_mut().find(|(x, _)| *x == b) {
                        Some(c) => c.1 += 1,
                        None => counts.push((b, 1)),
                    }
                }
            }
        }
        // Most frequent first; ties by id, so the result is deterministic.
        let best = counts
            .iter()
            .filter(|&&(_, c)| c >= 2 && depth < MAX_HORNER_DEPTH)
            .max_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(&a.0)));
        let Some(&(b, _)) = best else {
            return terms
                .iter()
                .map(|(c, f)| (c.is_negative(), self.product(c.abs_value(), f)))
                .collect();
        };
        let (mut with, without): (Vec<Term>, Vec<Term>) = terms
            .into_iter()
            .partition(|(_, f)| f.iter().any(|&(x, n)| x == b && n > 0));
        for (_, f) in &mut with {
            if let Some(i) = f.iter().position(|&(x, _)| x == b) {
                f[i].1 -= 1;
                if f[i].1 == 0 {
                    f.remove(i);
                }
            }
        }
        // Pull a common sign out too: −a·x − b·x = −(a + b)·x.
        let negative = with.iter().all(|(c, _)| c.is_negative());
        if negative {
            for (c, _) in &mut with {
                *c = -*c;
            }
        }
        let inner_parts = self.horner(with, depth + 1);
        let inner = self.signed_sum(inner_parts);
        let base = self.node(b);
        let mut parts = vec![(negative, self.emit(Op::Mul(base, inner)))];
        parts.extend(self.horner(without, depth + 1));
        parts
    }

    /// `Σ ±partᵢ` with positive parts added first and negative ones subtracted.
    fn signed_sum(&mut self, parts: Vec<(bool, Slot)>) -> Slot {
        let mut pos: Option<Slot> = None;
        let mut neg: Vec<Slot> = Vec::new();
        for (negative, mag) in parts {
            if negative {
                neg.push(mag);
            } else {
                pos = Some(match pos {
                    Some(acc) => self.emit(Op::Add(acc, mag)),
                    None => mag,
                });
            }
        }
        let (mut acc, rest) = match (pos, neg.split_first()) {
            (Some(p), _) => (p, &neg[..]),
            // Every part is negative: negate the first, subtract the rest.
            (None, Some((&first, rest))) => (self.emit(Op::Neg(first)), rest),
            (None, None) => (self.constant(Rational::ZERO), &neg[..]),
        };
        for &n in rest {
            acc = self.emit(Op::Sub(acc, n));
        }
        acc
    }
}
