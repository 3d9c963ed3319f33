//! The tippe top's page in headless Chromium: at the start its stem half (the sphere's half
//! on the body's +z side, drawn in the part's orange) is up, at the end it is down, at the
//! pixels where the projection of the computed sphere centre says; the sky above it is the
//! background, and the canvas is drawn by WebGL. Skips, saying why, without Chromium.

mod support;

use precess::animate::{self, Camera, Options, PageTable, TableState};
use precess::contact::{ContactDynamics, attitude_of};
use precess::nalgebra::Vector3;
use support::browser::{self, hue, project};
use support::{OFFSET, RADIUS, tippe_run};

/// The orange of the part (hue 31°) and its complement (211°), within 25°.
fn is_hue(c: [u8; 3], target: f64) -> bool {
    let (h, s) = hue(c);
    let d = (h - target).rem_euclid(360.0);
    s > 0.3 && d.min(360.0 - d) < 25.0
}

#[test]
fn the_tippe_top_turns_over_in_the_browser() {
    let Some(chromium) = browser::chromium() else {
        return;
    };
    let (model, run) = tippe_run(8.0, 0.01);
    let first = run.states()[0].table_state();
    let last = run.states()[run.len() - 1].table_state();
    // The run itself turned the top over (cos of the axis's tilt from +1 to −1).
    assert!((attitude_of(first) * Vector3::z()).z > 0.99);
    assert!((attitude_of(last) * Vector3::z()).z < -0.9);
    let animation = animate::contact(&model, &run, Options::default()).unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("animate-browser");
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("tippe_top.html");
    let table = PageTable {
        caption: "the inverted state".into(),
        rows: vec![(
            "final height of the centre of mass (m)".into(),
            model.contact(last).height,
            RADIUS + OFFSET,
        )],
    };
    animate::write_page(&page, &animation, "Tippe top", &table, None).unwrap();
    for (name, y, t) in [
        ("start", first, run.times()[0]),
        ("end", last, run.times()[run.len() - 1]),
    ] {
        // The sphere's centre in space, from the state: the centre of mass at (x, y, h)
        // and the centre αR above it along the body's z.
        let r = attitude_of(y);
        let cm = Vector3::new(y[0], y[1], model.contact(y).height);
        let centre = cm + r * Vector3::new(0.0, 0.0, OFFSET);
        let camera = Camera {
            target: centre.into(),
            distance: 0.2,
            yaw: 20.0,
            pitch: 8.0,
            fovy: 40.0,
        };
        let up = project(&camera, centre + Vector3::new(0.0, 0.0, 0.6 * RADIUS));
        let down = project(&camera, centre - Vector3::new(0.0, 0.0, 0.6 * RADIUS));
        let mid = project(&camera, centre);
        let sky = project(&camera, centre + Vector3::new(0.0, 0.0, 3.0 * RADIUS));
        let points = [up, down, mid, sky];
        let probe: Vec<String> = points
            .iter()
            .map(|(x, y)| format!("{},{}", x.round(), y.round()))
            .collect();
        let query = format!(
            "t={t}&yaw={}&pitch={}&dist={}&tx={}&ty={}&tz={}&probe={}",
            camera.yaw,
            camera.pitch,
            camera.distance,
            centre.x,
            centre.y,
            centre.z,
            probe.join(";")
        );
        let url = browser::url(&page, &query);
        let profile = dir.join(format!("profile-{name}"));
        let dom = browser::dump_dom(&chromium, &url, &profile);
        let pixels = browser::probes(&dom);
        assert_eq!(pixels.len(), 4, "{dom}");
        let [up, down, mid, sky] = [pixels[0].1, pixels[1].1, pixels[2].1, pixels[3].1];
        let (stem, foot) = if name == "start" {
            (up, down)
        } else {
            (down, up)
        };
        assert!(
            is_hue(stem, 31.0),
            "{name}: the stem half should be orange there, is {stem:?}"
        );
        assert!(
            is_hue(foot, 211.0),
            "{name}: the other half should be azure there, is {foot:?}"
        );
        assert!(
            is_hue(mid, 31.0) || is_hue(mid, 211.0),
            "{name}: the body is not at its centre: {mid:?}"
        );
        let background = animate::BACKGROUND.map(|v| (v * 255.0).round() as u8);
        assert!(
            sky.iter().zip(background).all(|(a, b)| a.abs_diff(b) <= 2),
            "{name}: above the top should be background, is {sky:?}"
        );
        browser::screenshot(
            &chromium,
            &url,
            &profile,
            &dir.join(format!("tippe_top_{name}.png")),
        );
    }
    println!("screenshots and page in {}", dir.display());
}
