//! A mechanism closed by `closes` exports the pieces of its equations (M, f, φ, A, Ȧq̇,
//! T + V) over (t, q, q̇), each the bits of its `LoopDynamics` method; a user effort is an
//! input u.

use super::derived::{cases, compare};
use precess::codegen::Export;
use precess::mechanism::loops::LoopDynamics;
use precess::models::SliderCrank;
use precess::prelude::*;

/// A four-bar of field masses whose crank is driven by a user effort of a field.
#[derive(Mechanism)]
#[mechanism(gravity = [0.0, -9.81, 0.0])]
#[body(crank, joint = revolute(axis = z), q = theta1, effort = Bar::drive,
       parts(rod(mass = m1, length = 1.0, axis = x, at = [0.5, 0.0, 0.0])))]
#[body(coupler, parent = crank, joint = revolute(axis = z, at = [1.0, 0.0, 0.0]), q = theta2,
       parts(rod(mass = m2, length = 3.0, axis = x, at = [1.5, 0.0, 0.0])),
       closes = rocker(at = [3.0, 0.0, 0.0], to = [2.5, 0.0, 0.0]))]
#[body(rocker, joint = revolute(axis = z, at = [3.0, 0.0, 0.0]), q = theta3,
       parts(rod(mass = m3, length = 2.5, axis = x, at = [1.25, 0.0, 0.0])))]
struct Bar {
    m1: f64,
    m2: f64,
    m3: f64,
    tau: f64,
}

impl Bar {
    fn drive(&self, _t: f64, _q: &[f64; 3], _qd: &[f64; 3]) -> f64 {
        self.tau
    }
}

/// Per function of a closed mechanism's export, its `LoopDynamics` method's outputs at each
/// case (a matrix row by row).
fn pieces<T: LoopDynamics<3, 2, 1>>(
    cases: &[super::support::Case],
    model: impl Fn(&super::support::Case) -> T,
) -> Vec<(&'static str, Vec<Vec<f64>>)> {
    let names = [
        "mass",
        "forcing",
        "closure",
        "constraints",
        "rate_terms",
        "energy",
    ];
    let mut want: Vec<(&str, Vec<Vec<f64>>)> = names.iter().map(|&n| (n, vec![])).collect();
    for c in cases {
        let w = model(c);
        let q = [c.y[0], c.y[1], c.y[2]];
        let qd = [c.y[3], c.y[4], c.y[5]];
        let (mm, f) = w.mass_forcing(c.t, &q, &qd);
        let (phi, a) = w.closure(&q);
        // nalgebra is column-major; the export writes a matrix row by row.
        let values = [
            mm.transpose().as_slice().to_vec(),
            f.as_slice().to_vec(),
            phi.to_vec(),
            a.transpose().as_slice().to_vec(),
            w.rate_terms(&q, &qd).as_slice().to_vec(),
            vec![w.energy(&q, &qd)],
        ];
        for ((_, v), x) in want.iter_mut().zip(values) {
            v.push(x);
        }
    }
    want
}

#[test]
fn a_closed_mechanism_exports_the_pieces_of_its_equations_bit_for_bit() {
    let e = Bar::exported().expect("exported");
    assert_eq!(
        e.state(),
        [
            "theta1",
            "theta2",
            "theta3",
            "theta1_dot",
            "theta2_dot",
            "theta3_dot"
        ]
    );
    assert_eq!(e.inputs(), ["effort_0"]);
    let cases = cases(&e, 1000, 15, |_, _| {});
    let want = pieces(&cases, |c| Bar {
        m1: c.param(&e, "m1"),
        m2: c.param(&e, "m2"),
        m3: c.param(&e, "m3"),
        tau: c.u[0],
    });
    compare("four_bar", &e, &cases, &want, 0);
}

#[test]
fn the_slider_crank_exports_its_pieces_bit_for_bit() {
    let e = SliderCrank::exported().expect("exported");
    assert!(e.parameters().is_empty() && e.inputs().is_empty());
    let cases = cases(&e, 1000, 16, |_, _| {});
    let want = pieces(&cases, |_| SliderCrank);
    compare("slider_crank", &e, &cases, &want, 0);
}
