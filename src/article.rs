//! The indefinite article before a name in messages, by how the name is spoken: `a TMCM-142`,
//! `an SMD4` ("es-em-dee"), `an unknown module`.

/// `name` with `a` or `an` before it (`with_article("SMD4")` is `an SMD4`).
pub fn with_article(name: &str) -> String {
    format!("{} {name}", article(name))
}

/// `a` or `an`, whichever `name` takes.
pub fn article(name: &str) -> &'static str {
    if starts_with_vowel_sound(name) {
        "an"
    } else {
        "a"
    }
}

/// Product names, abbreviations and type names (`SMD4`, `TMCM-142`, `FPGA`, `f64`) are spelt out
/// letter by letter, so their first letter's name counts; other words are read as words.
fn starts_with_vowel_sound(name: &str) -> bool {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    let second = chars.next();
    let spelt = (first.is_ascii_uppercase()
        && second.is_none_or(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '-'))
        || (first.is_ascii_alphabetic() && second.is_some_and(|c| c.is_ascii_digit()));
    if spelt {
        let first = first.to_ascii_uppercase();
        // The letters whose names start with a vowel: "ay", "ee", "ef", "aitch", "eye", "el",
        // "em", "en", "oh", "ar", "es", "ex".
        return "AEFHILMNORSX".contains(first);
    }
    if first == '8' {
        return true;
    }
    let lower = name.to_ascii_lowercase();
    if lower.starts_with('u') {
        // "a unit", "a usual", but "an unknown", "an untested".
        return !["uni", "use", "usu", "uti", "ura"]
            .iter()
            .any(|p| lower.starts_with(p));
    }
    lower.starts_with(['a', 'e', 'i', 'o'])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_spelt_letter_by_letter_take_the_article_of_their_first_letter() {
        assert_eq!(with_article("SMD4"), "an SMD4");
        assert_eq!(with_article("SMD2"), "an SMD2");
        assert_eq!(with_article("TMCM-142"), "a TMCM-142");
        assert_eq!(with_article("PD-1141"), "a PD-1141");
        assert_eq!(with_article("FPGA"), "an FPGA");
        assert_eq!(with_article("USB adapter"), "a USB adapter");
    }

    #[test]
    fn words_take_the_article_of_their_sound() {
        assert_eq!(with_article("unknown module"), "an unknown module");
        assert_eq!(with_article("unit"), "a unit");
        assert_eq!(with_article("SMD4 drive"), "an SMD4 drive");
        assert_eq!(with_article("TMCL module"), "a TMCL module");
        assert_eq!(with_article("Eval board"), "an Eval board");
        assert_eq!(with_article("module"), "a module");
        assert_eq!(with_article("8-axis module"), "an 8-axis module");
        assert_eq!(article(""), "a");
        // Script value types.
        assert_eq!(with_article("array"), "an array");
        assert_eq!(with_article("i64"), "an i64");
        assert_eq!(with_article("f64"), "an f64");
        assert_eq!(with_article("u8"), "a u8");
        assert_eq!(with_article("map"), "a map");
    }
}
