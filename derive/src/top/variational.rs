//! The top's side of the `variational(tangents = m, sensitivities = [field, …])` group of
//! `#[top]`, whose keys, checks and emission are the engine's (`lang::variational`, shared
//! with `#[mechanism]`): the top's state is its declared chart's (q, q̇), n = 6, a user
//! torque function is refused, and the generated type checks the fields as the top does.

use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

use crate::lang::check::Checker;
use crate::lang::ctxt::Ctxt;
use crate::lang::keys;
use crate::lang::private::Private;
use crate::lang::symbols::SymbolTokens;
use crate::lang::syntax::KeyValue;
use crate::lang::variational::{Scene, Target};

pub use crate::lang::variational::{VARIATIONAL, VariationalKey, form};

/// The entries of the top's state (q, q̇).
const STATE_LEN: usize = 6;

/// Checks one `variational(...)` group of the top, after every other value of the scene was
/// read. `torque` is true when the top declares a user torque function. `None` after
/// recording the errors.
pub fn check(
    ck: &Checker,
    name: &Ident,
    keys: &[KeyValue],
    torque: bool,
) -> Option<VariationalKey> {
    let scene = Scene {
        whose: "the top's",
        n: STATE_LEN,
        user: torque.then_some(keys::TORQUE),
    };
    crate::lang::variational::check(ck, name, keys, &scene)
}

/// The generated type for the declared chart's state (q, q̇) and right-hand side (q̇, q̈),
/// the fields read through `symbols`; its check_parameters is the top's `check_all`.
pub fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    symbols: &SymbolTokens,
    system: (&[ExprId], &[ExprId]),
    key: &VariationalKey,
) -> TokenStream {
    let p = Private;
    let target = Target {
        attribute: keys::TOP,
        field: format_ident!("top"),
        chart: "in its declared chart",
        check_doc: " The top's checks of its body and settings, before any step.",
        check: quote!(#p::TopDynamics::check_all(self.top).map_err(#p::TopError::into_ode_error)),
    };
    crate::lang::variational::expand(cx, ident, arena, symbols, system, key, &target)
}

#[cfg(test)]
mod tests {
    use precess_core::codegen::{Op, Program};
    use precess_core::sym::Arena;
    use precess_core::top::TopScene;
    use precess_core::variational::VariationalEquations;
    use quote::quote;

    use crate::lang::tests::{method, rigid_body as expand};

    /// The emitted right-hand side is the interpreted program written out: one `let` per
    /// instruction of the program `VariationalSystem` runs for the same scene (built here
    /// by hand in precess-core), so the generated type saves the interpreter's dispatch and
    /// nothing else. Run with `--nocapture` for the counts.
    #[test]
    fn the_emitted_equations_are_the_interpreted_program() {
        let code = expand(quote! {
            #[rigid(
                body(mass = m, at = [0.0, 0.0, l], inertia = diag(i1, i2, i3), about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = g, variational(sensitivities = [m, l, g]))]
            struct Heavy { m: f64, l: f64, g: f64, i1: f64, i2: f64, i3: f64 }
        });
        assert!(!code.contains("compile_error"), "{code}");
        assert!(code.contains("struct HeavyVariational"), "{code}");
        assert!(
            code.contains("System < 60usize > for HeavyVariational"),
            "{code}"
        );
        let rhs = method(&code, "__precess_variational_rhs");
        // One `let __pN` per instruction, a sine and a cosine sharing one `sin_cos` (the
        // `let (…) = { … }` blocks only group the statements).
        let lets = rhs.matches("let __p").count() + 2 * rhs.matches("sin_cos (").count();
        let writes = rhs.matches("dydt [").count();

        let mut a = Arena::new();
        let z = a.zero();
        let i = ["i1", "i2", "i3"].map(|n| a.parameter(n));
        let mut scene = TopScene::free(&mut a, [[i[0], z, z], [z, i[1], z], [z, z, i[2]]]);
        scene.mass = a.parameter("m");
        scene.center = [z, z, a.parameter("l")];
        scene.gravity = Some(a.parameter("g"));
        let Ok(derivation) = scene.derive(&mut a) else {
            panic!("the heavy top derives");
        };
        let Ok(eq) = VariationalEquations::from_top(&mut a, &derivation, 6, &["m", "l", "g"])
        else {
            panic!("the equations build");
        };
        let program = Program::lower(&a, eq.outputs());
        let instructions = program
            .ops()
            .iter()
            .filter(|op| !matches!(op, Op::Const(_)))
            .count();
        let (f, all) = eq.op_counts(&a);
        println!(
            "emitted: {lets} lets, {writes} outputs; interpreted program: {instructions} instructions, ops f {} / augmented {}",
            f.total(),
            all.total()
        );
        assert_eq!(writes, 60);
        assert_eq!(lets, instructions, "{rhs}");
    }
}
