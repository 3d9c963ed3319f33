precess::taylor_system! {
    struct Missing;
    state [x, y, z];
    taylor = 20;
    d/dt x = y;
    d/dt y = x;
    d/dt y = z;
    d/dt w = x;
}

precess::taylor_system! {
    struct NoState;
    taylor = 20;
}

precess::taylor_system! {
    struct NoOrder;
    state [x];
    d/dt x = x;
}

fn main() {}
