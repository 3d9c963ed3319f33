//! Headless Chromium for the page's tests, and the viewer's camera computed on this side.

use std::path::{Path, PathBuf};
use std::process::Command;

use precess::animate::Camera;
use precess::nalgebra::{Matrix4, Point3, Vector3, Vector4};

/// The viewer's canvas, in pixels.
pub const CANVAS: (f64, f64) = (640.0, 480.0);

/// The Chromium to run: `PRECESS_CHROMIUM` if set, else `/usr/bin/chromium`; `None` (with
/// the reason printed) when there is none, and the test skips.
pub fn chromium() -> Option<PathBuf> {
    let path = std::env::var_os("PRECESS_CHROMIUM")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/bin/chromium"));
    if path.is_file() {
        Some(path)
    } else {
        println!(
            "skipped: no Chromium at {} (install Debian's chromium, or set PRECESS_CHROMIUM)",
            path.display()
        );
        None
    }
}

/// The flags of a headless run on a machine with no GPU and no network: WebGL through
/// SwiftShader, no background connections, a fresh profile in `profile`.
fn flags(profile: &Path) -> Vec<String> {
    [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--hide-scrollbars",
        "--window-size=1200,760",
        "--virtual-time-budget=3000",
    ]
    .iter()
    .map(|s| s.to_string())
    .chain([format!("--user-data-dir={}", profile.display())])
    .collect()
}

/// The page's DOM after its script ran (`--dump-dom`).
pub fn dump_dom(chromium: &Path, url: &str, profile: &Path) -> String {
    let out = Command::new(chromium)
        .args(flags(profile))
        .arg("--dump-dom")
        .arg(url)
        .output()
        .expect("chromium runs");
    assert!(
        out.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// A screenshot of the page as a PNG at `png`.
pub fn screenshot(chromium: &Path, url: &str, profile: &Path, png: &Path) {
    let out = Command::new(chromium)
        .args(flags(profile))
        .arg(format!("--screenshot={}", png.display()))
        .arg(url)
        .output()
        .expect("chromium runs");
    assert!(
        out.status.success() && png.is_file(),
        "no screenshot: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The pixels the page wrote into `#probe` (`x,y:r,g,b;…`), as ((x, y), [r, g, b]).
pub fn probes(dom: &str) -> Vec<((u32, u32), [u8; 3])> {
    let start = dom.find("<pre id=\"probe\">").expect("the probe element") + 16;
    let text = &dom[start..start + dom[start..].find("</pre>").expect("its end")];
    assert!(!text.contains("no webgl"), "the browser had no WebGL 2");
    text.split(';')
        .filter(|s| !s.is_empty())
        .map(|item| {
            let (xy, rgb) = item.split_once(':').expect("x,y:r,g,b");
            let n: Vec<u32> = xy.split(',').map(|v| v.parse().expect("a pixel")).collect();
            let c: Vec<u8> = rgb
                .split(',')
                .map(|v| v.parse().expect("a channel"))
                .collect();
            ((n[0], n[1]), [c[0], c[1], c[2]])
        })
        .collect()
}

/// Where the viewer draws the space point `p` (z up), in canvas pixels from the top-left:
/// the same view and projection as `viewer.js` (glTF's axes (x, y, z) = space (x, z, −y)).
pub fn project(camera: &Camera, p: Vector3<f64>) -> (f64, f64) {
    let gl = |v: [f64; 3]| Vector3::new(v[0], v[2], -v[1]);
    let target = gl(camera.target);
    let (yaw, pitch) = (camera.yaw.to_radians(), camera.pitch.to_radians());
    let eye = target
        + camera.distance
            * Vector3::new(
                pitch.cos() * yaw.sin(),
                pitch.sin(),
                pitch.cos() * yaw.cos(),
            );
    let view = Matrix4::look_at_rh(&Point3::from(eye), &Point3::from(target), &Vector3::y());
    let aspect = CANVAS.0 / CANVAS.1;
    let (near, far) = (camera.distance / 100.0, camera.distance * 100.0);
    let proj = Matrix4::new_perspective(aspect, camera.fovy.to_radians(), near, far);
    let c = proj * view * Vector4::new(p.x, p.z, -p.y, 1.0);
    let ndc = (c.x / c.w, c.y / c.w);
    (
        (ndc.0 + 1.0) / 2.0 * CANVAS.0,
        (1.0 - ndc.1) / 2.0 * CANVAS.1,
    )
}

/// The hue of an RGB colour in degrees and its saturation (max − min)/max.
pub fn hue(c: [u8; 3]) -> (f64, f64) {
    let [r, g, b] = c.map(|v| f64::from(v) / 255.0);
    let (hi, lo) = (r.max(g).max(b), r.min(g).min(b));
    if hi - lo < 1e-9 {
        return (0.0, 0.0);
    }
    let h = if hi == r {
        60.0 * ((g - b) / (hi - lo)).rem_euclid(6.0)
    } else if hi == g {
        60.0 * ((b - r) / (hi - lo) + 2.0)
    } else {
        60.0 * ((r - g) / (hi - lo) + 4.0)
    };
    (h, (hi - lo) / hi)
}

/// The URL of the page at `path` with the query `query`.
pub fn url(path: &Path, query: &str) -> String {
    format!("file://{}?{query}", path.display())
}
