//! Compile-fail cases of the precess macros: each `tests/ui/<case>.rs` must fail to compile
//! with exactly the spanned message in `tests/ui/<case>.stderr`.
//!
//! The cases keep trybuild's layout and its normalisation of the compiler's output (the
//! `error: aborting due to …` and `For more information …` lines dropped, line ends
//! trimmed), so `trybuild::TestCases::compile_fail("tests/ui/*.rs")` still reads them. They
//! are compiled here, though, against the workspace's own build of precess rather than in a
//! project of trybuild's: trybuild compiled the whole macro stack (syn, nalgebra, the
//! optimised engine, the macro) a second time in a target of its own, about 200 s of CPU in
//! `.ci/run`, where the 199 cases themselves check in a few seconds. cargo says where its
//! build of the facade is (`cargo build -p precess --message-format=json`: after the tests'
//! build only the facade with its default features is compiled, in a fraction of a second);
//! each case is then one `rustc --emit=metadata` run against it, with trybuild's flags.
//!
//! `UI=overwrite cargo test -p precess-ui` writes the compiler's output as the expected one
//! (review the diff before committing it).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Where cargo's build of the facade is: its metadata file and the folder of its
/// dependencies.
struct Facade {
    rmeta: PathBuf,
    deps: PathBuf,
}

impl Facade {
    /// The facade whose metadata is `rmeta`, in `deps/` beside what it depends on.
    fn at(rmeta: PathBuf) -> Self {
        let deps = rmeta.parent().expect("in a folder").to_path_buf();
        Facade { rmeta, deps }
    }
}

/// Asks cargo to build the facade (its dependencies are the tests' own, already built) and
/// reads the artifact's path from its JSON messages; or takes that path from
/// `PRECESS_UI_FACADE` when it is set (`.ci/run` sets it: there, cargo's build lock is held by
/// the checks that build beside the tests, and asking cargo from inside a test waited for
/// them).
fn facade(workspace: &Path) -> Facade {
    if let Some(rmeta) = std::env::var_os("PRECESS_UI_FACADE").filter(|p| !p.is_empty()) {
        let rmeta = PathBuf::from(rmeta);
        assert!(
            rmeta.is_file(),
            "PRECESS_UI_FACADE names no file: {}",
            rmeta.display()
        );
        return Facade::at(rmeta);
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .current_dir(workspace)
        .args(["build", "-p", "precess", "--profile", "test"])
        .args(["--message-format=json", "--quiet"])
        .output()
        .expect("cargo runs");
    assert!(
        out.status.success(),
        "cargo build -p precess failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let rmeta = stdout
        .lines()
        .filter(|l| l.contains(r#""reason":"compiler-artifact""#))
        .filter(|l| l.contains(r#""name":"precess","#) && l.contains(r#""kind":["lib"]"#))
        .find_map(|l| {
            let files = &l[l.find(r#""filenames":["#)? + 13..];
            // The metadata file, in `deps/` beside what it depends on (the .rlib cargo
            // also names is a copy one folder up).
            files[..files.find(']')?]
                .split(',')
                .map(|f| f.trim_matches('"'))
                .find(|f| f.ends_with(".rmeta"))
                .map(PathBuf::from)
        })
        .expect("cargo names the facade's artifact");
    Facade::at(rmeta)
}

/// The compiler's output as trybuild compares it: its closing summary lines dropped, every
/// line's end trimmed, no trailing blank lines.
fn normalise(stderr: &str) -> String {
    let dropped = [
        "error: aborting due to ",
        "For more information about this error, try `rustc --explain",
        "Some errors have detailed explanations:",
        "For more information about an error, try `rustc --explain",
    ];
    let lines: Vec<&str> = stderr
        .lines()
        .filter(|l| !dropped.iter().any(|d| l.starts_with(d)))
        .map(str::trim_end)
        .collect();
    lines.join("\n").trim_end().to_string()
}

/// One case: compiled for its metadata only, with trybuild's flags; `Err` says how it
/// differed from what was expected.
fn check_case(case: &Path, facade: &Facade, out_dir: &Path, overwrite: bool) -> Result<(), String> {
    let stem = case.file_stem().and_then(|s| s.to_str()).unwrap_or("case");
    let relative = Path::new("tests/ui").join(case.file_name().unwrap_or_default());
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let out = Command::new(rustc)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["--edition=2024", "--crate-type=bin", "--emit=metadata"])
        .arg(format!("--crate-name={}", stem.replace('-', "_")))
        .arg("--out-dir")
        .arg(out_dir)
        .args([
            "--error-format=human",
            "--color=never",
            "--diagnostic-width=140",
        ])
        .args(["--cfg", "trybuild", "--verbose", "-A", "dead_code"])
        .arg("-L")
        .arg(format!("dependency={}", facade.deps.display()))
        .arg("--extern")
        .arg(format!("precess={}", facade.rmeta.display()))
        .arg(&relative)
        .output()
        .map_err(|e| format!("rustc did not run: {e}"))?;
    let actual = normalise(&String::from_utf8_lossy(&out.stderr));
    let expected_path = case.with_extension("stderr");
    if overwrite {
        std::fs::write(&expected_path, format!("{actual}\n")).map_err(|e| e.to_string())?;
    }
    if out.status.success() {
        return Err(format!("{stem}: compiled, but it should fail:\n{actual}"));
    }
    let expected = std::fs::read_to_string(&expected_path).map_err(|_| {
        format!(
            "{stem}: no {}; the output was:\n{actual}",
            expected_path.display()
        )
    })?;
    if normalise(&expected) == actual {
        Ok(())
    } else {
        Err(format!(
            "{stem}: the message differs.\n--- expected\n{}\n--- actual\n{actual}",
            normalise(&expected)
        ))
    }
}

#[test]
fn ui() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let workspace = manifest.parent().expect("the ui crate is in the workspace");
    let facade = facade(workspace);
    let out_dir = facade.deps.with_file_name("ui-cases");
    std::fs::create_dir_all(&out_dir).expect("a folder for the cases' metadata");
    let mut cases: Vec<PathBuf> = std::fs::read_dir(manifest.join("tests/ui"))
        .expect("the cases' folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    cases.sort();
    assert!(!cases.is_empty(), "no cases in tests/ui");
    let overwrite = std::env::var("UI").is_ok_and(|v| v == "overwrite");
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                while let Some(case) = cases.get(next.fetch_add(1, Ordering::Relaxed)) {
                    if let Err(e) = check_case(case, &facade, &out_dir, overwrite) {
                        failures.lock().unwrap_or_else(|p| p.into_inner()).push(e);
                    }
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap_or_else(|p| p.into_inner());
    println!("{} ui cases, {} failed", cases.len(), failures.len());
    assert!(
        failures.is_empty(),
        "{} of {} ui cases failed:\n\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n\n")
    );
}
