//! Properties over random bodies: point masses against direct summation, and the symbolic
//! path (every value a parameter, as for a derived parametric body) against the numeric
//! builder, both through the one implementation in precess-core.

use nalgebra::{Matrix3, Vector3};
use precess::body::{
    Axis, BodyBuilder, Description, MassProperties, Part, RigidBody, Shape, mass_properties,
};
use precess::sym::{Arena, ExprId};
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f64> {
    -2.0..2.0f64
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    [coordinate(), coordinate(), coordinate()]
}

/// A random part: one of five shapes with positive dimensions.
fn part() -> impl Strategy<Value = Part<f64>> {
    let axis = prop_oneof![Just(Axis::X), Just(Axis::Y), Just(Axis::Z)];
    let shape = (
        0usize..5,
        0.1..3.0f64,
        0.05..1.0f64,
        0.05..1.0f64,
        axis,
        any::<bool>(),
    )
        .prop_map(|(k, mass, a, b, axis, reversed)| match k {
            0 => Shape::Particle { mass },
            1 => Shape::Sphere { mass, radius: a },
            2 => Shape::Cuboid {
                mass,
                size: [a, b, a + b],
            },
            3 => Shape::Cylinder {
                mass,
                radius: a,
                length: b,
                axis,
            },
            _ => Shape::Cone {
                mass,
                radius: a,
                height: b,
                axis,
                reversed,
            },
        });
    (shape, point()).prop_map(|(shape, at)| Part::new(shape, at))
}

fn matrix(t: &[[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| t[i][j])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn point_masses_match_direct_summation(ps in prop::collection::vec((0.1..3.0f64, point()), 4..12), pivot in point()) {
        let mut b = BodyBuilder::new().pivot(pivot);
        for &(m, x) in &ps {
            b = b.part(Shape::Particle { mass: m }, x);
        }
        // Four or more random points are not on a line (with probability one).
        let body = b.build().expect("a valid body");
        let o = Vector3::from(pivot);
        let mut direct = Matrix3::zeros();
        for &(m, x) in &ps {
            let d = Vector3::from(x) - o;
            direct += m * (Matrix3::identity() * d.norm_squared() - d * d.transpose());
        }
        let err = (body.inertia() - direct).abs().max() / direct.abs().max();
        prop_assert!(err < 1e-13, "relative error {err:e}");
    }

    #[test]
    fn symbolic_path_matches_numeric(parts in prop::collection::vec(part(), 1..5), pivot in prop::option::of(point())) {
        let numeric = Description { parts, pivot };
        // Every value becomes its own parameter symbol, bound to the value in `env`.
        let mut a = Arena::new();
        let mut env: Vec<f64> = Vec::new();
        let symbolic: Description<ExprId> = numeric.map(&mut |&v| {
            let e = a.parameter(&format!("v{}", env.len()));
            env.push(v);
            e
        });
        let Ok(sp) = mass_properties(&mut a, &symbolic) else {
            return Err(TestCaseError::fail("symbolic mass properties failed"));
        };
        let np: MassProperties<f64> = mass_properties(&mut precess::body::Numeric, &numeric).expect("valid");
        let ev = |t: &[[ExprId; 3]; 3]| Matrix3::from_fn(|i, j| a.eval(t[i][j], &env));
        // The size of the terms summed, not of the result: a lone particle's tensor about its
        // own centre is zero, and both paths then hold rounding-sized noise.
        let scale = matrix(&np.inertia).abs().max()
            + np.mass * (1.0 + Vector3::from(np.center).norm_squared());
        prop_assert!((ev(&sp.inertia) - matrix(&np.inertia)).abs().max() <= 1e-12 * scale);
        prop_assert!((ev(&sp.inertia_cm) - matrix(&np.inertia_cm)).abs().max() <= 1e-12 * scale);
        prop_assert!((a.eval(sp.mass, &env) - np.mass).abs() <= 1e-14 * np.mass);
        for k in 0..3 {
            prop_assert!((a.eval(sp.center[k], &env) - np.center[k]).abs() <= 1e-12);
        }
    }
}
