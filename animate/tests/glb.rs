//! The `.glb` of a run read back: the container, the JSON against glTF's rules, every
//! accessor inside its view and its min/max equal to its data, and the keyframes equal to the
//! trajectory's times and attitudes.

mod support;

use gltf_json::Root;
use gltf_json::validation::Validate;
use precess::animate::{self, Options, glb};
use precess::contact::{ContactDynamics, attitude_of};
use precess::nalgebra::{Quaternion, UnitQuaternion, Vector3};
use precess::prelude::*;
use support::{RADIUS, Spinner, floats, precession, tippe_run};

/// The document of `bytes`, after the container's and glTF's own checks and the accessors'.
fn read(bytes: &[u8]) -> (Root, Vec<u8>) {
    let chunks = glb::parse(bytes).expect("a glb");
    let root = Root::from_slice(chunks.json).expect("glTF JSON");
    let mut errors = Vec::new();
    root.validate(&root, gltf_json::Path::new, &mut |path, error| {
        errors.push(format!("{}: {error:?}", path()));
    });
    assert!(errors.is_empty(), "{errors:?}");
    let bin = chunks.bin.to_vec();
    assert_eq!(root.buffers.len(), 1);
    assert!(root.buffers[0].byte_length.0 as usize <= bin.len());
    for (i, view) in root.buffer_views.iter().enumerate() {
        let end = view.byte_offset.map_or(0, |o| o.0) + view.byte_length.0;
        assert!(
            end <= root.buffers[0].byte_length.0,
            "view {i} ends at {end}"
        );
    }
    for (i, a) in root.accessors.iter().enumerate() {
        let data = floats(&root, &bin, i);
        let width = a.type_.unwrap().multiplicity();
        let (min, max) = (a.min.as_ref().unwrap(), a.max.as_ref().unwrap());
        for c in 0..width {
            let column = data.iter().skip(c).step_by(width);
            let lo = column.clone().fold(f32::INFINITY, |a, b| a.min(*b));
            let hi = column.fold(f32::NEG_INFINITY, |a, b| a.max(*b));
            assert_eq!(min[c].as_f64().unwrap() as f32, lo, "accessor {i} min[{c}]");
            assert_eq!(max[c].as_f64().unwrap() as f32, hi, "accessor {i} max[{c}]");
        }
    }
    (root, bin)
}

/// The (input, output) accessors of channel `path` of the animation's node `node`.
fn channel(root: &Root, node: usize, path: &str) -> (usize, usize) {
    let anim = &root.animations[0];
    let ch = anim
        .channels
        .iter()
        .find(|c| {
            c.target.node.value() == node
                && format!("{:?}", c.target.path.unwrap()).eq_ignore_ascii_case(path)
        })
        .expect("a channel");
    let s = &anim.samplers[ch.sampler.value()];
    (s.input.value(), s.output.value())
}

#[test]
fn a_top_s_keyframes_are_its_times_and_its_figure_axis() {
    let run = precession();
    let spinner = Spinner;
    let zxz = |y: &[f64; 3]| {
        UnitQuaternion::from_matrix(&spinner.rotation_in(AngleSequence::Zxz, &[y[0], y[1], y[2]]))
    };
    let scale = 2.5;
    let options = Options {
        time_scale: scale,
        traces: true,
    };
    let animation = animate::top(&spinner, &run, zxz, options).unwrap();
    let (root, bin) = read(&animation.to_glb().unwrap());
    let node = root
        .nodes
        .iter()
        .position(|n| n.name.as_deref() == Some("top"))
        .unwrap();
    let (input, output) = channel(&root, node, "rotation");
    let times = floats(&root, &bin, input);
    assert_eq!(times.len(), run.len());
    for (t, k) in run.times().iter().zip(&times) {
        assert_eq!(*k, (t * scale) as f32);
    }
    let rotations = floats(&root, &bin, output);
    for (y, q) in run.states().iter().zip(rotations.chunks_exact(4)) {
        let norm = q.iter().map(|v| f64::from(*v).powi(2)).sum::<f64>().sqrt();
        assert!((norm - 1.0).abs() < 1e-6, "|q| = {norm}");
        let q =
            UnitQuaternion::new_normalize(Quaternion::new(q[3], q[0], q[1], q[2]).cast::<f64>());
        // The figure axis R e₃ of the ZXZ angles: (sin φ sin θ, −cos φ sin θ, cos θ).
        let (phi, theta, psi) = (y[0], y[1], y[2]);
        let axis = Vector3::new(
            phi.sin() * theta.sin(),
            -phi.cos() * theta.sin(),
            theta.cos(),
        );
        assert!((q * Vector3::z() - axis).norm() < 1e-6);
        // And R e₁ = (cos φ cos ψ − sin φ cos θ sin ψ, sin φ cos ψ + cos φ cos θ sin ψ, sin θ sin ψ).
        let e1 = Vector3::new(
            phi.cos() * psi.cos() - phi.sin() * theta.cos() * psi.sin(),
            phi.sin() * psi.cos() + phi.cos() * theta.cos() * psi.sin(),
            theta.sin() * psi.sin(),
        );
        assert!((q * Vector3::x() - e1).norm() < 1e-6);
    }
    // The pivot is the origin: no translation at all.
    let (_, moves) = channel(&root, node, "translation");
    assert!(floats(&root, &bin, moves).iter().all(|v| v.abs() < 1e-7));
    // The root turns space z up into glTF y up.
    let top_node = root.scenes[0].nodes[0].value();
    assert_eq!(
        root.nodes[top_node].rotation.unwrap().0,
        animate::Z_UP_TO_Y_UP
    );
}

#[test]
fn a_tippe_top_s_keyframes_place_its_sphere_on_the_table() {
    let (model, run) = tippe_run(0.5, 0.005);
    let animation = animate::contact(&model, &run, Options::default()).unwrap();
    let glb = animation.to_glb().unwrap();
    let (root, bin) = read(&glb);
    let node = root
        .nodes
        .iter()
        .position(|n| n.name.as_deref() == Some("body"))
        .unwrap();
    let (input, output) = channel(&root, node, "rotation");
    let times = floats(&root, &bin, input);
    assert_eq!(times.len(), run.len());
    for (t, k) in run.times().iter().zip(&times) {
        assert_eq!(*k, *t as f32);
    }
    let rotations = floats(&root, &bin, output);
    let (_, moves) = channel(&root, node, "translation");
    let moves = floats(&root, &bin, moves);
    let centre = Vector3::new(0.0, 0.0, support::OFFSET);
    for (k, y) in run.states().iter().map(|s| &s.x).enumerate() {
        let q = &rotations[4 * k..4 * k + 4];
        let q =
            UnitQuaternion::new_normalize(Quaternion::new(q[3], q[0], q[1], q[2]).cast::<f64>());
        let state = attitude_of(y);
        assert!(
            q.angle_to(&state) < 1e-6,
            "sample {k}: {}",
            q.angle_to(&state)
        );
        // The sphere's centre, where the keyframe puts it, is R above the table: a sphere on
        // a plane touches it at the foot of its centre.
        let position = Vector3::new(moves[3 * k], moves[3 * k + 1], moves[3 * k + 2]).cast::<f64>();
        let sphere = position + q * centre;
        assert!((sphere.z - RADIUS).abs() < 1e-6, "sample {k}: {}", sphere.z);
        // The centre of mass is the state's (x, y).
        let cm = position + q * Vector3::zeros();
        assert!((cm.x - y[0]).abs() < 1e-6 && (cm.y - y[1]).abs() < 1e-6);
        assert!((model.contact(y).space.z).abs() < 1e-9);
    }
    // Nodes: the body, the table, the contact trace, and the root.
    let names: Vec<_> = root.nodes.iter().filter_map(|n| n.name.clone()).collect();
    assert_eq!(
        names,
        ["body", "table", "contact point", "precess space (z up)"]
    );
}

#[test]
fn repeated_times_are_written_once() {
    let mut run = precession();
    let last = *run.times().last().unwrap();
    let state = *run.states().last().unwrap();
    run.push(last, state, &[]).unwrap();
    let zxz = |y: &[f64; 3]| {
        UnitQuaternion::from_matrix(&Spinner.rotation_in(AngleSequence::Zxz, &[y[0], y[1], y[2]]))
    };
    let animation = animate::top(&Spinner, &run, zxz, Options::default()).unwrap();
    assert_eq!(animation.keyframes(0).unwrap().times.len(), run.len() - 1);
    read(&animation.to_glb().unwrap());
}

#[test]
fn bad_inputs_are_typed_errors() {
    let run = precession();
    let nan =
        |_: &[f64; 3]| UnitQuaternion::new_unchecked(Quaternion::new(f64::NAN, 0.0, 0.0, 0.0));
    let err = animate::top(&Spinner, &run, nan, Options::default()).unwrap_err();
    assert!(
        matches!(err, animate::AnimateError::NonFinite { index: 0, .. }),
        "{err}"
    );
    let slow = Options {
        time_scale: -1.0,
        traces: false,
    };
    let err = animate::top(&Spinner, &run, |_| UnitQuaternion::identity(), slow).unwrap_err();
    assert!(matches!(err, animate::AnimateError::BadTimeScale { scale } if scale == -1.0));
    let empty = precess::ode::Trajectory::<[f64; 3]>::new(vec![]);
    let err = animate::top(
        &Spinner,
        &empty,
        |_| UnitQuaternion::identity(),
        Options::default(),
    );
    assert!(matches!(err, Err(animate::AnimateError::NoSamples { .. })));
}
