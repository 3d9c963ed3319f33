//! The body language's values as the Rust that builds them at run time (`Shape`,
//! `Orientation`, `Axis`, `About` through the hidden path), their numbers already lowered:
//! the description `RigidBody::description` returns, and the parts a mechanism's generated
//! `check_parameters` judges.

use precess_core::body::{About, Axis, Orientation, Shape};
use proc_macro2::TokenStream;
use quote::quote;

use super::private::Private;

/// An axis as the Rust value generated code builds.
fn axis(a: Axis) -> TokenStream {
    match a {
        Axis::X => quote!(#Private::Axis::X),
        Axis::Y => quote!(#Private::Axis::Y),
        Axis::Z => quote!(#Private::Axis::Z),
    }
}

/// A rotation of the body language as the Rust value generated code builds.
pub fn orientation(o: &Orientation<TokenStream>) -> TokenStream {
    let p = quote!(#Private::Orientation);
    match o {
        Orientation::AxisAngle { axis, angle } => {
            quote!(#p::AxisAngle { axis: [#(#axis),*], angle: #angle })
        }
        Orientation::Matrix(rows) => {
            let rows = rows.iter().map(|r| quote!([#(#r),*]));
            quote!(#p::Matrix([#(#rows),*]))
        }
        Orientation::Sequence(turns) => {
            let turns = turns.iter().map(|(a, angle)| {
                let a = axis(*a);
                quote!((#a, #angle))
            });
            quote!(#p::Sequence(#Private::vec![#(#turns),*]))
        }
    }
}

/// A shape of the body language as the Rust value generated code builds.
pub fn shape(s: &Shape<TokenStream>) -> TokenStream {
    let p = quote!(#Private::Shape);
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
                About::Center => quote!(#Private::About::Center),
                About::Pivot => quote!(#Private::About::Pivot),
            };
            quote!(#p::Explicit { mass: #mass, inertia: [#(#rows),*], about: #about })
        }
    }
}
