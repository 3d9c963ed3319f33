//! Building an [`Exported`] scene from an arena: each function lowered by
//! [`Program::lower`] exactly as the Rust code is, its inputs renumbered into the
//! environment `[t, y, u, p]`.

use std::ops::Range;

use super::names::identifier;
use super::{ExportError, Exported, ExportedFunction};
use crate::codegen::program::{Op, Program, Slot};
use crate::sym::{Arena, ExprId, SymbolId, SymbolKind};

/// Builds an [`Exported`] scene over one arena: the state (and the inputs, if any) first,
/// then one function at a time; a symbol of kind [`SymbolKind::Parameter`] a function reads
/// becomes a parameter (named as the symbol), the arena's time symbol the time `t`.
///
/// ```
/// use precess_core::codegen::ExportBuilder;
/// use precess_core::sym::Arena;
/// // A pendulum θ̈ = −(g/l) sin θ over the state (θ, θ̇).
/// let mut a = Arena::new();
/// let (theta, omega) = (a.input("theta"), a.input("omega"));
/// let (g, l) = (a.parameter("g"), a.parameter("l"));
/// let s = a.sin(theta);
/// let gl = a.div(g, l).unwrap();
/// let k = a.mul(gl, s);
/// let acc = a.neg(k);
/// let mut b = ExportBuilder::new("pendulum", &a, &[theta, omega]).unwrap();
/// b.function(&a, "rhs", "the state derivative", &[omega, acc], (2, 1)).unwrap();
/// let e = b.finish();
/// assert_eq!(e.parameters(), ["g", "l"]);
/// let f = e.eval("rhs", 0.0, &[0.5, 2.0], &[9.81, 1.0]).unwrap();
/// assert_eq!(f, vec![2.0, -9.81 * 0.5f64.sin() / 1.0]);
/// ```
#[derive(Clone, Debug)]
pub struct ExportBuilder {
    exported: Exported,
    state: Vec<SymbolId>,
    inputs: Vec<SymbolId>,
    parameters: Vec<SymbolId>,
    time: Option<SymbolId>,
}

/// The symbols of `entries`, each a bare symbol (`first` is the index of the first in the
/// state, for the error), and their names as identifiers.
fn symbols(
    arena: &Arena,
    entries: &[ExprId],
    first: usize,
) -> Result<(Vec<SymbolId>, Vec<String>), ExportError> {
    let symbols = entries
        .iter()
        .enumerate()
        .map(|(index, &e)| {
            arena.as_symbol(e).ok_or(ExportError::StateNotSymbol {
                index: first + index,
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let names = symbols
        .iter()
        .map(|&s| identifier(&arena.symbol(s).name))
        .collect();
    Ok((symbols, names))
}

impl ExportBuilder {
    /// A scene called `name` (written as a C and Python identifier) over the state `state`,
    /// each entry a bare symbol of `arena`, without inputs.
    ///
    /// # Errors
    /// [`ExportError::StateNotSymbol`] for an entry that is not a symbol,
    /// [`ExportError::DuplicateName`] for two entries written alike.
    pub fn new(name: &str, arena: &Arena, state: &[ExprId]) -> Result<Self, ExportError> {
        Self::with_inputs(name, arena, state, &[])
    }

    /// A scene over the state `state` whose functions also read the inputs `inputs` (bare
    /// symbols of `arena`, named as they are): values the Rust code takes from a user
    /// function, which the caller of the C or the Python passes as the array `u`.
    ///
    /// ```
    /// use precess_core::codegen::ExportBuilder;
    /// use precess_core::sym::Arena;
    /// // A cart pushed by a force F the caller supplies: ẍ = F/m.
    /// let mut a = Arena::new();
    /// let (x, v, force) = (a.input("x"), a.input("v"), a.input("force"));
    /// let m = a.parameter("m");
    /// let acc = a.div(force, m).unwrap();
    /// let mut b = ExportBuilder::with_inputs("cart", &a, &[x, v], &[force]).unwrap();
    /// b.function(&a, "rhs", "the state derivative", &[v, acc], (2, 1)).unwrap();
    /// let e = b.finish();
    /// assert_eq!(e.inputs(), ["force"]);
    /// assert_eq!(e.eval_with_inputs("rhs", 0.0, &[0.0, 1.0], &[3.0], &[2.0]).unwrap(), vec![1.0, 1.5]);
    /// assert!(e.c_header().contains("void cart_rhs(double t, const double *y, const double *u, const cart_params *p, double *out);"));
    /// assert!(e.python().contains("def rhs(t, y, u, *, m):"));
    /// ```
    ///
    /// # Errors
    /// [`ExportError::StateNotSymbol`] for an entry of either that is not a symbol (its
    /// index counted through the state, then the inputs), [`ExportError::DuplicateName`] for
    /// two entries written alike.
    pub fn with_inputs(
        name: &str,
        arena: &Arena,
        state: &[ExprId],
        inputs: &[ExprId],
    ) -> Result<Self, ExportError> {
        let (state_symbols, state_names) = symbols(arena, state, 0)?;
        let (input_symbols, input_names) = symbols(arena, inputs, state.len())?;
        let builder = ExportBuilder {
            exported: Exported {
                name: identifier(name),
                state: state_names,
                inputs: input_names,
                parameters: Vec::new(),
                functions: Vec::new(),
            },
            state: state_symbols,
            inputs: input_symbols,
            parameters: Vec::new(),
            time: arena.time_symbol(),
        };
        builder.exported.check_names()?;
        Ok(builder)
    }

    /// Names the state's entries `names` (written as C and Python identifiers) rather than
    /// as their symbols are named.
    ///
    /// # Errors
    /// [`ExportError::InputLength`] for a count other than the state's,
    /// [`ExportError::DuplicateName`] for two names written alike.
    pub fn name_state(&mut self, names: &[&str]) -> Result<&mut Self, ExportError> {
        if names.len() != self.state.len() {
            return Err(ExportError::InputLength {
                what: "state names",
                found: names.len(),
                expected: self.state.len(),
            });
        }
        self.exported.state = names.iter().map(|n| identifier(n)).collect();
        self.exported.check_names()?;
        Ok(self)
    }

    /// Names the inputs `names` (written as C and Python identifiers) rather than as their
    /// symbols are named.
    ///
    /// # Errors
    /// [`ExportError::InputLength`] for a count other than the inputs',
    /// [`ExportError::DuplicateName`] for two names written alike.
    pub fn name_inputs(&mut self, names: &[&str]) -> Result<&mut Self, ExportError> {
        if names.len() != self.inputs.len() {
            return Err(ExportError::InputLength {
                what: "input names",
                found: names.len(),
                expected: self.inputs.len(),
            });
        }
        self.exported.inputs = names.iter().map(|n| identifier(n)).collect();
        self.exported.check_names()?;
        Ok(self)
    }

    /// Adds the function `name` computing `outputs`, of shape `(rows, cols)` (row by row).
    ///
    /// # Errors
    /// [`ExportError::Shape`] if `rows · cols ≠ outputs.len()`, [`ExportError::Unbound`] if
    /// an output reads a symbol that is neither the time, the state, an input nor a parameter,
    /// [`ExportError::DuplicateName`] for a name already used.
    pub fn function(
        &mut self,
        arena: &Arena,
        name: &str,
        doc: &str,
        outputs: &[ExprId],
        shape: (usize, usize),
    ) -> Result<&mut Self, ExportError> {
        self.function_of(arena, name, doc, outputs, 0..outputs.len(), shape)
    }

    /// As [`ExportBuilder::function`], the function's outputs being `lowered[kept]`: the
    /// others are lowered with them but not returned, so the program is the one a Rust
    /// method lowering all of `lowered` runs (which program an output is lowered in can
    /// change its rounding: a reciprocal shared by two products is computed once).
    ///
    /// # Errors
    /// As [`ExportBuilder::function`]; [`ExportError::Shape`] too for a range past `lowered`.
    pub fn function_of(
        &mut self,
        arena: &Arena,
        name: &str,
        doc: &str,
        lowered: &[ExprId],
        kept: Range<usize>,
        (rows, cols): (usize, usize),
    ) -> Result<&mut Self, ExportError> {
        let name = identifier(name);
        let shape_error = || ExportError::Shape {
            function: name.clone(),
            outputs: kept.len(),
            rows,
            cols,
        };
        if kept.end > lowered.len() || rows.checked_mul(cols) != Some(kept.len()) {
            return Err(shape_error());
        }
        let mut program = Program::lower(arena, lowered);
        program.outputs = program.outputs[kept].to_vec();
        let program = self.renumber(arena, &name, prune(&program))?;
        self.exported.functions.push(ExportedFunction {
            name,
            doc: doc.to_owned(),
            rows,
            cols,
            program,
        });
        self.exported.check_names()?;
        Ok(self)
    }

    /// Adds the function `name`, the Jacobian `∂fᵢ/∂yⱼ` of `of` with respect to the state
    /// (`of.len()` rows, one column per state entry; the inputs held), differentiated in
    /// `arena`.
    ///
    /// # Errors
    /// As [`ExportBuilder::function`].
    pub fn jacobian(
        &mut self,
        arena: &mut Arena,
        name: &str,
        doc: &str,
        of: &[ExprId],
    ) -> Result<&mut Self, ExportError> {
        let n = self.state.len();
        let mut entries = Vec::with_capacity(of.len() * n);
        for &f in of {
            for &s in &self.state {
                entries.push(arena.diff(f, s));
            }
        }
        self.function(arena, name, doc, &entries, (of.len(), n))
    }

    /// The scene built.
    pub fn finish(self) -> Exported {
        self.exported
    }

    /// `program` with each input read from its place in `[t, y, u, p]`.
    fn renumber(
        &mut self,
        arena: &Arena,
        function: &str,
        program: Program,
    ) -> Result<Program, ExportError> {
        let n = self.state.len() + self.inputs.len();
        let mut ops = program.ops;
        for op in &mut ops {
            let Op::Input(s) = *op else { continue };
            let place = if Some(s) == self.time {
                0
            } else if let Some(k) = self.state.iter().chain(&self.inputs).position(|&x| x == s) {
                1 + k
            } else if arena.symbol(s).kind == SymbolKind::Parameter {
                let k = match self.parameters.iter().position(|&x| x == s) {
                    Some(k) => k,
                    None => {
                        self.parameters.push(s);
                        let name = identifier(&arena.symbol(s).name);
                        self.exported.parameters.push(name);
                        self.exported.check_names()?;
                        self.parameters.len() - 1
                    }
                };
                1 + n + k
            } else {
                return Err(ExportError::Unbound {
                    function: function.to_owned(),
                    symbol: arena.symbol(s).name.clone(),
                });
            };
            *op = Op::Input(SymbolId(place as u32));
        }
        Ok(Program {
            ops,
            outputs: program.outputs,
        })
    }
}

/// The program without the instructions no output needs, the rest renumbered in order
/// (the values of those kept are unchanged: each is the same operation on the same values).
fn prune(program: &Program) -> Program {
    let mut live = vec![false; program.ops.len()];
    for &o in &program.outputs {
        live[o as usize] = true;
    }
    for i in (0..program.ops.len()).rev() {
        if !live[i] {
            continue;
        }
        for a in operands(&program.ops[i]) {
            live[a as usize] = true;
        }
    }
    let mut new_slot = vec![0 as Slot; program.ops.len()];
    let mut ops = Vec::new();
    for (i, op) in program.ops.iter().enumerate() {
        if !live[i] {
            continue;
        }
        new_slot[i] = ops.len() as Slot;
        let m = |s: Slot| new_slot[s as usize];
        ops.push(match *op {
            Op::Add(a, b) => Op::Add(m(a), m(b)),
            Op::Sub(a, b) => Op::Sub(m(a), m(b)),
            Op::Mul(a, b) => Op::Mul(m(a), m(b)),
            Op::Div(a, b) => Op::Div(m(a), m(b)),
            Op::Neg(a) => Op::Neg(m(a)),
            Op::Sqrt(a) => Op::Sqrt(m(a)),
            Op::Powf(a, r) => Op::Powf(m(a), r),
            Op::Sin(a) => Op::Sin(m(a)),
            Op::Cos(a) => Op::Cos(m(a)),
            Op::Func(f, a) => Op::Func(f, m(a)),
            other @ (Op::Const(_) | Op::Input(_)) => other,
        });
    }
    let outputs = program
        .outputs
        .iter()
        .map(|&o| new_slot[o as usize])
        .collect();
    Program { ops, outputs }
}

/// The slots an instruction reads.
pub(super) fn operands(op: &Op) -> impl Iterator<Item = Slot> {
    let (a, b) = match *op {
        Op::Const(_) | Op::Input(_) => (None, None),
        Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => (Some(a), Some(b)),
        Op::Neg(a) | Op::Sqrt(a) | Op::Powf(a, _) | Op::Sin(a) | Op::Cos(a) | Op::Func(_, a) => {
            (Some(a), None)
        }
    };
    a.into_iter().chain(b)
}
