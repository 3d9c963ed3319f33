//! The C99 emitter: a header (the parameters' struct, the sizes, one prototype per function)
//! and a source (one function each, one `const double` per instruction, no allocation).

use std::fmt::Write;

use super::syntax::Syntax;
use super::{Exported, ExportedFunction};

/// C's spelling: `const double v3 = sin(v2);`, `y[0]`, `p->m`.
const C: Syntax = Syntax {
    local: "v",
    math: "",
    literal,
    state: |k| format!("y[{k}]"),
    input: |k| format!("u[{k}]"),
    parameter: |p| format!("p->{p}"),
};

/// A constant as a C99 expression: the shortest decimal that reads back to the same double
/// (C's strtod, as compilers parse literals, rounds correctly), parenthesised when negative.
fn literal(x: f64) -> String {
    if x.is_nan() {
        "NAN".to_owned()
    } else if x.is_infinite() {
        if x > 0.0 { "INFINITY" } else { "(-INFINITY)" }.to_owned()
    } else if x.is_sign_negative() {
        format!("(-{:e})", -x)
    } else {
        format!("{x:e}")
    }
}

impl Exported {
    /// The C99 header, to be saved as `<name>.h` (the source includes it by that name).
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
    /// let h = b.finish().c_header();
    /// assert!(h.contains("typedef struct decay_params {\n    double k;\n} decay_params;"));
    /// assert!(h.contains("void decay_rhs(double t, const double *y, const decay_params *p, double *out);"));
    /// ```
    pub fn c_header(&self) -> String {
        let name = &self.name;
        let upper = name.to_uppercase();
        let mut s = String::new();
        let inputs = if self.inputs.is_empty() {
            String::new()
        } else {
            format!(",\n * the inputs u ({upper}_INPUT_LEN values, which the caller supplies)")
        };
        let _ = writeln!(
            s,
            "/* {name}.h: the equations of `{name}`, exported by precess.\n *\n * Every function reads the time t, the state y ({upper}_STATE_LEN values){inputs} and the\n * parameters p, and writes its outputs to out (a matrix row by row). None allocates.\n * For the bits precess computes, compile without contracting a*b + c into a fused\n * multiply-add (gcc, clang: -ffp-contract=off) and link the C library's libm. */"
        );
        let _ = writeln!(s, "#ifndef PRECESS_{upper}_H\n#define PRECESS_{upper}_H\n");
        let _ = writeln!(s, "#ifdef __cplusplus\nextern \"C\" {{\n#endif\n");
        let _ = writeln!(s, "/* The state y, by index. */");
        let _ = writeln!(s, "#define {upper}_STATE_LEN {}", self.state.len());
        for (k, y) in self.state.iter().enumerate() {
            let _ = writeln!(s, "#define {upper}_Y_{} {k}", y.to_uppercase());
        }
        if !self.inputs.is_empty() {
            let _ = writeln!(
                s,
                "\n/* The inputs u the caller supplies (in Rust, user functions' values), by index. */"
            );
            let _ = writeln!(s, "#define {upper}_INPUT_LEN {}", self.inputs.len());
            for (k, u) in self.inputs.iter().enumerate() {
                let _ = writeln!(s, "#define {upper}_U_{} {k}", u.to_uppercase());
            }
        }
        let _ = writeln!(
            s,
            "\n/* The parameters. */\ntypedef struct {name}_params {{"
        );
        for p in &self.parameters {
            let _ = writeln!(s, "    double {p};");
        }
        if self.parameters.is_empty() {
            // C99 has no empty struct.
            let _ = writeln!(s, "    char none;");
        }
        let _ = writeln!(s, "}} {name}_params;");
        for f in &self.functions {
            let fu = f.name.to_uppercase();
            let _ = writeln!(s, "\n/* {}: {} x {} */", f.doc, f.rows, f.cols);
            let _ = writeln!(s, "#define {upper}_{fu}_ROWS {}", f.rows);
            let _ = writeln!(s, "#define {upper}_{fu}_COLS {}", f.cols);
            let _ = writeln!(s, "{};", self.prototype(f));
        }
        let _ = writeln!(s, "\n#ifdef __cplusplus\n}}\n#endif\n\n#endif");
        s
    }

    /// The C99 source (`#include "<name>.h"`), one function per exported function.
    ///
    /// ```
    /// use precess_core::codegen::ExportBuilder;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let x = a.input("x");
    /// let s = a.sin(x);
    /// let mut b = ExportBuilder::new("wave", &a, &[x]).unwrap();
    /// b.function(&a, "rhs", "dx/dt", &[s], (1, 1)).unwrap();
    /// let c = b.finish().c_source();
    /// assert!(c.contains("const double v0 = y[0];"));
    /// assert!(c.contains("const double v1 = sin(v0);"));
    /// assert!(c.contains("out[0] = v1;"));
    /// ```
    pub fn c_source(&self) -> String {
        let name = &self.name;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "/* {name}.c: the equations of `{name}`, exported by precess (see {name}.h). */\n#include <math.h>\n#include \"{name}.h\""
        );
        for f in &self.functions {
            let _ = writeln!(s, "\n/* {} */\n{}\n{{", f.doc, self.prototype(f));
            let _ = writeln!(s, "    (void)t;\n    (void)y;\n    (void)p;");
            if !self.inputs.is_empty() {
                let _ = writeln!(s, "    (void)u;");
            }
            for (i, op) in f.program.ops.iter().enumerate() {
                let rhs = C.expression(self, op);
                let _ = writeln!(s, "    const double v{i} = {rhs};");
            }
            for (k, o) in f.program.outputs.iter().enumerate() {
                let _ = writeln!(s, "    out[{k}] = v{o};");
            }
            let _ = writeln!(s, "}}");
        }
        s
    }
}

impl Exported {
    /// `void name_f(double t, const double *y, const name_params *p, double *out)`, with
    /// `const double *u` after `y` when the scene has inputs.
    fn prototype(&self, f: &ExportedFunction) -> String {
        let name = &self.name;
        let u = if self.inputs.is_empty() {
            ""
        } else {
            " const double *u,"
        };
        format!(
            "void {name}_{}(double t, const double *y,{u} const {name}_params *p, double *out)",
            f.name
        )
    }
}
