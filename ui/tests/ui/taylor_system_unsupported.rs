precess::taylor_system! {
    struct Growth;
    state [x, y];
    taylor = 20;
    d/dt x = x.ln();
    d/dt y = y.powi(1.5) + x % y + tan(y);
}

fn main() {}
