//! `check_parameters` of the mechanism derive: the values the struct's fields give the
//! mechanism meet, at run time, the rules literals meet at compile time, by the same
//! functions — each part the body language's rules (`check_part`, a zero mass aside: a
//! massless part is allowed, literal or field), axes `check_axis` and a universal joint's `check_universal_axes` (a
//! direction each, not parallel), every other value finite, springs and dampers not
//! negative. Only what reads a field is checked: literals were checked while expanding.

use precess_core::body::{Description, Part, evaluate};
use precess_core::codegen::Emitted;
use precess_core::mechanism::loops::LoopSide;
use precess_core::mechanism::rolling::WheelSurface;
use precess_core::mechanism::{JointKind, MechanismScene};
use precess_core::sym::{Arena, ExprId};
use proc_macro2::{Span, TokenStream};
use quote::quote;
use syn::Ident;

use super::check::CheckedMechanism;
use crate::lang::private::Private;
use crate::lang::symbols::Lowering;
use crate::lang::tokens::{orientation, shape};

/// `fn check_parameters(&self)`, or nothing when no checked value reads a field.
pub fn method(low: &Lowering, arena: &mut Arena, checked: &CheckedMechanism) -> TokenStream {
    method_with_loops(low, arena, checked, &[])
}

/// As [`method`], with the closure rule on each planar loop's sides (closure, sides) that
/// read a field.
pub fn method_with_loops(
    low: &Lowering,
    arena: &mut Arena,
    checked: &CheckedMechanism,
    loops: &[(String, Vec<LoopSide>)],
) -> TokenStream {
    let p = Private;
    let user = |e: ExprId| checked.efforts.iter().any(|u| u.symbol == e);
    let mut checks = Checks::default();
    let scene: &MechanismScene = &checked.scene;
    if let Some(g) = &scene.gravity {
        for (k, &e) in g.iter().enumerate() {
            checks.finite(arena, "the mechanism", format!("gravity[{k}]"), e);
        }
    }
    for (body, parts) in scene.bodies.iter().zip(&checked.parts) {
        let joint = &body.joint;
        let owner = format!("joint `{}`", joint.name);
        for (k, &e) in joint.at.iter().enumerate() {
            checks.finite(arena, &owner, format!("at[{k}]"), e);
        }
        match &joint.kind {
            JointKind::Revolute { axis } | JointKind::Prismatic { axis } => {
                checks.axes(arena, &joint.name, std::slice::from_ref(axis));
            }
            JointKind::Universal { axes } => checks.axes(arena, &joint.name, axes),
            JointKind::Spherical { .. } | JointKind::Free { .. } => {}
        }
        for (coordinate, load) in joint.coordinates.iter().zip(&joint.loads) {
            if let Some(spring) = &load.spring {
                let of = |what: &str| format!("{what} of `{coordinate}`");
                checks.non_negative(arena, &owner, of("spring stiffness"), spring.stiffness);
                checks.finite(arena, &owner, of("spring rest"), spring.rest);
            }
            if let Some(c) = load.damper {
                checks.non_negative(arena, &owner, format!("damper of `{coordinate}`"), c);
            }
            if let Some(e) = load.effort.filter(|&e| !user(e)) {
                checks.finite(arena, &owner, format!("effort on `{coordinate}`"), e);
            }
        }
        let owner = format!("body `{}`", body.name);
        for (name, torque) in [
            ("body_torque", &body.body_torque),
            ("space_torque", &body.space_torque),
        ] {
            for (k, &e) in torque.iter().flatten().enumerate() {
                checks.finite(arena, &owner, format!("{name}[{k}]"), e);
            }
        }
        for (index, part) in parts.parts.iter().enumerate() {
            checks.part(arena, &body.name, index, part);
        }
    }
    if let Some(rolling) = &checked.rolling {
        for (wheel, body) in rolling.scene.wheels.iter().zip(&rolling.bodies) {
            checks.wheel(arena, body, &wheel.surface);
        }
    }
    for (closure, sides) in loops {
        checks.loop_sides(arena, closure, sides);
    }
    if checks.values.is_empty() {
        return TokenStream::new();
    }
    let Emitted { lets, outputs } = low.lower(arena, &checks.values);
    let tests = checks.tests.iter().map(|test| test(&outputs));
    quote! {
        fn check_parameters(&self) -> ::core::result::Result<(), #p::MechanismError> {
            #lets
            #(#tests)*
            ::core::result::Result::Ok(())
        }
    }
}

/// A test over the lowered values (by their index in `Checks::values`).
type Test = Box<dyn Fn(&[TokenStream]) -> TokenStream>;

/// The values to compute and the tests on them.
#[derive(Default)]
struct Checks {
    values: Vec<ExprId>,
    tests: Vec<Test>,
}

/// A rule a value that reads a field is held to at run time.
#[derive(Clone, Copy)]
enum Rule {
    /// Neither NaN nor ±∞.
    Finite,
    /// Zero or more.
    NonNegative,
    /// More than zero.
    Positive,
}

impl Rule {
    /// The test on `__v` that breaks the rule, and the `MechanismError` variant it returns.
    fn refusal(self) -> (TokenStream, Ident) {
        let (test, variant) = match self {
            Rule::Finite => (quote!(!__v.is_finite()), "NonFiniteParameter"),
            Rule::NonNegative => (quote!(__v < 0.0), "NegativeParameter"),
            // Not `__v <= 0.0`: NaN is no positive value either.
            Rule::Positive => (quote!(!(__v > 0.0)), "NonPositiveParameter"),
        };
        (test, Ident::new(variant, Span::call_site()))
    }
}

/// Whether `e` reads a field (a literal was checked while expanding).
fn reads_field(arena: &Arena, e: ExprId) -> bool {
    !arena.free_symbols(e).is_empty()
}

impl Checks {
    /// Adds a value; its index among the outputs.
    fn value(&mut self, e: ExprId) -> usize {
        self.values.push(e);
        self.values.len() - 1
    }

    /// A value that must be finite.
    fn finite(&mut self, arena: &Arena, owner: &str, quantity: String, e: ExprId) {
        self.held(arena, owner, quantity, e, &[Rule::Finite]);
    }

    /// A value that must be finite and not negative (a spring's stiffness, a damper).
    fn non_negative(&mut self, arena: &Arena, owner: &str, quantity: String, e: ExprId) {
        self.held(
            arena,
            owner,
            quantity,
            e,
            &[Rule::Finite, Rule::NonNegative],
        );
    }

    /// A value that must be positive (a rolling radius, an axle's squared length).
    fn positive(&mut self, arena: &Arena, owner: &str, quantity: String, e: ExprId) {
        self.held(arena, owner, quantity, e, &[Rule::Finite, Rule::Positive]);
    }

    /// The tests that `e`, when it reads a field, keeps each of `rules`, in order.
    fn held(&mut self, arena: &Arena, owner: &str, quantity: String, e: ExprId, rules: &[Rule]) {
        if !reads_field(arena, e) {
            return;
        }
        let i = self.value(e);
        for &rule in rules {
            let (owner, quantity) = (owner.to_owned(), quantity.clone());
            self.tests.push(Box::new(move |o| {
                let (p, v) = (Private, o.get(i).cloned().unwrap_or_default());
                let (refused, variant) = rule.refusal();
                quote! {{
                    let __v: f64 = #v;
                    if #refused {
                        return ::core::result::Result::Err(#p::MechanismError::#variant {
                            owner: ::std::string::String::from(#owner),
                            quantity: ::std::string::String::from(#quantity),
                            value: __v,
                        });
                    }
                }}
            }));
        }
    }

    /// A planar loop's sides, when one reads a field: their lengths √(side²) through
    /// `check_loop_sides`, the rule literal sides met while expanding.
    fn loop_sides(&mut self, arena: &Arena, closure: &str, sides: &[LoopSide]) {
        if !sides.iter().any(|s| reads_field(arena, s.squared)) {
            return;
        }
        let indices: Vec<usize> = sides.iter().map(|s| self.value(s.squared)).collect();
        let names: Vec<String> = sides.iter().map(|s| s.body.clone()).collect();
        let closure = closure.to_owned();
        self.tests.push(Box::new(move |o| {
            let p = Private;
            let values = indices
                .iter()
                .map(|&i| o.get(i).cloned().unwrap_or_default());
            quote! {
                #p::check_loop_sides(#closure, &[#((#names, f64::max(#values, 0.0).sqrt())),*])?;
            }
        }));
    }

    /// A rolling body's surface: its hub or centre finite, its radius positive, a disk's
    /// axle finite with a positive squared length (literals were checked while expanding).
    fn wheel(&mut self, arena: &mut Arena, body: &str, surface: &WheelSurface) {
        let owner = format!("body `{body}`");
        let (center, radius, axle) = match *surface {
            WheelSurface::Disk {
                center,
                axle,
                radius,
            } => (center, radius, Some(axle)),
            WheelSurface::Sphere { center, radius } => (center, radius, None),
        };
        for (k, &e) in center.iter().enumerate() {
            self.finite(arena, &owner, format!("rolling at[{k}]"), e);
        }
        self.positive(arena, &owner, "rolling radius".to_owned(), radius);
        if let Some(axle) = axle {
            for (k, &e) in axle.iter().enumerate() {
                self.finite(arena, &owner, format!("axle[{k}]"), e);
            }
            let squares: Vec<ExprId> = axle.iter().map(|&c| arena.mul(c, c)).collect();
            let squared = arena.sum(&squares);
            self.positive(arena, &owner, "|axle|²".to_owned(), squared);
        }
    }

    /// A joint's axes (one, or a universal joint's two) to `check_axis` or
    /// `check_universal_axes`, the functions the derive applied to literal axes, when any
    /// component reads a field.
    fn axes(&mut self, arena: &Arena, joint: &str, axes: &[[ExprId; 3]]) {
        if !axes.iter().flatten().any(|&e| reads_field(arena, e)) {
            return;
        }
        let first = self.values.len();
        for &e in axes.iter().flatten() {
            self.value(e);
        }
        let count = axes.len();
        let joint = joint.to_owned();
        self.tests.push(Box::new(move |o| {
            let p = Private;
            let vector = |a: usize| {
                let c = (0..3).map(|k| o.get(first + 3 * a + k).cloned().unwrap_or_default());
                quote!([#(#c),*])
            };
            let call = if count == 2 {
                let (outer, inner) = (vector(0), vector(1));
                quote!(#p::check_universal_axes(#joint, #outer, #inner))
            } else {
                let axis = vector(0);
                quote!(#p::check_axis(#joint, "axis", #axis))
            };
            quote!(#call?;)
        }));
    }

    /// A part that reads a field, built from the fields and put to `check_part` (its mass
    /// put to 1 when it is zero, so a massless link's geometry is still checked).
    fn part(&mut self, arena: &Arena, body: &str, index: usize, part: &Part<ExprId>) {
        let single = Description {
            parts: vec![part.clone()],
            pivot: None,
        };
        if evaluate(arena, &single).is_some() {
            return;
        }
        let indexed: Description<usize> = single.map(&mut |&e| {
            self.values.push(e);
            self.values.len() - 1
        });
        let Some(indexed) = indexed.parts.into_iter().next() else {
            return;
        };
        let body = body.to_owned();
        self.tests.push(Box::new(move |o| {
            let p = Private;
            let mass_index = *indexed.shape.mass();
            let mass = o.get(mass_index).cloned().unwrap_or_default();
            let token = |&i: &usize| {
                if i == mass_index {
                    quote!(__checked_mass)
                } else {
                    o.get(i).cloned().unwrap_or_default()
                }
            };
            let shape = shape(&indexed.shape.map(&mut |i| token(i)));
            let at: Vec<TokenStream> = indexed.at.iter().map(token).collect();
            let orientation = match &indexed.orientation {
                Some(or) => {
                    let or = orientation(&or.map(&mut |i| token(i)));
                    quote!(::core::option::Option::Some(#or))
                }
                None => quote!(::core::option::Option::None),
            };
            quote! {{
                let __mass: f64 = #mass;
                let __checked_mass = if __mass == 0.0 { 1.0 } else { __mass };
                let __part = #p::Part { shape: #shape, at: [#(#at),*], orientation: #orientation };
                if let ::core::result::Result::Err(error) = #p::check_part(#index, &__part) {
                    return ::core::result::Result::Err(#p::MechanismError::Part {
                        body: ::std::string::String::from(#body),
                        error,
                    });
                }
            }}
        }));
    }
}
