//! Property tests of the whole derive over random inputs in its value language: structs
//! whose fields take reserved-looking names, values of any magnitude over the f64 range
//! (subnormals, overflowing literals, zero), random expression depths, random parts, keys
//! and `#[top]` settings, with a few mistakes mixed in. Whatever the input, the derive never
//! panics and ends in one of two ways: finite code with no error, or errors each spanned on
//! tokens of the input (never the call site) and none an internal error.
//!
//! The default runs a few dozen cases per property to keep `cargo test` quick;
//! `PROPTEST_CASES=2000 cargo test -p precess-derive --lib` runs a deep search.

use proptest::prelude::*;
use proptest::test_runner::Config;

use crate::lang::ctxt::Ctxt;
use crate::lang::keys::{self, PARTS, PartKind};

/// Field names that look like the engine's own symbols or the generated code's locals,
/// and a few plain ones.
const NAMES: &[&str] = &[
    "m",
    "h",
    "r",
    "t",
    "time",
    "phi",
    "theta",
    "psi",
    "phi_dot",
    "theta_dot",
    "psi_ddot",
    "yaw",
    "pitch_dot",
    "roll_ddot",
    "omega",
    "omega_1",
    "omega0",
    "torque",
    "G_1",
    "G_3",
    "q",
    "q_dot",
    "u",
    "u0",
    "R00",
    "R21",
    "w0",
    "w2",
    "state",
    "attitude",
    "seq",
    "__u",
    "__r",
    "__p0",
    "x",
    "y",
    "z",
    "center",
    "pivot",
    "diag",
    "mass",
    "gravity",
    "position",
    "velocity",
    "quaternion",
    "v",
    "force",
    "r#type",
];

/// How far an input strays from a valid one.
#[derive(Clone, Copy, Debug)]
enum Mode {
    /// Plain decimals and declared f64 fields, valid keys: the body rules and the
    /// expansion are reached.
    Clean,
    /// The same shapes with literals from the whole f64 range and beyond.
    Range,
    /// Anything: unknown names, wrong types, stray or missing keys, bad suffixes.
    Wild,
}

fn modes() -> impl Strategy<Value = Mode> {
    prop_oneof![2 => Just(Mode::Clean), 1 => Just(Mode::Range), 1 => Just(Mode::Wild)]
}

/// A plain decimal such as `37`, `0.5` or `12.25`.
fn decimal() -> impl Strategy<Value = String> {
    (1u32..100_000, 0u32..5).prop_map(|(n, dot)| match dot {
        0 => format!("{n}"),
        d => format!(
            "{}.{:0>width$}",
            n / 10u32.pow(d),
            n % 10u32.pow(d),
            width = d as usize
        ),
    })
}

/// A number literal: any finite positive f64 in shortest form (subnormals included), a
/// value past the range, zero, a plain decimal, or now and then a suffix.
fn literal(mode: Mode) -> BoxedStrategy<String> {
    if let Mode::Clean = mode {
        return decimal().boxed();
    }
    let finite = any::<u64>().prop_filter_map("finite", |bits| {
        let x = f64::from_bits(bits).abs();
        (x.is_finite()).then(|| format!("{x:e}"))
    });
    let overflow = (309i32..=400).prop_map(|e| format!("1.5e{e}"));
    let underflow = (325i32..=400).prop_map(|e| format!("2e-{e}"));
    let plain = decimal();
    if let Mode::Range = mode {
        return prop_oneof![
            6 => finite,
            1 => overflow,
            1 => underflow,
            4 => plain,
            1 => Just("5e-324".to_owned()),
            1 => Just("1.7976931348623157e308f64".to_owned()),
        ]
        .boxed();
    }
    prop_oneof![
        6 => finite,
        1 => overflow,
        1 => underflow,
        4 => plain,
        1 => Just("0.0".to_owned()),
        1 => Just("5e-324".to_owned()),
        1 => Just("1.7976931348623157e308f64".to_owned()),
        1 => Just("3f32".to_owned()),
    ]
    .boxed()
}

/// A scalar value of depth up to `depth`: literals and fields combined by `+ - * /`,
/// negation and parentheses. Names are drawn from `fields` and, rarely, from all names.
fn value(mode: Mode, fields: Vec<String>, depth: u32) -> BoxedStrategy<String> {
    let field = proptest::sample::select(fields);
    let any_name = proptest::sample::select(NAMES).prop_map(str::to_owned);
    let leaf = match mode {
        Mode::Wild => prop_oneof![4 => literal(mode), 4 => field, 1 => any_name].boxed(),
        Mode::Clean | Mode::Range => prop_oneof![literal(mode), field.boxed()].boxed(),
    };
    leaf.prop_recursive(depth, 16, 2, |inner| {
        prop_oneof![
            (inner.clone(), "[-+*/]", inner.clone())
                .prop_map(|(a, op, b)| format!("({a} {op} {b})")),
            inner.clone().prop_map(|a| format!("-{a}")),
            inner.prop_map(|a| format!("({a})")),
        ]
    })
    .boxed()
}

fn vector(v: BoxedStrategy<String>) -> impl Strategy<Value = String> {
    [v.clone(), v.clone(), v].prop_map(|[a, b, c]| format!("[{a}, {b}, {c}]"))
}

/// One part of the table with every required key and some optional ones, and now and then
/// a key that does not belong.
fn part(mode: Mode, fields: Vec<String>, shape: Shape) -> impl Strategy<Value = String> {
    let v = value(mode, fields.clone(), shape.depth);
    let w = shape.vectors(mode, fields);
    let (axes, mistakes): (&[&str], _) = match mode {
        Mode::Wild => (&["x", "y", "-z", "w"], 0u8..20),
        Mode::Clean | Mode::Range => (&["x", "y", "-z"], 2u8..3),
    };
    (
        proptest::sample::select((0..PARTS.len()).collect::<Vec<_>>()),
        v.clone(),
        vector(w.clone()),
        vector(w),
        proptest::sample::select(axes),
        prop_oneof![Just("center"), Just("pivot")],
        any::<[bool; 3]>(),
        mistakes,
    )
        .prop_map(
            move |(index, scalar, vec_a, vec_b, axis, about, optional, stray)| {
                let table = &PARTS[index];
                let mut keys: Vec<String> = table
                    .required
                    .iter()
                    .map(|&k| match k {
                        keys::SIZE | keys::SEMI_AXES => format!("{k} = {vec_a}"),
                        keys::INERTIA if optional[2] => format!("{k} = diag{}", paren(&vec_b)),
                        keys::INERTIA => format!("{k} = [{vec_b}, {vec_a}, {vec_b}]"),
                        _ => format!("{k} = {scalar}"),
                    })
                    .collect();
                if optional[0] {
                    keys.push(format!("{} = {vec_b}", keys::AT));
                }
                if optional[1] && table.optional.contains(&keys::AXIS) {
                    keys.push(format!("{} = {axis}", keys::AXIS));
                }
                if optional[1] && table.kind == PartKind::Explicit {
                    keys.push(format!("{} = {about}", keys::ABOUT));
                }
                match stray {
                    0 => keys.push("colour = 1.0".to_owned()),
                    1 => _ = keys.pop(),
                    _ => {}
                }
                format!("{}({})", table.name, keys.join(", "))
            },
        )
}

/// `[a, b, c]` as `(a, b, c)`.
fn paren(vector: &str) -> String {
    format!("({})", vector.trim_start_matches('[').trim_end_matches(']'))
}

/// A whole struct: fields of random names (mostly f64, now and then another type or the
/// primitive's path), one or two parts, maybe a pivot, maybe a top.
/// How large the generated scenes may be.
#[derive(Clone, Copy, Debug)]
struct Shape {
    /// The depth of scalar expressions.
    depth: u32,
    /// Whether vectors and tensors may read fields. The engine's cost grows fast with
    /// field-valued positions in a top (issue 9's scaling item), so the quick run keeps
    /// them literal and the ignored deep run does not.
    field_vectors: bool,
    /// Whether the struct declares a top.
    top: bool,
}

impl Shape {
    /// The values of vector and tensor entries.
    fn vectors(self, mode: Mode, fields: Vec<String>) -> BoxedStrategy<String> {
        if self.field_vectors {
            value(mode, fields, self.depth)
        } else {
            literal(mode)
        }
    }
}

fn input(shape: Shape) -> impl Strategy<Value = String> {
    let names = proptest::sample::subsequence(NAMES, 1..5);
    (modes(), names)
        .prop_flat_map(move |(mode, names)| {
            let fields: Vec<String> = names.iter().map(|n| (*n).to_owned()).collect();
            let types: &[&str] = match mode {
                Mode::Wild => &["f64", "f64", "core::primitive::f64", "u32"],
                Mode::Clean | Mode::Range => &["f64", "f64", "core::primitive::f64"],
            };
            let types = proptest::collection::vec(proptest::sample::select(types), fields.len());
            let v = value(mode, fields.clone(), shape.depth);
            let w = shape.vectors(mode, fields.clone());
            let settings = (
                v.clone(),
                v,
                vector(w.clone()),
                any::<[bool; 5]>(),
                prop_oneof![Just("zxz"), Just("zyx")],
                // Order 1 is refused (spanned on the value); the others emit recurrences.
                proptest::sample::select(&[1usize, 2, 5][..]),
            )
                .prop_map(|(g, c, tau, on, angles, order)| {
                    let mut s = vec![format!("angles = {angles}")];
                    for (set, text) in [
                        (on[0], format!("gravity = {g}")),
                        (on[1], format!("damping = {c}")),
                        (on[2], format!("body_torque = {tau}")),
                        (on[3], format!("space_torque = {tau}")),
                        (on[4], format!("taylor = {order}")),
                    ] {
                        if set {
                            s.push(text);
                        }
                    }
                    format!("#[top({})]", s.join(", "))
                });
            (
                Just(fields.clone()),
                types,
                proptest::collection::vec(part(mode, fields, shape), 1..3),
                proptest::option::weighted(0.8, vector(w)),
                if shape.top {
                    settings.prop_map(Some).boxed()
                } else {
                    Just(None).boxed()
                },
            )
        })
        .prop_map(|(fields, types, parts, pivot, top)| {
            let pivot = pivot.map(|p| format!(", pivot = {p}")).unwrap_or_default();
            let body: Vec<String> = fields
                .iter()
                .zip(&types)
                .map(|(f, ty)| format!("{f}: {ty}"))
                .collect();
            format!(
                "#[rigid({}{pivot})]\n{}\nstruct Scene {{ {} }}",
                parts.join(", "),
                top.unwrap_or_default(),
                body.join(", ")
            )
        })
}

/// Runs the derive on `source` and checks its outcome.
fn derive_is_total(source: &str) -> Result<(), TestCaseError> {
    let input: syn::DeriveInput = match syn::parse_str(source) {
        Ok(input) => input,
        Err(e) => {
            return Err(TestCaseError::fail(format!(
                "generator wrote bad syntax: {e}\n{source}"
            )));
        }
    };
    let cx = Ctxt::new();
    let expanded = crate::rigid_body::expand(&cx, &input);
    match cx.check() {
        Ok(()) => {
            let Some(tokens) = expanded else {
                return Err(TestCaseError::fail(format!(
                    "no tokens and no error\n{source}"
                )));
            };
            let code = tokens.to_string();
            for bad in ["NAN", "INFINITY", "from_bits", "compile_error"] {
                prop_assert!(!code.contains(bad), "`{bad}` emitted for\n{source}");
            }
            // Every path into precess goes through the hidden module.
            prop_assert_eq!(
                code.matches(":: precess ::").count(),
                code.matches(":: precess :: __private ::").count(),
                "a path into precess outside __private for\n{}",
                source
            );
        }
        Err(errors) => {
            prop_assert!(!errors.is_empty());
            for e in errors {
                let message = e.to_string();
                prop_assert!(!message.contains("internal error"), "{message}\n{source}");
                let at = e.span().byte_range();
                prop_assert!(
                    at.end > at.start,
                    "`{message}` is not spanned on the input\n{source}"
                );
            }
        }
    }
    Ok(())
}

/// Cases per property: a few dozen by default, `PROPTEST_CASES` for a deep search.
fn config(default: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(default);
    Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    }
}

proptest! {
    #![proptest_config(config(64))]

    #[test]
    fn bodies_give_code_or_spanned_errors(source in input(Shape { depth: 3, field_vectors: true, top: false })) {
        derive_is_total(&source)?;
    }
}

proptest! {
    #![proptest_config(config(24))]

    #[test]
    fn tops_give_code_or_spanned_errors(source in input(Shape { depth: 1, field_vectors: false, top: true })) {
        derive_is_total(&source)?;
    }
}

proptest! {
    #![proptest_config(config(24))]

    /// Tops with field-valued positions: seconds each with today's engine, so run on demand
    /// (`cargo test -p precess-derive --lib -- --ignored`).
    #[test]
    #[ignore = "slow: field-valued positions make the top's derivation expensive"]
    fn general_tops_give_code_or_spanned_errors(source in input(Shape { depth: 2, field_vectors: true, top: true })) {
        derive_is_total(&source)?;
    }
}

/// A few inputs written out, so the generator's shapes are seen to parse and both ways out
/// are taken.
#[test]
fn written_out_inputs_take_both_ways() {
    let ok = "#[rigid(sphere(mass = theta_dot, radius = 1e-3 * t), pivot = [0.0, 0.0, 0.0])]\n#[top(gravity = 9.81, angles = zyx)]\nstruct Scene { theta_dot: f64, t: core::primitive::f64 }";
    let bad = "#[rigid(sphere(mass = 1e400, radius = omega_1 / 0.0), colour = 1)]\n#[top(friction = 1.0)]\nstruct Scene { omega_1: u32 }";
    for source in [ok, bad] {
        let input: syn::DeriveInput = syn::parse_str(source).expect("valid syntax");
        let cx = Ctxt::new();
        let expanded = crate::rigid_body::expand(&cx, &input);
        let errors = cx.check().err().unwrap_or_default();
        assert_eq!(source == ok, errors.is_empty(), "{errors:?}");
        assert_eq!(source == ok, expanded.is_some());
        derive_is_total(source).expect("total");
    }
}
