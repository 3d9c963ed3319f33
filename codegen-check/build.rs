//! Emits every generated program as a Rust function with precess-core's code generator.

// The uniform sampler is for the tests; the build script only draws shapes.
#[allow(dead_code)]
#[path = "src/generator.rs"]
mod generator;

use std::fmt::Write;

use precess_core::codegen::Program;

fn main() {
    let mut a = generator::arena_with_vars();
    let mut code = String::new();
    let mut table = String::from(
        "/// Every generated function, in program order.\npub const FUNCTIONS: &[Generated] = &[",
    );
    for k in 0..generator::PROGRAMS {
        let outs = generator::program(&mut a, k);
        let prog = Program::lower(&a, &outs);
        let emitted = prog.to_tokens(&mut |s| {
            let i = s.index();
            quote::quote!(env[#i])
        });
        let lets = emitted.lets.to_string();
        let outs: Vec<String> = emitted.outputs.iter().map(|t| t.to_string()).collect();
        let _ = writeln!(
            code,
            "#[allow(clippy::all, unused_parens, unused_variables)]\nfn f{k}(env: &[f64]) -> Vec<f64> {{ {lets} vec![{}] }}",
            outs.join(", ")
        );
        let _ = write!(table, "f{k}, ");
    }
    table.push_str("];\n");
    code.push_str(&table);
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR"));
    std::fs::write(out.join("generated.rs"), code).expect("OUT_DIR is writable");
    println!("cargo::rerun-if-changed=src/generator.rs");
    println!("cargo::rerun-if-changed=build.rs");
}
