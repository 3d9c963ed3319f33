//! A rolling mechanism exports the pieces of Maggi's equations (M, f, A, Ȧq̇, the heights,
//! T + V) over (t, q, q̇), each the bits of its `RollingDynamics` method; the projection
//! docs/export.md writes for the caller, run over them, gives `derivative`.

use super::derived::{cases, compare};
use super::support::Case;
use nalgebra::{DMatrix, DVector};
use precess::codegen::Export;
use precess::mechanism::rolling::RollingDynamics;
use precess::models::Bicycle;
use precess::prelude::*;

/// A disk of fields rolling on its rim: slides along x, y and z carry the hub, a spherical
/// joint turns the disk (n = 6 coordinates, 3 rows: no slip along x and y, the height; 3
/// free speeds).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81, up = z, speeds = [yaw, pitch, roll])]
#[body(slide_x, parent = ground, joint = prismatic(axis = x), q = x, parts(particle(mass = 0.0)))]
#[body(slide_y, parent = slide_x, joint = prismatic(axis = y), q = y, parts(particle(mass = 0.0)))]
#[body(slide_z, parent = slide_y, joint = prismatic(axis = z), q = z, parts(particle(mass = 0.0)))]
#[body(disk, parent = slide_z, joint = spherical(sequence = zyx), q = [yaw, pitch, roll],
       parts(disk(mass = m, radius = r)), rolls = disk_rim(radius = r, axle = z))]
struct RollingCoin {
    m: f64,
    r: f64,
}

#[test]
fn a_rolling_mechanism_exports_the_pieces_of_maggis_equations_bit_for_bit() {
    let e = RollingCoin::exported().expect("exported");
    // `y` is the emitted code's state array: the coordinate gets a trailing `_`.
    assert_eq!(e.state()[..6], ["x", "y_", "z", "yaw", "pitch", "roll"]);
    let dots = ["x", "y", "z", "yaw", "pitch", "roll"].map(|q| format!("{q}_dot"));
    assert_eq!(e.state()[6..], dots);
    let fns: Vec<&str> = e.functions().iter().map(|f| f.name()).collect();
    assert_eq!(
        fns,
        [
            "mass",
            "forcing",
            "constraints",
            "rate_terms",
            "heights",
            "energy"
        ]
    );
    // Leans up to a radian, so the disk stands (the projection below needs it).
    let cases = cases(&e, 1000, 8, |rng, c| {
        c.y[4] = rng.uniform(-1.0, 1.0);
        c.y[5] = rng.uniform(-1.0, 1.0);
    });
    let coin = |c: &Case| RollingCoin {
        m: c.param(&e, "m"),
        r: c.param(&e, "r"),
    };
    let split = |c: &Case| -> ([f64; 6], [f64; 6]) {
        (
            c.y[..6].try_into().expect("q"),
            c.y[6..].try_into().expect("q̇"),
        )
    };
    let want = pieces(&cases, |c| (coin(c), split(c)));
    // Maggi's projection as docs/export.md writes it, over the exported pieces, against the
    // Rust rolling rhs (`derivative`), from (q, u): u the free speeds (yaw, pitch, roll).
    let mut worst_projection = 0.0_f64;
    for c in cases.iter().take(200) {
        let w = coin(c);
        let (q, _) = split(c);
        let u = [c.y[9], c.y[10], c.y[11]];
        let (ind, dep) = ([3, 4, 5], [0, 1, 2]);
        let ev = |name: &str, qd: &[f64]| {
            let y: Vec<f64> = q.iter().chain(qd).copied().collect();
            e.eval(name, c.t, &y, &c.p).expect("eval")
        };
        let a = DMatrix::from_row_slice(3, 6, &ev("constraints", &[0.0; 6]));
        let block = |cols: [usize; 3]| DMatrix::from_fn(3, 3, |i, j| a[(i, cols[j])]);
        let a_d = block(dep).lu();
        // S: q̇ = S u, S_I = 1, S_D = −A_D⁻¹ A_I.
        let s_d = -a_d.solve(&block(ind)).expect("A_D regular");
        let mut s = DMatrix::zeros(6, 3);
        for j in 0..3 {
            s[(ind[j], j)] = 1.0;
            for i in 0..3 {
                s[(dep[i], j)] = s_d[(i, j)];
            }
        }
        let qd = &s * DVector::from_column_slice(&u);
        let mm = DMatrix::from_row_slice(6, 6, &ev("mass", qd.as_slice()));
        let f = DVector::from_vec(ev("forcing", qd.as_slice()));
        let b = DVector::from_vec(ev("rate_terms", qd.as_slice()));
        // s₀: the accelerations at u̇ = 0, s₀_I = 0, s₀_D = −A_D⁻¹ Ȧq̇.
        let s0_d = -a_d.solve(&b).expect("A_D regular");
        let mut s0 = DVector::zeros(6);
        for i in 0..3 {
            s0[dep[i]] = s0_d[i];
        }
        let k = s.transpose() * &mm * &s;
        let rhs = s.transpose() * (f - &mm * s0);
        let ud = k.lu().solve(&rhs).expect("K regular");
        let (want_qd, want_ud) = w.derivative(c.t, &q, &u).expect("the coin stands");
        for (got, want) in qd
            .iter()
            .chain(ud.iter())
            .zip(want_qd.iter().chain(&want_ud))
        {
            let d = (got - want).abs() / (1.0 + want.abs());
            assert!(d <= 1e-12, "{got} vs {want}");
            worst_projection = worst_projection.max(d);
        }
    }
    println!(
        "rolling: the projection over the exported pieces against derivative: {worst_projection:e}"
    );
    compare("rolling", &e, &cases, &want, 0);
}

/// Per function of a rolling mechanism's export, the outputs of its `RollingDynamics` method
/// at each case (a matrix row by row): the model and (q, q̇) of a case by `at`.
fn pieces<T: RollingDynamics<N, M, K>, const N: usize, const M: usize, const K: usize>(
    cases: &[Case],
    at: impl Fn(&Case) -> (T, ([f64; N], [f64; N])),
) -> Vec<(&'static str, Vec<Vec<f64>>)> {
    let names = [
        "mass",
        "forcing",
        "constraints",
        "rate_terms",
        "heights",
        "energy",
    ];
    let mut want: Vec<(&str, Vec<Vec<f64>>)> = names.iter().map(|&n| (n, vec![])).collect();
    for c in cases {
        let (w, (q, qd)) = at(c);
        let (mm, f) = w.mass_forcing(c.t, &q, &qd);
        let (a, b) = w.constraint_rows(&q, &qd);
        // nalgebra is column-major; the export writes a matrix row by row.
        let values = [
            mm.transpose().as_slice().to_vec(),
            f.as_slice().to_vec(),
            a.transpose().as_slice().to_vec(),
            b.as_slice().to_vec(),
            w.heights(&q).to_vec(),
            vec![w.energy(&q, &qd)],
        ];
        for ((_, v), x) in want.iter_mut().zip(values) {
            v.push(x);
        }
    }
    want
}

#[test]
fn the_benchmark_bicycle_exports_its_pieces_bit_for_bit() {
    let e = Bicycle::exported().expect("exported");
    assert_eq!(e.state().len(), 16);
    let b = Bicycle::benchmark();
    // The parameters the derive read, by name (`lambda` is a Python keyword: `lambda_`).
    let value = |name: &str| match name {
        "w" => b.w,
        "c" => b.c,
        "lambda_" => b.lambda,
        "g" => b.g,
        "r_r" => b.r_r,
        "m_r" => b.m_r,
        "i_rxx" => b.i_rxx,
        "i_ryy" => b.i_ryy,
        "x_b" => b.x_b,
        "z_b" => b.z_b,
        "m_b" => b.m_b,
        "i_bxx" => b.i_bxx,
        "i_byy" => b.i_byy,
        "i_bzz" => b.i_bzz,
        "i_bxz" => b.i_bxz,
        "x_h" => b.x_h,
        "z_h" => b.z_h,
        "m_h" => b.m_h,
        "i_hxx" => b.i_hxx,
        "i_hyy" => b.i_hyy,
        "i_hzz" => b.i_hzz,
        "i_hxz" => b.i_hxz,
        "r_f" => b.r_f,
        "m_f" => b.m_f,
        "i_fxx" => b.i_fxx,
        "i_fyy" => b.i_fyy,
        other => panic!("no field {other}"),
    };
    let cases = cases(&e, 1000, 10, |_, c| {
        c.p = e.parameters().iter().map(|n| value(n)).collect();
    });
    let want = pieces(&cases, |c| {
        let q: [f64; 8] = c.y[..8].try_into().expect("q");
        let qd: [f64; 8] = c.y[8..].try_into().expect("q̇");
        (b, (q, qd))
    });
    compare("bicycle", &e, &cases, &want, 0);
}
