//! "Did you mean …?" for mistyped command and parameter names.

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
    candidates
        .into_iter()
        .flat_map(|c| {
            let lower = c.to_ascii_lowercase();
            readings
                .iter()
                .map(move |r| (strsim::jaro_winkler(r, &lower), c))
                .collect::<Vec<_>>()
        })
        .filter(|(score, _)| *score >= 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, c)| c.to_string())
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
    }

    #[test]
    fn formats_the_hint() {
        assert_eq!(did_you_mean(&Some("GAP".into())), "; did you mean GAP?");
        assert_eq!(did_you_mean(&None), "");
    }
}
