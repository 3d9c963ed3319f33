//! What `#[top]` emits, checked on its tokens (run with `--nocapture` to read them).

use quote::quote;

use crate::lang::tests::rigid_body as expand;

/// The text of the `Zxz` arm of `accelerations_unchecked_in`.
fn zxz_accel(code: &str) -> &str {
    let start = code.find("fn accelerations_unchecked_in").unwrap_or(0);
    let rest = &code[start..];
    let arm = rest.find("AngleSequence :: Zxz =>").unwrap_or(0);
    let rest = &rest[arm..];
    let end = rest.find("AngleSequence :: Zyx =>").unwrap_or(rest.len());
    &rest[..end]
}

#[test]
fn symmetric_literal_top_emits_the_short_form() {
    let code = expand(quote! {
        #[rigid(
            body(mass = 1.0, at = [0.0, 0.0, 1.0], inertia = diag(1.0, 1.0, 0.5), about = pivot),
            pivot = [0.0, 0.0, 0.0],
        )]
        #[top(gravity = 1.0)]
        struct Reference;
    });
    assert!(!code.contains("compile_error"), "{code}");
    let accel = zxz_accel(&code);
    println!("ZXZ q'': {accel}\n");
    // One sin_cos of θ, no lone sine or cosine, one division (the shared 1/sin θ), and no
    // read of φ or ψ: the symmetric top's equations do not depend on them.
    assert_eq!(accel.matches("sin_cos").count(), 1, "{accel}");
    assert_eq!(
        accel.matches("f64 :: sin (").count() + accel.matches("f64 :: cos (").count(),
        0
    );
    assert_eq!(accel.matches(" / ").count(), 1, "{accel}");
    assert!(
        !accel.contains("state [0usize]") && !accel.contains("state [2usize]"),
        "{accel}"
    );
    // Undeclared torques generate nothing: no user call, no damping.
    assert!(!code.contains("__u"));
}

#[test]
fn declared_user_torque_is_called_and_fields_are_read() {
    let code = expand(quote! {
        #[rigid(disk(mass = m, radius = 0.04, at = [0.0, 0.0, h]), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81, damping = k, torque = drive)]
        struct Driven { m: f64, h: f64, k: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    let accel = zxz_accel(&code);
    // Bound once to the documented fn pointer type, then called.
    assert!(accel.contains("= drive ;"), "{accel}");
    assert!(accel.contains("__torque (self , t"), "{accel}");
    assert!(accel.contains("self . k") && accel.contains("self . m") && accel.contains("self . h"));
}

#[test]
fn top_errors_come_with_a_stub_impl() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]))]
        #[top(gravity = 9.81)]
        struct NoPivot;
    });
    assert!(code.contains("compile_error"));
    assert!(code.contains("impl :: precess :: __private :: TopDynamics for NoPivot"));
}

#[test]
fn top_without_rigid_reports_the_missing_attribute_once() {
    let code = expand(quote! {
        #[top(gravity = 9.81)]
        struct Bare;
    });
    assert_eq!(code.matches("compile_error").count(), 1, "{code}");
    assert!(code.contains("needs a `#[rigid(...)]`"), "{code}");
}

#[test]
fn rigid_and_top_errors_come_together() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1, colour = 3.0), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81, friction = 0.1)]
        struct Spinner;
    });
    assert!(code.contains("unknown key `colour`"), "{code}");
    assert!(code.contains("unknown key `friction`"), "{code}");
}

#[test]
fn a_bare_top_is_torque_free() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
        #[top]
        struct Free;
    });
    assert!(!code.contains("compile_error"), "{code}");
    assert!(code.contains("impl :: precess :: __private :: TopDynamics for Free"));
    // Nothing declared: every setting is None, and no user call.
    let start = code.find("fn top_parameters").unwrap_or(0);
    let parameters = &code[start
        ..code[start..]
            .find("fn accelerations_unchecked_in")
            .map_or(code.len(), |e| start + e)];
    assert_eq!(parameters.matches(":: None").count(), 4, "{parameters}");
    assert!(!code.contains("__u"));
}

#[test]
fn field_settings_are_read_for_the_run_time_check() {
    let code = expand(quote! {
        #[rigid(disk(mass = 1.0, radius = 0.04, at = [0.0, 0.0, 0.05]), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = g, damping = 0.5)]
        struct Spinner { g: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    let start = code.find("fn top_parameters").unwrap_or(0);
    let parameters = &code[start
        ..code[start..]
            .find("fn accelerations_unchecked_in")
            .map_or(code.len(), |e| start + e)];
    assert!(parameters.contains("= self . g ;"), "{parameters}");
    assert!(
        parameters.contains("gravity : :: core :: option :: Option :: Some (__p"),
        "{parameters}"
    );
    assert!(
        parameters.contains("damping : :: core :: option :: Option :: Some (0.5"),
        "{parameters}"
    );
}

#[test]
fn a_driven_top_emits_straight_line_code_over_its_whole_state() {
    let code = expand(quote! {
        #[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.001, rate = 3), rotor(axis = [1, 0, 0], inertia = 0.002, torque = motor))]
        struct Gyro;
    });
    assert!(!code.contains("compile_error"), "{code}");
    assert!(code.contains("TopDynamics < 7usize > for Gyro"), "{code}");
    assert!(
        code.contains("pub const ROTOR_1 : usize = 6usize"),
        "{code}"
    );
    assert!(code.contains("DRIVEN_ROTORS : & 'static [& 'static str] = & [\"rotor_1\"]"));
    let start = code.find("fn rhs_in").unwrap_or(0);
    let end = code[start..]
        .find("fn rotation_in")
        .map_or(code.len(), |e| start + e);
    let rhs = &code[start..end];
    println!("rhs_in: {rhs}\n");
    // The motors are called through `motor_torques` once per chart; the rest is arithmetic:
    // no loop, no branch.
    assert_eq!(
        rhs.matches("motor_torques (self , t , state").count(),
        2,
        "{rhs}"
    );
    // `motor_torques` binds the motor to its documented signature, and `MOTORS` names it.
    assert!(
        code.contains("fn (& Self , f64 , & [f64]) -> f64 = motor ;"),
        "{code}"
    );
    assert!(
        code.contains("MOTORS : & 'static [& 'static str] = & [\"motor\"]"),
        "{code}"
    );
    for word in [" for ", " while ", " loop ", " if "] {
        assert!(!rhs.contains(word), "{word} in {rhs}");
    }
}

#[test]
fn a_top_without_motors_emits_no_driven_method() {
    let code = expand(quote! {
        #[rigid(body(mass = 1.0, at = [0.0, 0.0, 0.1], inertia = diag(0.05, 0.05, 0.02), about = pivot), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81, rotor(axis = [0, 0, 1], inertia = 0.001, rate = 3))]
        struct Held;
    });
    assert!(!code.contains("compile_error"), "{code}");
    for word in [
        "rhs_in",
        "__motor",
        "DRIVEN_ROTORS",
        "TopDynamics <",
        "ROTOR_",
    ] {
        assert!(!code.contains(word), "{word} in {code}");
    }
}
