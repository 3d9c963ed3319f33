//! `impl MechanismPoses<N>`: each link's rotation, origin, centre and joint point at q, the
//! derivation's own kinematics lowered to straight-line code, and each link's declared parts
//! as a run-time description (what `precess::animate::mechanism` draws).

use precess_core::lagrange::Coordinates;
use precess_core::mechanism::{BodyKinematics, Parent};
use precess_core::sym::mat3::mat_vec;
use precess_core::sym::{Arena, ExprId};
use proc_macro2::TokenStream;
use quote::quote;
use syn::{Ident, LitStr};

use super::check::CheckedMechanism;
use super::expand::Method;
use crate::lang::ctxt::Ctxt;
use crate::lang::expansion::cannot_derive;
use crate::lang::private::Private;

/// The values lowered per link: R_b row by row (9), o_b (3), c_b (3), the joint point (3).
const PER_LINK: usize = 18;

/// The impl, or nothing after recording why the kinematics could not be formed.
pub(super) fn expand(
    cx: &Ctxt,
    ident: &Ident,
    arena: &mut Arena,
    method: &Method,
    checked: &CheckedMechanism,
    coordinates: &Coordinates,
) -> TokenStream {
    let scene = &checked.scene;
    let kinematics = scene
        .validate(arena)
        .and_then(|order| scene.kinematics(arena, &order, coordinates));
    let kinematics = match kinematics {
        Ok(k) => k,
        Err(e) => {
            cannot_derive(cx, ident, "the mechanism's link poses", &e);
            return TokenStream::new();
        }
    };
    let mut outputs = Vec::with_capacity(PER_LINK * kinematics.len());
    for (body, kin) in scene.bodies.iter().zip(&kinematics) {
        outputs.extend(kin.rotation.iter().flatten());
        outputs.extend(kin.origin);
        outputs.extend(kin.center);
        outputs.extend(joint_point(
            arena,
            &body.joint.parent,
            &body.joint.at,
            &kinematics,
        ));
    }
    let names: Vec<LitStr> = scene
        .bodies
        .iter()
        .map(|b| LitStr::new(&b.name, ident.span()))
        .collect();
    let p = Private;
    let n = coordinates.q.len();
    let poses = method.body(arena, &outputs, |o| {
        let links = o.chunks(PER_LINK).zip(&names).map(|(v, name)| {
            let (r, rest) = v.split_at(9);
            let (origin, rest) = rest.split_at(3);
            let (center, joint) = rest.split_at(3);
            quote! {
                #p::LinkPose {
                    name: #name,
                    rotation: #p::Matrix3::new(#(#r),*),
                    origin: #p::Vector3::new(#(#origin),*),
                    center: #p::Vector3::new(#(#center),*),
                    joint: #p::Vector3::new(#(#joint),*),
                }
            }
        });
        quote!(#p::vec![#(#links),*])
    });
    let parts = checked
        .parts
        .iter()
        .map(|d| crate::rigid::expand::description(method.low, arena, d));
    quote! {
        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery, unused_parens)]
        impl #p::MechanismPoses<#n> for #ident {
            fn link_poses(&self, q: &[f64; #n]) -> #p::vec::Vec<#p::LinkPose> {
                // `Method::body` reads q, q̇ and t by these names; poses depend on q alone.
                let t = 0.0_f64;
                let qdot = q;
                #poses
            }

            fn link_parts(&self) -> #p::vec::Vec<#p::Description<f64>> {
                #p::vec![#(#parts),*]
            }
        }
    }
}

/// o_p + R_p a: where the joint at `a` (parent axes) is, ground axes.
fn joint_point(
    arena: &mut Arena,
    parent: &Parent,
    at: &[ExprId; 3],
    kinematics: &[BodyKinematics],
) -> [ExprId; 3] {
    match parent {
        Parent::Ground => *at,
        Parent::Body(p) => match kinematics.get(*p) {
            Some(k) => {
                let turned = mat_vec(arena, &k.rotation, at);
                [0, 1, 2].map(|i| arena.add(k.origin[i], turned[i]))
            }
            None => *at,
        },
    }
}
