//! What `#[free]` emits, checked on its tokens (run with `--nocapture` to read them).

use quote::quote;

use crate::lang::tests::{method, rigid_body as expand};

#[test]
fn gravity_alone_makes_no_torque_and_reads_no_attitude() {
    let code = expand(quote! {
        #[rigid(cuboid(mass = 2.0, size = [0.1, 0.2, 0.3]))]
        #[free(gravity = 9.81)]
        struct Brick;
    });
    assert!(!code.contains("compile_error"), "{code}");
    let rhs = method(&code, "free_rhs");
    println!("free_rhs: {rhs}\n");
    // The quaternion is read only for q̇ (four products each), never for a rotation: no
    // division by |q|², and the weight's −9.81 appears as a literal.
    assert_eq!(rhs.matches(" / ").count(), 0, "{rhs}");
    assert!(rhs.contains("9.81"), "{rhs}");
    assert!(code.contains("const BEYOND_GRAVITY : :: core :: option :: Option < & 'static str > = :: core :: option :: Option :: None"), "{code}");
    // No user function, no run-time frame.
    assert!(
        !code.contains("__state") && !code.contains("let __pr"),
        "{code}"
    );
}

#[test]
fn symmetric_torque_free_body_emits_the_reduced_euler_equations() {
    let code = expand(quote! {
        #[rigid(cylinder(mass = 1.0, radius = 0.1, length = 0.5))]
        #[free]
        struct Rod;
    });
    assert!(!code.contains("compile_error"), "{code}");
    let rhs = method(&code, "free_rhs");
    // ω̇₃ = 0: the last entry of the array is the literal zero.
    let last = rhs.rsplit(',').next().unwrap_or("");
    assert!(
        last.trim_start().starts_with("0f64") || last.contains("0f64 ]"),
        "{rhs}"
    );
}

#[test]
fn a_thruster_reads_the_attitude_and_a_field() {
    let code = expand(quote! {
        #[rigid(cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]))]
        #[free(body_force(force = [0.0, 0.0, thrust], at = [0.05, 0.0, 0.0]), drag = 0.1)]
        struct Rocket { thrust: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    let rhs = method(&code, "free_rhs");
    assert!(rhs.contains("self . thrust"), "{rhs}");
    // R = (homogeneous form)/|q|²: one shared division.
    assert_eq!(rhs.matches(" / ").count(), 1, "{rhs}");
    assert!(code.contains("Option :: Some (\"a body force\")"), "{code}");
    assert!(method(&code, "check_parameters").contains("\"thrust\""));
}

#[test]
fn user_functions_are_called_only_where_read() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1))]
        #[free(force = wind, torque = spin_up)]
        struct Ball;
    });
    assert!(!code.contains("compile_error"), "{code}");
    assert!(method(&code, "free_rhs").contains("wind (self , t , & __state)"));
    assert!(method(&code, "power").contains("spin_up (self , t , & __state)"));
    // Energy and momenta do not depend on the forces.
    assert!(!method(&code, "energy").contains("__state"));
    assert!(!method(&code, "linear_momentum").contains("__state"));
}

#[test]
fn a_parametric_tilted_tensor_is_decomposed_at_run_time() {
    let code = expand(quote! {
        #[rigid(body(mass = 1.0, inertia = [[a, 0.1, 0.0], [0.1, 2.0, 0.0], [0.0, 0.0, 2.5]]))]
        #[free]
        struct Tilted { a: f64 }
    });
    assert!(!code.contains("compile_error"), "{code}");
    assert!(method(&code, "free_rhs").contains("let __pr ="), "{code}");
    assert!(method(&code, "principal_cm").contains("principal_frame"));
}

#[test]
fn free_and_top_together_are_refused_with_both_stubs() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81)]
        #[free(gravity = 9.81)]
        struct Both;
    });
    assert!(code.contains("cannot be combined"), "{code}");
    assert!(code.contains("TopDynamics for Both") && code.contains("FreeDynamics for Both"));
}

#[test]
fn repeated_wrenches_are_summed_and_each_called_once() {
    let code = expand(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1))]
        #[free(gravity = 9.81, wrench = table, wrench = wall)]
        struct Ball;
    });
    assert!(!code.contains("compile_error"), "{code}");
    // The right-hand side, the wrench and the power read the wrench (energy and momenta do
    // not): in each, each function is bound once as a typed pointer, both are called and
    // added, and the sum is resolved once. (The whole code is searched: `method` would stop
    // at the pointer type's `fn`.)
    for needle in [
        "= table ;",
        "= wall ;",
        "__wrench_fn0 (self , t , & __state) + __wrench_fn1 (self , t , & __state)",
        ". space_part (& __state . position)",
    ] {
        assert_eq!(code.matches(needle).count(), 3, "{needle}: {code}");
    }
    assert!(
        code.contains("Option :: Some (\"a user wrench\")"),
        "{code}"
    );
    // Energy and momenta do not depend on the forces.
    assert!(!method(&code, "energy").contains("__state"));
    assert!(!method(&code, "angular_momentum_origin").contains("__w"));
}
