//! "Did you mean …?" for mistyped command and parameter names. A name a few edits away wins, the
//! fewest edits per letter first — edits counted by Damerau–Levenshtein, so two letters swapped
//! (`GPA` for `GAP`) are one edit like a wrong, missing or extra letter. Failing that, a long name that keeps
//! most of the typed letters in order (Jaro–Winkler) is suggested, as for `max_curent`.

/// The candidate closest to `word`, if it is close enough to be a plausible typo.
pub fn nearest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<String> {
    nearest_of(&[word], candidates)
}

/// The candidate closest to any of several readings of what was typed.
pub fn nearest_of<'a>(
    readings: &[&str],
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<String> {
    let readings: Vec<String> = readings
        .iter()
        .filter(|r| !r.is_empty())
        .map(|r| r.to_ascii_lowercase())
        .collect();
    let mut by_edits: Option<(f64, f64, &str)> = None;
    let mut by_likeness: Option<(f64, &str)> = None;
    for candidate in candidates {
        let lower = candidate.to_ascii_lowercase();
        for reading in &readings {
            let edits = strsim::damerau_levenshtein(reading, &lower);
            let likeness = strsim::jaro_winkler(reading, &lower);
            if edits <= allowed_edits(reading) {
                // Edits per letter: one wrong letter in two is a worse guess than one in three.
                let longer = reading.chars().count().max(lower.chars().count());
                let share = edits as f64 / longer as f64;
                let better =
                    by_edits.is_none_or(|(s, l, _)| share < s || (share == s && likeness > l));
                if better {
                    by_edits = Some((share, likeness, candidate));
                }
            }
            if likeness >= LIKENESS && by_likeness.is_none_or(|(l, _)| likeness > l) {
                by_likeness = Some((likeness, candidate));
            }
        }
    }
    by_edits
        .map(|(_, _, c)| c)
        .or(by_likeness.map(|(_, c)| c))
        .map(str::to_string)
}

/// Jaro–Winkler similarity from which a name counts as a likely misspelling.
const LIKENESS: f64 = 0.8;

/// How many edits a typo of `word` plausibly has: one in a short name, more in longer ones.
fn allowed_edits(word: &str) -> usize {
    match word.chars().count() {
        0 => 0,
        1..=5 => 1,
        6..=9 => 2,
        _ => 3,
    }
}

/// "; did you mean X?" or nothing, for error messages.
pub fn did_you_mean(suggestion: &Option<String>) -> String {
    match suggestion {
        Some(s) => format!("; did you mean {s}?"),
        None => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_close_names_and_ignores_far_ones() {
        let names = ["GAP", "SAP", "MVP", "actual_position"];
        assert_eq!(nearest("GAPP", names).as_deref(), Some("GAP"));
        assert_eq!(
            nearest("actual_positon", names).as_deref(),
            Some("actual_position")
        );
        assert_eq!(nearest("zzzzzz", names), None);
        assert_eq!(nearest("QQQ", names), None);
    }

    #[test]
    fn two_swapped_letters_are_one_edit() {
        let names = [
            "GAP",
            "SAP",
            "GGP",
            "MVP",
            "actual_position",
            "actual_speed",
        ];
        assert_eq!(nearest("GPA", names).as_deref(), Some("GAP"));
        assert_eq!(nearest("SPA", names).as_deref(), Some("SAP"));
        assert_eq!(nearest("VMP", names).as_deref(), Some("MVP"));
        assert_eq!(
            nearest("acutal_position", names).as_deref(),
            Some("actual_position")
        );
        assert_eq!(
            nearest("actual_spede", names).as_deref(),
            Some("actual_speed")
        );
    }

    #[test]
    fn fewer_edits_win_over_a_longer_shared_prefix() {
        // One edit from MST, two from MVP: the closer one is suggested.
        assert_eq!(nearest("MTS", ["MVP", "MST"]).as_deref(), Some("MST"));
    }

    #[test]
    fn any_reading_may_match_and_the_smaller_share_of_edits_wins() {
        assert_eq!(
            nearest_of(&["AGPA", "GPA"], ["GAP", "SAP"]).as_deref(),
            Some("GAP")
        );
        // `GPA` may be `PA` after address G: one edit from JA, but one in two letters.
        assert_eq!(
            nearest_of(&["GPA", "PA"], ["GAP", "JA", "SAP"]).as_deref(),
            Some("GAP")
        );
    }

    #[test]
    fn formats_the_hint() {
        assert_eq!(did_you_mean(&Some("GAP".into())), "; did you mean GAP?");
        assert_eq!(did_you_mean(&None), "");
    }
}
