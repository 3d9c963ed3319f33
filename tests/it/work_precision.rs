//! One cheap rung of the work-precision report (`examples/work_precision.rs`, `--quick`),
//! run so that its code cannot rot: every problem gets measured, every error against its
//! independent reference is small, and the document is written between its markers with
//! what was outside them kept. No timing is asserted.

use precess_testkit::work_precision;
use precess_testkit::work_precision::problems::Problem;

#[test]
fn quick_rungs_measure_small_errors_and_write_the_report() {
    work_precision::set_quick(true);
    let rows = work_precision::report::measure_all(1, false).unwrap();
    for problem in Problem::ALL {
        assert!(
            rows.iter().any(|r| r.problem == problem),
            "no rung for {problem:?}"
        );
    }
    for r in &rows {
        let e = r.outcome.error;
        // The quick rungs are the coarsest: bounds sit a decade or more above the measured
        // errors (largest: split2 at h = 0.1 on (a), 5.6e-4; RKMK4 on the top, 2.4e-4).
        let bound = match r.problem {
            Problem::Separatrix | Problem::HeavyTop => 2e-3,
            Problem::B5 => 1e-4,
            Problem::FastTop | Problem::Forms => 1e-5,
            Problem::LongRun => 1e-7,
        };
        assert!(
            e.is_nan() && r.method.starts_with("exact") || e < bound,
            "{:?} {} setting {}: error {e:e}",
            r.problem,
            r.method,
            r.setting
        );
        assert!(r.seconds >= 0.0);
    }
    // The closed form of B5 against the 30-digit value: at the rounding level.
    let b5_exact = rows
        .iter()
        .find(|r| r.problem == Problem::B5 && r.method.starts_with("exact"))
        .unwrap();
    assert!(b5_exact.outcome.error < 1e-14);

    // Under the target's scratch space: the report written here replaces the last run's.
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("work-precision");
    let doc = dir.join("docs/performance.md");
    std::fs::create_dir_all(doc.parent().unwrap()).unwrap();
    let outside = "# Performance\n\nkept above\n\n<!-- work-precision:begin -->\nold\n<!-- work-precision:end -->\n\n## Mechanisms at scale\n\nkept below\n";
    std::fs::write(&doc, outside).unwrap();
    work_precision::report::write(&dir, &rows).unwrap();
    let text = std::fs::read_to_string(&doc).unwrap();
    assert!(text.starts_with("# Performance\n\nkept above\n"));
    assert!(
        text.ends_with("<!-- work-precision:end -->\n\n## Mechanisms at scale\n\nkept below\n")
    );
    assert!(!text.contains("\nold\n"));
    assert!(text.contains("### (a) Torque-free body"));
    for p in Problem::ALL {
        assert!(dir.join(format!("docs/img/perf/{}.svg", p.key())).exists());
    }
    assert!(dir.join("docs/perf/references.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
