//! The Python emitter: a module over NumPy whose functions take many states at once.

use std::fmt::Write;

use super::Exported;
use super::syntax::Syntax;

/// NumPy's spelling: `_v3 = np.sin(_v2)`, `y[0]`, the parameter as a float64 array.
const PYTHON: Syntax = Syntax {
    local: "_v",
    math: "np.",
    literal,
    state: |k| format!("y[{k}]"),
    input: |k| format!("u[{k}]"),
    parameter: |p| format!("np.asarray({p}, dtype=np.float64)"),
};

/// A constant as a NumPy double: the shortest decimal that reads back to it.
fn literal(x: f64) -> String {
    if x.is_nan() {
        "np.float64(np.nan)".to_owned()
    } else if x.is_infinite() {
        if x > 0.0 {
            "np.float64(np.inf)"
        } else {
            "np.float64(-np.inf)"
        }
        .to_owned()
    } else {
        format!("np.float64({x:e})")
    }
}

impl Exported {
    /// The Python module (save it as `<name>.py`): for each function
    /// `f(t, y, *, p₀, …)`, with `y` of shape `(n,)` or `(n, k)` (k states, as SciPy's
    /// `solve_ivp(..., vectorized=True)` passes them) and the parameters as keyword arguments
    /// (numbers, or arrays broadcasting against a row of `y`); a scene with inputs takes them
    /// as `f(t, y, u, *, p₀, …)`, `u` of shape `(m,)` or `(m, k)`, broadcasting as `y`; returning an array of shape
    /// `(rows,)` or `(rows, cols)` followed by the states' shape. Every instruction is one
    /// NumPy operation on float64, in the program's order.
    ///
    /// ```
    /// use precess_core::codegen::ExportBuilder;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.input("x");
    /// let k = a.parameter("k");
    /// let f = a.mul(k, x);
    /// let mut b = ExportBuilder::new("decay", &a, &[x]).unwrap();
    /// b.function(&a, "rhs", "dx/dt", &[f], (1, 1)).unwrap();
    /// let py = b.finish().python();
    /// assert!(py.contains("def rhs(t, y, *, k):"));
    /// assert!(py.contains("STATE = (\"x\",)"));
    /// ```
    pub fn python(&self) -> String {
        let name = &self.name;
        let tuple = |v: &[String]| {
            let quoted: Vec<String> = v.iter().map(|x| format!("\"{x}\",")).collect();
            format!("({})", quoted.join(" "))
        };
        let mut s = String::new();
        let inputs = if self.inputs.is_empty() {
            ""
        } else {
            ", the inputs u (INPUTS, values the caller supplies;\nshape (m,) or (m, k))"
        };
        let _ = writeln!(
            s,
            "\"\"\"The equations of `{name}`, exported by precess.\n\nEach function takes the time t, the state y (shape (n,), or (n, k) for k states at\nonce){inputs} and the parameters as keyword arguments, and returns its outputs (shape (rows,)\nor (rows, cols), followed by the states' shape).\n\"\"\"\n\nimport numpy as np\n"
        );
        let _ = writeln!(s, "NAME = \"{name}\"");
        let _ = writeln!(s, "STATE = {}", tuple(&self.state));
        if !self.inputs.is_empty() {
            let _ = writeln!(s, "INPUTS = {}", tuple(&self.inputs));
        }
        let _ = writeln!(s, "PARAMETERS = {}", tuple(&self.parameters));
        for f in &self.functions {
            let kwargs: String = self.parameters.iter().map(|p| format!(", {p}")).collect();
            let star = if self.parameters.is_empty() {
                ""
            } else {
                ", *"
            };
            let u = if self.inputs.is_empty() { "" } else { ", u" };
            let _ = writeln!(s, "\n\ndef {}(t, y{u}{star}{kwargs}):", f.name);
            let _ = writeln!(s, "    \"\"\"{}: {} x {}.\"\"\"", f.doc, f.rows, f.cols);
            let _ = writeln!(s, "    y = np.asarray(y, dtype=np.float64)");
            let mut shapes = String::new();
            if !self.inputs.is_empty() {
                let _ = writeln!(s, "    u = np.asarray(u, dtype=np.float64)");
                shapes.push_str(", u.shape[1:]");
            }
            let _ = writeln!(s, "    t = np.asarray(t, dtype=np.float64)");
            for p in &self.parameters {
                let _ = write!(shapes, ", np.shape({p})");
            }
            let _ = writeln!(
                s,
                "    _shape = np.broadcast_shapes(y.shape[1:], t.shape{shapes})"
            );
            let _ = writeln!(s, "    with np.errstate(all=\"ignore\"):");
            for (i, op) in f.program.ops.iter().enumerate() {
                let rhs = PYTHON.expression(self, op);
                let _ = writeln!(s, "        _v{i} = {rhs}");
            }
            let _ = writeln!(s, "        _out = np.empty(({},) + _shape)", f.len());
            for (k, o) in f.program.outputs.iter().enumerate() {
                let _ = writeln!(s, "        _out[{k}] = _v{o}");
            }
            if f.cols == 1 {
                let _ = writeln!(s, "    return _out");
            } else {
                let _ = writeln!(
                    s,
                    "    return _out.reshape(({}, {}) + _shape)",
                    f.rows, f.cols
                );
            }
        }
        s
    }
}
