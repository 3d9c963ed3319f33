//! The messages for a word the language does not know: the "unknown key" message every
//! attribute and group gives, and the "did you mean" suggestion it, and the "unknown part"
//! message, end with.

use std::fmt::Display;

use syn::Ident;

use super::PARTS;
use crate::lang::ctxt::Ctxt;

/// The message for `written`, a key `place` does not take (`place` says where it was
/// written: ``for `sphere` ``, ``in `#[top]` ``): the keys `place` takes, then the `others`
/// that may stand there too (groups, each with the words it covers and its form as the
/// message gives it), and the "did you mean" over all those words:
/// ``unknown key `radus` for `sphere`: allowed keys are mass, radius, at; did you mean `radius`?``.
/// Every attribute and group gives this one message for a key it does not take.
pub fn unknown_key(
    written: impl Display,
    place: &str,
    keys: &[&str],
    others: &[(&[&str], String)],
) -> String {
    let written = written.to_string();
    let listed: String = others
        .iter()
        .map(|(_, form)| format!(", or {form}"))
        .collect();
    let known = keys
        .iter()
        .chain(others.iter().flat_map(|(words, _)| words.iter()))
        .copied();
    format!(
        "unknown key `{written}` {place}: allowed keys are {}{listed}{}",
        keys.join(", "),
        did_you_mean(&written, known)
    )
}

/// The key of `allowed` that `key` is, or `None` after recording on `key` that `place`
/// does not take it ([`unknown_key`]): the lookup of every group whose keys are one list.
pub fn known_key(
    cx: &Ctxt,
    key: &Ident,
    place: &str,
    allowed: &[&'static str],
) -> Option<&'static str> {
    let found = allowed.iter().find(|&&k| key == k).copied();
    if found.is_none() {
        cx.error_spanned_by(key, unknown_key(key, place, allowed, &[]));
    }
    found
}

/// `; did you mean `…`?` when exactly one of `known` is close to `written` (see
/// [`closest`]), else nothing: the suffix every "unknown part" and "unknown key" message
/// ends with, for any table of the keys (parts, part keys, `#[rigid]` and `#[top]` keys).
pub fn did_you_mean<'k>(written: &str, known: impl IntoIterator<Item = &'k str>) -> String {
    closest(written, known)
        .map(|k| format!("; did you mean `{k}`?"))
        .unwrap_or_default()
}

/// The one word of `known` nearest to `written`, if it is near enough to be a slip: at most
/// one edit per three letters written (at least one), and no other word as near. A tie
/// would be a guess, so it gives nothing.
pub fn closest<'k>(written: &str, known: impl IntoIterator<Item = &'k str>) -> Option<&'k str> {
    let limit = (written.chars().count() / 3).max(1);
    let mut best: Option<(usize, &'k str)> = None;
    let mut tied = false;
    for k in known {
        let d = edit_distance(written, k);
        match best {
            Some((b, w)) if d == b && w != k => tied = true,
            Some((b, _)) if d >= b => {}
            _ => {
                best = Some((d, k));
                tied = false;
            }
        }
    }
    match best {
        Some((d, k)) if d <= limit && !tied => Some(k),
        _ => None,
    }
}

/// The number of single-letter insertions, deletions, substitutions and swaps of two
/// neighbours that turn `a` into `b` (optimal string alignment; letters compared ignoring
/// case, so `Mass` is one step from nothing but a capital).
fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().flat_map(char::to_lowercase).collect();
    let b: Vec<char> = b.chars().flat_map(char::to_lowercase).collect();
    // rows[i][j]: the distance between the first i letters of a and the first j of b.
    let mut rows = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in rows.iter_mut().enumerate() {
        if let Some(first) = row.first_mut() {
            *first = i;
        }
    }
    if let Some(first) = rows.first_mut() {
        for (j, cell) in first.iter_mut().enumerate() {
            *cell = j;
        }
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut d = (rows[i - 1][j] + 1)
                .min(rows[i][j - 1] + 1)
                .min(rows[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(rows[i - 2][j - 2] + 1);
            }
            rows[i][j] = d;
        }
    }
    rows[a.len()][b.len()]
}

/// Every part name and alias.
pub fn part_names() -> impl Iterator<Item = &'static str> {
    PARTS
        .iter()
        .flat_map(|p| std::iter::once(p.name).chain(p.alias))
}

/// Words people write for a part that are not its name, each with the part meant. Spelling
/// alone would mislead here (`cube` is one letter from `tube`).
const PART_SYNONYMS: &[(&str, &str)] = &[
    ("cube", "cuboid"),
    ("block", "cuboid"),
    ("brick", "cuboid"),
    ("ball", "sphere"),
    ("point", "particle"),
    ("disc", "disk"),
    ("hoop", "ring"),
    ("pipe", "tube"),
    ("stick", "rod"),
    ("bar", "rod"),
    ("spheroid", "ellipsoid"),
];

/// `; did you mean `…`?` for an unknown part: the part a known synonym stands for, else as
/// [`did_you_mean`] over the part names and aliases.
pub fn did_you_mean_part(written: &str) -> String {
    let lower = written.to_lowercase();
    match PART_SYNONYMS.iter().find(|(word, _)| *word == lower) {
        Some((_, part)) => format!("; did you mean `{part}`?"),
        None => did_you_mean(written, part_names()),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{DAMPING, GRAVITY, PIVOT, RIGID_KEYS, TOP_KEYS, find_part};
    use super::*;

    #[test]
    fn the_unknown_key_message_lists_the_keys_then_the_groups() {
        assert_eq!(
            unknown_key("radus", "for `sphere`", &["mass", "radius", "at"], &[]),
            "unknown key `radus` for `sphere`: allowed keys are mass, radius, at; did you mean `radius`?"
        );
        // A group is listed after the keys, and a slip of its name is suggested too.
        let others: &[(&[&str], String)] = &[(&["rotor"], "a rotor `rotor(axis)`".to_owned())];
        assert_eq!(
            unknown_key("rotr", "in `#[top]`", &["gravity"], others),
            "unknown key `rotr` in `#[top]`: allowed keys are gravity, or a rotor `rotor(axis)`; did you mean `rotor`?"
        );
    }

    #[test]
    fn edit_distance_counts_each_kind_of_slip_once() {
        assert_eq!(edit_distance("gravity", "gravity"), 0);
        assert_eq!(edit_distance("gravty", "gravity"), 1); // deletion
        assert_eq!(edit_distance("graavity", "gravity"), 1); // insertion
        assert_eq!(edit_distance("gravitu", "gravity"), 1); // substitution
        assert_eq!(edit_distance("garvity", "gravity"), 1); // swap of neighbours
        assert_eq!(edit_distance("Radius", "radius"), 0);
        assert_eq!(edit_distance("", "at"), 2);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }

    #[test]
    fn a_suggestion_only_for_one_close_word() {
        assert_eq!(closest("gravty", TOP_KEYS.iter().copied()), Some(GRAVITY));
        assert_eq!(closest("dampnig", TOP_KEYS.iter().copied()), Some(DAMPING));
        assert_eq!(closest("spher", part_names()), Some("sphere"));
        assert_eq!(closest("bx", part_names()), Some("box"));
        assert_eq!(closest("pivto", RIGID_KEYS.iter().copied()), Some(PIVOT));
        // Far from every key: no guess.
        assert_eq!(closest("friction", TOP_KEYS.iter().copied()), None);
        assert_eq!(closest("torus", part_names()), None);
        // Two keys equally near: no guess either.
        assert_eq!(closest("ab", ["ac", "ad"]), None);
        assert_eq!(
            did_you_mean("radus", ["mass", "radius", "at"]),
            "; did you mean `radius`?"
        );
        assert_eq!(did_you_mean("colour", ["mass", "radius", "at"]), "");
        // A synonym is what was meant, not the nearest spelling.
        assert_eq!(did_you_mean_part("cube"), "; did you mean `cuboid`?");
        assert_eq!(did_you_mean_part("Ball"), "; did you mean `sphere`?");
        assert_eq!(did_you_mean_part("spehre"), "; did you mean `sphere`?");
        for (_, part) in PART_SYNONYMS {
            assert!(find_part(part).is_some(), "{part} is no part");
        }
    }
}
