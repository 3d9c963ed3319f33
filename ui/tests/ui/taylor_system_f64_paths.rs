mod units {
    #[allow(non_camel_case_types)]
    pub type f64 = f32;
}

// The primitive's paths are f64, as for `#[rigid]`'s fields; a user's type that happens to
// be called `f64` is not.
precess::taylor_system! {
    struct Paths {
        a: core::primitive::f64,
        b: ::core::primitive::f64,
        c: std::primitive::f64,
        d: ::std::primitive::f64,
        e: units::f64,
    }
    state [x];
    taylor = 20;
    d/dt x = -(a + b + c + d + e) * x;
}

fn main() {}
