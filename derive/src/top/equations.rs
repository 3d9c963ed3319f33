//! `TopDynamics::equations`: the scene's equations typeset by precess-core while the macro
//! expands ([`TopScene::typeset`], the function the run-time API calls too), emitted as
//! `'static` string literals and integer counts, so reading them costs nothing at run time.

use precess_core::codegen::{MethodCost, OpCount, Typeset};
use precess_core::sym::mat3::Mat3;
use precess_core::sym::{Arena, ExprId, SymbolKind};
use precess_core::top::TopScene;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

use crate::lang::ctxt::Ctxt;
use crate::lang::private::Private;

/// The method `fn equations(&self) -> &'static Typeset` of `scene`, or nothing after
/// recording why its equations could not be derived.
///
/// Called after the other methods are lowered: the angle-form expressions rebuilt here in
/// the same arena are the very ones lowered (hash-consed), and the Eulerian form is rebuilt
/// over the inputs `eulerian_rhs` read, so each count is that of the emitted code.
pub fn method(cx: &Ctxt, ident: &Ident, arena: &mut Arena, scene: &TopScene) -> TokenStream {
    let Some((attitude, omega)) = eulerian_inputs(arena) else {
        cx.error_spanned_by(
            ident,
            "internal error of the derive: the inputs of `eulerian_rhs` were not found; please report this",
        );
        return TokenStream::new();
    };
    let typeset = match scene.typeset_reading(arena, &attitude, &omega) {
        Ok(t) => t,
        Err(e) => {
            cx.error_spanned_by(
                ident,
                format!("cannot typeset the top's equations of motion: {e}"),
            );
            return TokenStream::new();
        }
    };
    let p = Private;
    let body = typeset_tokens(&typeset);
    quote! {
        fn equations(&self) -> &'static #p::Typeset {
            static EQUATIONS: #p::Typeset = #body;
            &EQUATIONS
        }
    }
}

/// The input symbols `R{i}{j}` (attitude matrix) and `w{k}` (ω) that `expand::eulerian`
/// made for `eulerian_rhs`, the latest of each name (shown with primes, `R00'`, when a field
/// has the name).
fn eulerian_inputs(arena: &Arena) -> Option<(Mat3, [ExprId; 3])> {
    let mut attitude: [[Option<ExprId>; 3]; 3] = [[None; 3]; 3];
    let mut omega: [Option<ExprId>; 3] = [None; 3];
    for (s, symbol) in arena.symbols() {
        if symbol.kind != SymbolKind::Input {
            continue;
        }
        let e = arena.symbol_expr(s);
        let name = symbol.name.trim_end_matches('\'').as_bytes();
        let digit = |b: u8| (b'0'..=b'2').contains(&b).then(|| usize::from(b - b'0'));
        match name {
            [b'R', i, j] => {
                if let (Some(i), Some(j)) = (digit(*i), digit(*j)) {
                    attitude[i][j] = Some(e);
                }
            }
            [b'w', k] => {
                if let Some(k) = digit(*k) {
                    omega[k] = Some(e);
                }
            }
            _ => {}
        }
    }
    let mut rows = [[arena.zero(); 3]; 3];
    for (row, found) in rows.iter_mut().zip(attitude) {
        for (entry, f) in row.iter_mut().zip(found) {
            *entry = f?;
        }
    }
    let [w0, w1, w2] = omega;
    Some((rows, [w0?, w1?, w2?]))
}

/// A constant expression building `t` from string literals.
fn typeset_tokens(t: &Typeset) -> TokenStream {
    let p = Private;
    let lines = |lines: &[std::borrow::Cow<'static, str>]| {
        let lines = lines.iter().map(AsRef::<str>::as_ref);
        quote!(#p::Cow::Borrowed(&[#(#p::Cow::Borrowed(#lines)),*]))
    };
    let lagrangian = t.lagrangian.as_ref();
    let equations = lines(&t.equations);
    let accelerations = lines(&t.accelerations);
    let conserved = lines(&t.conserved);
    let definitions = lines(&t.definitions);
    let costs = t.costs.iter().map(cost_tokens);
    let values = t.values.iter().map(|(symbol, value)| {
        let (symbol, value) = (symbol.as_ref(), value.as_ref());
        quote!((#p::Cow::Borrowed(#symbol), #p::Cow::Borrowed(#value)))
    });
    quote! {
        #p::Typeset {
            lagrangian: #p::Cow::Borrowed(#lagrangian),
            equations: #equations,
            accelerations: #accelerations,
            conserved: #conserved,
            definitions: #definitions,
            values: #p::Cow::Borrowed(&[#(#values),*]),
            costs: #p::Cow::Borrowed(&[#(#costs),*]),
        }
    }
}

fn cost_tokens(c: &MethodCost) -> TokenStream {
    let p = Private;
    let method = c.method.as_ref();
    let OpCount {
        adds,
        muls,
        divs,
        negs,
        sqrts,
        powfs,
        trig,
        sin_cos,
    } = c.ops;
    quote! {
        #p::MethodCost {
            method: #p::Cow::Borrowed(#method),
            ops: #p::OpCount {
                adds: #adds,
                muls: #muls,
                divs: #divs,
                negs: #negs,
                sqrts: #sqrts,
                powfs: #powfs,
                trig: #trig,
                sin_cos: #sin_cos,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use quote::quote;

    use crate::lang::tests::rigid_body as expand;

    /// The text of one method's arm for the ZXZ chart, or of a whole method.
    fn method<'a>(code: &'a str, name: &str, zxz_arm: bool) -> &'a str {
        let start = code.find(&format!("fn {name}")).unwrap_or(0);
        let rest = &code[start..];
        // The next method's ` fn `; a bound user torque, `let __torque : fn (..) = ..`,
        // holds one too, after a colon.
        let end = rest
            .match_indices(" fn ")
            .map(|(i, _)| i)
            .find(|&i| i > 3 && !rest[..i].ends_with(" :"))
            .unwrap_or(rest.len());
        let rest = &rest[..end];
        if !zxz_arm {
            return rest;
        }
        let arm = rest.find("AngleSequence :: Zxz =>").unwrap_or(0);
        let rest = &rest[arm..];
        let end = rest.find("AngleSequence :: Zyx =>").unwrap_or(rest.len());
        &rest[..end]
    }

    /// The integer the emitted `OpCount` of `method` gives `field`.
    fn emitted_count(code: &str, method: &str, field: &str) -> usize {
        let at = code
            .find(&format!(
                "method : :: precess :: __private :: Cow :: Borrowed (\"{method}\")"
            ))
            .unwrap_or_else(|| panic!("no cost for {method}"));
        let rest = &code[at..];
        let f = rest.find(&format!("{field} : ")).expect("field") + field.len() + 3;
        let digits: String = rest[f..].chars().take_while(char::is_ascii_digit).collect();
        digits.parse().expect("an integer")
    }

    /// The operations in the emitted Rust of a method, counted on its text: binary `+`,
    /// `-`, `*`, `/` between operands, `-` after `=` as a negation, and the calls to
    /// `f64::sqrt`, `f64::sin`, `f64::cos` and `f64::sin_cos`.
    fn counted(text: &str) -> [usize; 7] {
        let negs = text.matches("= - ").count();
        let subs = text.matches(" - ").count() - negs;
        [
            text.matches(" + ").count() + subs,
            text.matches(" * ").count(),
            text.matches(" / ").count(),
            negs,
            text.matches("f64 :: sqrt (").count(),
            text.matches("f64 :: sin (").count() + text.matches("f64 :: cos (").count(),
            text.matches("f64 :: sin_cos (").count(),
        ]
    }

    const FIELDS: [&str; 7] = ["adds", "muls", "divs", "negs", "sqrts", "trig", "sin_cos"];

    /// The counts emitted with the equations are those of the code emitted beside them,
    /// counted here on the tokens rather than on the program: for the symmetric heavy top
    /// and for a general top under every torque (whose Eulerian form is the one whose count
    /// depends on which symbols it is rebuilt over).
    #[test]
    fn emitted_counts_match_the_emitted_code() {
        let heavy = expand(quote! {
            #[rigid(
                body(mass = m, at = [0.0, 0.0, l], inertia = diag(a, a, c), about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = g)]
            struct Heavy { m: f64, l: f64, a: f64, c: f64, g: f64 }
        });
        let general = expand(quote! {
            #[rigid(
                body(mass = m, at = [x, y, z], inertia = [[a, f, e], [f, b, d], [e, d, c]], about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = 9.81, damping = k, body_torque = [0.0, 0.1, s], torque = drive)]
            struct General { m: f64, x: f64, y: f64, z: f64, a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, k: f64, s: f64 }
        });
        // The description of tests/derive_equations.rs, whose Eulerian form counts
        // differently when rebuilt over fresh inputs.
        let tensor = expand(quote! {
            #[rigid(
                body(mass = M, at = [x, y, z], inertia = [[A, F, E], [F, B, D], [E, D, C]], about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = g, damping = k)]
            struct General { A: f64, B: f64, C: f64, D: f64, E: f64, F: f64, M: f64, x: f64, y: f64, z: f64, g: f64, k: f64 }
        });
        // Fields named as the Eulerian form's inputs: those are then shown primed.
        let clash = expand(quote! {
            #[rigid(
                body(mass = R00, at = [0.0, 0.0, w1], inertia = diag(1.0, 2.0, 3.0), about = pivot),
                pivot = [0.0, 0.0, 0.0],
            )]
            #[top(gravity = 9.81)]
            struct Clash { R00: f64, w1: f64 }
        });
        for (code, conserved) in [
            (heavy, true),
            (general, false),
            (tensor, false),
            (clash, false),
        ] {
            assert!(!code.contains("compile_error"), "{code}");
            for (name, emitted, arm) in [
                ("accelerations", "accelerations_unchecked_in", true),
                ("energy", "energy_in", true),
                ("rotation_in", "rotation_in", true),
                ("rate_matrix_in", "rate_matrix_in", true),
                ("angle_jacobian", "angle_jacobian", false),
                ("eulerian_rhs", "eulerian_rhs", false),
                ("conserved_momenta", "conserved_momenta", false),
            ] {
                let text = method(&code, emitted, arm);
                // The user torque's call computes ω = B q̇ with one matrix product, which
                // is not the method's own code.
                let text = text.replace(") * :: precess :: __private :: Vector3", ") MATVEC");
                let found = counted(&text);
                // Every method computes something (only the heavy top conserves momenta).
                if name != "conserved_momenta" || conserved {
                    assert!(found.iter().sum::<usize>() > 0, "{name}: {text}");
                }
                for (field, n) in FIELDS.iter().zip(found) {
                    assert_eq!(
                        emitted_count(&code, name, field),
                        n,
                        "{name}.{field} in {text}"
                    );
                }
            }
        }
    }

    /// A user torque prints as τ, not as the inputs the generated code reads.
    #[test]
    fn user_torque_prints_as_tau() {
        let code = expand(quote! {
            #[rigid(disk(mass = 1.0, radius = 0.04, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
            #[top(torque = drive)]
            struct Driven;
        });
        assert!(!code.contains("compile_error"), "{code}");
        let eq = method(&code, "equations", false);
        assert!(eq.contains(r"\\tau_{1}") && !eq.contains("u0"), "{eq}");
    }
}
