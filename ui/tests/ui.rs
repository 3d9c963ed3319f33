//! Compile-fail cases of `#[derive(RigidBody)]`: one per error, each expecting the exact
//! spanned message in `tests/ui/<case>.stderr`.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
