//! Tables and help fitted to the terminal: a row wider than the terminal continues on the next
//! lines, indented to the column it started in, instead of being wrapped by the terminal at
//! whatever letter meets the edge. Output that is not a terminal is left as it is, one row a line,
//! for the programs that read it.

use std::io::{self, IsTerminal, Write};

/// The terminal's width, when stdout is a terminal that tells it (never without the `cli`
/// feature, which brings the terminal).
pub fn terminal_width() -> Option<usize> {
    if !std::io::stdout().is_terminal() {
        return None;
    }
    #[cfg(feature = "cli")]
    {
        crossterm::terminal::size()
            .ok()
            .map(|(w, _)| usize::from(w))
            .filter(|w| *w > 0)
    }
    #[cfg(not(feature = "cli"))]
    None
}

/// Writes `row` as a line fitted to the terminal's width (see [`fit`]).
pub fn write_fitted(out: &mut dyn Write, row: &str, indent: usize) -> io::Result<()> {
    writeln!(out, "{}", fit(row, indent, terminal_width()))
}

/// `row` fitted to `width` columns (none: as it is): what follows column `indent` is wrapped at
/// spaces onto continuation lines starting at that column — or, where that leaves too little room,
/// a few columns in. A word longer than the room is cut.
pub fn fit(row: &str, indent: usize, width: Option<usize>) -> String {
    let chars: Vec<char> = row.chars().collect();
    let Some(width) = width else {
        return row.to_string();
    };
    if chars.len() <= width || width < 20 {
        return row.to_string();
    }
    let split = indent.min(chars.len());
    let head: String = chars[..split].iter().collect();
    let tail: String = chars[split..].iter().collect();
    let cont = if indent + 16 <= width { indent } else { 4 };
    let room = |line: usize| {
        if line == 0 {
            width.saturating_sub(split)
        } else {
            width - cont
        }
    };
    let mut lines: Vec<String> = vec![String::new()];
    for word in tail.split(' ').filter(|w| !w.is_empty()) {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let at = lines.len() - 1;
            let used = lines[at].chars().count();
            let gap = usize::from(used > 0);
            if used + gap + word.len() <= room(at) {
                if gap == 1 {
                    lines[at].push(' ');
                }
                lines[at].extend(word.iter());
                break;
            }
            if used > 0 || at == 0 {
                lines.push(String::new());
                continue;
            }
            // A word longer than a whole line: cut it.
            let rest = word.split_off(room(at));
            lines[at].extend(word.iter());
            lines.push(String::new());
            word = rest;
        }
    }
    let pad = " ".repeat(cont);
    let mut out = head.trim_end().to_string();
    for (i, line) in lines.iter().enumerate().filter(|(_, l)| !l.is_empty()) {
        if i == 0 {
            out = format!("{head}{line}");
        } else {
            out.push('\n');
            out.push_str(&pad);
            out.push_str(line);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_row_continues_at_its_column() {
        let row = "axis   6  max_current  RWE  0..15  1/15 of full scale (0 = 0 %, 15 = 100 %)";
        let fitted = fit(row, 35, Some(60));
        for line in fitted.lines() {
            assert!(line.chars().count() <= 60, "{line:?}");
        }
        let lines: Vec<&str> = fitted.lines().collect();
        assert!(lines.len() > 1, "{fitted}");
        assert!(lines[1].starts_with(&" ".repeat(35)), "{fitted}");
        assert_eq!(
            fitted.split_whitespace().collect::<Vec<_>>(),
            row.split_whitespace().collect::<Vec<_>>(),
            "nothing lost"
        );
    }

    #[test]
    fn short_rows_and_pipes_are_left_alone() {
        assert_eq!(fit("short", 2, Some(60)), "short");
        let long = "x".repeat(100);
        assert_eq!(fit(&long, 4, None), long);
        let cut = fit(&format!("ab {}", "y".repeat(100)), 3, Some(40));
        assert!(cut.lines().all(|l| l.chars().count() <= 40), "{cut}");
        // A head that leaves no room: the rest goes below, a few columns in.
        let wide = format!("{}unit text here", "h".repeat(58));
        let fitted = fit(&wide, 58, Some(60));
        assert!(fitted.lines().all(|l| l.chars().count() <= 60), "{fitted}");
        assert!(
            fitted.lines().nth(1).unwrap().starts_with("    unit"),
            "{fitted}"
        );
    }
}
