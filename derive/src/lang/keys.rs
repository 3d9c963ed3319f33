//! The words of the attribute language, each written once: the attribute names, the parts
//! with their keys, the keys of `#[top]`, `#[free]`, `#[body]` and `#[mechanism]`, and the
//! "did you mean" suggestions over them. The checkers match against these constants and
//! every error message lists them from here, so a new part or key is one edit. The messages
//! for a word it does not know (and their "did you mean") are in `unknown.rs`.

mod unknown;

pub use unknown::{closest, did_you_mean, did_you_mean_part, known_key, unknown_key};

/// `#[rigid(...)]`: the body's parts and pivot.
pub const RIGID: &str = "rigid";
/// `#[top(...)]`: the body as a top about its pivot.
pub const TOP: &str = "top";

/// The mass of a part.
pub const MASS: &str = "mass";
/// The density of a solid part, instead of its mass: mass = density × volume.
pub const DENSITY: &str = "density";
/// A radius (sphere, shell, cylinder, disk, ring, cone).
pub const RADIUS: &str = "radius";
/// A full length, end to end (cylinder, tube, rod).
pub const LENGTH: &str = "length";
/// The height of a cone, base to apex.
pub const HEIGHT: &str = "height";
/// The inner radius of a tube.
pub const INNER: &str = "inner";
/// The outer radius of a tube.
pub const OUTER: &str = "outer";
/// The edges of a box, `[a, b, c]`.
pub const SIZE: &str = "size";
/// The semi-axes of an ellipsoid, `[a, b, c]`.
pub const SEMI_AXES: &str = "semi_axes";
/// The inertia tensor of an explicit body.
pub const INERTIA: &str = "inertia";
/// Where a part sits.
pub const AT: &str = "at";
/// The explicit body's alias of [`AT`]: its centre of mass.
pub const CENTER: &str = "center";
/// The symmetry axis of an axisymmetric part.
pub const AXIS: &str = "axis";
/// The rotation of a part with axes, from its own axes to description axes.
pub const ROTATE: &str = "rotate";
/// The point an explicit tensor is taken about.
pub const ABOUT: &str = "about";
/// The body's fixed point, a top-level key of `#[rigid]`.
pub const PIVOT: &str = "pivot";

/// The kinds of part, one per row of [`PARTS`].
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum PartKind {
    /// A point mass.
    Particle,
    /// A solid sphere.
    Sphere,
    /// A thin spherical shell.
    Shell,
    /// A solid box.
    Cuboid,
    /// A solid cylinder.
    Cylinder,
    /// A thick-walled tube.
    Tube,
    /// A thin disk.
    Disk,
    /// A thin ring.
    Ring,
    /// A thin rod.
    Rod,
    /// A solid cone.
    Cone,
    /// A solid ellipsoid.
    Ellipsoid,
    /// A body given by its mass, centre and tensor.
    Explicit,
}

/// One part of the language: its name, an alias, and its keys.
pub struct PartKeys {
    /// What it is.
    pub kind: PartKind,
    /// Its name in `#[rigid]` (and in precess-core's errors).
    pub name: &'static str,
    /// Another name accepted for it.
    pub alias: Option<&'static str>,
    /// Keys it must have.
    pub required: &'static [&'static str],
    /// Keys it may have.
    pub optional: &'static [&'static str],
    /// True for a solid, whose `mass` may be given as a [`DENSITY`] instead.
    pub solid: bool,
}

impl PartKeys {
    /// Every key it accepts, required first.
    pub fn allowed(&self) -> impl Iterator<Item = &'static str> {
        let density: &[&str] = if self.solid { &[DENSITY] } else { &[] };
        self.required
            .iter()
            .chain(self.optional)
            .chain(density)
            .copied()
    }

    /// The key `written` stands for in this part (`center` is the explicit body's `at`).
    pub fn key(&self, written: &str) -> Option<&'static str> {
        let written = if self.kind == PartKind::Explicit && written == CENTER {
            AT
        } else {
            written
        };
        self.allowed().find(|&k| k == written)
    }

    /// The message for `written`, a key this part does not take: its keys, then a solid's
    /// [`DENSITY`] (in place of its mass) and the explicit body's [`CENTER`] (its `at`).
    pub fn unknown_key(&self, written: &str) -> String {
        let keys: Vec<&str> = self.required.iter().chain(self.optional).copied().collect();
        let mut others: Vec<(&[&str], String)> = Vec::new();
        if self.solid {
            others.push((&[DENSITY], format!("`{DENSITY}` in place of `{MASS}`")));
        }
        if self.kind == PartKind::Explicit {
            others.push((&[CENTER], format!("`{CENTER}` for `{AT}`")));
        }
        unknown_key(written, &format!("for `{}`", self.name), &keys, &others)
    }
}

const PLACED: &[&str] = &[AT];
// A part with axes may be turned; a particle, sphere or shell looks the same at any turn.
const PLACED_TURNED: &[&str] = &[AT, ROTATE];
const PLACED_ON_AXIS: &[&str] = &[AT, AXIS, ROTATE];

/// Every part, in the order the docs list them.
pub const PARTS: &[PartKeys] = &[
    part(PartKind::Particle, "particle", &[MASS], PLACED),
    part(PartKind::Sphere, "sphere", &[MASS, RADIUS], PLACED),
    part(PartKind::Shell, "shell", &[MASS, RADIUS], PLACED),
    PartKeys {
        alias: Some("box"),
        ..part(PartKind::Cuboid, "cuboid", &[MASS, SIZE], PLACED_TURNED)
    },
    part(
        PartKind::Cylinder,
        "cylinder",
        &[MASS, RADIUS, LENGTH],
        PLACED_ON_AXIS,
    ),
    part(
        PartKind::Tube,
        "tube",
        &[MASS, INNER, OUTER, LENGTH],
        PLACED_ON_AXIS,
    ),
    part(PartKind::Disk, "disk", &[MASS, RADIUS], PLACED_ON_AXIS),
    part(PartKind::Ring, "ring", &[MASS, RADIUS], PLACED_ON_AXIS),
    part(PartKind::Rod, "rod", &[MASS, LENGTH], PLACED_ON_AXIS),
    part(
        PartKind::Cone,
        "cone",
        &[MASS, RADIUS, HEIGHT],
        PLACED_ON_AXIS,
    ),
    part(
        PartKind::Ellipsoid,
        "ellipsoid",
        &[MASS, SEMI_AXES],
        PLACED_TURNED,
    ),
    part(
        PartKind::Explicit,
        "body",
        &[MASS, INERTIA],
        &[AT, ABOUT, ROTATE],
    ),
];

const fn part(
    kind: PartKind,
    name: &'static str,
    required: &'static [&'static str],
    optional: &'static [&'static str],
) -> PartKeys {
    PartKeys {
        kind,
        name,
        alias: None,
        required,
        optional,
        solid: matches!(
            kind,
            PartKind::Sphere
                | PartKind::Cuboid
                | PartKind::Cylinder
                | PartKind::Tube
                | PartKind::Cone
                | PartKind::Ellipsoid
        ),
    }
}

/// The part called `written`, by its name or its alias.
pub fn find_part(written: &str) -> Option<&'static PartKeys> {
    PARTS
        .iter()
        .find(|p| p.name == written || p.alias == Some(written))
}

/// The parts as the messages list them: `particle, sphere, …, cuboid (or box), …`.
pub fn part_list() -> String {
    let names: Vec<String> = PARTS
        .iter()
        .map(|p| match p.alias {
            Some(alias) => format!("{} (or {alias})", p.name),
            None => p.name.to_owned(),
        })
        .collect();
    names.join(", ")
}

/// g along −z in space.
pub const GRAVITY: &str = "gravity";
/// A constant torque fixed in the body.
pub const BODY_TORQUE: &str = "body_torque";
/// A constant torque fixed in space.
pub const SPACE_TORQUE: &str = "space_torque";
/// Linear damping −c ω.
pub const DAMPING: &str = "damping";
/// A user torque function.
pub const TORQUE: &str = "torque";
/// The angle sequence of the generalised coordinates.
pub const ANGLES: &str = "angles";

/// The maximum order of the generated Taylor recurrences (`impl TaylorSystem`).
pub const TAYLOR: &str = "taylor";

/// The keys of `#[top(...)]`, in the order the docs list them.
pub const TOP_KEYS: &[&str] = &[
    GRAVITY,
    BODY_TORQUE,
    SPACE_TORQUE,
    DAMPING,
    TORQUE,
    ANGLES,
    TAYLOR,
];

/// `#[free(...)]`: the body as a free body under the declared forces.
pub const FREE: &str = "free";
/// A force fixed in the body at a body point (a thruster), a part of `#[free]`.
pub const BODY_FORCE: &str = "body_force";
/// A force fixed in space at a body point, a part of `#[free]`.
pub const SPACE_FORCE: &str = "space_force";
/// Linear drag on the centre of mass, −c v.
pub const DRAG: &str = "drag";
/// The force of a force part; at the top level of `#[free]`, a user force function.
pub const FORCE: &str = "force";
/// Where a force part acts: `[x, y, z]` or `center`.
pub const FORCE_AT: &str = "at";
/// A user function returning force and torque together, a setting of `#[free]` that may
/// repeat (the wrenches add).
pub const WRENCH: &str = "wrench";
/// The value of [`FORCE_AT`] naming the centre of mass.
pub const CENTER_POINT: &str = "center";

/// The `key = value` settings of `#[free(...)]`, in the order the docs list them.
pub const FREE_KEYS: &[&str] = &[
    GRAVITY,
    BODY_TORQUE,
    SPACE_TORQUE,
    DRAG,
    DAMPING,
    FORCE,
    TORQUE,
    WRENCH,
    TAYLOR,
];
/// The force parts of `#[free(...)]`, `name(force = [..], at = [..])`.
pub const FREE_FORCES: &[&str] = &[BODY_FORCE, SPACE_FORCE];
/// The keys of a force part: both required.
pub const FORCE_KEYS: &[&str] = &[FORCE, FORCE_AT];

/// An internal rotor of a free body or a top, `rotor(axis = .., inertia = .., rate = ..)`.
pub const ROTOR: &str = "rotor";
/// A rotor's constant spin rate relative to the body.
pub const RATE: &str = "rate";
/// The keys of a rotor: all required.
pub const ROTOR_KEYS: &[&str] = &[AXIS, INERTIA, RATE, TORQUE];

/// The keys `#[rigid(...)]` takes beside its parts.
pub const RIGID_KEYS: &[&str] = &[PIVOT, TAYLOR];

/// `#[mechanism(...)]`: settings of the whole mechanism (gravity, route).
pub const MECHANISM: &str = "mechanism";
/// `#[body(name, ...)]`: one body of a mechanism with the joint to its parent (not
/// `link`, which is a built-in attribute of Rust).
pub const LINK: &str = "body";
/// The body a link hangs from: another link's name or [`GROUND`].
pub const PARENT: &str = "parent";
/// The inertial frame, as a parent.
pub const GROUND: &str = "ground";
/// The joint of a link, `kind(key = value, ...)`.
pub const JOINT: &str = "joint";
/// The name(s) of a joint's coordinate(s).
pub const COORDINATES: &str = "q";
/// A linear spring on a joint coordinate, `spring(k = .., rest = ..)`.
pub const SPRING: &str = "spring";
/// A spring's stiffness.
pub const STIFFNESS: &str = "k";
/// A spring's rest value.
pub const REST: &str = "rest";
/// A linear damper −c q̇ on a joint coordinate.
pub const DAMPER: &str = "damper";
/// A generalised force on a joint coordinate: a value or a user function.
pub const EFFORT: &str = "effort";
/// The parts of a link, `parts(particle(..), rod(..), ...)`.
pub const PARTS_GROUP: &str = "parts";
/// A joint's name (it defaults to its link's).
pub const NAME: &str = "name";
/// The two axes of a universal joint.
pub const AXES: &str = "axes";
/// The Euler-angle sequence of a spherical joint.
pub const SEQUENCE: &str = "sequence";
/// How the accelerations are solved: `auto`, `symbolic`, `factored` or `recursive`.
pub const ROUTE: &str = "route";
/// The joint kinds.
pub const JOINT_KINDS: &[&str] = &precess_core::mechanism::JointKind::NAMES;
/// The surface a mechanism's body rolls on the floor with, `rolls = disk(..)` or
/// `rolls = sphere(..)`.
pub const ROLLS: &str = "rolls";
/// A body's point held on another body's point, closing a kinematic loop:
/// `closes = other(at = [..], to = [..])`.
pub const CLOSES: &str = "closes";
/// The floor's upward normal of a mechanism with rolling bodies: a signed ground axis.
pub const UP: &str = "up";
/// The coordinates whose rates are a rolling mechanism's free speeds, `speeds = [a, b]`.
pub const SPEEDS: &str = "speeds";
/// The axle of a rolling disk, normal to its rim's plane.
pub const AXLE: &str = "axle";
/// A disk's rim, the surface a rolling disk touches the floor with (the table's and the
/// wheel's word).
pub const DISK_RIM: &str = "disk_rim";
/// `disk`, how a wheel's rim was first spelt in `rolls = disk(..)`: the same as [`DISK_RIM`].
pub const DISK: &str = "disk";
/// The surfaces of [`SURFACES`] a mechanism's wheel may roll on (`rolls = ..`): a disk rim
/// about its [`AXLE`] (the axle a required key), or a ball.
pub const WHEEL_SURFACES: &[&str] = &[DISK_RIM, "sphere"];
/// The `key = value` settings of `#[link(...)]` (besides its name and its groups).
pub const LINK_KEYS: &[&str] = &[
    PARENT,
    JOINT,
    COORDINATES,
    DAMPER,
    EFFORT,
    BODY_TORQUE,
    SPACE_TORQUE,
    ROLLS,
    CLOSES,
];
/// The `name(...)` groups of `#[link(...)]`.
pub const LINK_GROUPS: &[&str] = &[PARTS_GROUP, SPRING];
/// The keys of `#[mechanism(...)]`.
pub const MECHANISM_KEYS: &[&str] = &[GRAVITY, ROUTE, TAYLOR, UP, SPEEDS];
/// The routes of [`ROUTE`].
pub const ROUTES: &[&str] = &precess_core::mechanism::Route::NAMES;

/// `#[contact(...)]`: the body on a table, touching it with one convex surface.
pub const CONTACT: &str = "contact";
/// The surface the body touches the table with, `surface = sphere(radius = ..)`.
pub const SURFACE: &str = "surface";
/// The law of the contact, `law = rolling` or `law = sliding(viscous = c)`.
pub const LAW: &str = "law";
/// The keys of `#[contact(...)]`, in the order the docs list them; the first three are
/// required, `torque` (a user couple, a path to a function of the state) is optional.
pub const CONTACT_KEYS: &[&str] = &[SURFACE, LAW, GRAVITY, TORQUE];

/// The centre of a contact surface (sphere, ellipsoid, disk rim, torus).
pub const SURFACE_CENTER: &str = "center";
/// The vertex of a paraboloid contact surface.
pub const VERTEX: &str = "vertex";
/// The tube radius of a torus contact surface.
pub const TUBE: &str = "tube";
/// The radius of curvature at a paraboloid's vertex.
pub const CURVATURE_RADIUS: &str = "curvature_radius";

/// The rolling surfaces, `name(required keys; optional keys)`, in the order the docs list
/// them: each has its axes along description axes and an optional placement (the origin when
/// left out), which [`AT`] may also give; `lang::surface` reads them for `#[contact]` and
/// for a wheel's `rolls`.
pub const SURFACES: &[(&str, &[&str], &[&str])] = &[
    ("sphere", &[RADIUS], &[SURFACE_CENTER]),
    ("ellipsoid", &[SEMI_AXES], &[SURFACE_CENTER]),
    (DISK_RIM, &[RADIUS], &[SURFACE_CENTER]),
    ("torus", &[RADIUS, TUBE], &[SURFACE_CENTER]),
    ("paraboloid", &[CURVATURE_RADIUS], &[VERTEX]),
];

/// Pure rolling, `rolling` or `rolling(rolling_resistance = .., spin_resistance = ..)`.
pub const ROLLING: &str = "rolling";
/// Sliding under friction, `sliding(viscous = c)`, `sliding(coulomb = μ)` or
/// `sliding(frictionless)`.
pub const SLIDING: &str = "sliding";
/// Coulomb stick–slip, `stick_slip(mu = μ)`.
pub const STICK_SLIP: &str = "stick_slip";
/// A torque −c_r ω_∥ against rolling.
pub const ROLLING_RESISTANCE: &str = "rolling_resistance";
/// A torque −c_s ω_⊥ against spinning about the vertical.
pub const SPIN_RESISTANCE: &str = "spin_resistance";
/// Viscous sliding friction −c u.
pub const VISCOUS: &str = "viscous";
/// Viscous sliding friction scaled by the normal force, −μ N u.
pub const NORMAL_VISCOUS: &str = "normal_viscous";
/// Pivoting friction −ℓ_p N sign(ω·γ) γ against the spin about the vertical.
pub const PIVOTING: &str = "pivoting";
/// Coulomb sliding friction −μ N u/|u|.
pub const COULOMB: &str = "coulomb";
/// No sliding friction at all (a flag, no value).
pub const FRICTIONLESS: &str = "frictionless";
/// The friction coefficient of stick–slip.
pub const MU: &str = "mu";
/// The contact laws, `name(keys)`, in the order the docs list them.
pub const LAWS: &[(&str, &[&str])] = &[
    (ROLLING, &[ROLLING_RESISTANCE, SPIN_RESISTANCE, PIVOTING]),
    (SLIDING, &[VISCOUS, NORMAL_VISCOUS, COULOMB, FRICTIONLESS]),
    (
        STICK_SLIP,
        &[MU, ROLLING_RESISTANCE, SPIN_RESISTANCE, PIVOTING],
    ),
];

#[cfg(test)]
mod tests {
    use precess_core::body::{Axis, Shape};

    use super::*;

    /// A shape of `kind` with the number 1 everywhere.
    fn shape(kind: PartKind) -> Shape<f64> {
        let (mass, v, axis) = (1.0, [1.0; 3], Axis::Z);
        match kind {
            PartKind::Particle => Shape::Particle { mass },
            PartKind::Sphere => Shape::Sphere { mass, radius: 1.0 },
            PartKind::Shell => Shape::Shell { mass, radius: 1.0 },
            PartKind::Cuboid => Shape::Cuboid { mass, size: v },
            PartKind::Cylinder => Shape::Cylinder {
                mass,
                radius: 1.0,
                length: 1.0,
                axis,
            },
            PartKind::Tube => Shape::Tube {
                mass,
                inner: 0.5,
                outer: 1.0,
                length: 1.0,
                axis,
            },
            PartKind::Disk => Shape::Disk {
                mass,
                radius: 1.0,
                axis,
            },
            PartKind::Ring => Shape::Ring {
                mass,
                radius: 1.0,
                axis,
            },
            PartKind::Rod => Shape::Rod {
                mass,
                length: 1.0,
                axis,
            },
            PartKind::Cone => Shape::Cone {
                mass,
                radius: 1.0,
                height: 1.0,
                axis,
                reversed: false,
            },
            PartKind::Ellipsoid => Shape::Ellipsoid { mass, semi_axes: v },
            PartKind::Explicit => Shape::Explicit {
                mass,
                inertia: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                about: precess_core::body::About::Center,
            },
        }
    }

    /// precess-core names parts and keys in its errors; the checker spans those errors by
    /// looking the names up here, so both must spell them alike.
    #[test]
    fn core_names_every_part_and_key_as_the_table_does() {
        for p in PARTS {
            let s = shape(p.kind);
            assert_eq!(s.kind(), p.name);
            for (key, _) in s.dimensions() {
                assert!(p.required.contains(&key), "{} lacks {key}", p.name);
            }
        }
        assert_eq!(
            part_list(),
            "particle, sphere, shell, cuboid (or box), cylinder, tube, disk, ring, rod, cone, ellipsoid, body"
        );
        assert_eq!(find_part("box").map(|p| p.kind), Some(PartKind::Cuboid));
        let body = find_part("body").map(|p| p.key(CENTER));
        assert_eq!(body, Some(Some(AT)));
    }
}
