//! Axis ranges from the data, and tick labels that read well.

/// How an axis maps values to positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    /// Equal distances for equal differences.
    #[default]
    Linear,
    /// Equal distances for equal ratios (decades); every value must be positive.
    Log,
}

/// The range an axis shows for data spanning `lo..=hi`: the data with a margin on each side.
///
/// Linear: 5 % of the span on each side (at least 10⁻⁹ of the largest magnitude, so that a
/// quantity constant to rounding still gets a readable axis); a single value v ≠ 0 gets
/// ±5 % of |v|, and 0 gets ±1. Logarithmic: 5 % of the span in decades on each side, at least 0.1 decade (a factor
/// 10^0.1 ≈ 1.26; never past 10^±305), so that points on the frame stay visible. `lo` and
/// `hi` must be finite with
/// `lo ≤ hi` (and positive for [`Scale::Log`]); the figures check their data before asking.
///
/// # Examples
/// ```
/// use precess::plot::{Scale, axis_range};
/// assert_eq!(axis_range(0.0, 10.0, Scale::Linear), (-0.5, 10.5));
/// let (lo, hi) = axis_range(1e-6, 1e-2, Scale::Log);
/// // Four decades of data, 0.2 decade of margin each side.
/// assert!((lo.log10() + 6.2).abs() < 1e-12 && (hi.log10() + 1.8).abs() < 1e-12);
/// ```
pub fn axis_range(lo: f64, hi: f64, scale: Scale) -> (f64, f64) {
    match scale {
        Scale::Linear => {
            let span = hi - lo;
            let magnitude = lo.abs().max(hi.abs());
            let pad = if span > 0.0 {
                // A span of a few ulps (an energy conserved to 1e-16) is widened to 1e-9 of
                // the magnitude, and a subnormal one to 1e-300: a range narrower than the
                // spacing of the numbers in it has no ticks to step through.
                (0.05 * span).max(1e-9 * magnitude).max(1e-300)
            } else if lo != 0.0 {
                (0.05 * lo.abs()).max(1e-300)
            } else {
                1.0
            };
            (lo - pad, hi + pad)
        }
        Scale::Log => {
            let decades = (hi / lo).log10();
            let factor = 10f64.powf((0.05 * decades).max(0.1));
            // The margin stops short of the floating-point range's ends.
            ((lo / factor).max(1e-305), (hi * factor).min(1e305))
        }
    }
}

/// The smallest and largest of `values` (`None` when there are none).
pub(crate) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values.into_iter().fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// A tick label: plain decimals with at most six significant digits for magnitudes from
/// 10⁻³ to 10⁵, the exponent form (`2.5e-7`) otherwise, trailing zeros dropped either way,
/// so ticks read `0.25`, `1500`, `1e-6` rather than `0.25000000000000006` or `1.0e-6`.
///
/// # Examples
/// ```
/// use precess::plot::tick_label;
/// assert_eq!(tick_label(0.1 + 0.2), "0.3");
/// assert_eq!(tick_label(1500.0), "1500");
/// assert_eq!(tick_label(1e-6), "1e-6");
/// assert_eq!(tick_label(-2.5e7), "-2.5e7");
/// assert_eq!(tick_label(0.0), "0");
/// ```
pub fn tick_label(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        return "0".to_string();
    }
    if (1e-3..1e5).contains(&a) {
        // Six significant digits: as many decimals as the magnitude leaves.
        let decimals = (5 - a.log10().floor() as i32).clamp(0, 8) as usize;
        let s = format!("{v:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.')
        } else {
            &s
        };
        // −0.0000001 rounds to "-0".
        if s == "-0" { "0".into() } else { s.into() }
    } else {
        let s = format!("{v:.3e}");
        match s.split_once('e') {
            Some((mantissa, exponent)) => {
                let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
                format!("{mantissa}e{exponent}")
            }
            None => s,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_cover_the_data() {
        for (lo, hi) in [(0.0, 0.0), (3.0, 3.0), (-2.0, 7.0), (-1e-9, -1e-9)] {
            let (a, b) = axis_range(lo, hi, Scale::Linear);
            assert!(a < lo && hi < b, "{lo} {hi}: {a} {b}");
        }
        for (lo, hi) in [(1e-12, 1e-12), (1e-9, 1e3), (2.0, 3.0)] {
            let (a, b) = axis_range(lo, hi, Scale::Log);
            assert!(0.0 < a && a < lo && hi < b, "{lo} {hi}: {a} {b}");
        }
    }

    #[test]
    fn tick_labels_round_to_six_digits() {
        assert_eq!(tick_label(123.456789), "123.457");
        assert_eq!(tick_label(-0.004), "-0.004");
        assert_eq!(tick_label(2e-4), "2e-4");
        assert_eq!(tick_label(99999.0), "99999");
        assert_eq!(tick_label(1.0e5), "1e5");
    }
}
