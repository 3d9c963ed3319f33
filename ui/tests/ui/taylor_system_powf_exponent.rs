// `powf` takes its exponent as a number literal (converted exactly to a rational): an
// exponent that is a field, or a call, is refused on the exponent's tokens.
precess::taylor_system! {
    struct Power {
        r: f64,
    }
    state [x, y];
    taylor = 20;
    d/dt x = x.powf(r);
    d/dt y = powf(y, 1.5.sqrt());
}

fn main() {}
