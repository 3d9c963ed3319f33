//! One self-contained HTML page per run: the `.glb` (base64), the viewer (`viewer.js`, plain
//! WebGL 2, written for this crate) and the run's table, with nothing fetched at view time.

use std::fmt::Write as _;
use std::path::Path;

use precess_core::nalgebra::Vector3;

use crate::animation::Animation;
use crate::base64;
use crate::error::AnimateError;

/// The viewer's script.
const VIEWER: &str = include_str!("viewer.js");

/// The page's background, RGB in [0, 1]: a pale blue-grey, unlike any part's colour.
pub const BACKGROUND: [f32; 3] = [0.93, 0.95, 0.98];

/// The viewer's camera: it looks at `target` from `distance` away. In glTF's axes
/// (x, y up, z) = space (x, z, −y) the eye sits at target + distance (cos p sin y, sin p,
/// cos p cos y), p the pitch and y the yaw: yaw 0 looks from space −y towards +y, pitch 90°
/// looks straight down. The vertical field of view is `fovy` degrees. A page's query
/// (`?yaw=…&pitch=…&dist=…&tx=…&ty=…&tz=…`) overrides the values written into it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// The point looked at, in metres, space axes (z up).
    pub target: [f64; 3],
    /// The distance from it (m).
    pub distance: f64,
    /// The turn about the vertical (degrees).
    pub yaw: f64,
    /// The elevation above the horizontal (degrees).
    pub pitch: f64,
    /// The vertical field of view (degrees).
    pub fovy: f64,
}

impl Camera {
    /// A camera 20° above the horizontal, 30° round, framing the whole run: every body's
    /// bounding sphere (about the middle of its box) at every keyframe, and the traces, inside a
    /// sphere that fills 90 % of the height. (Framing the first keyframe alone lost a
    /// tumbling body's far end, or a top's disk as it precessed, out of the picture.)
    pub fn fit(animation: &Animation) -> Camera {
        // (centre, radius) of each sphere that must be seen.
        let mut spheres: Vec<(Vector3<f64>, f64)> = Vec::new();
        for track in &animation.tracks {
            // The sphere about the middle of the body's box in its own axes, carried by
            // each pose (about the node's origin instead, a top's sphere would be centred on
            // its pivot, half of it empty).
            let vertices = || {
                track
                    .groups
                    .iter()
                    .flat_map(|g| g.triangles.iter().flatten())
            };
            let (lo, hi) = vertices().fold(
                (
                    Vector3::repeat(f64::INFINITY),
                    Vector3::repeat(f64::NEG_INFINITY),
                ),
                |(lo, hi), p| (lo.inf(&Vector3::from(*p)), hi.sup(&Vector3::from(*p))),
            );
            let middle = if lo.x.is_finite() {
                (lo + hi) / 2.0
            } else {
                Vector3::zeros()
            };
            let reach = vertices()
                .map(|p| (Vector3::from(*p) - middle).norm())
                .fold(0.0, f64::max);
            spheres.extend(
                track
                    .poses
                    .iter()
                    .map(|pose| (pose.position + pose.attitude * middle, reach)),
            );
        }
        for trace in &animation.traces {
            spheres.extend(trace.points.iter().map(|p| (Vector3::from(*p), 0.0)));
        }
        let (lo, hi) = spheres.iter().fold(
            (
                Vector3::repeat(f64::INFINITY),
                Vector3::repeat(f64::NEG_INFINITY),
            ),
            |(lo, hi), (c, r)| (lo.inf(&c.add_scalar(-r)), hi.sup(&c.add_scalar(*r))),
        );
        let (centre, radius) = if spheres.is_empty() {
            (Vector3::zeros(), 1.0)
        } else {
            let centre = (lo + hi) / 2.0;
            let radius = spheres
                .iter()
                .map(|(c, r)| (c - centre).norm() + r)
                .fold(1e-3, f64::max);
            (centre, radius)
        };
        let fovy: f64 = 40.0;
        Camera {
            target: centre.into(),
            distance: radius / (0.9 * (fovy.to_radians() / 2.0).sin()),
            yaw: 30.0,
            pitch: 20.0,
            fovy,
        }
    }
}

/// The run's table beside the animation: quantities measured in the run against theory.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PageTable {
    /// The caption.
    pub caption: String,
    /// Rows of (quantity, measured, theory).
    pub rows: Vec<(String, f64, f64)>,
}

/// `s` with HTML's special characters escaped.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number as JavaScript reads it (non-finite ones as `null`, which the viewer never gets:
/// [`page`] checks the camera, and the time scale is checked where it is set).
fn js(v: f64) -> String {
    if v.is_finite() {
        format!("{v:?}")
    } else {
        "null".into()
    }
}

/// The page: `animation` playing in a WebGL canvas (640 × 480) with play/pause, a time
/// slider and an orbiting camera (`camera`, or [`Camera::fit`] when `None`), and `table`
/// beside it (each row with its relative difference |measured − theory| / |theory|, or the
/// absolute one against a theory of zero).
///
/// # Errors
/// As [`Animation::to_glb`]; [`AnimateError::BadCamera`] for a camera with a non-finite
/// value, a distance or a field of view not positive, or a field of view of 180° or more.
pub fn page(
    animation: &Animation,
    title: &str,
    table: &PageTable,
    camera: Option<Camera>,
) -> Result<String, AnimateError> {
    let glb = animation.to_glb()?;
    let cam = camera.unwrap_or_else(|| Camera::fit(animation));
    let finite = cam
        .target
        .iter()
        .chain([&cam.distance, &cam.yaw, &cam.pitch, &cam.fovy]);
    if !finite.into_iter().all(|v| v.is_finite())
        || cam.distance <= 0.0
        || !(cam.fovy > 0.0 && cam.fovy < 180.0)
    {
        return Err(AnimateError::BadCamera {
            distance: cam.distance,
            fovy: cam.fovy,
        });
    }
    let mut rows = String::new();
    for (name, measured, theory) in &table.rows {
        // Against a theory of zero the difference is absolute, and said so.
        let diff = (measured - theory).abs();
        let rel = if *theory == 0.0 {
            format!("{diff:.1e} (absolute)")
        } else {
            format!("{:.1e}", diff / theory.abs())
        };
        let _ = writeln!(
            rows,
            "<tr><td>{}</td><td>{measured:.6e}</td><td>{theory:.6e}</td><td>{rel}</td></tr>",
            escape(name)
        );
    }
    let start = animation.start();
    let mut html = String::with_capacity(glb.len() * 4 / 3 + VIEWER.len() + 4096);
    let _ = write!(
        html,
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title>
<style>
body {{ font: 13px sans-serif; margin: 12px; display: flex; gap: 16px; align-items: flex-start; }}
#side {{ max-width: 520px; }}
canvas {{ border: 1px solid #999; touch-action: none; cursor: grab; }}
table {{ border-collapse: collapse; }} td, th {{ padding: 2px 8px; border-bottom: 1px solid #ddd; text-align: right; }}
td:first-child, th:first-child {{ text-align: left; }} #probe {{ font-size: 10px; }}
</style></head>
<body>
<div><canvas id="view" width="640" height="480"></canvas>
<div><button id="play">play</button> <input id="slider" type="range" min="0" step="any" style="width: 420px">
<div id="time"></div><div>drag to turn the camera, scroll to zoom</div></div></div>
<div id="side"><h3>{title}</h3>
<table><caption>{caption}</caption>
<tr><th>quantity</th><th>measured</th><th>theory</th><th>relative difference</th></tr>
{rows}</table>
<p>time scale: {scale} s shown per s simulated</p><pre id="probe"></pre></div>
<script>
const GLB_BASE64 = "{glb}";
const CAMERA = {{ target: [{tx}, {ty}, {tz}], distance: {d}, yaw: {yaw}, pitch: {pitch}, fovy: {fovy} }};
const BACKGROUND = [{b0}, {b1}, {b2}];
const START = {start}, TIME_SCALE = {scale};
{viewer}</script>
</body></html>
"#,
        title = escape(title),
        caption = escape(&table.caption),
        scale = js(animation.time_scale),
        glb = base64::encode(&glb),
        tx = js(cam.target[0]),
        ty = js(cam.target[1]),
        tz = js(cam.target[2]),
        d = js(cam.distance),
        yaw = js(cam.yaw),
        pitch = js(cam.pitch),
        fovy = js(cam.fovy),
        b0 = BACKGROUND[0],
        b1 = BACKGROUND[1],
        b2 = BACKGROUND[2],
        start = js(if start.is_finite() { start } else { 0.0 }),
        viewer = VIEWER,
    );
    Ok(html)
}

/// Writes [`page`] to `path`.
///
/// # Errors
/// As [`page`], and [`AnimateError::Io`] if the file cannot be written.
pub fn write_page(
    path: impl AsRef<Path>,
    animation: &Animation,
    title: &str,
    table: &PageTable,
    camera: Option<Camera>,
) -> Result<(), AnimateError> {
    let path = path.as_ref();
    let html = page(animation, title, table, camera)?;
    std::fs::write(path, html).map_err(|source| AnimateError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Animation, Pose, part_groups};
    use precess_core::body::{Part, Shape};
    use precess_core::nalgebra::UnitQuaternion;

    fn ball() -> Animation {
        let parts = [Part::new(
            Shape::Sphere {
                mass: 1.0,
                radius: 0.1,
            },
            [0.0; 3],
        )];
        let groups = part_groups(&parts, None, 0.1).unwrap();
        let pose = Pose {
            position: Vector3::new(0.0, 0.0, 0.1),
            attitude: UnitQuaternion::identity(),
        };
        let mut a = Animation::new();
        a.add_body("ball", groups, [(0.0, pose), (1.0, pose)])
            .unwrap();
        a
    }

    #[test]
    fn the_page_fetches_nothing_and_escapes_its_text() {
        let table = PageTable {
            caption: "<b>".into(),
            rows: vec![("a & b".into(), 1.0, 0.0), ("c".into(), 1.5, 1.0)],
        };
        let html = page(&ball(), "x < y", &table, None).unwrap();
        // No address of any kind (':' is not a base64 character), no external script or style.
        for absent in ["://", " src=", " href=", "<link", "@import"] {
            assert!(!html.contains(absent), "the page holds {absent:?}");
        }
        assert!(
            html.contains("x &lt; y") && html.contains("&lt;b&gt;") && html.contains("a &amp; b")
        );
        assert!(html.contains("1.0e0 (absolute)") && html.contains("<td>5.0e-1</td>"));
    }

    #[test]
    fn a_bad_camera_is_refused() {
        let mut camera = Camera::fit(&ball());
        camera.fovy = 180.0;
        let err = page(&ball(), "", &PageTable::default(), Some(camera)).unwrap_err();
        assert!(matches!(err, AnimateError::BadCamera { fovy, .. } if fovy == 180.0));
    }
}
