//! The quaternion hook of the run loop: an attitude quaternion stored in a state array put
//! back on the unit sphere after every accepted step (free flights, bodies on a table).
//!
//! An embedded pair integrates q̇ = ½ q ⊗ ω componentwise, so |q| drifts by the local
//! errors; the right-hand sides read q/|q| and the motion stays right, but a state handed
//! back to a user should hold a rotation. Normalising is the cheapest projection onto the
//! sphere (the nearest point), and it changes the state only by the step's own error.

/// Puts the quaternion `x[at..at + 4]` on the unit sphere, scaled by its largest component
/// first so that the norm of a tiny quaternion does not underflow; returns whether it
/// changed. One already of unit norm to rounding (|q|² within 4 ε of 1) is left as it is,
/// so that a projection after every step changes, and restarts, only what drifted. A zero
/// or non-finite quaternion (or one that does not fit in `x`) is left as it is too: it
/// names no rotation, and the next step's right-hand side reports it.
///
/// ```
/// use precess_core::rigid::normalise_quaternion;
/// let mut x = [7.0, 0.0, 3.0, 0.0, 4.0, 9.0];
/// assert!(normalise_quaternion(&mut x, 1));
/// assert_eq!(x, [7.0, 0.0, 0.6, 0.0, 0.8, 9.0]);
/// assert!(!normalise_quaternion(&mut x, 1)); // already unit: unchanged, bit for bit
/// ```
pub fn normalise_quaternion(x: &mut [f64], at: usize) -> bool {
    let Some(q) = x.get_mut(at..at + 4) else {
        return false;
    };
    let scale = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return false;
    }
    let norm2: f64 = q.iter().map(|v| v * v).sum();
    if (norm2 - 1.0).abs() <= 4.0 * f64::EPSILON {
        return false;
    }
    let scaled = [q[0] / scale, q[1] / scale, q[2] / scale, q[3] / scale];
    let norm = scaled.iter().map(|v| v * v).sum::<f64>().sqrt();
    q.copy_from_slice(&scaled.map(|v| v / norm));
    true
}
