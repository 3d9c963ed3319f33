//! Where an asymmetric heavy top is chaotic: a map of its largest Lyapunov exponent over a
//! grid of initial tilts θ0 and spins ω3, one run per cell, computed by the ensemble over
//! every core with the variational equations (Benettin's method).
//!
//! ```sh
//! cargo run --release --example chaos_map [plot directory]
//! cargo run --release --example chaos_map -- --grid 120x80 --duration 200   # a finer map
//! cargo run --release --example chaos_map -- --shard 3/16 out/    # shard 3 of 16 only
//! cargo run --release --example chaos_map -- --merge out/*.csv    # the shards together
//! ```
//!
//! The top (I = 1, 1.5, 0.6; centre of mass (0.3, 0.2, 1); M g = 1, as `chaotic_top`) is
//! released from rest in the tilt, its figure axis θ0 from the vertical, spinning at ω3
//! about that axis. Each run averages the growth of one tangent vector over a fixed time
//! after a short transient (`common/chaos.rs`). A finite-time exponent of a regular orbit is
//! not zero but falls as ln T / T (a tangent vector of a torus grows linearly); a chaotic one
//! settles at its positive value. The map shows chaos at low spin and moderate tilt, and
//! order where the spin makes the top a gyroscope.
//!
//! The table checks the same code on tops whose exponent is known: Lagrange's and
//! Kovalevskaya's tops are integrable (exponent 0, reached as ln T / T: the row at 4T is
//! about a third of the row at T), and the torque-free body turning about its intermediate axis
//! has λ = ω √((I2 − I1)(I3 − I2)/(I1 I3)) exactly.
//!
//! `--shard k/n` runs only the k-th of n consecutive index ranges and writes its rows to
//! `chaos_map.shard-k-of-n.csv`; `--merge` reads such files and draws the map.

#[path = "common/chaos.rs"]
mod chaos;
mod common;
#[path = "common/shards.rs"]
mod shards;

use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

use chaos::{ASYMMETRIC, KOVALEVSKAYA, LAGRANGE, Map, TORQUE_FREE};
use common::Table;
use precess::ensemble::{Ensemble, EnsembleProgress, rayon};
use precess::plot::{self, ColourBar, MapAxis};
use shards::{parse_shard, shard};

/// The default map: 48 tilts × 36 spins, each run averaged over 100 time units (above
/// ω3 ≈ 4 every orbit of this top is regular).
const MAP: Map = Map {
    nx: 48,
    ny: 36,
    theta: (0.0, std::f64::consts::PI),
    spin: (0.0, 5.0),
    duration: 100.0,
};

/// The CSV header of the rows.
const HEADER: &str = "index,theta0,omega3,lambda";

/// What the command line asked for.
struct Args {
    dir: PathBuf,
    map: Map,
    shard: Option<(usize, usize)>,
    merge: Vec<PathBuf>,
}

fn args() -> Result<Args, Box<dyn Error>> {
    let mut out = Args {
        dir: PathBuf::from("target/precess-plots"),
        map: MAP,
        shard: None,
        merge: Vec::new(),
    };
    let (mut merging, mut positional) = (false, Vec::new());
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--grid" => {
                let g = it.next().ok_or("--grid needs NXxNY")?;
                let bad = || format!("--grid {g}: expected NXxNY, two counts above zero");
                let (x, y) = g.split_once('x').ok_or_else(bad)?;
                let (nx, ny): (usize, usize) =
                    (x.parse().map_err(|_| bad())?, y.parse().map_err(|_| bad())?);
                if nx == 0 || ny == 0 {
                    return Err(bad().into());
                }
                (out.map.nx, out.map.ny) = (nx, ny);
            }
            "--duration" => {
                let d = it.next().ok_or("--duration needs a time")?;
                let bad = || format!("--duration {d}: expected a positive time");
                let t: f64 = d.parse().map_err(|_| bad())?;
                if !(t.is_finite() && t > 0.0) {
                    return Err(bad().into());
                }
                out.map.duration = t;
            }
            "--shard" => {
                let s = it.next().ok_or("--shard needs k/n")?;
                out.shard = Some(parse_shard(&s)?);
            }
            "--merge" => merging = true,
            "--out" => out.dir = it.next().ok_or("--out needs a directory")?.into(),
            _ => positional.push(PathBuf::from(arg)),
        }
    }
    if merging {
        if positional.is_empty() {
            return Err("--merge needs the shards' CSV files".into());
        }
        out.merge = positional;
    } else if let Some(dir) = positional.first() {
        out.dir = dir.clone();
    }
    std::fs::create_dir_all(&out.dir)?;
    Ok(out)
}

fn main() -> Result<(), Box<dyn Error>> {
    let args = args()?;
    let map = args.map;
    if !args.merge.is_empty() {
        let mut lambda = vec![f64::NAN; map.runs()];
        let mut rows = 0;
        for file in &args.merge {
            rows += read_rows(&std::fs::read_to_string(file)?, &mut lambda)?;
        }
        println!(
            "merged {rows} rows of {} from {} files",
            map.runs(),
            args.merge.len()
        );
        let regular = checks(map.duration)?;
        return draw(&map, &lambda, regular, &args.dir);
    }

    let system = ASYMMETRIC.system()?;
    let runs = match args.shard {
        Some((k, n)) => shard(k, n, map.runs()),
        None => 0..map.runs(),
    };
    let bar = indicatif::ProgressBar::new(runs.len() as u64);
    let report = |p: EnsembleProgress| bar.set_position(p.done as u64);
    let start = Instant::now();
    let results = Ensemble::new(runs.clone())
        .progress(&report)
        .run(|i| chaos::largest_exponent(&system, &map.state(i), map.duration));
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    println!(
        "{} runs ({} tilts × {} spins{}) of T = {} in {seconds:.2} s on {} thread(s): {:.0} runs/s",
        runs.len(),
        map.nx,
        map.ny,
        match args.shard {
            Some((k, n)) => format!(", shard {k} of {n}"),
            None => String::new(),
        },
        map.duration,
        rayon::current_num_threads(),
        runs.len() as f64 / seconds
    );
    for e in results.errors().take(5) {
        eprintln!("  {e}");
    }
    if results.failures() > 0 {
        eprintln!("  {} runs failed; the rest are kept", results.failures());
    }
    let mut lambda = vec![f64::NAN; map.runs()];
    let mut csv = String::from(HEADER);
    csv.push('\n');
    for (i, l) in results.outputs() {
        lambda[i] = *l;
        let (theta0, omega3) = map.cell(i);
        csv.push_str(&format!("{i},{theta0},{omega3},{l}\n"));
    }
    let name = match args.shard {
        Some((k, n)) => format!("chaos_map.shard-{k}-of-{n}.csv"),
        None => "chaos_map.csv".to_owned(),
    };
    let path = args.dir.join(name);
    std::fs::write(&path, csv)?;
    println!("  rows: {}", path.display());
    if args.shard.is_some() {
        println!("  merge the shards with: --merge <their CSV files> (and the same --grid)");
        return Ok(());
    }
    let regular = checks(map.duration)?;
    draw(&map, &lambda, regular, &args.dir)
}

/// Reads rows written by `main` into `lambda` (by index); returns how many it read.
fn read_rows(text: &str, lambda: &mut [f64]) -> Result<usize, Box<dyn Error>> {
    let mut read = 0;
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line == HEADER {
            continue;
        }
        let bad = || format!("line {}: expected `{HEADER}`, found `{line}`", n + 1);
        let fields: Vec<&str> = line.split(',').collect();
        let [index, _, _, l] = fields.as_slice() else {
            return Err(bad().into());
        };
        let index: usize = index.parse().map_err(|_| bad())?;
        let slot = lambda.get_mut(index).ok_or_else(|| {
            format!(
                "line {}: run {index} is outside the map (another --grid?)",
                n + 1
            )
        })?;
        *slot = l.parse().map_err(|_| bad())?;
        read += 1;
    }
    Ok(read)
}

/// The tops with known exponents, through the same code as the map, against theory;
/// returns the largest finite-time exponent of the integrable tops at the map's time, the
/// level a regular orbit of the map reaches too.
fn checks(duration: f64) -> Result<f64, Box<dyn Error>> {
    let mut regular: f64 = 0.0;
    let mut table = Table::default();
    let start = Instant::now();
    // Two starts: tilted 1 rad and turning about all three axes, a generic orbit of each
    // top; and the start of the map's cell θ0 = 0.5, ω3 = 1, where the map's top is chaotic
    // and a top that is not integrable would likely be too.
    let starts = [
        ("generic start", chaos::state(1.0, [0.7, -0.2, 2.5])),
        ("θ0 = 0.5, ω3 = 1", chaos::state(0.5, [0.0, 0.0, 1.0])),
    ];
    for (name, top) in [("Lagrange", LAGRANGE), ("Kovalevskaya", KOVALEVSKAYA)] {
        let system = top.system()?;
        for (label, x0) in &starts {
            let (short, long) = rayon::join(
                || chaos::largest_exponent(&system, x0, duration),
                || chaos::largest_exponent(&system, x0, 4.0 * duration),
            );
            let short = short?;
            regular = regular.max(short);
            table.row(
                format!("{name} top, {label}: λ₁, T = {duration}"),
                short,
                0.0,
            );
            let long_label = format!("{name} top, {label}: λ₁, T = {}", 4.0 * duration);
            table.row(long_label, long?, 0.0);
        }
    }
    // Body x (I = 1) is the intermediate axis of (1, 1.5, 0.6); the rotation about it is an
    // equilibrium, so the exponent is exact for any averaging time once the vector aligns.
    let omega = 2.0;
    let [i1, i2, i3] = TORQUE_FREE.inertia;
    let exact = chaos::intermediate_axis_exponent(i3, i1, i2, omega);
    let spin = chaos::state(0.0, [omega, 0.0, 0.0]);
    let measured = chaos::largest_exponent(&TORQUE_FREE.system()?, &spin, 40.0)?;
    table.row(
        format!("torque-free, ω = {omega} about the intermediate axis, λ₁"),
        measured,
        exact,
    );
    table.print(&format!(
        "Checks with known exponents (the same equations and settings as the map; {:.2} s). \
         Integrable tops: theory 0, the error column is |λ₁|",
        start.elapsed().as_secs_f64()
    ));
    Ok(regular)
}

/// Prints the map's statistics and writes the heat map.
/// A run counts as chaotic above three times `regular`, the finite-time exponent of the
/// integrable tops over the same time.
fn draw(map: &Map, lambda: &[f64], regular: f64, dir: &Path) -> Result<(), Box<dyn Error>> {
    let finite: Vec<f64> = lambda.iter().copied().filter(|l| l.is_finite()).collect();
    if finite.is_empty() {
        return Err("no run gave an exponent".into());
    }
    let top = finite.iter().copied().fold(0.0, f64::max);
    // Regular orbits fall as ln T / T, the integrable tops show the level; well above it
    // is chaos.
    let level = 3.0 * regular;
    let chaotic = finite.iter().filter(|&&l| l > level).count();
    println!(
        "\n  λ₁ over the map: largest {top:.4}, {chaotic} of {} runs above {level:.4} \
         (3 × the integrable tops' λ₁ at the same T): {:.0} % chaotic",
        finite.len(),
        100.0 * chaotic as f64 / finite.len() as f64
    );
    let title = format!(
        "Largest Lyapunov exponent of an asymmetric heavy top ({} runs, T = {})",
        map.runs(),
        map.duration
    );
    let figure = plot::Map {
        title,
        x: MapAxis::linear("initial tilt θ0 of the figure axis", "rad", map.theta),
        y: MapAxis::linear("initial spin ω3 about the figure axis", "rad/s", map.spin),
        // From 0, so that the colour reads λ₁ itself (unless no run has a positive one).
        colour: match ColourBar::new("λ₁", "1/s") {
            bar if top > 0.0 => bar.range(0.0, top),
            bar => bar,
        },
    };
    // Row j of the runs is spin j, lowest first, as the map's rows run.
    let rows: Vec<&[f64]> = lambda.chunks(map.nx).collect();
    let path = plot::map(dir.join("chaos_map.svg"), &figure, &rows)?;
    println!("  figure: {}", path.display());
    Ok(())
}
