//! Names as C and Python write them: identifiers that are neither language's keyword nor a
//! name the emitted code uses itself.

use super::{ExportError, Exported};

/// Words C99 or Python reserve, and the names the emitted code binds (`t`, `y`, `u`, `p`,
/// `out`, `np`, `math`): a name among them gets a trailing `_`.
const RESERVED: &[&str] = &[
    // C99
    "auto",
    "break",
    "case",
    "char",
    "const",
    "continue",
    "default",
    "do",
    "double",
    "else",
    "enum",
    "extern",
    "float",
    "for",
    "goto",
    "if",
    "inline",
    "int",
    "long",
    "register",
    "restrict",
    "return",
    "short",
    "signed",
    "sizeof",
    "static",
    "struct",
    "switch",
    "typedef",
    "union",
    "unsigned",
    "void",
    "volatile",
    "while",
    "_Bool",
    "_Complex",
    "_Imaginary",
    // Python
    "False",
    "None",
    "True",
    "and",
    "as",
    "assert",
    "async",
    "await",
    "class",
    "def",
    "del",
    "elif",
    "except",
    "finally",
    "from",
    "global",
    "import",
    "in",
    "is",
    "lambda",
    "nonlocal",
    "not",
    "or",
    "pass",
    "raise",
    "try",
    "with",
    "yield",
    // The emitted code's own names.
    "t",
    "y",
    "u",
    "p",
    "out",
    "np",
    "math",
];

/// `name` as an identifier of both languages: every character other than an ASCII letter,
/// digit or `_` becomes `_`, a leading digit gets a `_` before it, a reserved word a `_`
/// after it, and a name starting with `_` (the emitted code's locals) a `p` before it.
pub(super) fn identifier(name: &str) -> String {
    let mut s: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert(0, '_');
    }
    if s.starts_with('_') {
        s.insert(0, 'p');
    }
    if RESERVED.contains(&s.as_str()) {
        s.push('_');
    }
    s
}

impl Exported {
    /// Refuses two values (state entries, inputs, parameters) or two functions written
    /// alike.
    pub(super) fn check_names(&self) -> Result<(), ExportError> {
        let mut seen: Vec<&str> = Vec::new();
        let values = self
            .state
            .iter()
            .chain(&self.inputs)
            .chain(&self.parameters)
            .map(String::as_str);
        for name in values {
            if seen.contains(&name) {
                return Err(ExportError::DuplicateName {
                    name: name.to_owned(),
                });
            }
            seen.push(name);
        }
        for (i, f) in self.functions.iter().enumerate() {
            if self.functions[..i].iter().any(|g| g.name == f.name) {
                return Err(ExportError::DuplicateName {
                    name: f.name.clone(),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::identifier;

    #[test]
    fn names_are_identifiers_of_both_languages() {
        assert_eq!(identifier("theta_dot"), "theta_dot");
        assert_eq!(identifier("R00"), "R00");
        assert_eq!(identifier("omega 1"), "omega_1");
        assert_eq!(identifier("1st"), "p_1st");
        assert_eq!(identifier("lambda"), "lambda_");
        assert_eq!(identifier("double"), "double_");
        assert_eq!(identifier("y"), "y_");
        assert_eq!(identifier("u"), "u_");
        assert_eq!(identifier("_v3"), "p_v3");
    }
}
