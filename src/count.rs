//! Counts in messages with the right number of the noun: `1 parameter`, `3 parameters`.

/// `n` and `noun`, plural unless `n` is 1 (`counted(1, "sample")` is `1 sample`).
pub fn counted(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_is_singular_everything_else_plural() {
        assert_eq!(counted(1, "parameter"), "1 parameter");
        assert_eq!(counted(0, "parameter"), "0 parameters");
        assert_eq!(counted(57, "setting"), "57 settings");
    }
}
