//! Expansion: the checked body's expressions lowered by precess-core's code generator and
//! quoted into a `RigidBody` impl. Constants become literals; a field becomes `self.field`;
//! generated code names everything through `::precess::__private`.

use precess_core::body::{Axis, Description, Frame, Shape};
use precess_core::codegen::{Emitted, Program, f64_literal};
use precess_core::sym::{ExprId, SymbolId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::{DeriveInput, Ident};

use crate::ast::Input;
use crate::check::{self, Checked};
use crate::ctxt::Ctxt;
use crate::fallback;
use crate::top;

/// The whole derive: the impl, or the errors and a stub impl.
pub fn derive(input: &DeriveInput) -> TokenStream {
    let mut cx = Ctxt::default();
    let expanded = Input::from_syn(&mut cx, input).and_then(|ast| {
        let mut checked = check::check(&mut cx, &ast)?;
        let spec = top::check(&mut cx, &ast, &mut checked)?;
        let top = match spec {
            Some(spec) => top::expand(&mut cx, ast.ident, &mut checked, spec)?,
            None => TokenStream::new(),
        };
        let body = expand(&mut cx, ast.ident, checked)?;
        Some(quote!(#body #top))
    });
    match expanded {
        Some(tokens) if cx.is_ok() => tokens,
        _ => {
            let mut out = fallback::expand(input, &cx);
            if input.attrs.iter().any(|a| a.path().is_ident("top")) {
                out.extend(top::fallback(&input.ident));
            }
            out
        }
    }
}

/// Maps the arena's symbols to Rust expressions.
struct Inputs {
    fields: Vec<(SymbolId, Ident)>,
    omega: [Option<SymbolId>; 3],
    torque: [Option<SymbolId>; 3],
}

impl Inputs {
    fn tokens(&self, s: SymbolId) -> TokenStream {
        if let Some((_, f)) = self.fields.iter().find(|(id, _)| *id == s) {
            return quote!(self.#f);
        }
        if let Some(i) = self.omega.iter().position(|&o| o == Some(s)) {
            return quote!(omega[#i]);
        }
        if let Some(i) = self.torque.iter().position(|&t| t == Some(s)) {
            return quote!(torque[#i]);
        }
        quote!(f64::NAN)
    }
}

/// Lowers `outputs` and emits them. A constant whose exact value did not fold to one
/// rational (an overflow kept it as a product) is rounded to one literal first, so a body of
/// literals never computes at run time.
fn emit(c: &mut Checked, inputs: &Inputs, outputs: &[ExprId]) -> Emitted {
    let a = &mut c.arena;
    let folded: Vec<ExprId> = outputs
        .iter()
        .map(|&e| {
            if a.as_rational(e).is_some() || !a.free_symbols(e).is_empty() {
                return e;
            }
            let v = a.eval(e, &[]);
            a.float(v).unwrap_or(e)
        })
        .collect();
    Program::lower(&c.arena, &folded).to_tokens(&mut |s| inputs.tokens(s))
}

/// A method body: the `let`s, then `build` applied to the output expressions.
fn body(
    c: &mut Checked,
    inputs: &Inputs,
    outputs: &[ExprId],
    build: impl FnOnce(&[TokenStream]) -> TokenStream,
) -> TokenStream {
    let Emitted { lets, outputs } = emit(c, inputs, outputs);
    let out = build(&outputs);
    quote! { #lets #out }
}

fn vector(o: &[TokenStream]) -> TokenStream {
    quote!(::precess::__private::Vector3::new(#(#o),*))
}

fn matrix(o: &[TokenStream]) -> TokenStream {
    quote!(::precess::__private::Matrix3::new(#(#o),*))
}

fn flat(t: &[[ExprId; 3]; 3]) -> Vec<ExprId> {
    t.iter().flatten().copied().collect()
}

fn expand(cx: &mut Ctxt, ident: &Ident, mut c: Checked) -> Option<TokenStream> {
    let p = quote!(::precess::__private);
    let fields = c
        .fields
        .iter()
        .filter_map(|f| {
            c.arena
                .find_parameter(&f.to_string())
                .map(|s| (s, f.clone()))
        })
        .collect();
    let mut sym = |name: &str| c.arena.input(name);
    let omega_e = [sym("omega_1"), sym("omega_2"), sym("omega_3")];
    let torque_e = [sym("G_1"), sym("G_2"), sym("G_3")];
    let inputs = Inputs {
        fields,
        omega: omega_e.map(|x| c.arena.as_symbol(x)),
        torque: torque_e.map(|x| c.arena.as_symbol(x)),
    };
    let props = c.body.props.clone();
    let mass = body(&mut c, &inputs, &[props.mass], |o| o[0].clone());
    let center = body(&mut c, &inputs, &props.center, vector);
    let reference = body(&mut c, &inputs, &props.reference, vector);
    let inertia = body(&mut c, &inputs, &flat(&props.inertia), matrix);
    let inertia_cm = body(&mut c, &inputs, &flat(&props.inertia_cm), matrix);
    let frame = c.body.frame.clone();
    let principal = match &frame {
        Frame::Diagonal(m) => body(&mut c, &inputs, m, |o| {
            let v = vector(o);
            quote!(#p::Principal::diagonal(#v))
        }),
        Frame::Constant(pr) => {
            let m: Vec<TokenStream> = pr.moments.iter().map(|&x| f64_literal(x)).collect();
            let r = pr.rotation.matrix();
            let rows: Vec<TokenStream> = (0..3)
                .flat_map(|i| (0..3).map(move |j| (i, j)))
                .map(|(i, j)| f64_literal(r[(i, j)]))
                .collect();
            let (m, r) = (vector(&m), matrix(&rows));
            quote!(#p::Principal { moments: #m, rotation: #p::Rotation3::from_matrix_unchecked(#r) })
        }
        Frame::DecomposedAtRunTime => quote!(#p::principal_frame(&#p::RigidBody::inertia(self))),
    };
    let rhs = match c.body.euler_rhs(&mut c.arena, omega_e, torque_e) {
        Ok(Some(rhs)) => body(&mut c, &inputs, &rhs, vector),
        Ok(None) => quote! {
            let principal = #p::RigidBody::principal(self);
            #p::euler_rhs_principal(&principal.moments, omega, torque)
        },
        Err(e) => {
            cx.error(ident, format!("cannot form Euler's equations: {e}"));
            return None;
        }
    };
    let d = description(&mut c, &inputs);
    let validate = if c.fields.is_empty() {
        // Literal bodies were checked while expanding.
        quote! {
            fn validate(&self) -> ::core::result::Result<(), #p::BodyError> {
                ::core::result::Result::Ok(())
            }
        }
    } else {
        // The trait's default checks the description built from the fields.
        TokenStream::new()
    };
    Some(quote! {
        #[automatically_derived]
        #[allow(clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::RigidBody for #ident {
            #[inline]
            fn mass(&self) -> f64 { #mass }
            #[inline]
            fn center_of_mass(&self) -> #p::Vector3<f64> { #center }
            #[inline]
            fn reference_point(&self) -> #p::Vector3<f64> { #reference }
            #[inline]
            fn inertia(&self) -> #p::Matrix3<f64> { #inertia }
            #[inline]
            fn inertia_cm(&self) -> #p::Matrix3<f64> { #inertia_cm }
            #[inline]
            fn principal(&self) -> #p::Principal { #principal }
            #[inline]
            fn euler_rhs(&self, omega: &#p::Vector3<f64>, torque: &#p::Vector3<f64>) -> #p::Vector3<f64> { #rhs }
            fn description(&self) -> #p::Description<f64> { #d }
            #validate
        }
    })
}

/// The description as a run-time value, each value an expression of the fields.
fn description(c: &mut Checked, inputs: &Inputs) -> TokenStream {
    let p = quote!(::precess::__private);
    let mut all = Vec::new();
    let indexed: Description<usize> = c.description.map(&mut |&e| {
        all.push(e);
        all.len() - 1
    });
    let Emitted { lets, outputs } = emit(c, inputs, &all);
    let d = indexed.map(&mut |&i| outputs[i].clone());
    let parts = d.parts.iter().map(|part| {
        let shape = shape(&part.shape);
        let at = &part.at;
        quote!(#p::Part { shape: #shape, at: [#(#at),*] })
    });
    let pivot = match &d.pivot {
        Some(v) => quote!(::core::option::Option::Some([#(#v),*])),
        None => quote!(::core::option::Option::None),
    };
    quote! {{
        #lets
        #p::Description { parts: #p::vec![#(#parts),*], pivot: #pivot }
    }}
}

fn axis(a: Axis) -> TokenStream {
    match a {
        Axis::X => quote!(::precess::__private::Axis::X),
        Axis::Y => quote!(::precess::__private::Axis::Y),
        Axis::Z => quote!(::precess::__private::Axis::Z),
    }
}

fn shape(s: &Shape<TokenStream>) -> TokenStream {
    let p = quote!(::precess::__private::Shape);
    match s {
        Shape::Particle { mass } => quote!(#p::Particle { mass: #mass }),
        Shape::Sphere { mass, radius } => quote!(#p::Sphere { mass: #mass, radius: #radius }),
        Shape::Shell { mass, radius } => quote!(#p::Shell { mass: #mass, radius: #radius }),
        Shape::Cuboid { mass, size } => quote!(#p::Cuboid { mass: #mass, size: [#(#size),*] }),
        Shape::Ellipsoid { mass, semi_axes } => {
            quote!(#p::Ellipsoid { mass: #mass, semi_axes: [#(#semi_axes),*] })
        }
        Shape::Cylinder {
            mass,
            radius,
            length,
            axis: a,
        } => {
            let a = axis(*a);
            quote!(#p::Cylinder { mass: #mass, radius: #radius, length: #length, axis: #a })
        }
        Shape::Tube {
            mass,
            inner,
            outer,
            length,
            axis: a,
        } => {
            let a = axis(*a);
            quote!(#p::Tube { mass: #mass, inner: #inner, outer: #outer, length: #length, axis: #a })
        }
        Shape::Disk {
            mass,
            radius,
            axis: a,
        } => {
            let a = axis(*a);
            quote!(#p::Disk { mass: #mass, radius: #radius, axis: #a })
        }
        Shape::Ring {
            mass,
            radius,
            axis: a,
        } => {
            let a = axis(*a);
            quote!(#p::Ring { mass: #mass, radius: #radius, axis: #a })
        }
        Shape::Rod {
            mass,
            length,
            axis: a,
        } => {
            let a = axis(*a);
            quote!(#p::Rod { mass: #mass, length: #length, axis: #a })
        }
        Shape::Cone {
            mass,
            radius,
            height,
            axis: a,
            reversed,
        } => {
            let a = axis(*a);
            quote!(#p::Cone { mass: #mass, radius: #radius, height: #height, axis: #a, reversed: #reversed })
        }
        Shape::Explicit {
            mass,
            inertia,
            about,
        } => {
            let rows = inertia.iter().map(|r| quote!([#(#r),*]));
            let about = match about {
                precess_core::body::About::Center => quote!(::precess::__private::About::Center),
                precess_core::body::About::Pivot => quote!(::precess::__private::About::Pivot),
            };
            quote!(#p::Explicit { mass: #mass, inertia: [#(#rows),*], about: #about })
        }
    }
}
