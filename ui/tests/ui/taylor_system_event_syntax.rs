// A misspelt statement lists the event among what is expected; an event's function is a
// right-hand side like any other, so an unknown name in it is refused as there.
precess::taylor_system! {
    struct Misspelt;
    state [x];
    taylor = 20;
    d/dt x = -x;
    evnt Crossing = x;
}

precess::taylor_system! {
    struct Unknown;
    state [x];
    taylor = 20;
    d/dt x = -x;
    event Crossing = y - 1.0;
}

fn main() {}
