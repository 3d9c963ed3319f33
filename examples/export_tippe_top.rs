//! The tippe top exported to C and Python, and the Python integrated by SciPy.
//!
//! The top of `tippe_top` (`precess::models::TippeTop`: a sphere of radius R with its centre
//! of mass αR below the centre, gliding with viscous friction) implements `precess::codegen::Export`:
//! the derive wrote its equations as text while it expanded. This example writes them as
//! `top.h`, `top.c` and `top.py` (to `target/precess-export/`), checks that the Python module
//! gives the derived Rust method's bits at the start, and integrates it with SciPy's
//! `solve_ivp` (DOP853, tolerances 1e-12) through the turn-over, against precess's own run
//! of the same top and against theory: Jellett's quantity λ (docs/contact.md) is conserved
//! under sliding friction, and the inverted top keeps the energy λ₀ leaves it.
//!
//! Needs `python3` with NumPy and SciPy (`pip install --user numpy scipy`); without them it
//! writes the files and says why it stops there.

mod common;

use std::error::Error;
use std::path::Path;
use std::process::Command;

use common::{Axes, Series, Table, plot};
use precess::codegen::Export;
use precess::contact::{ContactDynamics, ContactRun, Phase};
use precess::models::TippeTop as Top;
use precess::models::tippe_top::MASS;
use precess::ode::{AdaptiveConfig, Run};

/// The end of both runs [s]: the axis has turned over and settled by then.
const END: f64 = 12.0;
/// The sampling interval [s].
const EVERY: f64 = 0.05;

/// Integrates the module with `solve_ivp` and prints, per sample, t, the state's θ (deg),
/// the energy and Jellett's λ; then the number of right-hand-side calls and the wall time.
const SCRIPT: &str = r#"
import sys, time, json
import numpy as np
from scipy.integrate import solve_ivp
sys.path.insert(0, sys.argv[1])
import top
y0 = np.array(json.loads(sys.argv[2]))
c = float(sys.argv[3]); end = float(sys.argv[4]); every = float(sys.argv[5])
ts = np.arange(0.0, end + every / 2, every)
start = time.perf_counter()
sol = solve_ivp(lambda t, y: top.rhs_sliding(t, y, viscous=c), (0.0, end), y0,
                method="DOP853", rtol=1e-12, atol=1e-12, t_eval=ts, vectorized=True)
wall = time.perf_counter() - start
if not sol.success:
    sys.exit(sol.message)
y = sol.y
w, x, yy, z = y[4], y[5], y[6], y[7]
gamma3 = (w * w + z * z - x * x - yy * yy) / (w * w + x * x + yy * yy + z * z)
theta = np.degrees(np.arccos(np.clip(gamma3, -1.0, 1.0)))
energy = top.energy_sliding(0.0, y, viscous=c)[0]
jellett = top.jellett(0.0, y, viscous=c)[0]
for row in zip(sol.t, theta, energy, jellett):
    print(" ".join(repr(float(v)) for v in row))
print("stats", sol.nfev, wall)
"#;

/// The first NumPy evaluation of the right-hand side at `y0`, as bits.
const FIRST: &str = r#"
import sys, json
import numpy as np
sys.path.insert(0, sys.argv[1])
import top
y0 = np.array(json.loads(sys.argv[2]))
print(" ".join(format(int(b), "x") for b in top.rhs_sliding(0.0, y0, viscous=float(sys.argv[3])).view(np.uint64)))
"#;

fn main() -> Result<(), Box<dyn Error>> {
    let theory = Top::theory();
    let viscous = 5.0 * MASS;
    let model = Top { viscous };
    let y0 = Top::start(0.1, 140.0);

    // The exported files.
    let dir = Path::new("target/precess-export");
    std::fs::create_dir_all(dir)?;
    std::fs::write(dir.join("top.h"), Top::c_header()?)?;
    std::fs::write(dir.join("top.c"), Top::c_source()?)?;
    std::fs::write(dir.join("top.py"), Top::python_module()?)?;
    let exported = Top::exported()?;
    let ops: usize = exported
        .functions()
        .iter()
        .map(|f| f.program().ops().len())
        .sum();
    println!(
        "Exported `Top` to {}/top.{{h,c,py}}: state {:?}, parameters {:?}, functions {:?} ({ops} instructions)",
        dir.display(),
        exported.state(),
        exported.parameters(),
        exported
            .functions()
            .iter()
            .map(|f| f.name())
            .collect::<Vec<_>>()
    );

    // precess's own run of the same top, sampled as SciPy's.
    let mut cfg = AdaptiveConfig::with_tol(1e-12, 1e-12);
    cfg.max_steps = 10_000_000;
    let mut run = ContactRun::new(&model, model.law().first_phase(), 0.0, y0, cfg)?;
    let out = Run::new(&mut run, END)
        .sample_every(EVERY)
        .quantity("θ (deg)", |_t, s| {
            Top::axis_up(s).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .integrate()?;
    let times = out.trajectory.times().to_vec();
    let theta = out.trajectory.column("θ (deg)").ok_or("no θ column")?;

    let y0_json = format!("{:?}", y0.to_vec());
    let python = |script: &str| {
        Command::new("python3")
            .args(["-c", script])
            .arg(dir)
            .arg(&y0_json)
            .arg(viscous.to_string())
            .args([END.to_string(), EVERY.to_string()])
            .output()
    };
    match python("import numpy, scipy") {
        Ok(o) if o.status.success() => {}
        Ok(o) => {
            println!(
                "SciPy part skipped: python3 lacks numpy or scipy ({})",
                String::from_utf8_lossy(&o.stderr).trim()
            );
            return Ok(());
        }
        Err(e) => {
            println!("SciPy part skipped: no python3 ({e})");
            return Ok(());
        }
    }

    // The module's first right-hand side against the derived method's, bit for bit.
    let first = python(FIRST)?;
    let mut want = [0.0; 11];
    model.phase_rhs(Phase::Sliding, 0.0, &y0, &mut want);
    let bits: Vec<u64> = String::from_utf8_lossy(&first.stdout)
        .split_whitespace()
        .map(|w| u64::from_str_radix(w, 16))
        .collect::<Result<_, _>>()?;
    let same = bits.len() == 11 && bits.iter().zip(&want).all(|(b, w)| *b == w.to_bits());
    println!("NumPy's dy/dt at the start has the derived Rust method's bits: {same}");

    let o = python(SCRIPT)?;
    if !o.status.success() {
        return Err(format!("solve_ivp failed: {}", String::from_utf8_lossy(&o.stderr)).into());
    }
    let text = String::from_utf8_lossy(&o.stdout);
    let mut scipy: Vec<[f64; 4]> = Vec::new();
    let mut stats = (0.0, 0.0);
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.first() == Some(&"stats") {
            stats = (words[1].parse()?, words[2].parse()?);
            continue;
        }
        let v: Vec<f64> = words.iter().map(|w| w.parse()).collect::<Result<_, _>>()?;
        scipy.push([v[0], v[1], v[2], v[3]]);
    }
    let (e0, l0) = (model.energy(Phase::Sliding, &y0), model.jellett(&y0));
    let n = scipy.len().min(times.len());
    let worst_theta = (0..n)
        .map(|k| (scipy[k][1] - theta[k]).abs())
        .fold(0.0, f64::max);
    let jellett_drift = scipy
        .iter()
        .map(|r| (r[3] - l0).abs() / l0)
        .fold(0.0, f64::max);
    let last = scipy.last().ok_or("no SciPy samples")?;
    println!(
        "solve_ivp (DOP853, 1e-12): {} samples to t = {END} s, {} right-hand sides in {:.2} s",
        scipy.len(),
        stats.0,
        stats.1
    );
    let mut table = Table::default();
    table.row("max |θ_SciPy − θ_precess| (deg)", worst_theta, 0.0);
    table.row("max |λ/λ₀ − 1| along SciPy's solution", jellett_drift, 0.0);
    table.row("final θ, SciPy (deg)", last[1], 180.0);
    table.row(
        "final energy, SciPy (J)",
        last[2],
        theory.inverted_energy(l0),
    );
    table.row(
        "energy lost, fraction",
        1.0 - last[2] / e0,
        1.0 - theory.inverted_energy(l0) / e0,
    );
    table.print("The exported Python under solve_ivp, against precess and Jellett's integral");

    let axes = Axes {
        title: "Tippe top: the exported Python under SciPy and precess's own run",
        x: "t (s)",
        y: "θ (deg)",
        log_x: false,
        log_y: false,
    };
    let ours: Vec<(f64, f64)> = times.iter().copied().zip(theta.iter().copied()).collect();
    let theirs: Vec<(f64, f64)> = scipy.iter().map(|r| (r[0], r[1])).collect();
    let f = plot(
        "export_tippe_top.svg",
        &axes,
        &[
            Series::line("precess", ours),
            Series::markers("solve_ivp on top.py", theirs),
        ],
    )?;
    println!("\nfigure: {}", f.display());
    Ok(())
}
