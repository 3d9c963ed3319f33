precess::taylor_system! {
    struct Oscillator {
        omega: f64,
    }
    state [x, v];
    taylor = 20;
    d/dt x = v;
    d/dt v = -omgea * omega * x;
}

fn main() {}
