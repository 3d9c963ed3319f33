//! The arena: hash-consed expression nodes and the symbol table.

use super::hash::IdMap;
use super::rational::Rational;

/// Handle to an expression in an [`Arena`]. Equal expressions (after the canonical
/// constructors) have equal ids, so comparing ids compares expressions.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct ExprId(pub(crate) u32);

impl ExprId {
    /// Position of the node in the arena; children always sit before their parents.
    pub fn index(self) -> usize {
        self.0 as usize
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

/// One node of the expression graph. Constructors in [`Arena`] keep these canonical:
/// sums and products are flat and sorted, constants are folded, like terms are collected.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// An exact rational constant.
    Const(Rational),
    /// A symbol.
    Sym(SymbolId),
    /// A sum of at least two terms.
    Add(Box<[ExprId]>),
    /// A product of at least two factors; a rational coefficient comes first.
    Mul(Box<[ExprId]>),
    /// An integer power other than 0 and 1 of a non-constant base.
    Pow(ExprId, i64),
    /// The principal square root.
    Sqrt(ExprId),
    /// Sine.
    Sin(ExprId),
    /// Cosine.
    Cos(ExprId),
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
#[derive(Clone, Debug)]
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
    pub(crate) memo: super::memo::Memo,
}

impl Default for Arena {
    fn default() -> Self {
        Self::new()
    }
}

impl Arena {
    /// An empty arena holding only the constants 0 and 1.
    pub fn new() -> Arena {
        let mut arena = Arena {
            nodes: Vec::new(),
            interned: IdMap::default(),
            symbols: Vec::new(),
            symbol_nodes: Vec::new(),
            by_name: IdMap::default(),
            shown: IdMap::default(),
            time: None,
            derivatives: IdMap::default(),
            memo: Default::default(),
        };
        arena.intern(Node::Const(Rational::ZERO));
        arena.intern(Node::Const(Rational::ONE));
        arena
    }

    /// Interns a node as it is; the canonical constructors call this last.
    pub(crate) fn intern(&mut self, node: Node) -> ExprId {
        if let Some(&id) = self.interned.get(&node) {
            return id;
        }
        let id = ExprId(self.nodes.len() as u32);
        self.nodes.push(node.clone());
        self.interned.insert(node, id);
        id
    }

    /// The node behind an id.
    pub fn node(&self, id: ExprId) -> &Node {
        &self.nodes[id.index()]
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
        ExprId(0)
    }

    /// The constant 1.
    pub fn one(&self) -> ExprId {
        ExprId(1)
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
    fn new_symbol(&mut self, name: &str, latex: String, kind: SymbolKind) -> SymbolId {
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
            return self.symbol_nodes[s.index()];
        }
        let kind = if coordinate {
            SymbolKind::Coordinate
        } else {
            SymbolKind::Parameter
        };
        let s = self.new_symbol(name, latex_name(name), kind);
        self.by_name.insert(key, s);
        self.symbol_nodes[s.index()]
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
        self.symbol_nodes[s.index()]
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
        self.symbol_nodes[s.index()]
    }

    /// The time symbol if [`Arena::time`] has made it, without making it.
    pub fn time_symbol(&self) -> Option<SymbolId> {
        self.time
    }

    /// The symbol table entry of `s`.
    pub fn symbol(&self, s: SymbolId) -> &Symbol {
        &self.symbols[s.index()]
    }

    /// The expression that is the bare symbol `s`.
    pub fn symbol_expr(&self, s: SymbolId) -> ExprId {
        self.symbol_nodes[s.index()]
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
            SymbolKind::Parameter | SymbolKind::Input | SymbolKind::Time => return None,
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
fn latex_name(name: &str) -> String {
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
