// `t` in a right-hand side is the time: a field of that name would shadow it.
precess::taylor_system! {
    struct Forced {
        k: f64,
        t: f64,
    }
    state [x];
    taylor = 20;
    d/dt x = -k * x + t.sin();
}

fn main() {}
