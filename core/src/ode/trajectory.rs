//! Recorded motion: times, states and derived quantities per sample, written as CSV.
//!
//! The CSV is written by hand rather than with the `csv` crate: the file is a header and rows
//! of numbers, with nothing to parse and only names to quote, and precess-core is a
//! dependency of the proc-macro, so every crate it pulls in is built by every user of the
//! derive.

use std::io;

use super::error::OdeError;

/// A state that a trajectory writes as CSV columns.
///
/// Implemented for `[f64; N]` (columns `y0`, `y1`, …) and for the splittings' `BodyMomentum`
/// (`q_w, q_x, q_y, q_z, m_1, m_2, m_3`); [`Trajectory::set_state_names`] renames them.
pub trait StateColumns {
    /// Number of columns.
    fn column_count() -> usize;
    /// The default name of column `i`.
    fn column_name(i: usize) -> String;
    /// The value of column `i` (NaN past the last column).
    fn column(&self, i: usize) -> f64;
}

impl<const N: usize> StateColumns for [f64; N] {
    fn column_count() -> usize {
        N
    }
    fn column_name(i: usize) -> String {
        format!("y{i}")
    }
    fn column(&self, i: usize) -> f64 {
        self.get(i).copied().unwrap_or(f64::NAN)
    }
}

/// The most samples a [`Trajectory`] holds: ten million, some 0.5 GB for a state of six
/// numbers. A run that would record more is refused with [`OdeError::TooManySamples`] (before
/// any work when the sampling says how many it takes); sample less often, or watch every step
/// with [`Run::observe`](super::Run::observe), which stores nothing.
pub const MAX_SAMPLES: usize = 10_000_000;

/// Named quantities derived from each sample (energy, |L|, conserved momenta), computed when
/// the sample is recorded.
///
/// [`Run::quantity`](super::Run::quantity) turns a closure into one; a scene can offer its
/// standard set (the top's is `precess_core::top::TopQuantities`).
pub trait Quantities<St> {
    /// The names of the quantities, in order (asked once, when a run starts).
    fn names(&self) -> Vec<String>;
    /// Writes the quantities at `(t, state)` into `out` (as long as [`Quantities::names`]).
    fn evaluate(&mut self, t: f64, state: &St, out: &mut [f64]);
}

/// One quantity from a closure `|t, y| value`.
pub(crate) struct Named<F> {
    pub(crate) name: String,
    pub(crate) f: F,
}

impl<St, F: FnMut(f64, &St) -> f64> Quantities<St> for Named<F> {
    fn names(&self) -> Vec<String> {
        vec![self.name.clone()]
    }
    fn evaluate(&mut self, t: f64, state: &St, out: &mut [f64]) {
        if let Some(o) = out.first_mut() {
            *o = (self.f)(t, state);
        }
    }
}

/// Samples of a motion: times, states, and per sample the derived quantities named in
/// [`Trajectory::quantity_names`].
///
/// Made by [`Run`](super::Run); see there for an example.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory<St> {
    times: Vec<f64>,
    states: Vec<St>,
    names: Vec<String>,
    /// Row-major: `names.len()` values per sample.
    values: Vec<f64>,
    state_names: Option<Vec<String>>,
}

impl<St> Trajectory<St> {
    /// An empty trajectory with derived quantities `names`.
    pub fn new(names: Vec<String>) -> Self {
        Self {
            times: Vec::new(),
            states: Vec::new(),
            names,
            values: Vec::new(),
            state_names: None,
        }
    }

    /// Appends a sample at `t`, not before the last; `values` must hold one value per
    /// quantity name.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteTime`] for a NaN or infinite `t`; [`OdeError::DecreasingTime`]
    /// for a `t` before the last sample's time (a repeat is kept: `sample_at` may list a
    /// time twice); [`OdeError::TooManySamples`] past [`MAX_SAMPLES`];
    /// [`OdeError::ColumnCount`] for a wrong number of values,
    /// [`OdeError::NonFiniteQuantity`] for a NaN or infinite value.
    pub fn push(&mut self, t: f64, state: St, values: &[f64]) -> Result<(), OdeError> {
        if !t.is_finite() {
            return Err(OdeError::NonFiniteTime { t });
        }
        if let Some(&previous) = self.times.last()
            && t < previous
        {
            return Err(OdeError::DecreasingTime { t, previous });
        }
        if self.times.len() >= MAX_SAMPLES {
            return Err(OdeError::TooManySamples {
                samples: (self.times.len() + 1) as f64,
                max: MAX_SAMPLES,
            });
        }
        if values.len() != self.names.len() {
            return Err(OdeError::ColumnCount {
                expected: self.names.len(),
                got: values.len(),
            });
        }
        if let Some(column) = values.iter().position(|v| !v.is_finite()) {
            return Err(OdeError::NonFiniteQuantity {
                column,
                t,
                value: values[column],
            });
        }
        self.times.push(t);
        self.states.push(state);
        self.values.extend_from_slice(values);
        Ok(())
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Whether there are no samples.
    pub fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    /// The sample times, ascending (strictly for `sample_every` and `sample_steps`).
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// The states, one per time.
    pub fn states(&self) -> &[St] {
        &self.states
    }

    /// The names of the derived quantities.
    pub fn quantity_names(&self) -> &[String] {
        &self.names
    }

    /// The derived quantities of sample `i`, in the order of [`Trajectory::quantity_names`]
    /// (`None` past the last sample).
    pub fn quantities(&self, i: usize) -> Option<&[f64]> {
        let k = self.names.len();
        self.values.get(i * k..(i + 1) * k)
    }

    /// The quantity `name` over all samples (`None` if no quantity has that name).
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let j = self.names.iter().position(|n| n == name)?;
        let k = self.names.len();
        Some(self.values.iter().skip(j).step_by(k).copied().collect())
    }
}

impl<St: StateColumns> Trajectory<St> {
    /// Names the state columns in the CSV header (default: [`StateColumns::column_name`]).
    ///
    /// # Errors
    /// [`OdeError::ColumnCount`] unless there is one name per state column.
    pub fn set_state_names<S: Into<String>>(
        &mut self,
        names: impl IntoIterator<Item = S>,
    ) -> Result<(), OdeError> {
        let names: Vec<String> = names.into_iter().map(Into::into).collect();
        if names.len() != St::column_count() {
            return Err(OdeError::ColumnCount {
                expected: St::column_count(),
                got: names.len(),
            });
        }
        self.state_names = Some(names);
        Ok(())
    }

    /// The names of the state columns: those given to [`Trajectory::set_state_names`], else
    /// the defaults of [`StateColumns::column_name`].
    pub fn state_column_names(&self) -> Vec<String> {
        match &self.state_names {
            Some(names) => names.clone(),
            None => (0..St::column_count()).map(St::column_name).collect(),
        }
    }

    /// Writes the trajectory as CSV: a header `t, <state columns>, <quantities>`, then one
    /// row per sample. Numbers are written so that they read back to the same `f64`.
    ///
    /// # Errors
    /// The writer's.
    pub fn write_csv<W: io::Write>(&self, mut out: W) -> io::Result<()> {
        let mut line = String::from("t");
        let m = St::column_count();
        for i in 0..m {
            line.push(',');
            match &self.state_names {
                Some(names) => push_name(&mut line, names.get(i).map_or("", |s| s.as_str())),
                None => push_name(&mut line, &St::column_name(i)),
            }
        }
        for name in &self.names {
            line.push(',');
            push_name(&mut line, name);
        }
        writeln!(out, "{line}")?;
        for (i, (t, state)) in self.times.iter().zip(&self.states).enumerate() {
            line.clear();
            push_number(&mut line, *t);
            for j in 0..m {
                line.push(',');
                push_number(&mut line, state.column(j));
            }
            for v in self.quantities(i).unwrap_or(&[]) {
                line.push(',');
                push_number(&mut line, *v);
            }
            writeln!(out, "{line}")?;
        }
        Ok(())
    }

    /// The CSV of [`Trajectory::write_csv`] as a string.
    pub fn to_csv(&self) -> String {
        let mut bytes = Vec::new();
        // Writing to a Vec cannot fail.
        let _ = self.write_csv(&mut bytes);
        String::from_utf8_lossy(&bytes).into_owned()
    }
}

/// Appends a header field, quoted (RFC 4180) when it holds a comma, a quote or a line break.
fn push_name(line: &mut String, name: &str) {
    if name.contains([',', '"', '\n', '\r']) {
        line.push('"');
        line.push_str(&name.replace('"', "\"\""));
        line.push('"');
    } else {
        line.push_str(name);
    }
}

/// Appends a number in the shortest form that reads back exactly: plain decimals for
/// moderate magnitudes, the exponent form (`1.5e-7`) for very small or large ones.
fn push_number(line: &mut String, v: f64) {
    use std::fmt::Write;
    let a = v.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || (1e-4..1e15).contains(&a) || !a.is_finite() {
        write!(line, "{v}")
    } else {
        write!(line, "{v:e}")
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly() {
        for v in [
            0.1,
            -2.5e-7,
            6.02214076e23,
            1.0 / 3.0,
            0.0,
            -0.0,
            123456.789,
        ] {
            let mut s = String::new();
            push_number(&mut s, v);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), v.to_bits(), "{s}");
        }
    }

    #[test]
    fn names_with_commas_are_quoted() {
        let mut s = String::new();
        push_name(&mut s, "a,\"b\"");
        assert_eq!(s, "\"a,\"\"b\"\"\"");
    }
}
