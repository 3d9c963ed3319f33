//! The emitted Rust, compiled, against the interpreter of the same instructions. Both execute
//! the same IEEE operations in the same order, so they must agree to the bit.

use precess_codegen_check::generated::FUNCTIONS;
use precess_codegen_check::generator::{self, Rng};
use precess_core::codegen::Program;

#[test]
fn every_generated_function_matches_the_interpreter_bit_for_bit() {
    let mut a = generator::arena_with_vars();
    assert_eq!(FUNCTIONS.len(), generator::PROGRAMS);
    let mut rng = Rng::new(42);
    let mut compared = 0;
    for (k, f) in FUNCTIONS.iter().enumerate() {
        let outs = generator::program(&mut a, k);
        let prog = Program::lower(&a, &outs);
        for _ in 0..20 {
            let env: Vec<f64> = (0..generator::VARS.len())
                .map(|_| rng.uniform(-2.0, 2.0))
                .collect();
            let compiled = f(&env);
            let interpreted = prog.eval(&env);
            assert_eq!(compiled.len(), interpreted.len());
            for (c, i) in compiled.iter().zip(&interpreted) {
                assert!(
                    c.to_bits() == i.to_bits() || (c.is_nan() && i.is_nan()),
                    "program {k} at {env:?}: compiled {c}, interpreted {i}\n{}",
                    outs.iter()
                        .map(|&e| a.display(e))
                        .collect::<Vec<_>>()
                        .join("; ")
                );
                compared += 1;
            }
            // And both against direct evaluation of the expression graph.
            for (&e, i) in outs.iter().zip(&interpreted) {
                let direct = a.eval(e, &env);
                assert!(
                    (direct - i).abs() <= 1e-9 * (1.0 + direct.abs()),
                    "program {k}: {direct} vs {i}"
                );
            }
        }
    }
    assert!(compared >= 20 * generator::PROGRAMS);
}
