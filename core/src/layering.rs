//! The layering rule, checked on the source: no scene names another scene, and the layers
//! the scenes share (`body`, `rigid`) name no scene. A new scene (rolling contact, say) is
//! added to `SCENES` and meets the same rule; `docs/conventions.md` states it.

use std::fs;
use std::path::{Path, PathBuf};

/// The scene modules, each a folder of `src/`.
const SCENES: [&str; 4] = ["top", "free", "mechanism", "contact"];

/// The shared layers below the scenes.
const SHARED: [&str; 2] = ["body", "rigid"];

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let entries = fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            out.push(path);
        }
    }
}

/// The lines of the files under `src/{module}` that name `scene` by path, in code or in
/// docs: `crate::scene`, `precess_core::scene`, `precess::scene`.
fn mentions(module: &str, scene: &str) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("src")
        .join(module);
    let mut files = Vec::new();
    sources(&root, &mut files);
    let needles = ["crate::", "precess_core::", "precess::"].map(|p| format!("{p}{scene}"));
    let mut found = Vec::new();
    for file in files {
        let text = fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for (n, line) in text.lines().enumerate() {
            let names = needles.iter().any(|needle| {
                line.match_indices(needle.as_str()).any(|(i, _)| {
                    // `crate::top` but not `crate::topology`.
                    let next = line[i + needle.len()..].chars().next();
                    !next.is_some_and(|c| c.is_alphanumeric() || c == '_')
                })
            });
            if names {
                found.push(format!("{}:{}: {}", file.display(), n + 1, line.trim()));
            }
        }
    }
    found
}

#[test]
fn no_scene_names_another() {
    for scene in SCENES {
        for other in SCENES.iter().filter(|&&o| o != scene) {
            let found = mentions(scene, other);
            assert!(
                found.is_empty(),
                "{scene} names {other}:\n{}",
                found.join("\n")
            );
        }
    }
}

#[test]
fn the_shared_layers_name_no_scene() {
    for layer in SHARED {
        for scene in SCENES {
            let found = mentions(layer, scene);
            assert!(
                found.is_empty(),
                "{layer} names {scene}:\n{}",
                found.join("\n")
            );
        }
    }
}
