//! What [`Run::taylor_event`](crate::ode::Run::taylor_event) asks of an event function: g's
//! normalised Taylor coefficients along a step from the step's jet, as a trait, so that g can
//! be interpreted ([`TaylorEvent`], a tape walked at every step), compiled (the type
//! `taylor_system!` emits for an `event Name = …;` statement: the same recurrences as Rust,
//! beside the system's own), or one state component read off the jet ([`StateEvent`], no
//! recurrence at all).
//!
//! Given the step's state y = c₀ and rows c₁ … c_p, the series y(t + τ) = Σₖ cₖ τᵏ, an
//! implementation writes gₖ = (g∘y)⁽ᵏ⁾(t)/k! for k = 0 … p. For g built of the operations of
//! the Taylor recurrences, gₖ depends on c₀ … c_k only, and is computed by the same recurrence
//! as one more component of the system would be (for a product g = a b,
//! gₖ = Σⱼ₌₀ᵏ aⱼ b_{k−j}), with the state's series read from the jet instead of made from f.

use super::TaylorEvent;

/// An event function g(t, y) whose Taylor coefficients along a step come from the step's
/// jet: what [`Run::taylor_event`](crate::ode::Run::taylor_event) expands and isolates.
///
/// # Examples
/// g = y₀ on x = cos t, by its component ([`StateEvent`]) and as an interpreted expression:
/// both read the jet's column.
/// ```
/// use precess_core::sym::Arena;
/// use precess_core::taylor::{EventSeries, StateEvent, TaylorEvent};
/// let mut a = Arena::new();
/// let (x, v) = (a.coordinate("x"), a.coordinate("v"));
/// let interpreted = TaylorEvent::new(&a, [x, v], None, x, &[])?;
/// let component = StateEvent::<2>::new(0)?;
/// let jet = [[1.0, 0.0], [0.0, -1.0], [-0.5, 0.0]];
/// let (mut g, mut h) = ([0.0; 3], [0.0; 3]);
/// interpreted.coefficients_into(&mut Default::default(), 0.0, &jet[0], &jet[1..], &mut g);
/// component.coefficients_into(&mut (), 0.0, &jet[0], &jet[1..], &mut h);
/// assert_eq!(g, [1.0, 0.0, -0.5]);
/// assert_eq!(g, h);
/// # Ok::<(), precess_core::taylor::TaylorError>(())
/// ```
pub trait EventSeries<const N: usize> {
    /// Scratch kept across the steps of a run (sized on first use, then reused).
    type Workspace: Default;

    /// g₀ … g_p into `out` (p = `out.len() − 1`, at most `rows.len()`: `out` is never
    /// longer than `rows.len() + 1`) along the series whose value is `y` and whose rows
    /// c₁ … c_p are `rows[..p]`, at time `t`.
    fn coefficients_into(
        &self,
        ws: &mut Self::Workspace,
        t: f64,
        y: &[f64; N],
        rows: &[[f64; N]],
        out: &mut [f64],
    );

    /// g(t, y): the coefficient of order 0.
    fn value(&self, ws: &mut Self::Workspace, t: f64, y: &[f64; N]) -> f64 {
        let mut out = [0.0];
        self.coefficients_into(ws, t, y, &[], &mut out);
        out[0]
    }
}

impl<const N: usize> EventSeries<N> for TaylorEvent<N> {
    type Workspace = Vec<f64>;

    fn coefficients_into(
        &self,
        ws: &mut Vec<f64>,
        t: f64,
        y: &[f64; N],
        rows: &[[f64; N]],
        out: &mut [f64],
    ) {
        self.series_into(ws, t, y, rows, out);
    }
}

impl<G: EventSeries<N> + ?Sized, const N: usize> EventSeries<N> for &G {
    type Workspace = G::Workspace;

    fn coefficients_into(
        &self,
        ws: &mut G::Workspace,
        t: f64,
        y: &[f64; N],
        rows: &[[f64; N]],
        out: &mut [f64],
    ) {
        (**self).coefficients_into(ws, t, y, rows, out);
    }
}

/// g = yᵢ, one state component: its coefficients are the jet's column i, copied with no
/// recurrence (gₖ = cₖ,ᵢ). For an event whose function is a component of the state (a
/// height, an angle's rate), the cheapest expansion there is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateEvent<const N: usize> {
    index: usize,
}

impl<const N: usize> StateEvent<N> {
    /// The event on component `index` of the state.
    ///
    /// # Errors
    /// [`TaylorError::EventComponentOutOfRange`](super::TaylorError::EventComponentOutOfRange)
    /// if `index` is not below the dimension `N`.
    pub fn new(index: usize) -> Result<Self, super::TaylorError> {
        if index < N {
            Ok(Self { index })
        } else {
            Err(super::TaylorError::EventComponentOutOfRange {
                index,
                dimension: N,
            })
        }
    }

    /// The component read.
    pub fn index(&self) -> usize {
        self.index
    }

    /// g₀ … g_p of g = y_`index` into `out`: the jet's column, y_`index` and then row k's
    /// entry for k = 1 … p (p as in [`EventSeries::coefficients_into`]); nothing for an
    /// `index` past the state. What [`StateEvent`] and the component events
    /// `taylor_system!` emits both write.
    #[inline]
    pub fn column_into(index: usize, y: &[f64; N], rows: &[[f64; N]], out: &mut [f64]) {
        let (Some((first, rest)), Some(&value)) = (out.split_first_mut(), y.get(index)) else {
            return;
        };
        *first = value;
        for (o, row) in rest.iter_mut().zip(rows) {
            *o = row[index];
        }
    }
}

impl<const N: usize> EventSeries<N> for StateEvent<N> {
    type Workspace = ();

    #[inline]
    fn coefficients_into(
        &self,
        _ws: &mut (),
        _t: f64,
        y: &[f64; N],
        rows: &[[f64; N]],
        out: &mut [f64],
    ) {
        Self::column_into(self.index, y, rows, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Arena;

    /// A deterministic pseudo-random jet (xorshift), entries in (−1, 1).
    fn jet<const N: usize>(seed: u64, p: usize) -> Vec<[f64; N]> {
        let mut s = seed | 1;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        };
        (0..=p).map(|_| std::array::from_fn(|_| next())).collect()
    }

    #[test]
    fn a_state_event_is_the_interpreted_component_bit_for_bit() {
        let mut a = Arena::new();
        let y: [_; 4] = ["a", "b", "c", "d"].map(|n| a.coordinate(n));
        for seed in 1..20u64 {
            let c = jet::<4>(seed, 15);
            for i in 0..4 {
                let interpreted = TaylorEvent::new(&a, y, None, y[i], &[]).unwrap();
                let direct = StateEvent::<4>::new(i).unwrap();
                let (mut g, mut h) = ([0.0; 16], [0.0; 16]);
                EventSeries::coefficients_into(
                    &interpreted,
                    &mut Vec::new(),
                    0.3,
                    &c[0],
                    &c[1..],
                    &mut g,
                );
                direct.coefficients_into(&mut (), 0.3, &c[0], &c[1..], &mut h);
                assert_eq!(g.map(f64::to_bits), h.map(f64::to_bits));
                assert_eq!(direct.value(&mut (), 0.3, &c[0]), c[0][i]);
            }
        }
    }

    #[test]
    fn a_component_past_the_state_is_refused_with_its_numbers() {
        let e = StateEvent::<3>::new(3).unwrap_err();
        assert_eq!(
            e,
            crate::taylor::TaylorError::EventComponentOutOfRange {
                index: 3,
                dimension: 3
            }
        );
    }
}
