//! The arena: hash-consed expression nodes and the symbol table.

use std::sync::LazyLock;
use std::sync::atomic::{AtomicU32, Ordering};

use super::hash::IdMap;
pub use super::node::Node;
use super::rational::Rational;

/// The next arena tag; 0 is never handed out, so `ExprId::new(_, 0)` is foreign everywhere.
static NEXT_TAG: AtomicU32 = AtomicU32::new(1);

fn fresh_tag() -> u32 {
    match NEXT_TAG.fetch_add(1, Ordering::Relaxed) {
        // After 2³² arenas the counter wraps; skip the reserved 0.
        0 => NEXT_TAG.fetch_add(1, Ordering::Relaxed),
        t => t,
    }
}

/// What [`Arena::node`] answers for an id this arena does not own: an unbound symbol, which
/// evaluates to NaN and prints as `<foreign>`.
static FOREIGN_NODE: Node = Node::Sym(SymbolId(u32::MAX));

static FOREIGN_SYMBOL: LazyLock<Symbol> = LazyLock::new(|| Symbol {
    name: "<foreign>".to_owned(),
    latex: r"\langle\text{foreign}\rangle".to_owned(),
    kind: SymbolKind::Input,
});

/// Handle to an expression in an [`Arena`]. Equal expressions (after the canonical
/// constructors) have equal ids, so comparing ids compares expressions.
///
/// An id carries the tag of the arena that made it, so an id from another arena is never
/// taken for one of this arena's expressions (see [`Arena::owns`]). Within one arena, ids
/// order by their position, children before parents.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct ExprId(u64);

impl ExprId {
    pub(crate) fn new(index: u32, tag: u32) -> ExprId {
        // The index in the low half: the hasher's bucket bits vary from id to id.
        ExprId((u64::from(tag) << 32) | u64::from(index))
    }

    /// Position of the node in the arena; children always sit before their parents.
    pub fn index(self) -> usize {
        self.0 as u32 as usize
    }

    /// The tag of the arena that made the id.
    fn tag(self) -> u32 {
        (self.0 >> 32) as u32
    }
}

/// Handle to a symbol in an [`Arena`].
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct SymbolId(pub(crate) u32);

impl SymbolId {
    /// Position of the symbol in the arena's symbol table (the index an environment uses).
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What a symbol stands for, which decides how the time derivative treats it.
///
/// Only [`SymbolKind::Parameter`] and [`SymbolKind::Coordinate`] symbols are found by name;
/// time, rates and inputs are identities the engine hands out and looks up by id, so a user
/// parameter called `t`, `theta_dot` or `omega0` can never stand for them.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum SymbolKind {
    /// A constant of the problem (mass, length, g): d/dt is zero.
    Parameter,
    /// A value the engine feeds in at evaluation (a body rate, a torque, a rotation entry):
    /// constant for d/dt, never found by name, a fresh symbol each time one is made.
    Input,
    /// Time itself: d/dt is one.
    Time,
    /// A name for a time-independent expression ([`Arena::abbreviate`]): an atom to the
    /// canonical form, its definition to evaluation, lowering and differentiation.
    Abbreviation,
    /// A generalised coordinate q: d/dt is its rate q̇.
    Coordinate,
    /// The `order`-th time derivative of the coordinate `of`.
    Derivative {
        /// The coordinate differentiated.
        of: SymbolId,
        /// 1 for the rate q̇, 2 for the acceleration q̈, …
        order: u8,
    },
}

/// A named symbol.
#[derive(Clone, PartialEq, Debug)]
pub struct Symbol {
    /// The name as Rust code and plain text show it, e.g. `theta_dot`.
    pub name: String,
    /// The LaTeX form, e.g. `\dot{\theta}`.
    pub latex: String,
    /// What it stands for.
    pub kind: SymbolKind,
}

/// Arena of hash-consed expressions and of the symbols they use.
///
/// ```
/// use precess_core::sym::Arena;
/// let mut a = Arena::new();
/// let x = a.parameter("x");
/// let s = a.sin(x);
/// let c = a.cos(x);
/// let s2 = a.powi(s, 2).unwrap();
/// let c2 = a.powi(c, 2).unwrap();
/// let one = a.one();
/// let sum = a.add(s2, c2);
/// // sin²x + cos²x − 1 is the zero node itself.
/// assert_eq!(a.sub(sum, one), a.zero());
/// ```
#[derive(Debug)]
pub struct Arena {
    nodes: Vec<Node>,
    interned: IdMap<Node, ExprId>,
    symbols: Vec<Symbol>,
    symbol_nodes: Vec<ExprId>,
    /// Parameters and coordinates by (name, is-coordinate): the only symbols found by name.
    by_name: IdMap<(String, bool), SymbolId>,
    /// Every display name in use, so two symbols never print alike.
    shown: IdMap<String, SymbolId>,
    time: Option<SymbolId>,
    derivatives: IdMap<SymbolId, SymbolId>,
    /// The expression each abbreviation stands for, and the abbreviations by the values of
    /// their definitions at two points modulo a prime.
    pub(crate) definitions: IdMap<SymbolId, ExprId>,
    pub(crate) abbreviations: IdMap<[u64; 2], Vec<ExprId>>,
    /// The tag stamped on the ids this arena makes.
    tag: u32,
    /// Arenas this one was cloned from, with their length at the time: their ids below that
    /// length denote the same expressions here.
    inherited: Vec<(u32, u32)>,
    /// The ids of 0 and 1, made first.
    zero_one: [ExprId; 2],
    pub(crate) memo: super::memo::Memo,
}

impl Clone for Arena {
    /// A copy that owns every id of `self` made so far; ids either copy makes afterwards
    /// carry a new tag, so they are never mistaken for the other copy's.
    fn clone(&self) -> Arena {
        let mut inherited = self.inherited.clone();
        inherited.push((self.tag, self.nodes.len() as u32));
        Arena {
            nodes: self.nodes.clone(),
            interned: self.interned.clone(),
            symbols: self.symbols.clone(),
            symbol_nodes: self.symbol_nodes.clone(),
            by_name: self.by_name.clone(),
            shown: self.shown.clone(),
            time: self.time,
            derivatives: self.derivatives.clone(),
            definitions: self.definitions.clone(),
            abbreviations: self.abbreviations.clone(),
            tag: fresh_tag(),
            inherited,
            zero_one: self.zero_one,
            memo: self.memo.clone(),
        }
    }
}

impl Arena {
    /// A new arena holding only what `roots` need: the nodes they reach, every symbol (by
    /// the same [`SymbolId`]s, so environments and lowered programs carry over) and every
    /// abbreviation's definition. Returns it with the roots' ids in it, in order. A copy for
    /// a caller that goes on from a few expressions of a large arena: cheaper than
    /// [`Clone::clone`], which copies every node the derivation built on the way.
    ///
    /// The nodes are copied in their order here, so children still sort by id as the
    /// constructors sort them, and an expression built again in the new arena is the copied
    /// node itself.
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (x, y) = (a.parameter("x"), a.parameter("y"));
    /// let scratch = a.mul(x, y);
    /// let _ = a.cos(scratch);
    /// let sum = a.add(x, y);
    /// let s = a.sin(sum);
    /// let e = a.mul(s, x);
    /// let (mut b, roots) = a.extract(&[e])?;
    /// let f = roots[0];
    /// // x y and its cosine stay behind.
    /// assert_eq!(b.len(), a.len() - 2);
    /// assert_eq!(b.eval(f, &[0.3, 0.4]), a.eval(e, &[0.3, 0.4]));
    /// let (bx, by) = (b.parameter("x"), b.parameter("y"));
    /// let again = b.add(bx, by);
    /// let again = b.sin(again);
    /// assert_eq!(b.mul(again, bx), f);
    /// # Ok::<(), precess_core::sym::SymError>(())
    /// ```
    ///
    /// # Errors
    /// [`super::SymError::ForeignExpression`] for a root this arena does not own.
    pub fn extract(&self, roots: &[ExprId]) -> Result<(Arena, Vec<ExprId>), super::SymError> {
        self.check_owned(roots)?;
        let mut wanted = roots.to_vec();
        wanted.extend(self.zero_one);
        wanted.extend(&self.symbol_nodes);
        wanted.extend(self.definitions.values());
        // Children sit before their parents, so in this order every child is copied first.
        let order = self.walk(&wanted, true, |_| true);
        let mut copy = Arena {
            nodes: Vec::with_capacity(order.len()),
            symbols: self.symbols.clone(),
            by_name: self.by_name.clone(),
            shown: self.shown.clone(),
            time: self.time,
            derivatives: self.derivatives.clone(),
            ..Arena::unfilled()
        };
        copy.interned.reserve(order.len());
        let mut moved: Vec<u32> = vec![u32::MAX; self.nodes.len()];
        let at = |moved: &[u32], copy: &Arena, id: ExprId| ExprId::new(moved[id.index()], copy.tag);
        for id in order {
            let m = |c: &ExprId| at(&moved, &copy, *c);
            let node = match self.node(id) {
                Node::Const(r) => Node::Const(*r),
                Node::Sym(s) => Node::Sym(*s),
                Node::Add(c) => Node::Add(c.iter().map(m).collect()),
                Node::Mul(c) => Node::Mul(c.iter().map(m).collect()),
                Node::Pow(b, n) => Node::Pow(m(b), *n),
                Node::Powr(b, r) => Node::Powr(m(b), *r),
                Node::Sqrt(u) => Node::Sqrt(m(u)),
                Node::Sin(u) => Node::Sin(m(u)),
                Node::Cos(u) => Node::Cos(m(u)),
                Node::Func(f, u) => Node::Func(*f, m(u)),
            };
            moved[id.index()] = copy.intern(node).index() as u32;
        }
        copy.zero_one = self.zero_one.map(|e| at(&moved, &copy, e));
        copy.symbol_nodes = self
            .symbol_nodes
            .iter()
            .map(|&e| at(&moved, &copy, e))
            .collect();
        copy.definitions = self
            .definitions
            .iter()
            .map(|(&s, &e)| (s, at(&moved, &copy, e)))
            .collect();
        copy.abbreviations = self
            .abbreviations
            .iter()
            .map(|(&k, v)| (k, v.iter().map(|&e| at(&moved, &copy, e)).collect()))
            .collect();
        let roots = roots.iter().map(|&e| at(&moved, &copy, e)).collect();
        Ok((copy, roots))
    }
}

impl Default for Arena {
    fn default() -> Self {
        Self::new()
    }
}

impl Arena {
    /// An arena with nothing in it, not even the constants 0 and 1 (`zero_one` unset): what
    /// [`Arena::new`] and [`Arena::extract`] fill.
    fn unfilled() -> Arena {
        Arena {
            nodes: Vec::new(),
            interned: IdMap::default(),
            symbols: Vec::new(),
            symbol_nodes: Vec::new(),
            by_name: IdMap::default(),
            shown: IdMap::default(),
            time: None,
            derivatives: IdMap::default(),
            definitions: IdMap::default(),
            abbreviations: IdMap::default(),
            tag: fresh_tag(),
            inherited: Vec::new(),
            zero_one: [ExprId::new(0, 0); 2],
            memo: Default::default(),
        }
    }

    /// An empty arena holding only the constants 0 and 1.
    pub fn new() -> Arena {
        let mut arena = Arena::unfilled();
        arena.zero_one = [
            arena.intern(Node::Const(Rational::ZERO)),
            arena.intern(Node::Const(Rational::ONE)),
        ];
        arena
    }

    /// Interns a node as it is; the canonical constructors call this last.
    pub(crate) fn intern(&mut self, node: Node) -> ExprId {
        if let Some(&id) = self.interned.get(&node) {
            return id;
        }
        // 2³² nodes would need hundreds of gigabytes: the allocator fails long before.
        let id = ExprId::new(self.nodes.len() as u32, self.tag);
        self.nodes.push(node.clone());
        self.interned.insert(node, id);
        id
    }

    /// True if `id` was made by this arena (or by the arena it was cloned from, before the
    /// clone). Every method accepts foreign ids without panicking: [`Arena::node`] reads one
    /// as an unbound symbol shown `<foreign>` (NaN when evaluated), and the fallible methods
    /// return [`SymError::ForeignExpression`](super::SymError::ForeignExpression).
    ///
    /// ```
    /// use precess_core::sym::Arena;
    /// let (mut a, mut b) = (Arena::new(), Arena::new());
    /// let x = a.parameter("x");
    /// assert!(a.owns(x));
    /// assert!(!b.owns(x));
    /// assert!(b.eval(x, &[1.0]).is_nan());
    /// ```
    pub fn owns(&self, id: ExprId) -> bool {
        let i = id.index();
        if id.tag() == self.tag {
            return i < self.nodes.len();
        }
        self.inherited
            .iter()
            .any(|&(tag, len)| tag == id.tag() && i < len as usize)
    }

    /// `Err(SymError::ForeignExpression)` unless every id of `ids` is this arena's.
    pub(crate) fn check_owned(&self, ids: &[ExprId]) -> Result<(), super::SymError> {
        match ids.iter().find(|&&id| !self.owns(id)) {
            Some(&id) => Err(super::SymError::ForeignExpression { index: id.index() }),
            None => Ok(()),
        }
    }

    /// The node behind an id; for an id of another arena, an unbound symbol shown
    /// `<foreign>` (see [`Arena::owns`]).
    #[inline]
    pub fn node(&self, id: ExprId) -> &Node {
        if id.tag() == self.tag
            && let Some(n) = self.nodes.get(id.index())
        {
            return n;
        }
        if self.owns(id) {
            return &self.nodes[id.index()];
        }
        &FOREIGN_NODE
    }

    /// All nodes, children before parents.
    pub fn nodes_slice(&self) -> &[Node] {
        &self.nodes
    }

    /// Number of nodes (a measure of how much the engine built).
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Never true: the arena always holds 0 and 1.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The constant 0.
    pub fn zero(&self) -> ExprId {
        self.zero_one[0]
    }

    /// The constant 1.
    pub fn one(&self) -> ExprId {
        self.zero_one[1]
    }

    /// The rational constant `r`.
    pub fn constant(&mut self, r: Rational) -> ExprId {
        self.intern(Node::Const(r))
    }

    /// The integer constant `n`.
    pub fn integer(&mut self, n: i64) -> ExprId {
        self.constant(Rational::integer(n))
    }

    /// The constant value of `id`, if it is a constant.
    pub fn as_rational(&self, id: ExprId) -> Option<Rational> {
        match self.node(id) {
            Node::Const(r) => Some(*r),
            _ => None,
        }
    }

    /// The symbol behind `id`, if it is a bare symbol.
    pub fn as_symbol(&self, id: ExprId) -> Option<SymbolId> {
        match self.node(id) {
            Node::Sym(s) => Some(*s),
            _ => None,
        }
    }

    /// A new symbol of `kind`, shown as `name` or, where another symbol already shows that
    /// name, as `name'` (then `name''` …) with the same LaTeX: no two symbols print alike.
    pub(crate) fn new_symbol(&mut self, name: &str, latex: String, kind: SymbolKind) -> SymbolId {
        let sym = SymbolId(self.symbols.len() as u32);
        let mut shown = name.to_owned();
        while self.shown.contains_key(&shown) {
            shown.push('\'');
        }
        self.shown.insert(shown.clone(), sym);
        self.symbols.push(Symbol {
            name: shown,
            latex,
            kind,
        });
        let node = self.intern(Node::Sym(sym));
        self.symbol_nodes.push(node);
        sym
    }

    /// The parameter or coordinate `name` (created on first use). Kinds never merge: a
    /// struct field called `theta` and the coordinate θ are distinct symbols.
    fn named(&mut self, name: &str, coordinate: bool) -> ExprId {
        let key = (name.to_owned(), coordinate);
        if let Some(&s) = self.by_name.get(&key) {
            return self.symbol_expr(s);
        }
        let kind = if coordinate {
            SymbolKind::Coordinate
        } else {
            SymbolKind::Parameter
        };
        let s = self.new_symbol(name, latex_name(name), kind);
        self.by_name.insert(key, s);
        self.symbol_expr(s)
    }

    /// The parameter named `name` (created on first use; a second call returns the same).
    pub fn parameter(&mut self, name: &str) -> ExprId {
        self.named(name, false)
    }

    /// The generalised coordinate named `name`.
    pub fn coordinate(&mut self, name: &str) -> ExprId {
        self.named(name, true)
    }

    /// A fresh input symbol shown as `name`: a value the caller feeds in at evaluation (a
    /// body rate, a torque component). Each call makes a new symbol, never found by name,
    /// so it cannot meet a parameter of the same name.
    pub fn input(&mut self, name: &str) -> ExprId {
        let s = self.new_symbol(name, latex_name(name), SymbolKind::Input);
        self.symbol_expr(s)
    }

    /// The time symbol, shown as `t` (one per arena, created on first use). A parameter
    /// named `t` is a different symbol.
    pub fn time(&mut self) -> ExprId {
        let s = match self.time {
            Some(s) => s,
            None => {
                let s = self.new_symbol("t", "t".to_owned(), SymbolKind::Time);
                self.time = Some(s);
                s
            }
        };
        self.symbol_expr(s)
    }

    /// The time symbol if [`Arena::time`] has made it, without making it.
    pub fn time_symbol(&self) -> Option<SymbolId> {
        self.time
    }

    /// The symbol table entry of `s`.
    ///
    /// A symbol id past the table (from a larger arena) reads as the `<foreign>` input.
    pub fn symbol(&self, s: SymbolId) -> &Symbol {
        self.symbols.get(s.index()).unwrap_or(&FOREIGN_SYMBOL)
    }

    /// The expression that is the bare symbol `s` (a foreign id for a symbol past the
    /// table).
    pub fn symbol_expr(&self, s: SymbolId) -> ExprId {
        self.symbol_nodes
            .get(s.index())
            .copied()
            .unwrap_or(ExprId::new(u32::MAX, 0))
    }

    /// Number of symbols, the length an evaluation environment needs.
    pub fn symbol_count(&self) -> usize {
        self.symbols.len()
    }

    /// Every symbol, in the order made (the order of an evaluation environment).
    pub fn symbols(&self) -> impl ExactSizeIterator<Item = (SymbolId, &Symbol)> + '_ {
        self.symbols
            .iter()
            .enumerate()
            .map(|(i, s)| (SymbolId(i as u32), s))
    }

    /// The parameter named `name`, if one was made.
    pub fn find_parameter(&self, name: &str) -> Option<SymbolId> {
        self.by_name.get(&(name.to_owned(), false)).copied()
    }

    /// The coordinate named `name`, if one was made.
    pub fn find_coordinate(&self, name: &str) -> Option<SymbolId> {
        self.by_name.get(&(name.to_owned(), true)).copied()
    }

    /// The time derivative of a coordinate or of one of its derivatives (q → q̇ → q̈ …),
    /// created on first use; `None` for parameters and time, whose rate is not a symbol.
    pub fn rate_of(&mut self, s: SymbolId) -> Option<SymbolId> {
        if let Some(&d) = self.derivatives.get(&s) {
            return Some(d);
        }
        let (of, order) = match self.symbol(s).kind {
            SymbolKind::Coordinate => (s, 1u8),
            SymbolKind::Derivative { of, order } => (of, order.checked_add(1)?),
            SymbolKind::Parameter
            | SymbolKind::Input
            | SymbolKind::Time
            | SymbolKind::Abbreviation => return None,
        };
        let base = self.symbol(of);
        let suffix = match order {
            1 => "_dot".to_owned(),
            2 => "_ddot".to_owned(),
            n => format!("_d{n}"),
        };
        let name = format!("{}{suffix}", base.name);
        let latex = match order {
            1 => format!("\\dot{{{}}}", base.latex),
            2 => format!("\\ddot{{{}}}", base.latex),
            n => format!("{}^{{({n})}}", base.latex),
        };
        let d = self.new_symbol(&name, latex, SymbolKind::Derivative { of, order });
        self.derivatives.insert(s, d);
        Some(d)
    }

    /// The rate q̇ of the coordinate expression `q` (see [`Arena::rate_of`]).
    pub fn rate(&mut self, q: ExprId) -> Option<ExprId> {
        let s = self.as_symbol(q)?;
        let d = self.rate_of(s)?;
        Some(self.symbol_expr(d))
    }
}

/// LaTeX for a plain name: Greek letters get their command, `_x` a subscript.
pub(crate) fn latex_name(name: &str) -> String {
    const GREEK: &[&str] = &[
        "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
        "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
        "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
    ];
    let (head, sub) = match name.split_once('_') {
        Some((h, s)) if !h.is_empty() && !s.is_empty() => (h, Some(s)),
        _ => (name, None),
    };
    let head = if GREEK.contains(&head) {
        format!("\\{head}")
    } else {
        head.to_owned()
    };
    match sub {
        Some(s) => format!("{head}_{{{}}}", s.replace('_', ",")),
        None => head,
    }
}
