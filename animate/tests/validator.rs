//! The `.glb` files through the Khronos glTF validator (npm's `gltf-validator`, run by node):
//! a top with every kind of part, the tippe top on its table, a free body flying, and a
//! double pendulum swinging. No errors and no warnings.
//! Skips, saying why, without node or the package.

mod support;

use std::path::PathBuf;
use std::process::Command;

use precess::animate::{self, Animation, Options, Pose, part_groups};
use precess::body::{About, Axis, Orientation, Part, Shape};
use precess::free::FreeState;
use precess::nalgebra::{UnitQuaternion, Vector3};
use precess::ode::Trajectory;
use precess::prelude::*;

/// A brick with a ball on it, free in space.
#[derive(RigidBody)]
#[rigid(
    cuboid(mass = 1.0, size = [0.1, 0.2, 0.3]),
    sphere(mass = 0.5, radius = 0.03, at = [0.05, 0.1, 0.15]),
)]
#[free(gravity = 9.81)]
struct Brick;

/// The brick falling and turning (written down, not integrated: the file is what is tested).
fn falling_brick() -> Animation {
    let mut run = Trajectory::new(vec![]);
    for k in 0..=100 {
        let t = 0.01 * k as f64;
        let state = FreeState {
            position: Vector3::new(t, 0.0, -4.905 * t * t),
            velocity: Vector3::new(1.0, 0.0, -9.81 * t),
            attitude: UnitQuaternion::from_euler_angles(3.0 * t, t, 0.5 * t),
            omega_principal: Vector3::zeros(),
        };
        run.push(t, state, &[]).unwrap();
    }
    animate::free(&Brick, &run, Options::default()).unwrap()
}

/// A double pendulum whose lower link is a rod with a ball (bars, joints, parts, a trace).
#[derive(Mechanism)]
#[mechanism(gravity = 9.81)]
#[body(upper, parent = ground, joint = revolute(axis = x), q = theta1,
       parts(particle(mass = 1.0, at = [0.0, 0.0, -0.5])))]
#[body(lower, parent = upper, joint = revolute(axis = x, at = [0.0, 0.0, -0.5]), q = theta2,
       parts(rod(mass = 0.2, length = 0.4, axis = z, at = [0.0, 0.0, -0.2]),
             sphere(mass = 0.5, radius = 0.05, at = [0.0, 0.0, -0.4])))]
struct Swing;

/// The double pendulum swinging (written down, not integrated).
fn swinging() -> Animation {
    let mut run = Trajectory::new(vec![]);
    for k in 0..=100 {
        let t = 0.02 * k as f64;
        run.push(t, [(3.0 * t).sin(), 2.0 * t, 0.0, 0.0], &[])
            .unwrap();
    }
    animate::mechanism(&Swing, &run, Options::default()).unwrap()
}

/// The validator's package folder: `PRECESS_GLTF_VALIDATOR` if set, else
/// `target/npm/node_modules/gltf-validator` in the workspace (where `.ci/run` installs it).
fn validator() -> Option<PathBuf> {
    let dir = std::env::var_os("PRECESS_GLTF_VALIDATOR")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("../target/npm/node_modules/gltf-validator")
        });
    let node = Command::new("node").arg("--version").output();
    if node.map_or(true, |o| !o.status.success()) {
        println!("skipped: no node on the PATH");
        return None;
    }
    if !dir.join("package.json").is_file() {
        println!(
            "skipped: no gltf-validator at {} (npm install --prefix target/npm gltf-validator, or set PRECESS_GLTF_VALIDATOR)",
            dir.display()
        );
        return None;
    }
    Some(dir)
}

/// The validator's report on `glb`: (errors, warnings, the messages).
fn validate(dir: &PathBuf, name: &str, glb: &[u8]) -> (u64, u64, String) {
    let file = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}.glb"));
    std::fs::write(&file, glb).unwrap();
    let script = r#"
        const validator = require(process.argv[1]);
        const bytes = new Uint8Array(require("fs").readFileSync(process.argv[2]));
        validator.validateBytes(bytes, { maxIssues: 100 })
            .then((r) => console.log(JSON.stringify(r.issues)))
            .catch((e) => { console.error(String(e)); process.exit(2); });
    "#;
    let out = Command::new("node")
        .arg("-e")
        .arg(script)
        .arg(dir)
        .arg(&file)
        .output()
        .expect("node runs");
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{text} {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let count = |key: &str| -> u64 {
        let at = text.find(&format!("\"{key}\":")).expect("a count") + key.len() + 3;
        let digits: String = text[at..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        digits.parse().expect("a number")
    };
    (count("numErrors"), count("numWarnings"), text)
}

/// A body of every kind of part, turning and moving.
fn every_part() -> Animation {
    let m = 1.0;
    let inertia = [[0.02, 0.001, 0.0], [0.001, 0.03, 0.0], [0.0, 0.0, 0.04]];
    let shapes = [
        Shape::Particle { mass: m },
        Shape::Sphere {
            mass: m,
            radius: 0.05,
        },
        Shape::Shell {
            mass: m,
            radius: 0.04,
        },
        Shape::Cuboid {
            mass: m,
            size: [0.1, 0.05, 0.02],
        },
        Shape::Cylinder {
            mass: m,
            radius: 0.02,
            length: 0.1,
            axis: Axis::X,
        },
        Shape::Tube {
            mass: m,
            inner: 0.01,
            outer: 0.02,
            length: 0.1,
            axis: Axis::Y,
        },
        Shape::Disk {
            mass: m,
            radius: 0.05,
            axis: Axis::Z,
        },
        Shape::Ring {
            mass: m,
            radius: 0.05,
            axis: Axis::X,
        },
        Shape::Rod {
            mass: m,
            length: 0.2,
            axis: Axis::Y,
        },
        Shape::Cone {
            mass: m,
            radius: 0.03,
            height: 0.06,
            axis: Axis::Z,
            reversed: true,
        },
        Shape::Ellipsoid {
            mass: m,
            semi_axes: [0.03, 0.02, 0.01],
        },
        Shape::Explicit {
            mass: m,
            inertia,
            about: About::Center,
        },
    ];
    let parts: Vec<Part<f64>> = shapes
        .into_iter()
        .enumerate()
        .map(|(k, s)| {
            let part = Part::new(s, [0.15 * (k % 4) as f64, 0.15 * (k / 4) as f64, 0.0]);
            if k == 3 {
                part.rotated(Orientation::axis_angle([1.0, 1.0, 0.0], 0.5))
            } else {
                part
            }
        })
        .collect();
    let groups = part_groups(&parts, None, 0.3).unwrap();
    let samples = (0..=50).map(|k| {
        let t = 0.02 * k as f64;
        let attitude = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 2.0 * t);
        (
            t,
            Pose {
                position: Vector3::new(0.0, 0.0, 0.2 + t),
                attitude,
            },
        )
    });
    let mut animation = Animation::new();
    animation.add_body("every part", groups, samples).unwrap();
    animation.add_table([0.2, 0.2], 0.5);
    animation.add_pivot([0.0; 3], 0.01);
    animation
        .add_trace("a line", animate::TRACE, vec![[0.0; 3], [0.1, 0.1, 0.1]])
        .unwrap();
    animation
}

#[test]
fn the_khronos_validator_finds_no_error_and_no_warning() {
    let Some(dir) = validator() else {
        return;
    };
    let (model, run) = support::tippe_run(2.0, 0.005);
    let tippe = animate::contact(&model, &run, Options::default()).unwrap();
    let animations = [
        ("every_part", every_part()),
        ("tippe_top", tippe),
        ("free_body", falling_brick()),
        ("double_pendulum", swinging()),
    ];
    for (name, animation) in animations {
        let (errors, warnings, report) = validate(&dir, name, &animation.to_glb().unwrap());
        println!("{name}: {report}");
        assert_eq!((errors, warnings), (0, 0), "{name}: {report}");
    }
}
