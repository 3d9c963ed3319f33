// Forms a right-hand side cannot take, each refused on its own tokens: a path that is not a
// plain name, a call through a path, an expression of another kind; and a state declared
// twice, and the order given twice.
precess::taylor_system! {
    struct Forms;
    state [x, y];
    taylor = 20;
    d/dt x = std::f64::consts::PI * x;
    d/dt y = f64::sin(y) + if x > 0.0 { x } else { y };
}

precess::taylor_system! {
    struct Twice;
    state [x];
    state [y];
    taylor = 20;
    d/dt x = -x;
}

precess::taylor_system! {
    struct Orders;
    state [x];
    taylor = 20;
    taylor = 30;
    d/dt x = -x;
}

fn main() {}
