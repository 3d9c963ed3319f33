//! The Whipple bicycle against Meijaard, Papadopoulos, Ruina & Schwab (2007).

use precess_testkit::bicycle::{Linear, Parameters, Whipple};

#[test]
fn probe() {
    let bike = Whipple::new(&Parameters::benchmark()).expect("derives");
    println!("ops {:?}", bike.op_counts);
    let lin = bike.linearise().expect("linearises");
    let p = Linear::published();
    println!("M {:.14} vs {:.14}", lin.m, p.m);
    println!("C1 {:.14} vs {:.14}", lin.c1, p.c1);
    println!("K0 {:.14} vs {:.14}", lin.k0, p.k0);
    println!("K2 {:.14} vs {:.14}", lin.k2, p.k2);
    println!(
        "weave {:?} capsize {:?}",
        lin.weave_speed(4.0, 5.0),
        lin.capsize_speed(5.5, 7.0)
    );
    println!(
        "pub weave {:?} capsize {:?}",
        p.weave_speed(4.0, 5.0),
        p.capsize_speed(5.5, 7.0)
    );
}
