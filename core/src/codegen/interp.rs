//! The f64 interpreter of a [`Program`]: the oracle the generated Rust is tested against.

use super::program::{Op, Program};

impl Program {
    /// Runs the program with symbol `s` set to `env[s.index()]` (NaN if missing) and
    /// returns the outputs.
    pub fn eval(&self, env: &[f64]) -> Vec<f64> {
        let mut scratch = Vec::new();
        let mut out = vec![0.0; self.outputs.len()];
        self.eval_into(env, &mut scratch, &mut out);
        out
    }

    /// As [`Program::eval`], reusing `scratch` and writing the outputs into `out`
    /// (extra outputs are left untouched, missing ones skipped).
    pub fn eval_into(&self, env: &[f64], scratch: &mut Vec<f64>, out: &mut [f64]) {
        scratch.clear();
        scratch.reserve(self.ops.len());
        for op in &self.ops {
            let v = |s: &u32| scratch[*s as usize];
            let x = match op {
                Op::Const(c) => *c,
                Op::Input(s) => env.get(s.index()).copied().unwrap_or(f64::NAN),
                Op::Add(a, b) => v(a) + v(b),
                Op::Sub(a, b) => v(a) - v(b),
                Op::Mul(a, b) => v(a) * v(b),
                Op::Div(a, b) => v(a) / v(b),
                Op::Neg(a) => -v(a),
                Op::Sqrt(a) => v(a).sqrt(),
                Op::Powf(a, r) => v(a).powf(*r),
                Op::Sin(a) => v(a).sin(),
                Op::Cos(a) => v(a).cos(),
                Op::Func(f, a) => f.value(v(a)),
            };
            scratch.push(x);
        }
        for (o, &s) in out.iter_mut().zip(&self.outputs) {
            *o = scratch[s as usize];
        }
    }
}
