precess::taylor_system! {
    struct Growth;
    state [x, y];
    taylor = 20;
    d/dt x = x.exp();
    d/dt y = y.powi(1.5) + x % y + tan(y);
}

precess::taylor_system! {
    struct Forced;
    state [x];
    taylor = 20;
    d/dt x = -x + t.sin();
}

fn main() {}
