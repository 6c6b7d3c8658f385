//! Terminal charts of a recording, drawn with braille dots (2×4 per character cell), one chart per
//! recorded parameter against time — enough to see the shape of a ramp at a glance.
//!
//! Hand-written rather than a charting crate: about a hundred lines, no dependency, and the output
//! is plain text that tests can read back dot by dot.

use std::io::{self, Write};

use super::record::Recording;

/// The braille bit of the dot at column `dx` (0..2) and row `dy` (0..4) of a cell.
fn dot_bit(dx: usize, dy: usize) -> u8 {
    const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
    BITS[dx][dy]
}

/// A grid of braille cells.
struct Canvas {
    cells: Vec<Vec<u8>>,
    width: usize,
    height: usize,
}

impl Canvas {
    fn new(width: usize, height: usize) -> Canvas {
        Canvas {
            cells: vec![vec![0; width]; height],
            width,
            height,
        }
    }

    /// Sets the dot at (x, y) in dot coordinates, y = 0 at the top.
    fn set(&mut self, x: usize, y: usize) {
        if x < self.width * 2 && y < self.height * 4 {
            self.cells[y / 4][x / 2] |= dot_bit(x % 2, y % 4);
        }
    }

    /// Draws a straight line of dots between two points (Bresenham).
    fn line(&mut self, (x0, y0): (i64, i64), (x1, y1): (i64, i64)) {
        let (dx, dy) = ((x1 - x0).abs(), -(y1 - y0).abs());
        let (sx, sy) = ((x1 - x0).signum(), (y1 - y0).signum());
        let (mut x, mut y, mut err) = (x0, y0, dx + dy);
        loop {
            self.set(x as usize, y as usize);
            if x == x1 && y == y1 {
                break;
            }
            let e2 = 2 * err;
            if e2 >= dy {
                err += dy;
                x += sx;
            }
            if e2 <= dx {
                err += dx;
                y += sy;
            }
        }
    }

    fn rows(&self) -> Vec<String> {
        self.cells
            .iter()
            .map(|row| {
                row.iter()
                    .map(|&bits| char::from_u32(0x2800 + u32::from(bits)).unwrap_or(' '))
                    .collect()
            })
            .collect()
    }
}

/// A chart of `points` (x ascending): a title line, `height` rows of `width` braille cells with
/// the value range on the left, and the x range below.
pub fn chart(title: &str, points: &[(f64, f64)], width: usize, height: usize) -> Vec<String> {
    let width = width.max(2);
    let height = height.max(2);
    let mut lines = vec![title.to_string()];
    if points.is_empty() {
        lines.push("(no samples)".into());
        return lines;
    }
    let (x_lo, x_hi) = range(points.iter().map(|p| p.0));
    let (y_lo, y_hi) = range(points.iter().map(|p| p.1));
    let (w, h) = (width * 2 - 1, height * 4 - 1);
    let scale =
        |v: f64, lo: f64, hi: f64, n: usize| ((v - lo) / (hi - lo) * n as f64).round() as i64;
    let dots: Vec<(i64, i64)> = points
        .iter()
        .map(|&(x, y)| (scale(x, x_lo, x_hi, w), h as i64 - scale(y, y_lo, y_hi, h)))
        .collect();
    let mut canvas = Canvas::new(width, height);
    canvas.set(dots[0].0 as usize, dots[0].1 as usize);
    for pair in dots.windows(2) {
        canvas.line(pair[0], pair[1]);
    }
    let top = number(y_hi);
    let bottom = number(y_lo);
    let label_width = top.len().max(bottom.len());
    for (i, row) in canvas.rows().into_iter().enumerate() {
        let label = match i {
            0 => top.clone(),
            i if i == height - 1 => bottom.clone(),
            _ => String::new(),
        };
        let axis = if label.is_empty() { '│' } else { '┤' };
        lines.push(format!("{label:>label_width$} {axis}{row}"));
    }
    lines.push(format!("{:label_width$} └{}", "", "─".repeat(width)));
    let left = format!("{} s", number(x_lo));
    let right = format!("{} s", number(x_hi));
    let gap = width.saturating_sub(left.len() + right.len()).max(1);
    lines.push(format!(
        "{:label_width$}  {left}{}{right}",
        "",
        " ".repeat(gap)
    ));
    lines
}

/// The range of the values, widened when flat so a constant draws as a line in the middle.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if hi > lo {
        (lo, hi)
    } else {
        (lo - 1.0, hi + 1.0)
    }
}

fn number(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{v:.0}")
    } else {
        format!("{v:.3}")
    }
}

/// Draws every column of `recording` as a chart, `width` characters wide in all; a column of
/// text (an SMD4's flag words) is named, not drawn.
pub fn write_recording(recording: &Recording, width: usize, out: &mut dyn Write) -> io::Result<()> {
    for (i, name) in recording.columns.iter().enumerate() {
        if !recording.numeric(i) {
            writeln!(out, "{name}: not numbers, not drawn (see the CSV file)\n")?;
            continue;
        }
        let points = recording.series(i);
        let label = points.iter().map(|p| number(p.1).len()).max().unwrap_or(1) + 2;
        let cells = width.saturating_sub(label + 2).max(10);
        for line in chart(name, &points, cells, 8) {
            writeln!(out, "{line}")?;
        }
        writeln!(out)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The dots of a chart's plot area as (x, y) pairs, y = 0 at the top.
    fn dots(lines: &[String], height: usize) -> Vec<(usize, usize)> {
        let mut found = Vec::new();
        for (row, line) in lines[1..=height].iter().enumerate() {
            let cells: Vec<char> = line
                .chars()
                .skip_while(|c| *c != '┤' && *c != '│')
                .skip(1)
                .collect();
            for (col, c) in cells.iter().enumerate() {
                let bits = (*c as u32 - 0x2800) as u8;
                for dx in 0..2 {
                    for dy in 0..4 {
                        if bits & dot_bit(dx, dy) != 0 {
                            found.push((col * 2 + dx, row * 4 + dy));
                        }
                    }
                }
            }
        }
        found
    }

    #[test]
    fn a_rising_ramp_runs_from_bottom_left_to_top_right_without_gaps() {
        let points: Vec<(f64, f64)> = (0..=20)
            .map(|i| (i as f64 * 0.1, i as f64 * 50.0))
            .collect();
        let lines = chart("actual_position", &points, 20, 5);
        assert_eq!(lines[0], "actual_position");
        let dots = dots(&lines, 5);
        assert!(dots.contains(&(0, 19)), "bottom left: {dots:?}");
        assert!(dots.contains(&(39, 0)), "top right");
        for x in 0..40 {
            let ys: Vec<usize> = dots.iter().filter(|d| d.0 == x).map(|d| d.1).collect();
            assert!(!ys.is_empty(), "column {x} has a dot");
        }
        let top_of = |x| dots.iter().filter(|d| d.0 == x).map(|d| d.1).min().unwrap();
        assert!(
            (1..40).all(|x| top_of(x) <= top_of(x - 1)),
            "monotonic rise"
        );
    }

    #[test]
    fn labels_show_the_value_range_and_the_time_range() {
        let points = [(0.0, -500.0), (1.5, 1000.0)];
        let lines = chart("v", &points, 30, 4);
        assert!(lines[1].trim_start().starts_with("1000 ┤"), "{:?}", lines);
        assert!(lines[4].trim_start().starts_with("-500 ┤"));
        assert!(lines[2].contains('│'));
        let x_axis = lines.last().unwrap();
        assert!(x_axis.trim_start().starts_with("0 s"), "{x_axis}");
        assert!(x_axis.trim_end().ends_with("1.500 s"));
    }

    #[test]
    fn a_constant_draws_a_flat_line_in_the_middle_and_no_samples_say_so() {
        let points = [(0.0, 7.0), (1.0, 7.0), (2.0, 7.0)];
        let lines = chart("c", &points, 10, 4);
        let dots = dots(&lines, 4);
        let rows: std::collections::BTreeSet<usize> = dots.iter().map(|d| d.1).collect();
        assert_eq!(rows.len(), 1);
        assert_eq!(*rows.iter().next().unwrap(), 7, "middle of 16 dot rows");
        assert_eq!(chart("e", &[], 10, 4), ["e", "(no samples)"]);
    }

    #[test]
    fn every_column_of_a_recording_gets_its_chart() {
        let rec = Recording::from_csv(
            "time_ms,actual_position,actual_speed\n0,0,0\n100,10,100\n200,40,100\n",
        )
        .unwrap();
        let mut out = Vec::new();
        write_recording(&rec, 60, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let titles: Vec<&str> = text.lines().filter(|l| l.starts_with("actual_")).collect();
        assert_eq!(titles, ["actual_position", "actual_speed"]);
        assert!(text.lines().all(|l| l.chars().count() <= 60), "{text}");
    }
}
