//! Running an exported scene's C (compiled by the system's `cc`) and Python (with NumPy) on
//! many states, and comparing the outputs with the Rust evaluation in units in the last
//! place. Each runner returns `None`, after printing why, when its tool is absent.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use precess::codegen::Exported;

/// One evaluation point: the time, the state, the inputs (empty for a scene without) and the
/// parameters (in the export's order).
#[derive(Clone, Debug)]
pub struct Case {
    pub t: f64,
    pub y: Vec<f64>,
    pub u: Vec<f64>,
    pub p: Vec<f64>,
}

impl Case {
    /// The value of the parameter `name`.
    pub fn param(&self, e: &Exported, name: &str) -> f64 {
        let k = e.parameters().iter().position(|p| p == name);
        self.p[k.unwrap_or_else(|| panic!("no parameter {name} in {:?}", e.parameters()))]
    }
}

/// Per case, per function (in the export's order), the outputs.
pub type Outputs = Vec<Vec<Vec<f64>>>;

/// The directory of one test's files, under the target's scratch space (not the system's
/// temporary directory, where a directory per run piled up): a run overwrites the last one's.
fn dir(test: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("export-{test}"));
    std::fs::create_dir_all(&d).expect("temporary directory");
    d
}

/// The inputs as text: the count, then per case t, y, u, p as the hexadecimal bits.
fn input_text(cases: &[Case]) -> String {
    let mut s = format!("{}\n", cases.len());
    for c in cases {
        let values = std::iter::once(c.t)
            .chain(c.y.iter().copied())
            .chain(c.u.iter().copied())
            .chain(c.p.iter().copied());
        for v in values {
            let _ = write!(s, "{:x} ", v.to_bits());
        }
        s.push('\n');
    }
    s
}

/// Reads `cases.len()` lines of hexadecimal bits, split per function.
fn parse_outputs(e: &Exported, text: &str, cases: usize) -> Outputs {
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), cases, "one line per case");
    lines
        .iter()
        .map(|l| {
            let mut v = l
                .split_whitespace()
                .map(|w| f64::from_bits(u64::from_str_radix(w, 16).expect("hex bits")));
            e.functions()
                .iter()
                .map(|f| (0..f.len()).map(|_| v.next().expect("an output")).collect())
                .collect()
        })
        .collect()
}

/// A C `main` reading the cases and printing every function's outputs.
fn c_driver(e: &Exported) -> String {
    let (name, n, m) = (e.name(), e.state().len(), e.inputs().len());
    let mut s = format!(
        "#include <stdio.h>\n#include <string.h>\n#include \"{name}.h\"\n\
         static double rd(void) {{ unsigned long long b = 0; if (scanf(\"%llx\", &b) != 1) return 0.0; double x; memcpy(&x, &b, 8); return x; }}\n\
         static void wr(double x) {{ unsigned long long b; memcpy(&b, &x, 8); printf(\"%llx \", b); }}\n\
         int main(void) {{\n int k = 0; if (scanf(\"%d\", &k) != 1) return 1;\n for (int i = 0; i < k; i++) {{\n  double t = rd(); double y[{}]; double u[{}]; {name}_params p;\n  for (int j = 0; j < {n}; j++) y[j] = rd();\n  for (int j = 0; j < {m}; j++) u[j] = rd();\n  (void)u;\n",
        n.max(1),
        m.max(1)
    );
    for q in e.parameters() {
        let _ = writeln!(s, "  p.{q} = rd();");
    }
    let u = if m == 0 { "" } else { " u," };
    for f in e.functions() {
        let _ = writeln!(
            s,
            "  {{ double out[{len}]; {name}_{f}(t, y,{u} &p, out); for (int j = 0; j < {len}; j++) wr(out[j]); }}",
            len = f.len().max(1),
            f = f.name()
        );
    }
    s.push_str("  printf(\"\\n\");\n }\n return 0;\n}\n");
    s
}

/// The C compiler's name, or `None` after printing why the C is not tested.
pub fn c_compiler() -> Option<&'static str> {
    match Command::new("cc").arg("--version").output() {
        Ok(o) if o.status.success() => Some("cc"),
        Ok(o) => {
            println!("skipped: `cc --version` failed ({})", o.status);
            None
        }
        Err(e) => {
            println!("skipped: no C compiler `cc` on this machine ({e})");
            None
        }
    }
}

/// Compiles the export's C (`-std=c99 -O2 -ffp-contract=off`, warnings as errors) with a
/// driver, runs it on `cases`, and returns its outputs; `None` without a compiler.
pub fn run_c(test: &str, e: &Exported, cases: &[Case]) -> Option<Outputs> {
    let cc = c_compiler()?;
    let d = dir(test);
    let name = e.name();
    std::fs::write(d.join(format!("{name}.h")), e.c_header()).expect("write the header");
    std::fs::write(d.join(format!("{name}.c")), e.c_source()).expect("write the source");
    std::fs::write(d.join("driver.c"), c_driver(e)).expect("write the driver");
    let exe = d.join("driver");
    let out = Command::new(cc)
        .args([
            "-std=c99",
            "-O2",
            "-ffp-contract=off",
            "-Wall",
            "-Werror",
            "-o",
        ])
        .arg(&exe)
        .arg(d.join(format!("{name}.c")))
        .arg(d.join("driver.c"))
        .arg("-lm")
        .output()
        .expect("run cc");
    assert!(
        out.status.success(),
        "cc failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(run(
        Command::new(&exe),
        &d,
        &input_text(cases),
        e,
        cases.len(),
    ))
}

/// Runs `cmd` with `input` on its standard input (from a file in `d`: a pipe written whole
/// before the output is read would deadlock once the output fills its pipe) and parses what
/// it prints.
fn run(mut cmd: Command, d: &std::path::Path, input: &str, e: &Exported, cases: usize) -> Outputs {
    let path = d.join("cases.txt");
    std::fs::write(&path, input).expect("write the cases");
    let out = cmd
        .stdin(Stdio::from(
            std::fs::File::open(&path).expect("open the cases"),
        ))
        .output()
        .expect("run the program");
    assert!(
        out.status.success(),
        "the program failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    parse_outputs(e, &String::from_utf8_lossy(&out.stdout), cases)
}

/// `python3` with NumPy, or `None` after printing why the Python is not tested.
pub fn python() -> Option<&'static str> {
    match Command::new("python3")
        .args(["-c", "import numpy"])
        .output()
    {
        Ok(o) if o.status.success() => Some("python3"),
        Ok(o) => {
            println!(
                "skipped: python3 has no numpy ({})",
                String::from_utf8_lossy(&o.stderr).trim()
            );
            None
        }
        Err(e) => {
            println!("skipped: no python3 on this machine ({e})");
            None
        }
    }
}

/// Runs the export's Python module on all `cases` at once (y of shape (n, k), each
/// parameter an array of k values: one vectorised call per function) and returns its
/// outputs; `None` without python3 and NumPy.
pub fn run_python(test: &str, e: &Exported, cases: &[Case]) -> Option<Outputs> {
    let py = python()?;
    let d = dir(test);
    let name = e.name();
    std::fs::write(d.join(format!("{name}.py")), e.python()).expect("write the module");
    let (n, m) = (e.state().len(), e.inputs().len());
    let kwargs: String = e
        .parameters()
        .iter()
        .enumerate()
        .map(|(j, q)| format!("{q}=a[:, {}], ", 1 + n + m + j))
        .collect();
    // The inputs, positional after y, of shape (m, k) as y is (n, k).
    let u = if m == 0 {
        String::new()
    } else {
        format!("a[:, {}:{}].T, ", 1 + n, 1 + n + m)
    };
    let script = format!(
        "import sys\nimport numpy as np\nsys.path.insert(0, sys.argv[1])\nimport {name} as m\n\
         lines = sys.stdin.read().split('\\n')\nk = int(lines[0])\n\
         a = np.array([[int(w, 16) for w in l.split()] for l in lines[1:k + 1]], dtype=np.uint64).view(np.float64)\n\
         a = a.reshape(k, -1)\nt = a[:, 0]\ny = a[:, 1:1 + {n}].T\n\
         outs = [np.asarray(getattr(m, f)(t, y, {u}{kwargs})).reshape(-1, k) for f in {fns:?}]\n\
         o = np.concatenate(outs, axis=0).T.copy()\n\
         for row in o.view(np.uint64):\n    print(' '.join(format(int(x), 'x') for x in row))\n",
        fns = e
            .functions()
            .iter()
            .map(|f| f.name().to_owned())
            .collect::<Vec<_>>(),
    );
    let mut cmd = Command::new(py);
    cmd.args(["-c", &script]).arg(&d);
    Some(run(cmd, &d, &input_text(cases), e, cases.len()))
}

/// The distance in units in the last place, 0 for two NaNs (the equations' own NaN, where a
/// state leaves their domain, is no difference between the languages).
pub fn ulps(a: f64, b: f64) -> u64 {
    if a.is_nan() && b.is_nan() {
        return 0;
    }
    let key = |x: f64| {
        let i = x.to_bits() as i64;
        if i < 0 { i64::MIN - i } else { i }
    };
    key(a).abs_diff(key(b))
}

/// The largest distance in ulps between `got` (per case, per function) and `want` (per case,
/// the outputs of the function `name`), and how many values were compared.
pub fn worst(e: &Exported, got: &Outputs, name: &str, want: &[Vec<f64>]) -> (u64, usize) {
    let k = e
        .functions()
        .iter()
        .position(|f| f.name() == name)
        .unwrap_or_else(|| panic!("no function {name}"));
    let mut worst = 0;
    let mut count = 0;
    for (case, w) in got.iter().zip(want) {
        assert_eq!(case[k].len(), w.len(), "{name}: output count");
        for (a, b) in case[k].iter().zip(w) {
            worst = worst.max(ulps(*a, *b));
            count += 1;
        }
    }
    (worst, count)
}
