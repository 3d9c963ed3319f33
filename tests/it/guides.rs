//! Every guide in `docs/` is compiled as a doctest (`src/guides.rs` includes each one), and
//! its Rust blocks are all compiled: a block fenced `rust,ignore` (or `no_run`) would be a
//! guide's example that nothing checks.

use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The guides, by file name.
fn guides() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("docs"))
        .expect("docs/ is readable")
        .map(|entry| entry.expect("a directory entry").file_name())
        .filter_map(|name| name.into_string().ok())
        .filter(|name| name.ends_with(".md"))
        .collect();
    names.sort();
    names
}

#[test]
fn every_guide_is_included_as_doctests() {
    let guides_rs = std::fs::read_to_string(root().join("src/guides.rs")).expect("src/guides.rs");
    let missing: Vec<String> = guides()
        .into_iter()
        .filter(|name| !guides_rs.contains(&format!("include_str!(\"../docs/{name}\")")))
        .collect();
    assert!(guides().len() > 20, "the guides were not found");
    assert!(
        missing.is_empty(),
        "guides not compiled as doctests: {missing:?}"
    );
    assert!(guides_rs.contains("include_str!(\"../README.md\")"));
}

#[test]
fn no_rust_block_of_a_guide_is_skipped() {
    let mut skipped = Vec::new();
    for name in guides().into_iter().chain(["../README.md".to_string()]) {
        let text = std::fs::read_to_string(root().join("docs").join(&name)).expect("a guide");
        for (line, fence) in text.lines().enumerate() {
            let info = fence.trim_start().strip_prefix("```").unwrap_or("");
            let words: Vec<&str> = info.split(',').map(str::trim).collect();
            if words[0] == "rust" && words.iter().any(|w| matches!(*w, "ignore" | "no_run")) {
                skipped.push(format!("{name}:{}", line + 1));
            }
        }
    }
    assert!(
        skipped.is_empty(),
        "Rust blocks that are not compiled and run: {skipped:?}"
    );
}
