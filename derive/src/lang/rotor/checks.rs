//! The rules rotors add to a scene's body, in the generated `check_parameters` for values
//! that read fields and now for literals: each rotor's inertia positive and axis non-zero,
//! and with wheels driven by motors, the body's inertia left positive definite as they turn
//! freely. `#[top]` and `#[free]` emit them through here alike.

use precess_core::codegen::Emitted;
use precess_core::rigid::Rotor;
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;

use super::Driven;
use crate::lang::ctxt::Ctxt;
use crate::lang::symbols::Lowering;

/// Statements for `check_parameters` of a scene with rotors: each rotor's inertia positive
/// and axis non-zero ([`check_tokens_indexed`]; the constant ones given as their indices
/// among every rotor declared and the rotors), then, with `driven` rotors, the body's inertia
/// (`inertia`, an expression of type `Matrix3<f64>` reading `self`: about the pivot for a
/// top, the centre of mass for a free body) left positive definite with the wheels turning
/// freely (`<error>::check_driven_inertia`), `error` the scene's error enum.
pub fn check_tokens(
    low: &Lowering,
    arena: &Arena,
    (index, constant): (&[usize], &[Rotor]),
    driven: &[(usize, Driven)],
    error: &TokenStream,
    inertia: &TokenStream,
) -> TokenStream {
    let mut shapes: Vec<(usize, [ExprId; 3], ExprId)> = index
        .iter()
        .zip(constant)
        .map(|(&k, r)| (k, r.axis, r.inertia))
        .collect();
    shapes.extend(driven.iter().map(|(k, d)| (*k, d.axis, d.inertia)));
    let mut tokens = check_tokens_indexed(low, arena, &shapes, error);
    if driven.is_empty() {
        return tokens;
    }
    let values: Vec<ExprId> = driven
        .iter()
        .flat_map(|(_, d)| d.axis.into_iter().chain([d.inertia]))
        .collect();
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let wheels = outputs.chunks(4).zip(driven).map(|(o, (k, _))| {
        let (a, j) = (&o[..3], &o[3]);
        quote!((#k, [#(#a),*], #j))
    });
    tokens.extend(quote!({
        #lets
        #error::check_driven_inertia(&#inertia, &[#(#wheels),*])?;
    }));
    tokens
}

/// Statements for `check_parameters`: each rotor's inertia positive and axis non-zero for the
/// current field values (all finite already), else `<error>::InvalidRotor`, with `error` the
/// attribute's error enum (`FreeError`, `TopError`: both carry the variant); the rotors given
/// as (index among every rotor declared, axis, inertia).
fn check_tokens_indexed(
    low: &Lowering,
    arena: &Arena,
    rotors: &[(usize, [ExprId; 3], ExprId)],
    error: &TokenStream,
) -> TokenStream {
    let values: Vec<ExprId> = rotors
        .iter()
        .flat_map(|&(_, axis, inertia)| std::iter::once(inertia).chain(axis))
        .collect();
    if values.is_empty() {
        return TokenStream::new();
    }
    let Emitted { lets, outputs } = low.lower(arena, &values);
    let checks = outputs.chunks(4).zip(rotors).map(|(o, &(k, _, _))| {
        let (j, a) = (&o[0], &o[1..]);
        quote! {
            let __j: f64 = #j;
            let __a: f64 = (#((#a) * (#a))+*).sqrt();
            if !(__j.is_finite() && __j > 0.0 && __a.is_finite() && __a > 0.0) {
                return ::core::result::Result::Err(#error::InvalidRotor {
                    rotor: #k,
                    inertia: __j,
                    axis_norm: __a,
                });
            }
        }
    });
    quote!({ #lets #(#checks)* })
}

/// Where the driven-rotor rule of [`literal_driven_inertia`] is read: the scene's word for
/// the body (`"top"`, `"body"`) and the point its inertia is about (`"the pivot"`, `"its
/// centre of mass"`), for the message.
pub struct InertiaAbout<'a> {
    /// The scene's word for the body.
    pub body: &'a str,
    /// The point the inertia is about.
    pub point: &'a str,
}

/// With literal values, the rule driven rotors add in every scene that has them: the body's
/// `inertia` (about `about.point`) stays positive definite as each wheel's axial moment is
/// taken out, I − Σ J â âᵀ. An error spanned on the first rotor's `inertia` that breaks it;
/// `None` after recording it. A value that reads a field is left to the generated run-time
/// check.
pub fn literal_driven_inertia(
    cx: &Ctxt,
    arena: &Arena,
    inertia: &[[ExprId; 3]; 3],
    driven: &[(usize, Driven)],
    about: InertiaAbout<'_>,
) -> Option<()> {
    let constant = |e: ExprId| arena.free_symbols(e).is_empty().then(|| arena.eval(e, &[]));
    let literal = || {
        let mut m = precess_core::nalgebra::Matrix3::zeros();
        for i in 0..3 {
            for j in 0..3 {
                m[(i, j)] = constant(inertia[i][j])?;
            }
        }
        let mut wheels = Vec::new();
        for (_, d) in driven {
            let axis = [
                constant(d.axis[0])?,
                constant(d.axis[1])?,
                constant(d.axis[2])?,
            ];
            wheels.push((axis, constant(d.inertia)?));
        }
        Some((m, wheels))
    };
    let Some((m, wheels)) = literal() else {
        return Some(());
    };
    let Some((k, smallest)) = precess_core::rigid::first_singular_driven(&m, &wheels) else {
        return Some(());
    };
    let (declared, d) = &driven[k];
    let InertiaAbout { body, point } = about;
    cx.error_spanned_by(
        &d.inertia_expr,
        format!(
            "rotor {declared}'s `inertia` is too large for the {body}: with its driven wheels turning freely the {body} keeps I − Σ J â âᵀ about {point}, whose smallest principal moment here is {} kg m^2; it must be positive beyond rounding (a wheel's J below the {body}'s own moment about the wheel's axis by more than {:.0e} of its largest moment)",
            readable(smallest),
            precess_core::rigid::DRIVEN_ROUNDING
        ),
    );
    None
}

/// A moment as the messages print it: four decimals where that shows it (`-0.0100`), else
/// four significant digits in exponent form (`4.441e-16`, where `{:.4}` printed `0.0000`).
fn readable(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x:.4}")
    } else {
        format!("{x:.3e}")
    }
}
