//! Tests of the shared front end across every attribute and macro: what generated code may
//! name, and the `taylor = K` key handled alike wherever it is allowed.

use proc_macro2::TokenStream;
use quote::quote;

/// The expansion of `#[derive(RigidBody)]` on `input`, as text (the attributes' own tests
/// read it too).
pub(crate) fn rigid_body(input: TokenStream) -> String {
    let input: syn::DeriveInput = syn::parse2(input).expect("a struct");
    crate::rigid_body::derive(&input).to_string()
}

/// The text of one generated method, from its name to the next `fn`.
pub(crate) fn method<'a>(code: &'a str, name: &str) -> &'a str {
    let start = code.find(&format!("fn {name} ")).unwrap_or(0);
    let rest = &code[start..];
    let end = rest[3..].find(" fn ").map_or(rest.len(), |e| e + 3);
    &rest[..end]
}

/// The expansion of `#[derive(Mechanism)]` on `input`.
fn mechanism(input: TokenStream) -> String {
    let input: syn::DeriveInput = syn::parse2(input).expect("a struct");
    crate::mechanism::derive(&input).to_string()
}

/// Every path into precess in `code` that does not go through the hidden module.
fn outside_private(code: &str) -> Vec<String> {
    code.match_indices(":: precess ::")
        .map(|(i, _)| code[i..].chars().take(60).collect::<String>())
        .filter(|path| !path.starts_with(":: precess :: __private ::"))
        .collect()
}

/// One scene of each attribute and `taylor_system!`, each with `taylor = K` (the Taylor
/// emitter is where a path into core once leaked: `::precess::taylor::kernels`,
/// `::precess::exact::Dd`).
fn every_expansion() -> Vec<(&'static str, String)> {
    let system = crate::taylor_system::expand(quote! {
        pub struct Decay { pub k: f64 }
        state [x];
        taylor = 12;
        d/dt x = -k * x * t.sin() + x.sqrt();
    })
    .to_string();
    vec![
        (
            "rigid",
            rigid_body(quote! {
                #[rigid(cuboid(mass = m, size = [1.0, 2.0, 3.0]), taylor = 10)]
                struct Brick { m: f64 }
            }),
        ),
        (
            "top",
            rigid_body(quote! {
                #[rigid(disk(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.2]), pivot = [0.0, 0.0, 0.0])]
                #[top(gravity = 9.81, damping = c, taylor = 10)]
                struct Top { c: f64 }
            }),
        ),
        (
            "free",
            rigid_body(quote! {
                #[rigid(sphere(mass = 1.0, radius = 0.1))]
                #[free(gravity = 9.81, drag = 0.1, taylor = 10)]
                struct Ball;
            }),
        ),
        (
            "contact",
            rigid_body(quote! {
                #[rigid(sphere(mass = m, radius = 0.1))]
                #[contact(surface = sphere(radius = 0.1), law = stick_slip(mu = mu), gravity = 9.81)]
                struct Rolling { m: f64, mu: f64 }
            }),
        ),
        (
            "mechanism",
            mechanism(quote! {
                #[mechanism(gravity = 9.81, taylor = 10)]
                #[body(arm, parent = ground, joint = revolute(axis = x), q = theta,
                       parts(rod(mass = 1.0, length = 1.0, axis = z, at = [0.0, 0.0, -0.5])))]
                struct Pendulum;
            }),
        ),
        (
            "rolling mechanism",
            mechanism(quote! {
                #[mechanism(gravity = 9.81, up = z, speeds = [theta])]
                #[body(cart, parent = ground, joint = prismatic(axis = x), q = s,
                       parts(particle(mass = 1.0)))]
                #[body(wheel, parent = cart, joint = revolute(axis = y, at = [0.0, 0.0, r]),
                       q = theta, parts(disk(mass = 0.5, radius = r, axis = y)),
                       rolls = disk(radius = r, axle = y))]
                struct Cart { r: f64 }
            }),
        ),
        ("taylor_system", system),
        (
            "rolling stubs",
            mechanism(quote! {
                #[mechanism(gravity = 9.81, up = z, speeds = [theta])]
                #[body(wheel, parent = ground, joint = revolute(axis = y), q = theta,
                       parts(disk(mass = 0.5, radius = 0.5, axis = y)),
                       rolls = disk(radius = -0.5, axle = y))]
                struct Broken;
            }),
        ),
        (
            "stubs",
            rigid_body(quote! {
                #[rigid(sphere(mass = -1.0, radius = 0.1), pivot = [0.0, 0.0, 0.0])]
                #[top]
                struct Broken;
            }),
        ),
    ]
}

/// Generated code names precess only through `::precess::__private`, so a user's imports
/// and the facade's public layout cannot break it, and core's items it needs can be hidden.
#[test]
fn generated_code_names_precess_only_through_the_hidden_module() {
    for (what, code) in every_expansion() {
        assert!(code.contains(":: precess :: __private"), "{what}: {code}");
        assert!(
            !code.contains("compile_error") || what.ends_with("stubs"),
            "{what}: {code}"
        );
        let leaks = outside_private(&code);
        assert!(
            leaks.is_empty(),
            "{what} names precess outside __private: {leaks:?}"
        );
    }
}

/// A mechanism whose bodies roll implements `RollingDynamics<n, m, k>` and not the
/// `MechanismDynamics` and `System<2n>` of a state (q, q̇) it does not have.
#[test]
fn a_rolling_mechanism_implements_rolling_dynamics_only() {
    let code = every_expansion()
        .into_iter()
        .find(|(what, _)| *what == "rolling mechanism")
        .map(|(_, code)| code)
        .unwrap_or_default();
    assert!(
        code.contains("RollingDynamics < 2usize , 1usize , 1usize >"),
        "{code}"
    );
    assert!(!code.contains("MechanismDynamics"), "{code}");
    assert!(!code.contains("System <"), "{code}");
    assert!(code.contains("pub const STATE : usize = 3usize"), "{code}");
    // The field radius is checked at run time, as a literal is at compile time.
    assert!(
        method(&code, "check_parameters").contains("NonPositiveParameter"),
        "{code}"
    );
}

/// The first message of an expansion's errors, with the text it is spanned on.
fn first_error(code: &str) -> &str {
    let start = code.find("compile_error").unwrap_or(0);
    &code[start..code.len().min(start + 200)]
}

/// A repeated `taylor` is the same error wherever the key is allowed, naming the attribute.
#[test]
fn a_repeated_order_is_one_error_naming_its_attribute() {
    let cases = [
        (
            "`#[rigid]`",
            rigid_body(quote! {
                #[rigid(sphere(mass = 1.0, radius = 0.1), taylor = 10, taylor = 12)]
                struct A;
            }),
        ),
        (
            "`#[top]`",
            rigid_body(quote! {
                #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 1.0]), pivot = [0.0, 0.0, 0.0])]
                #[top(taylor = 10, gravity = 9.81, taylor = 12)]
                struct B;
            }),
        ),
        (
            "`#[free]`",
            rigid_body(quote! {
                #[rigid(sphere(mass = 1.0, radius = 0.1))]
                #[free(taylor = 10)]
                #[free(taylor = 12)]
                struct C;
            }),
        ),
        (
            "`#[mechanism]`",
            mechanism(quote! {
                #[mechanism(taylor = 10, taylor = 12)]
                #[body(arm, joint = revolute(axis = x), q = theta,
                       parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
                struct D;
            }),
        ),
        (
            "`taylor_system!`",
            crate::taylor_system::expand(quote! {
                struct E;
                state [x];
                taylor = 10;
                taylor = 12;
                d/dt x = x;
            })
            .to_string(),
        ),
    ];
    for (attribute, code) in cases {
        let expected = format!("duplicate key `taylor` in {attribute}");
        assert_eq!(
            code.matches("compile_error").count(),
            1,
            "{attribute}: {code}"
        );
        assert!(
            first_error(&code).contains(&expected),
            "{attribute}: {code}"
        );
    }
}

/// A word alone in a mechanism body's `parts(...)` is told what a part looks like, not the
/// `#[rigid]` top-level keys (`pivot`, `taylor`), which a mechanism body does not take.
#[test]
fn a_bare_word_among_a_bodys_parts_is_told_the_part_form() {
    let code = mechanism(quote! {
        #[body(arm, joint = revolute(axis = x), q = theta, parts(particle(mass = 1.0), rod))]
        struct Arm;
    });
    let error = first_error(&code);
    assert!(
        error.contains("expected a part `rod(key = value, ...)`"),
        "{error}"
    );
    assert!(!error.contains("pivot"), "{error}");
}

/// The shared grammar reads a list as `Punctuated::parse_terminated` did: a trailing comma
/// is allowed, a missing one is an error, and every form keeps its parts.
#[test]
fn the_item_grammar_reads_groups_settings_and_commas() {
    use super::syntax::Item;
    use syn::parse::Parser;
    let expected: super::syntax::Expected = |name| format!("no form for {name}");
    let parse = |tokens: TokenStream| {
        (|input: syn::parse::ParseStream| Item::parse_list(input, expected)).parse2(tokens)
    };
    let items = parse(quote!(
        sphere(mass = 1.0, radius = r,),
        pivot = [0.0, 0.0, 1.0],
    ))
    .expect("a list with trailing commas");
    assert_eq!(items.len(), 2);
    assert!(matches!(&items[0], Item::Group { name, keys } if name == "sphere" && keys.len() == 2));
    assert!(matches!(&items[1], Item::Setting(kv) if kv.key == "pivot"));
    // `box` is a keyword, and a part name.
    let items = parse(quote!(box(mass = 1.0))).expect("a keyword as a part name");
    assert!(matches!(&items[0], Item::Group { name, .. } if name == "box"));
    let missing = parse(quote!(taylor = 10 pivot = [0.0, 0.0, 0.0]));
    assert!(missing.is_err());
    let alone = parse(quote!(mass = 1.0, rod)).err().map(|e| e.to_string());
    assert_eq!(alone.as_deref(), Some("no form for rod"));
    assert!(parse(TokenStream::new()).is_ok_and(|items| items.is_empty()));
}

/// A repeated setting of `#[top]` or `#[mechanism]` names its attribute, as `#[rigid]`'s
/// and `#[free]`'s always did; the rest of the list is still checked.
#[test]
fn a_repeated_setting_names_its_attribute() {
    let top = rigid_body(quote! {
        #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 1.0]), pivot = [0.0, 0.0, 0.0])]
        #[top(gravity = 9.81, gravity = 1.62, angles = xyz)]
        struct Top;
    });
    assert!(
        first_error(&top).contains("duplicate key `gravity` in `#[top]`"),
        "{top}"
    );
    assert!(top.contains("`angles` expects"), "{top}");
    let mechanism = mechanism(quote! {
        #[mechanism(route = auto, route = symbolic)]
        #[body(arm, joint = revolute(axis = x), q = theta,
               parts(particle(mass = 1.0, at = [0.0, 0.0, -1.0])))]
        struct Arm;
    });
    let error = first_error(&mechanism);
    assert!(
        error.contains("duplicate key `route` in `#[mechanism]`"),
        "{mechanism}"
    );
}

/// An attribute's items expanded on a struct that declares it, as text.
type Expand = dyn Fn(TokenStream) -> String;

/// The keys and the groups (each backticked `name(` after the keys) that the unknown-key
/// message in `code` lists.
fn listed(code: &str) -> (Vec<String>, Vec<String>) {
    let start = code
        .find("allowed keys are ")
        .map_or(code.len(), |i| i + 17);
    let message = &code[start..];
    let message = &message[..message.find('"').unwrap_or(message.len())];
    let message = message.split("; did you mean").next().unwrap_or(message);
    let (keys, others) = message.split_once(", or ").unwrap_or((message, ""));
    let keys = keys.split(", ").map(str::to_owned).collect();
    let groups = others
        .split('`')
        .skip(1)
        .step_by(2)
        .filter_map(|form| form.split_once('(').map(|(name, _)| name.to_owned()))
        .collect();
    (keys, groups)
}

/// The unknown-key message of each attribute lists only what the attribute takes: every key
/// it names, and every group, written in that attribute, is no unknown key or group (its
/// value may be wrong: that is another error).
#[test]
fn every_key_and_group_an_unknown_key_message_lists_is_taken() {
    let top = |items: TokenStream| {
        rigid_body(quote! {
            #[rigid(sphere(mass = 1.0, radius = 0.1, at = [0.0, 0.0, 0.1]), pivot = [0.0, 0.0, 0.0])]
            #[top(#items)]
            struct Top;
        })
    };
    let free = |items: TokenStream| {
        rigid_body(quote! {
            #[rigid(sphere(mass = 1.0, radius = 0.1))]
            #[free(#items)]
            struct Body;
        })
    };
    let contact = |items: TokenStream| {
        rigid_body(quote! {
            #[rigid(sphere(mass = 1.0, radius = 0.1))]
            #[contact(#items)]
            struct Ball;
        })
    };
    let pendulum = |items: TokenStream| {
        mechanism(quote! {
            #[mechanism(#items)]
            #[body(arm, parent = ground, joint = revolute(axis = x), q = theta,
                   parts(rod(mass = 1.0, length = 1.0, axis = z, at = [0.0, 0.0, -0.5])))]
            struct Pendulum;
        })
    };
    let attributes: [(&str, &Expand, usize); 4] = [
        ("top", &top, 2),
        ("free", &free, 3),
        ("contact", &contact, 0),
        ("mechanism", &pendulum, 1),
    ];
    for (attribute, expand, group_count) in attributes {
        let code = expand(quote!(colour = 1.0));
        assert!(code.contains("unknown key `colour`"), "{attribute}: {code}");
        let (keys, groups) = listed(&code);
        assert!(keys.len() >= 3, "{attribute}: {keys:?}");
        assert_eq!(groups.len(), group_count, "{attribute}: {groups:?}");
        for key in &keys {
            let k = quote::format_ident!("{key}");
            let code = expand(quote!(#k = 1.0));
            assert!(
                !code.contains(&format!("unknown key `{key}`")),
                "{attribute}, {key}: {code}"
            );
        }
        for group in &groups {
            let g = quote::format_ident!("{group}");
            let code = expand(quote!(#g()));
            let unknown = [
                format!("unknown key `{group}`"),
                format!("unknown group `{group}("),
            ];
            for u in unknown {
                assert!(!code.contains(&u), "{attribute}, {group}: {code}");
            }
        }
    }
}
