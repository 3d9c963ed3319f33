precess::taylor_system! {
    struct Syntax;
    state [x];
    taylor = 20;
    d/dx x = x;
}

fn main() {}
