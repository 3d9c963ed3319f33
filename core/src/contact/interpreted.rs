//! A contact derivation evaluated at run time through the code generator's interpreter: the
//! path for scenes built at run time, and the reference for the generated code.

use nalgebra::{Matrix3, Vector3};

use super::checks::ContactValues;
use super::derivation::{ContactDerivation, ContactEquations};
use super::dynamics::{ContactDynamics, ContactMomenta, ContactPoint, Reaction};
use super::error::ContactError;
use super::scene::{ContactLaw, LawKind, Phase, coefficients};
use super::state::{STATE_LEN, attitude_of, layout};
#[cfg(doc)]
use crate::codegen::BindingError;
use crate::codegen::{Bindings, OpCount, Program};
use crate::rigid::SurfaceKind;
use crate::sym::{Arena, ExprId, SymbolId};

/// The programs of one phase.
#[derive(Debug)]
struct PhasePrograms {
    rhs: Program,
    /// N, then the friction (space axes).
    reaction: Program,
    energy: Program,
    /// M v, then K about the contact point.
    momenta: Program,
}

impl PhasePrograms {
    fn lower(arena: &Arena, e: &ContactEquations) -> PhasePrograms {
        let reaction: Vec<ExprId> = std::iter::once(e.normal).chain(e.friction).collect();
        let momenta: Vec<ExprId> = e
            .linear_momentum
            .iter()
            .chain(&e.angular_momentum_contact)
            .copied()
            .collect();
        PhasePrograms {
            rhs: Program::lower(arena, &e.rhs),
            reaction: Program::lower(arena, &reaction),
            energy: Program::lower(arena, &[e.energy]),
            momenta: Program::lower(arena, &momenta),
        }
    }

    fn all(&self) -> [&Program; 4] {
        [&self.rhs, &self.reaction, &self.energy, &self.momenta]
    }
}

/// A body on a table, its equations lowered once and interpreted.
///
/// # Examples
///
/// A uniform ball (I = 2/5 M ρ²) rolling on the table moves uniformly: ω̇ = 0, no friction
/// and N = M g.
///
/// ```
/// use approx::assert_relative_eq;
/// use nalgebra::{UnitQuaternion, Vector3};
/// use precess_core::contact::{
///     ContactDynamics, ContactLaw, ContactModel, ContactScene, Phase, Surface,
/// };
/// use precess_core::sym::Arena;
///
/// let mut a = Arena::new();
/// let (m, rho, g) = (a.parameter("m"), a.parameter("rho"), a.parameter("g"));
/// let z = a.zero();
/// let i = a.parameter("I");
/// let scene = ContactScene {
///     mass: m,
///     center: [z; 3],
///     inertia: [[i, z, z], [z, i, z], [z, z, i]],
///     surface: Surface::Sphere { center: [z; 3], radius: rho },
///     law: ContactLaw::Rolling { rolling_resistance: None, spin_resistance: None },
///     gravity: g,
/// };
/// let d = scene.derive(&mut a)?;
/// let model = ContactModel::new(&mut a, &d, &[("m", 2.0), ("rho", 0.1), ("g", 9.81), ("I", 0.008)])?;
/// let y = model.rolling_state([0.0, 0.0], &UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1), &Vector3::new(3.0, -1.0, 0.5))?;
/// let dy = model.accelerations(Phase::Rolling, 0.0, &y)?;
/// for k in 2..4 { assert_relative_eq!(dy[k], 0.0, epsilon = 1e-12); }
/// for k in 8..11 { assert_relative_eq!(dy[k], 0.0, epsilon = 1e-12); }
/// assert_relative_eq!(model.reaction(Phase::Rolling, &y).normal, 2.0 * 9.81, max_relative = 1e-14);
/// # Ok::<(), precess_core::contact::ContactError>(())
/// ```
#[derive(Debug)]
pub struct ContactModel {
    law: LawKind,
    surface: SurfaceKind,
    rolling: Option<PhasePrograms>,
    sliding: Option<PhasePrograms>,
    /// γ, r, the contact point in space, the height, the contact velocity, λ, R I ω.
    contact: Program,
    /// mass, centre, inertia, gravity, the surface's placement and lengths, the coefficients.
    parameters: Program,
    lengths: Vec<&'static str>,
    coefficients: Vec<&'static str>,
    /// Where μ sits among the coefficients, for a Coulomb or stick–slip law.
    mu: Option<usize>,
    state: [SymbolId; STATE_LEN],
    /// The user couple and the symbols its value is read as.
    torque: Option<UserCouple>,
    bindings: Bindings,
    /// The values set, so that a value refused by the rules is undone.
    values: Vec<(String, f64)>,
}

const CONTACT_OUTPUTS: usize = 17;

/// A user couple's function: (R, ω) → torque, description axes.
type CoupleFn = dyn Fn(&Matrix3<f64>, &Vector3<f64>) -> Vector3<f64> + Send + Sync;

/// The user couple of a model and the input symbols its value is read as.
struct UserCouple {
    symbols: [SymbolId; 3],
    f: Box<CoupleFn>,
}

impl std::fmt::Debug for UserCouple {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("UserCouple")
            .field("symbols", &self.symbols)
            .finish_non_exhaustive()
    }
}

impl ContactModel {
    /// Lowers the derivation, with a value for each parameter it reads (`(name, value)`
    /// pairs; [`ContactModel::set`] changes one later), and checks the parameters.
    ///
    /// # Errors
    /// In [`ContactError::Binding`]: [`BindingError::UnsetParameter`] naming a parameter
    /// left out, [`BindingError::UnknownParameter`] for a name the derivation does not read,
    /// [`BindingError::NonFinite`] for NaN or ±∞; then as
    /// [`ContactDynamics::check_parameters`].
    pub fn new(
        arena: &mut Arena,
        derivation: &ContactDerivation,
        parameters: &[(&str, f64)],
    ) -> Result<ContactModel, ContactError> {
        Self::build(arena, derivation, parameters, None)
    }

    /// As [`ContactModel::new`], for a derivation with a user couple
    /// ([`ContactTorques::user`](super::ContactTorques::user)): `torque(R, ω)` gives it in
    /// description axes from the attitude R (description → space) and ω (description axes),
    /// as `#[contact(torque = f)]` calls its function.
    ///
    /// # Errors
    /// As [`ContactModel::new`]; [`ContactError::UserTorque`] for a derivation without a
    /// user couple (and `new` gives it for one with).
    pub fn with_torque(
        arena: &mut Arena,
        derivation: &ContactDerivation,
        parameters: &[(&str, f64)],
        torque: impl Fn(&Matrix3<f64>, &Vector3<f64>) -> Vector3<f64> + Send + Sync + 'static,
    ) -> Result<ContactModel, ContactError> {
        Self::build(arena, derivation, parameters, Some(Box::new(torque)))
    }

    fn build(
        arena: &mut Arena,
        derivation: &ContactDerivation,
        parameters: &[(&str, f64)],
        torque: Option<Box<CoupleFn>>,
    ) -> Result<ContactModel, ContactError> {
        let d = derivation;
        let state = d.state.map(|e| {
            arena
                .as_symbol(e)
                .unwrap_or_else(|| unreachable!("the derivation's state entries are symbols"))
        });
        let rolling = d.rolling.as_ref().map(|e| PhasePrograms::lower(arena, e));
        let sliding = d.sliding.as_ref().map(|e| PhasePrograms::lower(arena, e));
        let mut contact: Vec<ExprId> = Vec::with_capacity(CONTACT_OUTPUTS);
        contact.extend(d.gamma);
        contact.extend(d.contact_body);
        contact.extend(d.contact_space);
        contact.push(d.height);
        contact.extend(d.contact_velocity);
        contact.push(d.jellett);
        contact.extend(d.angular_momentum_center);
        let contact = Program::lower(arena, &contact);
        let scene = &d.scene;
        let (placement, lengths) = scene.surface.dimensions();
        let law = match scene.law {
            ContactLaw::Rolling { .. } => LawKind::Rolling,
            ContactLaw::Sliding(_) => LawKind::Sliding,
            ContactLaw::StickSlip { .. } => LawKind::StickSlip,
        };
        let coefficients = coefficients(&scene.law, &d.torques);
        // μ is the Coulomb coefficient of a Coulomb or stick–slip law, named `mu`.
        let mu = coefficients.iter().position(|&(n, _)| n == "mu");
        let mut values: Vec<ExprId> = vec![scene.mass];
        values.extend(scene.center);
        values.extend(scene.inertia.iter().flatten());
        values.push(scene.gravity);
        values.extend(placement);
        values.extend(lengths.iter().map(|&(_, e)| e));
        values.extend(coefficients.iter().map(|&(_, e)| e));
        let parameters_program = Program::lower(arena, &values);
        let mut programs: Vec<&Program> = vec![&contact, &parameters_program];
        for p in rolling.iter().chain(&sliding) {
            programs.extend(p.all());
        }
        let owned: Vec<Program> = programs.into_iter().cloned().collect();
        let torque = match (d.torques.user, torque) {
            (None, None) => None,
            (Some(u), Some(f)) => Some(UserCouple {
                symbols: u.map(|e| {
                    arena
                        .as_symbol(e)
                        .unwrap_or_else(|| unreachable!("a user couple is input symbols"))
                }),
                f,
            }),
            (Some(_), None) => {
                return Err(ContactError::UserTorque {
                    reads: "reads",
                    given: "given none",
                });
            }
            (None, Some(_)) => {
                return Err(ContactError::UserTorque {
                    reads: "does not read",
                    given: "given one",
                });
            }
        };
        let supplied: Vec<SymbolId> = state
            .iter()
            .chain(torque.iter().flat_map(|c| &c.symbols))
            .copied()
            .collect();
        let bindings = Bindings::new(arena, &owned, &supplied, parameters)?;
        let model = ContactModel {
            law,
            surface: scene.surface.kind(),
            rolling,
            sliding,
            contact,
            parameters: parameters_program,
            lengths: lengths.iter().map(|&(n, _)| n).collect(),
            coefficients: coefficients.iter().map(|&(n, _)| n).collect(),
            mu,
            state,
            torque,
            bindings,
            values: parameters.iter().map(|&(n, v)| (n.to_owned(), v)).collect(),
        };
        model.check_parameters()?;
        Ok(model)
    }

    /// The names of the parameters the derivation reads, in alphabetical order.
    pub fn parameters(&self) -> impl ExactSizeIterator<Item = &str> + '_ {
        self.bindings.parameters()
    }

    /// Sets the parameter `name` and checks the parameters again.
    ///
    /// # Errors
    /// In [`ContactError::Binding`]: [`BindingError::UnknownParameter`] for a name the
    /// derivation does not read, [`BindingError::NonFinite`] for NaN or ±∞; as
    /// [`ContactDynamics::check_parameters`] for a value that breaks a rule. On every error
    /// the model keeps the value it had.
    pub fn set(&mut self, name: &str, value: f64) -> Result<&mut Self, ContactError> {
        self.bindings.set(name, value)?;
        if let Err(e) = self.check_parameters() {
            if let Some(&(_, old)) = self.values.iter().find(|(n, _)| n == name) {
                self.bindings.set(name, old)?;
            }
            return Err(e);
        }
        match self.values.iter_mut().find(|(n, _)| n == name) {
            Some(entry) => entry.1 = value,
            None => self.values.push((name.to_owned(), value)),
        }
        Ok(self)
    }

    /// The operations of `phase`'s right-hand side as lowered (after common subexpressions
    /// are shared), `None` for a phase the law has not derived: the cost the generated code
    /// pays per evaluation.
    pub fn op_count(&self, phase: Phase) -> Option<OpCount> {
        self.phase(phase).map(|p| p.rhs.op_count())
    }

    fn run(&self, p: &Program, y: &[f64; STATE_LEN], out: &mut [f64]) {
        let inputs = self.state.iter().copied().zip(*y);
        match &self.torque {
            None => self.bindings.eval(p, inputs, out),
            Some(c) => {
                let r = attitude_of(y).to_rotation_matrix().into_inner();
                let w = Vector3::new(y[layout::OMEGA], y[layout::OMEGA + 1], y[layout::OMEGA + 2]);
                let u = (c.f)(&r, &w);
                let couple = c.symbols.iter().copied().zip([u.x, u.y, u.z]);
                self.bindings.eval(p, inputs.chain(couple), out);
            }
        }
    }

    fn phase(&self, phase: Phase) -> Option<&PhasePrograms> {
        match phase {
            Phase::Rolling => self.rolling.as_ref(),
            Phase::Sliding => self.sliding.as_ref(),
        }
    }

    fn parameter_values(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.parameters.outputs().len()];
        self.run(&self.parameters, &[0.0; STATE_LEN], &mut out);
        out
    }

    fn contact_values(&self, y: &[f64; STATE_LEN]) -> [f64; CONTACT_OUTPUTS] {
        let mut out = [0.0; CONTACT_OUTPUTS];
        self.run(&self.contact, y, &mut out);
        out
    }
}

fn vector(v: &[f64]) -> Vector3<f64> {
    Vector3::new(v[0], v[1], v[2])
}

impl ContactDynamics for ContactModel {
    fn law(&self) -> LawKind {
        self.law
    }

    fn surface_kind(&self) -> SurfaceKind {
        self.surface
    }

    fn phase_rhs(&self, phase: Phase, _t: f64, y: &[f64; STATE_LEN], dydt: &mut [f64; STATE_LEN]) {
        match self.phase(phase) {
            Some(p) => self.run(&p.rhs, y, dydt),
            None => dydt.fill(f64::NAN),
        }
    }

    fn reaction(&self, phase: Phase, y: &[f64; STATE_LEN]) -> Reaction {
        let mut out = [f64::NAN; 4];
        if let Some(p) = self.phase(phase) {
            self.run(&p.reaction, y, &mut out);
        }
        Reaction {
            normal: out[0],
            friction: vector(&out[1..]),
        }
    }

    fn energy(&self, phase: Phase, y: &[f64; STATE_LEN]) -> f64 {
        let mut out = [f64::NAN];
        if let Some(p) = self.phase(phase) {
            self.run(&p.energy, y, &mut out);
        }
        out[0]
    }

    fn momenta(&self, phase: Phase, y: &[f64; STATE_LEN]) -> ContactMomenta {
        let mut out = [f64::NAN; 6];
        if let Some(p) = self.phase(phase) {
            self.run(&p.momenta, y, &mut out);
        }
        let c = self.contact_values(y);
        ContactMomenta {
            linear: vector(&out[..3]),
            center: vector(&c[14..17]),
            contact: vector(&out[3..]),
        }
    }

    fn contact(&self, y: &[f64; STATE_LEN]) -> ContactPoint {
        let c = self.contact_values(y);
        ContactPoint {
            gamma: vector(&c[..3]),
            body: vector(&c[3..6]),
            space: vector(&c[6..9]),
            height: c[9],
            velocity: vector(&c[10..13]),
        }
    }

    fn jellett(&self, y: &[f64; STATE_LEN]) -> f64 {
        self.contact_values(y)[13]
    }

    fn friction_coefficient(&self) -> Option<f64> {
        let at = self.mu?;
        let v = self.parameter_values();
        v.get(v.len() - self.coefficients.len() + at).copied()
    }

    fn check_parameters(&self) -> Result<(), ContactError> {
        self.values().check()
    }

    fn values(&self) -> ContactValues {
        let v = self.parameter_values();
        let n = self.lengths.len();
        let pick3 = |at: usize| [v[at], v[at + 1], v[at + 2]];
        ContactValues {
            mass: v[0],
            center: pick3(1),
            inertia: [pick3(4), pick3(7), pick3(10)],
            gravity: v[13],
            surface: self.surface,
            placement: pick3(14),
            lengths: self
                .lengths
                .iter()
                .copied()
                .zip(v[17..17 + n].iter().copied())
                .collect(),
            coefficients: self
                .coefficients
                .iter()
                .copied()
                .zip(v[17 + n..].iter().copied())
                .collect(),
        }
    }
}
