//! A run's test blocks as a JUnit XML report (`tmclsh run --junit FILE`), the format CI servers
//! (GitLab, Jenkins, GitHub test reporters) render: one `<testsuite>` for the script, one
//! `<testcase>` per `test` block, a `<failure>` for a failed assertion or device error (exit 1)
//! and an `<error>` for anything else (a timeout, a lost link, a refused call), each with its
//! message and `script:line:column`. A script without blocks is one case named after the script;
//! a failure outside every block is a case named `(script)`.

use std::fmt::Write;
use std::time::Duration;

use crate::escape::escape_control;
use crate::exit::{Exit, Failure};

use super::blocks::{Case, Report};

/// The report of the script `name` (its path as given) whose blocks did `report`, the whole run
/// having ended with `outcome`.
pub fn xml(name: &str, report: &Report, outcome: &Result<(), Failure>) -> String {
    let class = classname(name);
    let mut cases = report.cases.clone();
    if cases.is_empty() {
        cases.push(Case {
            name: class.clone(),
            time: Duration::ZERO,
            failure: outcome.clone().err(),
        });
    } else if let Some(failure) = &report.outside {
        cases.push(Case {
            name: "(script)".into(),
            time: Duration::ZERO,
            failure: Some(failure.clone()),
        });
    }
    let is_failure = |c: &Case| {
        c.failure
            .as_ref()
            .is_some_and(|f| f.exit == Exit::DeviceError)
    };
    let is_error = |c: &Case| {
        c.failure
            .as_ref()
            .is_some_and(|f| f.exit != Exit::DeviceError)
    };
    let failures = cases.iter().filter(|c| is_failure(c)).count();
    let errors = cases.iter().filter(|c| is_error(c)).count();
    let time: Duration = cases.iter().map(|c| c.time).sum();
    let counts = format!(
        "tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{}\"",
        cases.len(),
        seconds(time)
    );
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(out, "<testsuites name=\"tmclsh run\" {counts}>");
    let _ = writeln!(
        out,
        "  <testsuite name=\"{}\" {counts} skipped=\"0\">",
        attribute(name)
    );
    for case in &cases {
        let head = format!(
            "    <testcase name=\"{}\" classname=\"{}\" time=\"{}\"",
            attribute(&case.name),
            attribute(&class),
            seconds(case.time)
        );
        match &case.failure {
            None => {
                let _ = writeln!(out, "{head}/>");
            }
            Some(failure) => {
                let (element, kind) = if failure.exit == Exit::DeviceError {
                    ("failure", "assertion")
                } else {
                    ("error", "error")
                };
                let _ = writeln!(out, "{head}>");
                let _ = writeln!(
                    out,
                    "      <{element} message=\"{}\" type=\"{kind}\">exit code {}: {}</{element}>",
                    attribute(&failure.message),
                    failure.exit.code(),
                    text(&failure.message)
                );
                let _ = writeln!(out, "    </testcase>");
            }
        }
    }
    out.push_str("  </testsuite>\n</testsuites>\n");
    out
}

/// The script's file name without its extension: the class of its cases.
fn classname(name: &str) -> String {
    let file = std::path::Path::new(name);
    file.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| name.to_string())
}

fn seconds(time: Duration) -> String {
    format!("{:.3}", time.as_secs_f64())
}

/// Text for element content: control characters (which XML 1.0 cannot carry) as visible
/// escapes, the markup characters as entities.
fn text(raw: &str) -> String {
    escape_control(raw)
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Text for an attribute value: as [`text`], quotes as entities and a line feed as `&#10;`.
fn attribute(raw: &str) -> String {
    text(raw)
        .replace('"', "&quot;")
        .replace('\'', "&apos;")
        .replace('\n', "&#10;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_and_control_characters_are_escaped() {
        assert_eq!(
            attribute("a<b & \"c\"\n\x1b[2J"),
            "a&lt;b &amp; &quot;c&quot;&#10;\\x1B[2J"
        );
        assert_eq!(text("x > y\x07"), "x &gt; y\\x07");
    }

    #[test]
    fn a_script_without_blocks_is_one_case_named_after_it() {
        let failed = Err(Failure::new(Exit::Link, "s.rhai:2:1: timeout"));
        let xml = xml("dir/s.rhai", &Report::default(), &failed);
        assert!(
            xml.contains("<testcase name=\"s\" classname=\"s\""),
            "{xml}"
        );
        assert!(
            xml.contains("<error message=\"s.rhai:2:1: timeout\""),
            "{xml}"
        );
        assert!(
            xml.contains("tests=\"1\" failures=\"0\" errors=\"1\""),
            "{xml}"
        );
    }
}
