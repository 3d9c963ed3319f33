//! Abbreviations: a symbol that stands for a time-independent expression.
//!
//! A body of N point masses has inertia entries of 2N terms each; carried through the
//! Lagrangian, the determinant and the adjugate, they multiply into polynomials of N³
//! terms and more. Named once as `I_xx`, … they stay atoms: the derivation's size no
//! longer depends on N, and the generated code computes each entry once. Evaluation,
//! lowering, differentiation and substitution look through an abbreviation to its
//! definition, so values and derivatives are exact; the canonical form treats it as an
//! atom, so zero tests that must see through it use [`Arena::is_zero`].

use super::arena::{Arena, ExprId, SymbolId, SymbolKind, latex_name};
use super::error::SymError;

impl Arena {
    /// A symbol shown as `name` standing for `definition`, which must not depend on time,
    /// coordinates or their rates. Constants and bare symbols are returned as they are, a
    /// definition that is identically zero gives 0, and equal definitions share one
    /// abbreviation.
    ///
    /// ```
    /// use approx::assert_relative_eq;
    /// use precess_core::sym::Arena;
    /// let mut a = Arena::new();
    /// let (m, r) = (a.parameter("m"), a.parameter("r"));
    /// let r2 = a.mul(r, r);
    /// let def = a.mul(m, r2);
    /// let i = a.abbreviate("I", def).unwrap();
    /// let e = a.mul(i, i);
    /// assert_eq!(a.display(e), "I^2");
    /// assert_relative_eq!(a.eval(e, &[2.0, 3.0]), 324.0);
    /// let sm = a.as_symbol(m).unwrap();
    /// let d = a.diff(e, sm); // 2 I ∂I/∂m = 2 m r⁴
    /// assert_relative_eq!(a.eval(d, &[2.0, 3.0]), 324.0);
    /// ```
    ///
    /// # Errors
    /// [`SymError::TimeDependentAbbreviation`] if `definition` depends on time or a
    /// coordinate; [`SymError::ForeignExpression`] for an id of another arena;
    /// [`SymError::ExpansionTooLarge`] if deciding that it equals an earlier definition
    /// would need an expansion past the term limit.
    pub fn abbreviate(&mut self, name: &str, definition: ExprId) -> Result<ExprId, SymError> {
        self.check_owned(&[definition])?;
        if self.as_rational(definition).is_some() || self.as_symbol(definition).is_some() {
            return Ok(definition);
        }
        for s in self.free_symbols(definition) {
            let kind = self.symbol(s).kind;
            if matches!(
                kind,
                SymbolKind::Time | SymbolKind::Coordinate | SymbolKind::Derivative { .. }
            ) {
                return Err(SymError::TimeDependentAbbreviation {
                    name: name.to_owned(),
                    symbol: self.symbol(s).name.clone(),
                });
            }
        }
        // Definitions are matched by their values at two points modulo a prime (cheap for
        // any size) and confirmed exactly, so equal definitions share one symbol without
        // expanding either unless they match.
        let key = [1, 2].map(|seed| self.modular_value(definition, seed));
        let key = match key {
            [Some(a), Some(b)] => [a, b],
            _ => [u64::MAX, definition.index() as u64],
        };
        if key == [0, 0] && self.is_zero(definition)? {
            return Ok(self.zero());
        }
        let candidates = self.abbreviations.get(&key).cloned().unwrap_or_default();
        for c in candidates {
            let Some(d) = self.as_symbol(c).and_then(|s| self.definition(s)) else {
                continue;
            };
            let difference = self.sub(definition, d);
            if d == definition || self.is_zero(difference)? {
                return Ok(c);
            }
        }
        let s = self.new_symbol(name, latex_name(name), SymbolKind::Abbreviation);
        self.definitions.insert(s, definition);
        let e = self.symbol_expr(s);
        self.abbreviations.entry(key).or_default().push(e);
        Ok(e)
    }

    /// The expression an abbreviation stands for (`None` for other symbols).
    pub fn definition(&self, s: SymbolId) -> Option<ExprId> {
        self.definitions.get(&s).copied()
    }

    /// `e` with every abbreviation replaced by its definition, recursively.
    ///
    /// # Errors
    /// As [`Arena::subs`].
    pub fn inline_abbreviations(&mut self, e: ExprId) -> Result<ExprId, SymError> {
        if self.definitions.is_empty() {
            return Ok(e);
        }
        let pairs: Vec<(SymbolId, ExprId)> =
            self.definitions.iter().map(|(&s, &d)| (s, d)).collect();
        let mut out = e;
        // A definition may name older abbreviations: each pass removes one level.
        while self
            .free_symbols(out)
            .iter()
            .any(|s| self.definitions.contains_key(s))
        {
            out = self.subs(out, &pairs)?;
        }
        Ok(out)
    }
}
