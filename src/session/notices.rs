//! Notices summarised before they are shown: a module that floods the line with the same frame
//! (position-reached events, say) would otherwise get one stderr line per frame. Each distinct
//! notice is shown once, where it first came, with how many more alike followed.

/// `notices` with repeats folded into their first occurrence: `… (event)` then
/// `… (event) (and 49 more like it)`. Order of first occurrence is kept.
pub fn summarise(notices: Vec<String>) -> Vec<String> {
    if notices.len() < 2 {
        return notices;
    }
    let mut counted: Vec<(String, usize)> = Vec::new();
    let mut index: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for notice in notices {
        match index.get(&notice) {
            Some(&at) => counted[at].1 += 1,
            None => {
                index.insert(notice.clone(), counted.len());
                counted.push((notice, 0));
            }
        }
    }
    counted
        .into_iter()
        .map(|(notice, more)| match more {
            0 => notice,
            more => format!("{notice} (and {more} more like it)"),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeats_fold_into_the_first_with_a_count_in_order() {
        let event = "module 1 (A): target position reached (event)".to_string();
        let junk = "ignored unexpected data from the line: \"x\"".to_string();
        let mut notices = vec![junk.clone()];
        notices.extend(std::iter::repeat_n(event.clone(), 50));
        notices.push(junk.clone());
        notices.push("module 2 (B): target position reached (event)".into());
        assert_eq!(
            summarise(notices),
            [
                format!("{junk} (and 1 more like it)"),
                format!("{event} (and 49 more like it)"),
                "module 2 (B): target position reached (event)".to_string(),
            ]
        );
        assert_eq!(summarise(vec![event.clone()]), [event]);
    }
}
