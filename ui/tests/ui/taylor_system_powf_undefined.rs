// A real power of a negative constant has no real value, and zero to a negative power is
// a division by zero: both are refused on the power's tokens, not left to give NaN.
precess::taylor_system! {
    struct Undefined;
    state [x, y];
    taylor = 20;
    d/dt x = (-2.0).powf(1.5) * x;
    d/dt y = 0.0.powf(-0.5) + y;
}

fn main() {}
