//! The examples' animations: a run's `.glb` and its page beside the figures
//! (`precess::animate`, docs/animation.md).

use std::error::Error;
use std::path::Path;
use std::time::Instant;

use precess::animate::{self, Animation, PageTable};
use precess::ode::Trajectory;

use super::Table;

/// The samples of `run` from time `start` on, at least `dt` apart (the first of them always
/// kept): a run recorded at every step, or finer than a viewer needs, thinned so that its
/// `.glb` stays small.
pub fn thinned<St: Clone>(
    run: &Trajectory<St>,
    start: f64,
    dt: f64,
) -> Result<Trajectory<St>, Box<dyn Error>> {
    let mut out = Trajectory::new(vec![]);
    let mut last = f64::NEG_INFINITY;
    for (t, y) in run.times().iter().zip(run.states()) {
        if *t >= start && *t >= last + dt {
            out.push(*t, y.clone(), &[])?;
            last = *t;
        }
    }
    Ok(out)
}

/// Writes `<name>.glb` and `<name>.html` into `dir`: the animation, and the page that plays
/// it titled `title` beside `table` (under `caption`); prints both paths, their sizes and
/// the time taken.
pub fn write_animation(
    dir: &Path,
    name: &str,
    title: &str,
    animation: &Animation,
    table: &Table,
    caption: &str,
) -> Result<(), Box<dyn Error>> {
    let started = Instant::now();
    let (glb, page) = (
        dir.join(format!("{name}.glb")),
        dir.join(format!("{name}.html")),
    );
    animation.write_glb(&glb)?;
    let table = PageTable {
        caption: caption.to_string(),
        rows: table.rows.clone(),
    };
    animate::write_page(&page, animation, title, &table, None)?;
    let size = |p: &Path| std::fs::metadata(p).map_or(0, |m| m.len() / 1024);
    println!(
        "animation: {} ({} KiB), {} ({} KiB), {:.1} s of playback, written in {:.0} ms",
        glb.display(),
        size(&glb),
        page.display(),
        size(&page),
        animation.duration(),
        1e3 * started.elapsed().as_secs_f64()
    );
    Ok(())
}
