// Two events of one name, and one named as the system's struct: each would be a second
// item of that name. The types are still declared, so their uses raise nothing more.
precess::taylor_system! {
    struct Names;
    state [x, v];
    taylor = 20;
    d/dt x = v;
    d/dt v = -x;
    event Crossing = x;
    event Crossing = v;
    event Names = x - v;
}

fn main() {
    let system = Names;
    let _crossing = Crossing(&system);
}
