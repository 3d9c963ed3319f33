precess::taylor_system! {
    struct Tuple(f64);
    state [x];
    taylor = 20;
    d/dt x = x;
}

precess::taylor_system! {
    struct Typed {
        k: f32,
    }
    state [k, t, x, x];
    taylor = 101;
    d/dt x = k;
}

fn main() {}
