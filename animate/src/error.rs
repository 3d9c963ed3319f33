//! The one error of `precess::animate`.

use std::path::PathBuf;

/// Why an animation or its page could not be made.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum AnimateError {
    /// A part's values draw nothing.
    #[error("part {index} ({kind}) cannot be drawn: {why}")]
    BadPart {
        /// The part's position in the description.
        index: usize,
        /// The part's kind as the attribute language spells it.
        kind: &'static str,
        /// What is wrong with it.
        why: &'static str,
    },
    /// A contact surface's values draw nothing.
    #[error("the {surface} surface cannot be drawn: {why}")]
    BadSurface {
        /// The surface's name.
        surface: &'static str,
        /// What is wrong with it.
        why: &'static str,
    },
    /// The time scale is not a positive finite number.
    #[error(
        "the time scale must be a positive finite number of seconds shown per second simulated, not {scale}"
    )]
    BadTimeScale {
        /// The scale given.
        scale: f64,
    },
    /// A body was given no samples to keyframe.
    #[error("body {body:?} has no samples: an animation needs at least one")]
    NoSamples {
        /// The body's name.
        body: String,
    },
    /// A sample's time or pose is NaN or infinite.
    #[error(
        "sample {index} of body {body:?} (t = {t}) has a non-finite time, position or attitude"
    )]
    NonFinite {
        /// The body's name.
        body: String,
        /// The sample's index in the trajectory.
        index: usize,
        /// Its time.
        t: f64,
    },
    /// A sample's time comes before the previous one's.
    #[error(
        "sample {index} of body {body:?} is at t = {t}, before the previous sample at {previous}"
    )]
    DecreasingTime {
        /// The body's name.
        body: String,
        /// The sample's index.
        index: usize,
        /// Its time.
        t: f64,
        /// The previous sample's time.
        previous: f64,
    },
    /// The page's camera has a non-finite value, a distance not positive or a field of view
    /// outside (0°, 180°).
    #[error(
        "the camera needs finite values, a positive distance and a field of view in (0°, 180°), not distance {distance} m and field of view {fovy}°"
    )]
    BadCamera {
        /// The distance given.
        distance: f64,
        /// The field of view given (degrees).
        fovy: f64,
    },
    /// A trace has a non-finite point, or fewer than two points.
    #[error(
        "trace {trace:?} needs two or more finite points (point {index} of {len} is not usable)"
    )]
    BadTrace {
        /// The trace's name.
        trace: String,
        /// The first bad point (or the length when too short).
        index: usize,
        /// The number of points.
        len: usize,
    },
    /// The file would pass glTF's 4 GiB limit on a binary chunk.
    #[error(
        "the binary chunk would hold {bytes} bytes, past glTF's limit of 2³² − 1: sample the run less often"
    )]
    TooLarge {
        /// Its size.
        bytes: u64,
    },
    /// Bytes read as a `.glb` are not one: what is wrong, at which byte.
    #[error("not a binary glTF: {why} (at byte {at})")]
    BadGlb {
        /// What is wrong.
        why: &'static str,
        /// The byte offset where it was found.
        at: usize,
    },
    /// The glTF JSON could not be written (serde_json's error).
    #[error("writing the glTF JSON: {0}")]
    Json(#[from] gltf_json::Error),
    /// A file could not be written.
    #[error("writing {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The system's error.
        source: std::io::Error,
    },
}
