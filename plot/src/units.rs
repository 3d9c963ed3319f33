//! Axis labels with units: the unit a column's name carries by the scenes' conventions (SI,
//! angles in radians), and the label "name (unit)" an axis is given.
//!
//! A trajectory's columns carry names only (`Trajectory::state_column_names`,
//! `Trajectory::quantity_names`); the units follow from the names the scenes give them, which
//! are fixed: a top's angles and their rates, a free body's position, velocity, quaternion
//! and body rates, and the quantities each scene reports (energy, power, momenta).

/// The SI unit of the column `name` as the scenes name their columns, `None` for a name with
/// no known unit (a user's own column, a quaternion component, a ratio).
///
/// | names | unit |
/// | --- | --- |
/// | `t` | s |
/// | angles: `phi`, `theta`, `psi`, `yaw`, `pitch`, `roll`, `φ`, `θ`, `ψ` | rad |
/// | `<angle>_dot`, `omega`, `omega_k`, `ωk` | rad/s |
/// | `x`, `y`, `z` | m |
/// | `vx`, `vy`, `vz`, `slip`, `<length>_dot` | m/s |
/// | `energy`, `kinetic`, `potential` | J |
/// | `power` | W |
/// | `normal` | N |
/// | `p`, `p_<length>` | kg·m/s |
/// | `L`, `L_x`, `L_y`, `L_z`, `p_<angle>` | kg·m²/s |
///
/// # Examples
/// ```
/// use precess::plot::unit_of;
/// assert_eq!(unit_of("theta_dot"), Some("rad/s"));
/// assert_eq!(unit_of("energy"), Some("J"));
/// assert_eq!(unit_of("p_psi"), Some("kg·m²/s"));
/// assert_eq!(unit_of("qw"), None);
/// ```
pub fn unit_of(name: &str) -> Option<&'static str> {
    if let Some(coordinate) = name.strip_prefix("p_") {
        // The momentum conjugate to an angle is an angular momentum, to a length a momentum.
        return match unit_of(coordinate)? {
            "rad" => Some("kg·m²/s"),
            "m" => Some("kg·m/s"),
            _ => None,
        };
    }
    if let Some(base) = name.strip_suffix("_dot") {
        return match unit_of(base)? {
            "rad" => Some("rad/s"),
            "m" => Some("m/s"),
            _ => None,
        };
    }
    if is_angle(name) {
        return Some("rad");
    }
    let rate = name.starts_with("omega") || name.starts_with('ω');
    Some(match name {
        "t" => "s",
        _ if rate => "rad/s",
        "x" | "y" | "z" => "m",
        "vx" | "vy" | "vz" | "slip" => "m/s",
        "energy" | "kinetic" | "potential" => "J",
        "power" => "W",
        "normal" => "N",
        "p" => "kg·m/s",
        "L" | "L_x" | "L_y" | "L_z" => "kg·m²/s",
        _ => return None,
    })
}

/// Whether `name` is one of the scenes' angle coordinates.
fn is_angle(name: &str) -> bool {
    matches!(
        name,
        "phi" | "theta" | "psi" | "yaw" | "pitch" | "roll" | "φ" | "θ" | "ψ"
    )
}

/// An axis label with its unit: `label (unit)`, or `label` alone for an empty unit.
///
/// ```
/// use precess::plot::with_unit;
/// assert_eq!(with_unit("initial spin ω3", "rad/s"), "initial spin ω3 (rad/s)");
/// assert_eq!(with_unit("λ/λ₀", ""), "λ/λ₀");
/// ```
pub fn with_unit(label: &str, unit: &str) -> String {
    if unit.is_empty() {
        label.to_string()
    } else {
        format!("{label} ({unit})")
    }
}

/// The label of an axis that shows the columns `names`: each name with its unit
/// ([`unit_of`]), a shared unit said once (`theta, phi (rad)`), `value` past three columns
/// (with their unit when they share one).
pub(crate) fn columns_label(names: &[&str]) -> String {
    let units: Vec<Option<&str>> = names.iter().map(|n| unit_of(n)).collect();
    let shared = units
        .first()
        .copied()
        .flatten()
        .filter(|u| units.iter().all(|v| *v == Some(*u)));
    match shared {
        Some(unit) if names.len() <= 3 => with_unit(&names.join(", "), unit),
        Some(unit) => with_unit("value", unit),
        None if names.len() <= 3 => names
            .iter()
            .zip(&units)
            .map(|(n, u)| with_unit(n, u.unwrap_or("")))
            .collect::<Vec<_>>()
            .join(", "),
        None => "value".to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_say_a_shared_unit_once() {
        assert_eq!(columns_label(&["theta", "phi"]), "theta, phi (rad)");
        assert_eq!(columns_label(&["x", "energy"]), "x (m), energy (J)");
        assert_eq!(columns_label(&["y0", "energy"]), "y0, energy (J)");
        assert_eq!(
            columns_label(&["L_x", "L_y", "L_z", "L"]),
            "value (kg·m²/s)"
        );
        assert_eq!(columns_label(&["a", "b", "c", "d"]), "value");
        assert_eq!(unit_of("x_dot"), Some("m/s"));
        assert_eq!(unit_of("p_x"), Some("kg·m/s"));
        assert_eq!(unit_of("p_q1"), None);
        assert_eq!(unit_of("omega_3"), Some("rad/s"));
    }
}
