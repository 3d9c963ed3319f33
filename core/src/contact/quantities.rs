//! The standard quantities of a body on a table as trajectory columns: the energy, the
//! normal force, the slip speed, Jellett's quantity and the angular momentum about the
//! contact point, per sample of a run over the state of [`super::layout`].

use super::dynamics::ContactDynamics;
use super::scene::{ContactMode, Phase};
use super::state::STATE_LEN;
use crate::ode::{HybridState, Quantities};

/// The standard quantities of a body on a table in one phase: `energy` (½ M |v|² +
/// ½ ωᵀ I ω + M g z), `normal` (N), `slip` (|u|, the contact point's speed), `jellett`
/// (λ = −L·r), `K_z` and `K2` (K·ẑ and |K|², K the angular momentum about the contact
/// point: both conserved by the Chaplygin ball).
///
/// Add them to a [`Run`](crate::ode::Run) of a [`super::ContactRun`] with
/// [`Run::quantities`](crate::ode::Run::quantities): there each sample is evaluated under
/// its own phase (the state's mode), so N is rolling's or sliding's as the run was (with the
/// pivot couple in place where the spin was held); over
/// bare state arrays they are evaluated under the phase given to [`ContactQuantities::new`].
#[derive(Debug, Clone, Copy)]
pub struct ContactQuantities<'a, D: ?Sized> {
    body: &'a D,
    phase: Phase,
}

impl<'a, D: ContactDynamics + ?Sized> ContactQuantities<'a, D> {
    /// The quantities of `body` under the equations of `phase`.
    pub fn new(body: &'a D, phase: Phase) -> Self {
        Self { body, phase }
    }
}

impl<D: ContactDynamics + ?Sized> Quantities<[f64; STATE_LEN]> for ContactQuantities<'_, D> {
    fn names(&self) -> Vec<String> {
        ["energy", "normal", "slip", "jellett", "K_z", "K2"]
            .map(String::from)
            .to_vec()
    }

    fn evaluate(&mut self, _t: f64, y: &[f64; STATE_LEN], out: &mut [f64]) {
        let k = self.body.momenta(self.phase, y).contact;
        let values = [
            self.body.energy(self.phase, y),
            self.body.reaction(self.phase, y).normal,
            self.body.contact(y).velocity.norm(),
            self.body.jellett(y),
            k.z,
            k.norm_squared(),
        ];
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}

/// On a run's states, each under the phase it was integrated in.
impl<D: ContactDynamics + ?Sized> Quantities<HybridState<ContactMode, [f64; STATE_LEN]>>
    for ContactQuantities<'_, D>
{
    fn names(&self) -> Vec<String> {
        <Self as Quantities<[f64; STATE_LEN]>>::names(self)
    }

    fn evaluate(
        &mut self,
        t: f64,
        s: &HybridState<ContactMode, [f64; STATE_LEN]>,
        out: &mut [f64],
    ) {
        let mut at = Self {
            body: self.body,
            phase: s.mode.phase,
        };
        Quantities::<[f64; STATE_LEN]>::evaluate(&mut at, t, &s.x, out);
        // With the spin held, N is the one with the pivot couple in place.
        if s.mode.spin_held
            && let Ok(held) = super::pivot::held_spin(self.body, s.mode.phase, t, &s.x)
        {
            out[1] = held.reaction.normal;
        }
    }
}
