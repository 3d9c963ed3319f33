use precess::prelude::*;

#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
struct Nothing {
    m: f64,
}

fn main() {}
