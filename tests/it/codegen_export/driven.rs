//! A top with motors: the motors' torques are the export's inputs u, which the caller
//! supplies; with the same u the exported `rhs` gives the bits of `rhs_in` and `jacobian`
//! is ∂rhs/∂y at fixed u (checked against central differences of `rhs_in`).

use super::derived::{cases, compare};
use super::support::Case;
use precess::codegen::Export;
use precess::prelude::*;
use precess::top::TopDynamics;

/// A gyroscope on a pivot: a wheel spun at a constant rate, and two wheels turned by motors
/// whose torques are the fields `torque_a`, `torque_b` (read by the motors, not by the
/// equations: the export takes them as its inputs u, so both sides see the same torques).
#[derive(RigidBody)]
#[rigid(body(mass = m, at = [0.01, 0.0, -h], inertia = diag(a, a, c), about = pivot), pivot = [0.0, 0.0, 0.0])]
#[top(gravity = 9.81, angles = zyx, damping = drag,
      rotor(axis = [0, 1, 0], inertia = 0.01, rate = spin),
      rotor(axis = [0, 0, 1], inertia = j_spin, torque = Gimbal::spin_motor),
      rotor(axis = [1, 0, 1], inertia = j_tilt, torque = Gimbal::tilt_motor))]
struct Gimbal {
    m: f64,
    h: f64,
    a: f64,
    c: f64,
    drag: f64,
    spin: f64,
    j_spin: f64,
    j_tilt: f64,
    torque_a: f64,
    torque_b: f64,
}

impl Gimbal {
    fn spin_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_a
    }

    fn tilt_motor(&self, _t: f64, _y: &[f64]) -> f64 {
        self.torque_b
    }
}

#[test]
fn a_top_with_motors_exports_its_state_derivative_with_the_motor_torques_as_inputs() {
    let e = Gimbal::exported().expect("exported");
    assert_eq!(
        e.state(),
        [
            "yaw",
            "pitch",
            "roll",
            "yaw_dot",
            "pitch_dot",
            "roll_dot",
            "rotor_1",
            "rotor_2"
        ]
    );
    assert_eq!(e.inputs(), ["u_rotor_1", "u_rotor_2"]);
    assert_eq!(Gimbal::input_names().expect("inputs"), e.inputs());
    let mut fields = e.parameters().to_vec();
    fields.sort();
    // The motors' fields are the inputs' values, no parameters.
    assert_eq!(
        fields,
        ["a", "c", "drag", "h", "j_spin", "j_tilt", "m", "spin"]
    );
    let header = e.c_header();
    assert!(header.contains("#define GIMBAL_INPUT_LEN 2\n#define GIMBAL_U_U_ROTOR_1 0"));
    assert!(header.contains(
        "void gimbal_rhs(double t, const double *y, const double *u, const gimbal_params *p, double *out);"
    ));
    assert!(e.python().contains("def rhs(t, y, u, *, "));
    // Wheels light enough that I − Σ J â âᵀ stays positive definite, the pitch away from
    // the chart's gimbal lock at ±π/2 (where the finite differences below lose their digits).
    let cases = cases(&e, 1000, 6, |rng, c| {
        c.y[1] = rng.uniform(-1.2, 1.2);
        for (name, lo, hi) in [
            ("a", 0.5, 1.0),
            ("c", 0.5, 1.0),
            ("j_spin", 0.01, 0.2),
            ("j_tilt", 0.01, 0.2),
        ] {
            let k = e
                .parameters()
                .iter()
                .position(|p| p == name)
                .expect("a parameter");
            c.p[k] = rng.uniform(lo, hi);
        }
    });
    let top = |c: &Case| {
        let v = |n: &str| c.param(&e, n);
        Gimbal {
            m: v("m"),
            h: v("h"),
            a: v("a"),
            c: v("c"),
            drag: v("drag"),
            spin: v("spin"),
            j_spin: v("j_spin"),
            j_tilt: v("j_tilt"),
            torque_a: c.u[0],
            torque_b: c.u[1],
        }
    };
    let rhs_in = |c: &Case, y: &[f64; 8]| {
        let mut d = [0.0; 8];
        TopDynamics::<8>::rhs_in(&top(c), AngleSequence::Zyx, c.t, y, &mut d);
        d
    };
    let mut rhs: Vec<Vec<f64>> = Vec::new();
    let mut jac = Vec::new();
    for c in &cases {
        let y: [f64; 8] = c.y.clone().try_into().expect("8 states");
        let want = rhs_in(c, &y);
        let got = e
            .eval_with_inputs("rhs", c.t, &c.y, &c.u, &c.p)
            .expect("eval");
        assert_eq!(
            got.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            want.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        rhs.push(want.to_vec());
        // The Jacobian at fixed u against central differences of the Rust rhs_in.
        let j = e
            .eval_with_inputs("jacobian", c.t, &c.y, &c.u, &c.p)
            .expect("eval");
        for k in 0..8 {
            let step = 1e-6 * (1.0 + y[k].abs());
            let (mut up, mut down) = (y, y);
            up[k] += step;
            down[k] -= step;
            let (fu, fd) = (rhs_in(c, &up), rhs_in(c, &down));
            for i in 0..8 {
                let fd_ik = (fu[i] - fd[i]) / (2.0 * step);
                let scale = 1.0 + j[i * 8 + k].abs() + want[i].abs();
                assert!(
                    (j[i * 8 + k] - fd_ik).abs() <= 1e-6 * scale,
                    "d rhs_{i}/d y_{k}: {} vs {fd_ik}",
                    j[i * 8 + k]
                );
            }
        }
        jac.push(j);
    }
    compare("driven", &e, &cases, &[("rhs", rhs), ("jacobian", jac)], 0);
}
