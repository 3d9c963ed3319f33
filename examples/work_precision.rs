//! The work-precision report: `cargo run --release --example work_precision` runs DOP853,
//! Vern9, DOPRI5, RK4, RKMK4, the splittings of orders 2, 4 and 6 and the closed forms over
//! their ladders on six problems, and writes `docs/performance.md` (between its
//! work-precision markers) and the figures under `docs/img/perf/`.
//!
//! `--quick` runs one cheap rung per problem and one repeat (a smoke test); `--out DIR`
//! writes under DIR instead of the current directory (which should be the repository's
//! root). Peers' points (`scripts/peers.py`) are read from `docs/perf/peers.csv` if present.

use precess_testkit::work_precision;

use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut out = PathBuf::from(".");
    let mut quick = false;
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => quick = true,
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            other => return Err(format!("unknown argument {other:?} (--quick, --out DIR)").into()),
        }
    }
    work_precision::set_quick(quick);
    let results = work_precision::report::measure_all(if quick { 1 } else { 5 }, true)?;
    let written = work_precision::report::write(&out, &results)?;
    println!("wrote {}", written.display());
    Ok(())
}
