use precess::prelude::*;

mod units {
    #[allow(non_camel_case_types)]
    pub type f64 = f32;
}

// The primitive's paths are f64; a user's type that happens to be called `f64` is not.
#[derive(RigidBody)]
#[rigid(sphere(mass = m, radius = r, at = [a, b, c]))]
struct Body {
    m: core::primitive::f64,
    r: ::core::primitive::f64,
    a: std::primitive::f64,
    b: ::std::primitive::f64,
    c: units::f64,
}

fn main() {}
