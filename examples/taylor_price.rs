//! The size of the Taylor recurrences `taylor = K` generates: for a general top (a full
//! inertia tensor, the centre of mass off the axis, in the Lagrangian state [q, q̇]), a
//! free body (13 components) and a 10-link 3D chain (`chains::spatial_chain`, the recursive
//! route, state [q, q̇] of 20 components), the steps of the tape by kind, the flops of one
//! coefficient evaluation at order 20, and the size of the emitted Rust (tokens and
//! characters).
//!
//! Run with `cargo run --example taylor_price`.

use precess::free::FreeScene;
use precess::mechanism::Route;
use precess::mechanism::recursive::chains::spatial_chain;
use precess::rigid::AngleSequence;
use precess::sym::{Arena, ExprId};
use precess::taylor::Tape;
use precess::top::TopScene;

const ORDER: usize = 20;

fn report(name: &str, tape: &Tape, accel_program_ops: usize) {
    let count = tape.op_count();
    let code = tape.emitted(ORDER);
    println!("{name}:");
    println!("  rhs program: {accel_program_ops} instructions");
    println!("  tape: {} series, {count:?}", tape.series_count());
    println!("  flops at order {ORDER}: {}", count.flops(ORDER));
    println!(
        "  emitted: {} tokens, {} characters",
        code.token_count(),
        code.body.to_string().len()
    );
}

fn main() {
    let mut a = Arena::new();
    let num = |a: &mut Arena, x: f64| a.float(x).unwrap();
    let i = [[0.9, 0.05, -0.02], [0.05, 0.7, 0.03], [-0.02, 0.03, 0.4]];
    let inertia = i.map(|row| row.map(|x| num(&mut a, x)));
    let center = [0.04, -0.03, 0.25].map(|x| num(&mut a, x));
    let scene = TopScene {
        sequence: AngleSequence::Zxz,
        inertia,
        mass: num(&mut a, 1.3),
        center,
        gravity: Some(num(&mut a, 9.81)),
        body_torque: None,
        space_torque: None,
        damping: None,
        user_torque: None,
        rotors: Vec::new(),
    };
    let d = scene.derive(&mut a).unwrap();
    let co = d.coords();
    let state: Vec<ExprId> = co.q.iter().chain(&co.rates).copied().collect();
    let rhs: Vec<ExprId> = co
        .rates
        .iter()
        .chain(&d.accelerations.accel)
        .copied()
        .collect();
    let ops = precess::codegen::Program::lower(&a, &rhs).ops().len();
    report(
        "general top",
        &Tape::new(&a, &state, None, &rhs).unwrap(),
        ops,
    );

    let mut a = Arena::new();
    let mass = num(&mut a, 1.0);
    let moments = [3.0, 5.0, 7.0].map(|x| num(&mut a, x));
    let mut scene = FreeScene::new(&mut a, mass, moments);
    let (z, g) = (a.zero(), num(&mut a, -9.81));
    scene.gravity = Some([z, z, g]);
    let d = scene.derive(&mut a).unwrap();
    let ops = precess::codegen::Program::lower(&a, &d.rhs).ops().len();
    report(
        "free body",
        &Tape::new(&a, &d.state, None, &d.rhs).unwrap(),
        ops,
    );

    let mut a = Arena::new();
    let d = spatial_chain(&mut a, 10)
        .derive(&mut a, Route::Auto)
        .unwrap();
    let (state, rhs) = d.first_order::<20>().unwrap();
    let ops = precess::codegen::Program::lower(&a, &rhs).ops().len();
    report(
        &format!("10-link 3D chain ({} route)", d.route.name()),
        &Tape::new(&a, &state, None, &rhs).unwrap(),
        ops,
    );
}
