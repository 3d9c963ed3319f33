//! What the macro emits, checked on its tokens (run with `--nocapture` to read them).

use quote::quote;

use crate::lang::tests::{method, rigid_body as expand};

#[test]
fn literal_body_emits_constants_only() {
    let code = expand(quote! {
        #[rigid(
            cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
            disk(mass = 0.5, radius = 0.03, at = [0.0, 0.0, 0.05]),
            pivot = [0.0, 0.0, 0.0],
        )]
        struct Top;
    });
    println!("{code}\n");
    assert!(!code.contains("compile_error"));
    let rhs = method(&code, "euler_rhs_principal");
    // No division, no decomposition at run time.
    assert!(!rhs.contains('/'), "{rhs}");
    assert!(!code.contains("principal_frame"));
    // Symmetric about 3: ω̇3 = G3/I3 has no gyroscopic term, so only ω̇1 and ω̇2 add two
    // terms (each ω component is read once).
    println!("euler_rhs_principal: {rhs}");
    assert_eq!(rhs.matches("omega [").count(), 3, "{rhs}");
    assert_eq!(
        rhs.matches(" + ").count() + rhs.matches(" - ").count(),
        2,
        "{rhs}"
    );
    // Checked at compile time: validate() returns Ok at once.
    assert!(method(&code, "validate").contains("Ok (())"));
}

#[test]
fn parametric_body_reads_its_fields() {
    let code = expand(quote! {
        #[rigid(
            cylinder(mass = 0.2, radius = 0.004, length = 0.06, at = [0.0, 0.0, 0.03]),
            disk(mass = m, radius = r, at = [0.0, 0.0, h]),
            pivot = [0.0, 0.0, 0.0],
        )]
        struct Top { m: f64, r: f64, h: f64 }
    });
    println!("{code}\n");
    assert!(!code.contains("compile_error"));
    assert!(code.contains("self . m"));
    // validate() is the default, on the description rebuilt from the fields.
    assert!(!code.contains("fn validate"));
    assert!(method(&code, "description").contains("self . r"));
    // Diagonal symbolically: no decomposition at run time.
    assert!(!code.contains("principal_frame"));
    println!(
        "euler_rhs_principal: {}",
        method(&code, "euler_rhs_principal")
    );
}

#[test]
fn tilted_parametric_body_decomposes_at_run_time() {
    let code = expand(quote! {
        #[rigid(sphere(mass = m, radius = 0.1, at = [d, 0.0, d]), sphere(mass = 1.0, radius = 0.1))]
        struct Tilted { m: f64, d: f64 }
    });
    assert!(code.contains("principal_frame"));
    assert!(code.contains("euler_rhs_diagonal"));
}

#[test]
fn errors_come_with_a_stub_impl() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 0.0, radius = 0.1))]
        struct Bad;
    });
    assert!(code.contains("compile_error"));
    assert!(code.contains("unimplemented"));
}

#[test]
fn many_parametric_parts_expand() {
    // Twelve parts placed by fields in all three coordinates: not diagonal, so the frame is
    // decomposed at run time, and everything else is straight-line code in the fields.
    let code = expand(quote! {
        #[rigid(
            sphere(mass = m1, radius = r, at = [a, b, c]),
            sphere(mass = m2, radius = r, at = [-a, b, c]),
            cuboid(mass = m1 + m2, size = [a, b, c], at = [a, -b, c]),
            cylinder(mass = m1, radius = r, length = c, at = [b, a, c], axis = x),
            tube(mass = m2, inner = r / 2.0, outer = r, length = a, at = [c, b, a]),
            disk(mass = m1, radius = r, at = [a, a, b], axis = y),
            ring(mass = m2, radius = r, at = [b, b, a]),
            cone(mass = m1, radius = r, height = c, at = [c, c, a], axis = -x),
            ellipsoid(mass = m2, semi_axes = [a, b, c], at = [a, c, b]),
            shell(mass = m1, radius = r, at = [c, a, b]),
            rod(mass = m2, length = a, at = [b, c, a], axis = z),
            particle(mass = m1, at = [a, b, -c]),
            pivot = [0.0, 0.0, -a],
        )]
        struct Big { m1: f64, m2: f64, r: f64, a: f64, b: f64, c: f64 }
    });
    assert!(!code.contains("compile_error"));
    assert!(code.contains("principal_frame"));
    println!("emitted {} bytes", code.len());
}

#[test]
fn literal_rotations_fold_to_constants() {
    // sin, cos and √ of literals are folded while expanding, in the body and in the top's
    // equations: nothing trigonometric is left for run time.
    let code = expand(quote! {
        #[rigid(
            cylinder(mass = 2.5, radius = 0.3, length = 1.2, at = [0.0, 0.0, 0.5],
                     rotate = axis_angle([0.0, 1.0, 1.0], 0.5)),
            cuboid(mass = 1.0, size = [0.2, 0.5, 0.9], rotate = zxz(0.4, 0.7, -0.2)),
            pivot = [0.0, 0.0, 0.0],
        )]
        #[top(gravity = 9.81)]
        struct Turned;
    });
    assert!(!code.contains("compile_error"), "{code}");
    for name in [
        "inertia",
        "inertia_cm",
        "center_of_mass",
        "principal",
        "euler_rhs_principal",
    ] {
        let m = method(&code, name);
        for f in ["sin", "cos", "sqrt"] {
            assert!(!m.contains(f), "{name} calls {f}: {m}");
        }
    }
    // Not diagonal, but constant: decomposed now, not at run time.
    assert!(!code.contains("principal_frame"));
    // The rotation stays in the description, as written.
    assert!(method(&code, "description").contains("Orientation :: AxisAngle"));
}

#[test]
fn a_field_angle_is_turned_at_run_time() {
    let code = expand(quote! {
        #[rigid(rod(mass = 3.0, length = 2.0, rotate = y(angle)), sphere(mass = 1.0, radius = 0.1))]
        struct Swing { angle: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    let inertia = method(&code, "inertia");
    assert!(
        inertia.contains("self . angle") && inertia.contains("sin"),
        "{inertia}"
    );
    // Turned about its own axis, a cylinder stays symbolically diagonal.
    let code = expand(quote! {
        #[rigid(cylinder(mass = 1.0, radius = 0.1, length = 0.5, rotate = z(angle)))]
        struct Spun { angle: f64 }
    });
    assert!(!code.contains("principal_frame"), "{code}");
}
