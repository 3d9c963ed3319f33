//! An [`Animation`] as glTF 2.0: the JSON document (gltf-json's types) and its binary buffer.
//!
//! Layout: one scene whose one root node turns precess's z-up space into glTF's y-up (a turn
//! of −90° about x: space z becomes glTF y, space y becomes glTF −z); under it one node per
//! body (its mesh, its keyframed translation and rotation), per fixture and per trace. Every
//! mesh is a set of triangle primitives without indices or normals, one per colour; traces
//! are line strips. One animation holds two channels per body, linear in translation and
//! spherical-linear in rotation, over the body's keyframe times.

use std::collections::HashMap;

use gltf_json as json;
use json::validation::{Checked::Valid, USize64};
use json::{Index, Root};

use crate::animation::{Animation, Track};
use crate::error::AnimateError;
use crate::glb;
use crate::parts::{Group, Rgb};

/// The root node's rotation (x, y, z, w): −90° about x, from z up to y up.
pub const Z_UP_TO_Y_UP: [f32; 4] = [
    -std::f32::consts::FRAC_1_SQRT_2,
    0.0,
    0.0,
    std::f32::consts::FRAC_1_SQRT_2,
];

/// One body's keyframes as written: times [s of playback], translations, rotations (x, y, z, w).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Keyframes {
    /// Playback times, strictly increasing from 0 for the first body to start.
    pub times: Vec<f32>,
    /// Translations, space axes (z up).
    pub translations: Vec<[f32; 3]>,
    /// Unit quaternions (x, y, z, w), each in the hemisphere of the one before (q and −q are
    /// the same turn; the choice keeps the interpolation on the short arc).
    pub rotations: Vec<[f32; 4]>,
}

/// The keyframes of `track`, its times shifted by `start` and scaled by `scale`. A sample
/// whose time, in f32, does not pass the one before is left out: glTF asks for strictly
/// increasing times (a trajectory may record one instant twice).
pub(crate) fn keyframes(track: &Track, start: f64, scale: f64) -> Keyframes {
    let mut k = Keyframes::default();
    let mut last: Option<[f64; 4]> = None;
    for (t, pose) in track.times.iter().zip(&track.poses) {
        let time = ((t - start) * scale) as f32;
        if k.times.last().is_some_and(|&prev| time <= prev) {
            continue;
        }
        let q = pose.attitude.quaternion();
        let mut c = [q.i, q.j, q.k, q.w];
        if let Some(p) = last
            && p.iter().zip(&c).map(|(a, b)| a * b).sum::<f64>() < 0.0
        {
            c = c.map(|v| -v);
        }
        last = Some(c);
        k.times.push(time);
        k.translations.push(pose.position.map(|v| v as f32).into());
        k.rotations.push(c.map(|v| v as f32));
    }
    k
}

/// The binary buffer being filled and the JSON objects that point into it.
struct Writer {
    root: Root,
    bin: Vec<u8>,
    materials: HashMap<[u32; 3], Index<json::Material>>,
}

impl Writer {
    /// A buffer view over `bytes`, 4-aligned.
    fn view(
        &mut self,
        bytes: &[u8],
        target: Option<json::buffer::Target>,
    ) -> Index<json::buffer::View> {
        self.bin.resize(self.bin.len().next_multiple_of(4), 0);
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.root.push(json::buffer::View {
            buffer: Index::new(0),
            byte_length: USize64(bytes.len() as u64),
            byte_offset: Some(USize64(offset as u64)),
            byte_stride: None,
            name: None,
            target: target.map(Valid),
            extensions: None,
            extras: Default::default(),
        })
    }

    /// A float accessor of `N` components per element, with its per-component min and max.
    fn floats<const N: usize>(
        &mut self,
        data: &[[f32; N]],
        type_: json::accessor::Type,
        target: Option<json::buffer::Target>,
    ) -> Index<json::Accessor> {
        let bytes: Vec<u8> = data
            .iter()
            .flatten()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let view = self.view(&bytes, target);
        let (mut lo, mut hi) = ([f32::INFINITY; N], [f32::NEG_INFINITY; N]);
        for d in data {
            for c in 0..N {
                lo[c] = lo[c].min(d[c]);
                hi[c] = hi[c].max(d[c]);
            }
        }
        self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64(data.len() as u64),
            component_type: Valid(json::accessor::GenericComponentType(
                json::accessor::ComponentType::F32,
            )),
            extensions: None,
            extras: Default::default(),
            type_: Valid(type_),
            min: Some(json::Value::from(lo.to_vec())),
            max: Some(json::Value::from(hi.to_vec())),
            name: None,
            normalized: false,
            sparse: None,
        })
    }

    /// The matte material of `colour`, one per colour.
    fn material(&mut self, colour: Rgb) -> Index<json::Material> {
        let key = colour.map(f32::to_bits);
        if let Some(m) = self.materials.get(&key) {
            return *m;
        }
        let mut m = json::Material {
            double_sided: true,
            ..Default::default()
        };
        m.pbr_metallic_roughness.base_color_factor =
            json::material::PbrBaseColorFactor([colour[0], colour[1], colour[2], 1.0]);
        m.pbr_metallic_roughness.metallic_factor = json::material::StrengthFactor(0.0);
        m.pbr_metallic_roughness.roughness_factor = json::material::StrengthFactor(0.9);
        let index = self.root.push(m);
        self.materials.insert(key, index);
        index
    }

    /// A primitive of `points` drawn as `mode` in `colour`.
    fn primitive(
        &mut self,
        points: &[[f32; 3]],
        colour: Rgb,
        mode: json::mesh::Mode,
    ) -> json::mesh::Primitive {
        let positions = self.floats(
            points,
            json::accessor::Type::Vec3,
            Some(json::buffer::Target::ArrayBuffer),
        );
        let material = self.material(colour);
        json::mesh::Primitive {
            attributes: [(Valid(json::mesh::Semantic::Positions), positions)].into(),
            extensions: None,
            extras: Default::default(),
            indices: None,
            material: Some(material),
            mode: Valid(mode),
            targets: None,
        }
    }

    /// A node holding a mesh of `primitives` named `name`.
    fn mesh_node(
        &mut self,
        name: &str,
        primitives: Vec<json::mesh::Primitive>,
    ) -> Index<json::Node> {
        let mesh = self.root.push(json::Mesh {
            extensions: None,
            extras: Default::default(),
            name: Some(name.to_string()),
            primitives,
            weights: None,
        });
        self.root.push(json::Node {
            mesh: Some(mesh),
            name: Some(name.to_string()),
            ..Default::default()
        })
    }

    /// The triangle primitives of `groups`, empty groups left out.
    fn groups(&mut self, groups: &[Group]) -> Vec<json::mesh::Primitive> {
        groups
            .iter()
            .filter(|g| !g.triangles.is_empty())
            .map(|g| {
                let pts: Vec<[f32; 3]> = g
                    .triangles
                    .iter()
                    .flatten()
                    .map(|p| p.map(|v| v as f32))
                    .collect();
                self.primitive(&pts, g.colour, json::mesh::Mode::Triangles)
            })
            .collect()
    }
}

impl Animation {
    /// The glTF document and its binary buffer (the buffer's `byteLength` is the buffer's
    /// length padded to 4; it has no `uri`, as a `.glb`'s buffer is its binary chunk).
    ///
    /// # Errors
    /// [`AnimateError::TooLarge`] past glTF's 4 GiB limit.
    pub fn to_gltf(&self) -> Result<(Root, Vec<u8>), AnimateError> {
        let mut w = Writer {
            root: Root::default(),
            bin: Vec::new(),
            materials: HashMap::new(),
        };
        w.root.asset.generator = Some(format!("precess-animate {}", env!("CARGO_PKG_VERSION")));
        let (start, scale) = (self.start(), self.time_scale);
        let mut children = Vec::new();
        let mut channels = Vec::new();
        let mut samplers = Vec::new();
        for track in &self.tracks {
            let prims = w.groups(&track.groups);
            let node = w.mesh_node(&track.name, prims);
            children.push(node);
            let k = keyframes(track, start, scale);
            let times: Vec<[f32; 1]> = k.times.iter().map(|t| [*t]).collect();
            let input = w.floats(&times, json::accessor::Type::Scalar, None);
            let moves = w.floats(&k.translations, json::accessor::Type::Vec3, None);
            let turns = w.floats(&k.rotations, json::accessor::Type::Vec4, None);
            for (output, path) in [
                (moves, json::animation::Property::Translation),
                (turns, json::animation::Property::Rotation),
            ] {
                channels.push(json::animation::Channel {
                    sampler: Index::new(samplers.len() as u32),
                    target: json::animation::Target {
                        node,
                        path: Valid(path),
                        extensions: None,
                        extras: Default::default(),
                    },
                    extensions: None,
                    extras: Default::default(),
                });
                samplers.push(json::animation::Sampler {
                    input,
                    interpolation: Valid(json::animation::Interpolation::Linear),
                    output,
                    extensions: None,
                    extras: Default::default(),
                });
            }
        }
        for fixture in &self.fixtures {
            let prims = w.groups(&fixture.groups);
            children.push(w.mesh_node(&fixture.name, prims));
        }
        for trace in &self.traces {
            let pts: Vec<[f32; 3]> = trace.points.iter().map(|p| p.map(|v| v as f32)).collect();
            let prim = w.primitive(&pts, trace.colour, json::mesh::Mode::LineStrip);
            children.push(w.mesh_node(&trace.name, vec![prim]));
        }
        let root_node = w.root.push(json::Node {
            children: Some(children),
            name: Some("precess space (z up)".into()),
            rotation: Some(json::scene::UnitQuaternion(Z_UP_TO_Y_UP)),
            ..Default::default()
        });
        let scene = w.root.push(json::Scene {
            extensions: None,
            extras: Default::default(),
            name: Some("run".into()),
            nodes: vec![root_node],
        });
        w.root.scene = Some(scene);
        if !channels.is_empty() {
            w.root.push(json::Animation {
                extensions: None,
                extras: Default::default(),
                channels,
                name: Some("run".into()),
                samplers,
            });
        }
        w.bin.resize(w.bin.len().next_multiple_of(4), 0);
        let bytes = w.bin.len() as u64;
        if bytes > u64::from(u32::MAX) - 64 {
            return Err(AnimateError::TooLarge { bytes });
        }
        // A buffer of no bytes is not allowed (byteLength ≥ 1): an animation with nothing in
        // it has none.
        if bytes > 0 {
            w.root.push(json::Buffer {
                byte_length: USize64(bytes),
                name: None,
                uri: None,
                extensions: None,
                extras: Default::default(),
            });
        }
        Ok((w.root, w.bin))
    }

    /// The animation as a binary glTF 2.0 file (`.glb`), which Blender, three.js and any glTF
    /// viewer play, and [`crate::page`] embeds.
    ///
    /// # Errors
    /// [`AnimateError::TooLarge`] past glTF's 4 GiB limit; [`AnimateError::Json`] if the JSON
    /// cannot be written.
    pub fn to_glb(&self) -> Result<Vec<u8>, AnimateError> {
        let (root, bin) = self.to_gltf()?;
        glb::write(&root.to_vec()?, &bin)
    }
}
