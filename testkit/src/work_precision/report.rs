//! Running the ladders, timing them, and writing the tables, the figures and the CSV of
//! references that `scripts/peers.py` reads.

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use precess::plot::{Series, Style, Work};

use super::methods::{Outcome, Setting, methods};
use super::problems::{
    B5_T, B5_Y0, B5_Y20, Problem, SEP_I, SEP_M0, SEP_T, TopCase, separatrix_reference,
};

/// One measured rung.
#[derive(Debug, Clone)]
pub struct Row {
    /// The problem.
    pub problem: Problem,
    /// The method's name.
    pub method: String,
    /// What the setting is.
    pub kind: Setting,
    /// The setting.
    pub setting: f64,
    /// A plain-sums variant (the "before" of the floor).
    pub before: bool,
    /// Error, evaluations, steps.
    pub outcome: Outcome,
    /// Median wall time of the repeats, seconds.
    pub seconds: f64,
}

/// One peer's point from `docs/perf/peers.csv`.
#[derive(Debug, Clone)]
pub struct PeerRow {
    problem: String,
    peer: String,
    method: String,
    setting: String,
    error: f64,
    seconds: f64,
    evals: String,
}

/// The median of `repeats` timed runs after one warm-up run (whose outcome is returned:
/// every run of a setting does the same arithmetic).
fn timed(
    run: &dyn Fn(f64) -> Result<Outcome, Box<dyn Error>>,
    setting: f64,
    repeats: usize,
) -> Result<(Outcome, f64), Box<dyn Error>> {
    let outcome = run(setting)?;
    let mut times = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        std::hint::black_box(run(setting)?);
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    Ok((outcome, times[times.len() / 2]))
}

/// Runs every method on every problem: the whole ladder, or the quick rung in `--quick`.
///
/// # Errors
/// The first run that fails (a method refusing its setting is a bug of the report).
pub fn measure_all(repeats: usize, verbose: bool) -> Result<Vec<Row>, Box<dyn Error>> {
    let quick = super::quick_mode();
    let mut rows = Vec::new();
    for problem in Problem::ALL {
        for method in methods()? {
            for pr in method.problems.iter().filter(|p| p.problem == problem) {
                let settings = if quick {
                    vec![pr.quick]
                } else {
                    pr.ladder.clone()
                };
                for s in settings {
                    let (outcome, seconds) = timed(&pr.run, s, repeats)?;
                    if verbose {
                        println!(
                            "{:<11} {:<26} {:>9} error {:>9.2e} evals {:>9} steps {:>8} {:>10.3e} s",
                            problem.key(),
                            method.name,
                            setting_text(method.setting, s),
                            outcome.error,
                            outcome.evals.map_or("—".into(), |e| e.to_string()),
                            outcome.steps,
                            seconds
                        );
                    }
                    rows.push(Row {
                        problem,
                        method: method.name.to_string(),
                        kind: method.setting,
                        setting: s,
                        before: method.before,
                        outcome,
                        seconds,
                    });
                }
            }
        }
    }
    Ok(rows)
}

fn setting_text(kind: Setting, s: f64) -> String {
    match kind {
        Setting::Tolerance => format!("tol {s:.0e}"),
        Setting::Step => format!("h {}", short(s)),
        Setting::None => "—".into(),
    }
}

/// A number in 3 significant digits.
fn short(v: f64) -> String {
    if (1e-3..1e3).contains(&v.abs()) {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.2e}")
    }
}

fn time_text(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn error_text(e: f64) -> String {
    if e.is_nan() {
        "(reference)".into()
    } else {
        format!("{e:.2e}")
    }
}

/// Reads `docs/perf/peers.csv` under `root` (absent: no peers).
fn read_peers(root: &Path) -> Vec<PeerRow> {
    let Ok(text) = std::fs::read_to_string(root.join("docs/perf/peers.csv")) else {
        return Vec::new();
    };
    text.lines()
        .skip(1)
        .filter_map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            let [problem, peer, method, setting, error, seconds, evals] = f.as_slice() else {
                return None;
            };
            Some(PeerRow {
                problem: problem.to_string(),
                peer: peer.to_string(),
                method: method.to_string(),
                setting: setting.to_string(),
                error: error.parse().ok()?,
                seconds: seconds.parse().ok()?,
                evals: evals.to_string(),
            })
        })
        .collect()
}

/// The references and parameters `scripts/peers.py` needs, as `problem,key,value`.
fn references_csv() -> Result<String, Box<dyn Error>> {
    let mut s = String::from("problem,key,value\n");
    let mut put = |p: &str, k: &str, v: f64| writeln!(s, "{p},{k},{v:e}");
    for (k, v) in SEP_I.iter().enumerate() {
        put("separatrix", &format!("I{}", k + 1), *v)?;
    }
    for (k, v) in SEP_M0.iter().enumerate() {
        put("separatrix", &format!("m0_{}", k + 1), *v)?;
    }
    put("separatrix", "T", SEP_T)?;
    for (k, v) in separatrix_reference().iter().enumerate() {
        put("separatrix", &format!("ref_{}", k + 1), *v)?;
    }
    for (k, v) in B5_Y0.iter().enumerate() {
        put("b5", &format!("y0_{}", k + 1), *v)?;
    }
    put("b5", "T", B5_T)?;
    for (k, v) in B5_Y20.iter().enumerate() {
        put("b5", &format!("ref_{}", k + 1), *v)?;
    }
    for (name, w3) in [("heavy_top", 150.0), ("fast_top", 1000.0)] {
        let c = TopCase::new(w3)?;
        for (k, v) in [
            ("I1", c.i1),
            ("I3", c.i3),
            ("mass", c.mass),
            ("lever", c.lever),
            ("g", 9.81),
            ("theta0", c.theta0),
            ("omega3", c.omega3),
            ("T", c.t_end),
            ("period", c.period),
            ("ref_cos_theta", c.u_end),
        ] {
            put(name, k, v)?;
        }
    }
    Ok(s)
}

const BEGIN: &str = "<!-- work-precision:begin -->";
const END: &str = "<!-- work-precision:end -->";

/// Writes the figures, the references CSV and the report's section of
/// `docs/performance.md` under `root`; returns the path of the document.
///
/// # Errors
/// I/O and plotting errors; a document whose markers are out of order.
pub fn write(root: &Path, rows: &[Row]) -> Result<PathBuf, Box<dyn Error>> {
    let docs = root.join("docs");
    std::fs::create_dir_all(docs.join("img/perf"))?;
    std::fs::create_dir_all(docs.join("perf"))?;
    std::fs::write(docs.join("perf/references.csv"), references_csv()?)?;
    let peers = read_peers(root);
    let mut md = String::new();
    section_intro(&mut md, rows, &peers)?;
    for problem in Problem::ALL {
        let mine: Vec<&Row> = rows.iter().filter(|r| r.problem == problem).collect();
        if mine.is_empty() {
            continue;
        }
        let theirs: Vec<&PeerRow> = peers
            .iter()
            .filter(|p| p.problem == problem.key())
            .collect();
        let svg = format!("img/perf/{}.svg", problem.key());
        figure(&docs.join(&svg), problem, &mine, &theirs)?;
        writeln!(md, "\n### {}\n", problem.title())?;
        writeln!(md, "Error: {}.\n", problem.error_meaning())?;
        writeln!(md, "![work-precision, {}]({svg})\n", problem.key())?;
        writeln!(
            md,
            "| method | setting | error | evaluations | steps | median time |"
        )?;
        writeln!(md, "|---|---|---|---|---|---|")?;
        for r in &mine {
            writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} |",
                r.method,
                setting_text(r.kind, r.setting),
                error_text(r.outcome.error),
                r.outcome.evals.map_or("—".into(), |e| e.to_string()),
                r.outcome.steps,
                time_text(r.seconds)
            )?;
        }
        if !theirs.is_empty() {
            writeln!(
                md,
                "\nPeers (`scripts/peers.py`; times include Python call overhead):\n"
            )?;
            writeln!(
                md,
                "| peer | method | setting | error | evaluations | median time |"
            )?;
            writeln!(md, "|---|---|---|---|---|---|")?;
            for p in &theirs {
                writeln!(
                    md,
                    "| {} | {} | {} | {:.2e} | {} | {} |",
                    p.peer,
                    p.method,
                    p.setting,
                    p.error,
                    p.evals,
                    time_text(p.seconds)
                )?;
            }
        }
    }
    floor_table(&mut md, rows)?;
    adding_a_method(&mut md)?;
    let path = docs.join("performance.md");
    let old = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        format!(
            "# Performance\n\nSpeed against error, measured. The section between the markers \
             is written by `cargo run --release --example work_precision`; other sections \
             are kept as they are.\n\n{BEGIN}\n{END}\n"
        )
    });
    let (Some(b), Some(e)) = (old.find(BEGIN), old.find(END)) else {
        return Err(format!("{} lacks the markers {BEGIN} … {END}", path.display()).into());
    };
    if e < b {
        return Err(format!(
            "{}: the end marker precedes the begin marker",
            path.display()
        )
        .into());
    }
    let new = format!("{}{BEGIN}\n{md}\n{}", &old[..b], &old[e..]);
    std::fs::write(&path, new)?;
    Ok(path)
}

fn section_intro(md: &mut String, rows: &[Row], peers: &[PeerRow]) -> Result<(), Box<dyn Error>> {
    let quick = super::quick_mode();
    writeln!(md, "## Work–precision\n")?;
    writeln!(
        md,
        "Written by `cargo run --release --example work_precision`{}. Each method runs its \
         ladder (tolerances rtol = atol for the adaptive pairs, steps h for the fixed-step \
         methods) on each problem it applies to; errors are against independent references \
         only (closed forms and a 30-digit value), never another integrator. Time is the \
         median of {} repeats after one warm-up (`std::time::Instant`, set-up included), on \
         a 2-core machine shared with other builds: errors, evaluations and steps are exact \
         and repeatable, times carry ±20 % noise. \"plain sums\" are the fixed-step methods \
         with compensated summation switched off (`FixedStepConfig::compensated`, \
         `FreeBodySplitting::with_compensation(false)`): the \"before\" of the numerical \
         floor. The reference of (a) at T = 200 is the exact motion with its phase λt + u₀, \
         the moduli and D₁, D₂, D₃ in double-double (`docs/exact.md`); the tops' reference is \
         the elliptic closed form of `HeavyTopMotion` (cos θ(t)).",
        if quick {
            " in `--quick` mode (one rung per problem, one repeat)"
        } else {
            ""
        },
        if quick { 1 } else { 5 }
    )?;
    let mut present: Vec<String> = peers.iter().map(|p| p.peer.clone()).collect();
    present.sort();
    present.dedup();
    let absent: Vec<&str> = ["scipy", "heyoka", "mujoco"]
        .into_iter()
        .filter(|p| !present.iter().any(|q| q == p))
        .collect();
    writeln!(
        md,
        "\nPeers (`python3 scripts/peers.py`, read from `docs/perf/peers.csv`): present {}; \
         absent {}. Their times include Python call overhead.",
        if present.is_empty() {
            "none".into()
        } else {
            present.join(", ")
        },
        if absent.is_empty() {
            "none".into()
        } else {
            absent.join(", ")
        }
    )?;
    writeln!(md, "\nRungs measured: {}.", rows.len())?;
    Ok(())
}

/// The before/after of compensated summation on problem (a).
fn floor_table(md: &mut String, rows: &[Row]) -> Result<(), Box<dyn Error>> {
    writeln!(
        md,
        "\n### The numerical floor: plain against compensated sums on (a) and (e)\n"
    )?;
    writeln!(
        md,
        "| method | h | steps | error, plain | error, compensated | time, plain | time, compensated |"
    )?;
    writeln!(md, "|---|---|---|---|---|---|---|")?;
    for before in rows.iter().filter(|r| r.before) {
        let base = before.method.trim_end_matches(", plain sums");
        let Some(after) = rows.iter().find(|r| {
            !r.before
                && r.method == base
                && r.problem == before.problem
                && r.setting == before.setting
        }) else {
            continue;
        };
        writeln!(
            md,
            "| {} ({}) | {} | {} | {:.2e} | {:.2e} | {} | {} |",
            base,
            before.problem.key(),
            short(before.setting),
            before.outcome.steps,
            before.outcome.error,
            after.outcome.error,
            time_text(before.seconds),
            time_text(after.seconds)
        )?;
    }
    Ok(())
}

fn adding_a_method(md: &mut String) -> Result<(), Box<dyn Error>> {
    writeln!(
        md,
        "\n### Adding a method\n\n\
         A method is one entry of `methods()` in `testkit/src/work_precision/methods.rs`: a \
         `Method {{ name, setting, before, problems }}` whose `problems` hold one `ProblemRun \
         {{ problem, ladder, quick, run }}` per problem it applies to; `run` is a closure that \
         integrates one setting and returns an `Outcome {{ error, evals, steps }}` measured \
         against the problem's reference (`problems.rs`: `separatrix_reference()`, `B5_Y20`, \
         `TopCase::u_end`). The Taylor integrator is such an entry (`testkit/src/work_precision/\
         taylor.rs`): on (a) and (b) its recurrences are generated by `taylor_system!` from \
         the equations written in the source (and, as \"Taylor, interpreted\", the same \
         equations built at run time and interpreted by `TaylorTape`, and as \"Taylor, \
         extended\" those tapes with the low orders of each step in double-double), on (c) \
         and (d) they \
         are the ones the derive generates for the report's top (`taylor = 20`); \
         tables, figures, `--quick` and `tests/it/work_precision.rs` pick a new entry up with \
         no other change."
    )?;
    Ok(())
}

/// How a plain-sums variant's label ends.
const PLAIN_SUFFIX: &str = ", plain sums";

/// The log-log figure of error against median time, drawn by `precess::plot`: a line with
/// markers per method, markers alone for peers, a plain-sums variant dashed in its method's
/// colour (so the before and after of the numerical floor read as one method, and colours do
/// not run out). Runs whose error is 0 or not finite have no place on the log axis and are
/// left out.
fn figure(
    path: &Path,
    problem: Problem,
    mine: &[&Row],
    theirs: &[&PeerRow],
) -> Result<(), Box<dyn Error>> {
    let drawable = |(w, e): (f64, f64)| w > 0.0 && e > 0.0 && e.is_finite();
    let mut series: Vec<Series> = Vec::new();
    let mut add = |label: String, point: (f64, f64), style: Style| match series
        .iter_mut()
        .find(|s| s.label == label)
    {
        Some(s) => s.points.push(point),
        None => series.push(Series::styled(label, vec![point], style)),
    };
    for r in mine {
        let point = (r.seconds, r.outcome.error);
        if drawable(point) {
            let style = if r.method.ends_with(PLAIN_SUFFIX) {
                Style::Dashed
            } else {
                Style::LineAndMarkers
            };
            add(r.method.clone(), point, style);
        }
    }
    for p in theirs {
        let point = (p.seconds, p.error);
        if drawable(point) {
            add(format!("{} {}", p.peer, p.method), point, Style::Markers);
        }
    }
    if series.is_empty() {
        return Ok(());
    }
    // One colour per method, whatever its variants.
    let mut bases: Vec<String> = Vec::new();
    for s in &mut series {
        let base = s
            .label
            .strip_suffix(PLAIN_SUFFIX)
            .unwrap_or(&s.label)
            .to_string();
        let k = match bases.iter().position(|b| *b == base) {
            Some(k) => k,
            None => {
                bases.push(base);
                bases.len() - 1
            }
        };
        s.color = Some(k);
    }
    precess::plot::work_precision(path, problem.title(), Work::Seconds, &series)?;
    Ok(())
}
