//! Lowering an expression graph to a straight-line program with shared subexpressions.
//!
//! Hash-consing already shares equal subtrees; lowering adds value numbering at the level of
//! binary instructions, so `a·b` appearing inside two different products is computed once.
//! Negative coefficients become subtractions, negative powers divisions, and integer powers
//! square-and-multiply chains: the instruction list is what the emitted Rust executes.

use crate::sym::{Arena, ExprId, IdMap, Node, Rational, SymbolId};

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
    /// `sin a`.
    Sin(Slot),
    /// `cos a`.
    Cos(Slot),
}

/// Hashable identity of an instruction (constants by their bits) for value numbering.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Const(u64),
    Input(SymbolId),
    Bin(u8, Slot, Slot),
    Un(u8, Slot),
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
            Op::Sin(a) => Key::Un(2, a),
            Op::Cos(a) => Key::Un(3, a),
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
    shared_reciprocals: IdMap<ExprId, ()>,
}

/// The negative powers that appear as a factor of two or more products reachable from
/// `outputs`.
fn shared_reciprocals(arena: &Arena, outputs: &[ExprId]) -> IdMap<ExprId, ()> {
    let mut uses: IdMap<ExprId, u32> = IdMap::default();
    let mut seen: IdMap<ExprId, ()> = IdMap::default();
    let mut stack: Vec<ExprId> = outputs.to_vec();
    while let Some(e) = stack.pop() {
        if seen.insert(e, ()).is_some() {
            continue;
        }
        match arena.node(e) {
            Node::Const(_) | Node::Sym(_) => {}
            Node::Add(c) => stack.extend(c.iter()),
            Node::Mul(c) => {
                for &f in c.iter() {
                    if matches!(arena.node(f), Node::Pow(_, n) if *n < 0) {
                        *uses.entry(f).or_default() += 1;
                    }
                    stack.push(f);
                }
            }
            Node::Pow(b, _) => stack.push(*b),
            Node::Sqrt(u) | Node::Sin(u) | Node::Cos(u) => stack.push(*u),
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
            Node::Sym(sym) => self.emit(Op::Input(*sym)),
            Node::Add(terms) => self.sum(terms),
            Node::Mul(factors) => {
                let (c, rest) = self.coefficient(factors);
                let mag = self.product(c.abs_value(), rest);
                if c.is_negative() {
                    self.emit(Op::Neg(mag))
                } else {
                    mag
                }
            }
            Node::Pow(b, n) => self.power_slot(*b, *n),
            Node::Sqrt(u) => {
                let u = self.node(*u);
                self.emit(Op::Sqrt(u))
            }
            Node::Sin(u) => {
                let u = self.node(*u);
                self.emit(Op::Sin(u))
            }
            Node::Cos(u) => {
                let u = self.node(*u);
                self.emit(Op::Cos(u))
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

    /// `b^n` for any non-zero integer n, as multiplications (and one division if n < 0).
    fn power_slot(&mut self, b: ExprId, n: i64) -> Slot {
        let base = self.node(b);
        let pos = self.positive_power(base, n.unsigned_abs());
        if n < 0 {
            let one = self.constant(Rational::ONE);
            self.emit(Op::Div(one, pos))
        } else {
            pos
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

    /// `c · Π factors` with `c ≥ 0`: numerator factors multiplied, negative powers gathered
    /// into one denominator, so a quotient costs a single division.
    fn product(&mut self, c: Rational, factors: &[ExprId]) -> Slot {
        let mut num: Option<Slot> = None;
        let mut den: Option<Slot> = None;
        for &f in factors {
            let (target, slot) = match self.arena.node(f) {
                Node::Pow(b, n) if *n < 0 && !self.shared_reciprocals.contains_key(&f) => {
                    let base = self.node(*b);
                    (&mut den, self.positive_power(base, n.unsigned_abs()))
                }
                _ => (&mut num, self.node(f)),
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

    /// A sum with negative terms as subtractions: `a − 3b` is one multiply and one subtract.
    fn sum(&mut self, terms: &[ExprId]) -> Slot {
        let mut pos: Option<Slot> = None;
        let mut neg: Vec<Slot> = Vec::new();
        for &t in terms {
            let (c, rest): (Rational, &[ExprId]) = match self.arena.node(t) {
                Node::Mul(f) => self.coefficient(f),
                Node::Const(r) if r.is_negative() => (*r, &[]),
                _ => (Rational::ONE, std::slice::from_ref(&t)),
            };
            let mag = if rest.len() == 1 && c.abs_value().is_one() {
                self.node(rest[0])
            } else {
                self.product(c.abs_value(), rest)
            };
            if c.is_negative() {
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
            // Every term is negative: negate the first, subtract the rest.
            (None, Some((&first, rest))) => (self.emit(Op::Neg(first)), rest),
            (None, None) => (self.constant(Rational::ZERO), &neg[..]),
        };
        for &n in rest {
            acc = self.emit(Op::Sub(acc, n));
        }
        acc
    }
}
