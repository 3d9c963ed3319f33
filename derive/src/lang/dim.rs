//! Dimensions: the exponents of mass, length, time and angle a value carries, and the rule
//! by which a key's dimension admits a value's.
//!
//! SI counts the radian as 1, so a number without units is a radian wherever an angle
//! belongs. The checker still tracks the angle's exponent, because a value written with an
//! angle unit where a pure number belongs (`mu = 30 deg`) is a mistake that SI's rule would
//! turn into a silent 0.5236.

/// A physical dimension: the exponents of mass, length, time and angle.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
pub struct Dim {
    /// The exponent of mass.
    pub m: i8,
    /// The exponent of length.
    pub l: i8,
    /// The exponent of time.
    pub t: i8,
    /// The exponent of angle (rad). A value with no angle unit has 0, and is admitted as
    /// radians where an angle belongs ([`Dim::admits`]).
    pub a: i8,
}

/// A dimension with no angle in it.
pub const fn dim(m: i8, l: i8, t: i8) -> Dim {
    Dim { m, l, t, a: 0 }
}

/// A dimension with the angle's exponent `a`.
pub const fn angular(m: i8, l: i8, t: i8, a: i8) -> Dim {
    Dim { m, l, t, a }
}

impl Dim {
    /// A pure number, which no angle unit may be written into (a friction coefficient, an
    /// axis's components).
    pub const NONE: Dim = dim(0, 0, 0);
    /// An angle: rad, `deg`, `rev`, or a number without units (in rad).
    pub const ANGLE: Dim = angular(0, 0, 0, 1);
    /// An angular rate, rad/s: `rpm`, `rev/s`, `rad/s`, or `s^-1`.
    pub const ANGULAR_RATE: Dim = angular(0, 0, -1, 1);
    /// kg.
    pub const MASS: Dim = dim(1, 0, 0);
    /// m.
    pub const LENGTH: Dim = dim(0, 1, 0);
    /// kg/m³.
    pub const DENSITY: Dim = dim(1, -3, 0);
    /// kg m².
    pub const INERTIA: Dim = dim(1, 2, 0);
    /// m/s².
    pub const ACCELERATION: Dim = dim(0, 1, -2);
    /// N = kg m/s².
    pub const FORCE: Dim = dim(1, 1, -2);
    /// N m = kg m²/s².
    pub const TORQUE: Dim = dim(1, 2, -2);
    /// kg/s: a drag force per speed.
    pub const DRAG: Dim = dim(1, 0, -1);
    /// N m s per rad: a damping torque per angular rate (`1e-5 N m / rpm`, or `N m s`).
    pub const ROTARY_DAMPING: Dim = angular(1, 2, -1, -1);
    /// N m per rad: a rotary spring's torque per angle (`N m / deg`, or `N m`).
    pub const ROTARY_STIFFNESS: Dim = angular(1, 2, -2, -1);
    /// N/m = kg/s²: a spring's force per stretch.
    pub const STIFFNESS: Dim = dim(1, 0, -2);

    /// Whether a key of this dimension takes a value of dimension `v`: the same exponents of
    /// mass, length and time, and the same angle, or none where the key has one (SI's
    /// radian is 1: `3 s^-1` is 3 rad/s). A key without an angle takes none: `30 deg` is
    /// no friction coefficient.
    pub fn admits(self, v: Dim) -> bool {
        (self.m, self.l, self.t) == (v.m, v.l, v.t) && (v.a == self.a || v.a == 0)
    }

    /// Whether a sum of values of dimensions `self` and `o` has one dimension: the same
    /// exponents, an angle on one side only allowed (`3000 rpm + 2 s^-1`, the second in rad/s).
    pub fn sum(self, o: Dim) -> Option<Dim> {
        let same = (self.m, self.l, self.t) == (o.m, o.l, o.t);
        match (same, self.a, o.a) {
            (false, _, _) => None,
            (true, a, b) if a == b || b == 0 => Some(self),
            (true, 0, _) => Some(o),
            _ => None,
        }
    }

    /// The product's dimension; `None` past the exponents' range (no real unit gets there).
    pub fn times(self, o: Dim) -> Option<Dim> {
        Some(angular(
            self.m.checked_add(o.m)?,
            self.l.checked_add(o.l)?,
            self.t.checked_add(o.t)?,
            self.a.checked_add(o.a)?,
        ))
    }

    /// The dimension to the power `n`.
    pub fn pow(self, n: i64) -> Option<Dim> {
        let n = i8::try_from(n).ok()?;
        Some(angular(
            self.m.checked_mul(n)?,
            self.l.checked_mul(n)?,
            self.t.checked_mul(n)?,
            self.a.checked_mul(n)?,
        ))
    }

    /// The square root's dimension, if every exponent is even.
    pub fn sqrt(self) -> Option<Dim> {
        let even = [self.m, self.l, self.t, self.a].iter().all(|e| e % 2 == 0);
        even.then(|| angular(self.m / 2, self.l / 2, self.t / 2, self.a / 2))
    }

    /// What the errors call it: its name and its SI unit, `a length (m)`.
    pub fn describe(self) -> String {
        const NAMED: &[(Dim, &str)] = &[
            (Dim::NONE, "a pure number"),
            (Dim::ANGLE, "an angle (rad, or `deg`, `rev`)"),
            (
                Dim::ANGULAR_RATE,
                "an angular rate (rad/s, or `rpm`, `rev/s`)",
            ),
            (Dim::MASS, "a mass (kg)"),
            (Dim::LENGTH, "a length (m)"),
            (dim(0, 0, 1), "a time (s)"),
            (dim(0, 0, -1), "a rate (1/s)"),
            (dim(0, 1, -1), "a speed (m/s)"),
            (Dim::ACCELERATION, "an acceleration (m/s^2)"),
            (Dim::DENSITY, "a density (kg/m^3)"),
            (Dim::INERTIA, "a moment of inertia (kg m^2)"),
            (Dim::FORCE, "a force (N)"),
            (Dim::TORQUE, "a torque (N m)"),
            (Dim::DRAG, "a drag coefficient (kg/s)"),
            (Dim::ROTARY_DAMPING, "a rotary damping coefficient (N m s)"),
            (Dim::ROTARY_STIFFNESS, "a rotary stiffness (N m per rad)"),
            (Dim::STIFFNESS, "a stiffness (N/m)"),
        ];
        if let Some((_, name)) = NAMED.iter().find(|(d, _)| *d == self) {
            return (*name).to_owned();
        }
        let parts: Vec<String> = [
            ("kg", self.m),
            ("m", self.l),
            ("s", self.t),
            ("rad", self.a),
        ]
        .iter()
        .filter(|(_, n)| *n != 0)
        .map(|(u, n)| {
            if *n == 1 {
                (*u).to_owned()
            } else {
                format!("{u}^{n}")
            }
        })
        .collect();
        format!("a quantity in {}", parts.join(" "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_angle_fills_an_angle_slot_and_no_pure_one() {
        // SI's radian is 1: a number without an angle unit is radians where an angle belongs.
        assert!(Dim::ANGLE.admits(Dim::NONE));
        assert!(Dim::ANGULAR_RATE.admits(dim(0, 0, -1)));
        assert!(Dim::ROTARY_DAMPING.admits(dim(1, 2, -1)));
        // An angle where a pure number belongs is the mistake the angle's exponent catches.
        assert!(!Dim::NONE.admits(Dim::ANGLE));
        assert!(!Dim::TORQUE.admits(angular(1, 2, -2, 1)));
        assert!(!Dim::ANGLE.admits(angular(0, 0, 0, 2)));
        assert_eq!(Dim::ANGLE.sum(Dim::NONE), Some(Dim::ANGLE));
        assert_eq!(Dim::NONE.sum(Dim::ANGLE), Some(Dim::ANGLE));
        assert_eq!(Dim::LENGTH.sum(Dim::MASS), None);
        assert_eq!(Dim::ANGLE.sum(angular(0, 0, 0, -1)), None);
    }
}
