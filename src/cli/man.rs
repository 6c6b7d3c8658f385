//! `tmclsh man`: the manual page (roff), generated from the same clap definitions as `--help` and
//! the completions, so the three cannot disagree. `man/tmclsh.1` is its output, kept current by a
//! test. One page: the shell's options, then a section per subcommand with its synopsis and
//! options, then exit status, environment and files.

use std::io::{self, Write};

use clap::Command;
use clap_mangen::Man;

/// Prints the page.
pub fn run(out: &mut dyn Write) -> io::Result<()> {
    out.write_all(&render()?)
}

/// The whole page.
pub fn render() -> io::Result<Vec<u8>> {
    let mut cmd = super::command();
    cmd.build();
    let mut page = Vec::new();
    let man = Man::new(cmd.clone()).manual("tmclsh manual");
    man.render_title(&mut page)?;
    man.render_name_section(&mut page)?;
    man.render_synopsis_section(&mut page)?;
    man.render_description_section(&mut page)?;
    man.render_options_section(&mut page)?;
    // clap_mangen's own list points to a page per subcommand; here they are sections below.
    writeln!(page, ".SH COMMANDS")?;
    for sub in cmd
        .get_subcommands()
        .filter(|s| !s.is_hide_set() && s.get_name() != "help")
    {
        let about = sub.get_about().map(|a| a.to_string()).unwrap_or_default();
        writeln!(
            page,
            ".TP\n\\fBtmclsh {}\\fR\n{}",
            sub.get_name(),
            roff_text(&about)
        )?;
    }
    for sub in cmd.get_subcommands().filter(|s| !s.is_hide_set()) {
        subcommand(&mut page, sub, &format!("tmclsh {}", sub.get_name()))?;
    }
    page.extend_from_slice(TAIL.as_bytes());
    man.render_version_section(&mut page)?;
    Ok(page)
}

/// A section for `sub` (named `path`): what it does, its synopsis and its options; nested
/// subcommands (`snapshot save`) get a section each.
fn subcommand(page: &mut Vec<u8>, sub: &Command, path: &str) -> io::Result<()> {
    if sub.get_name() == "help" {
        return Ok(());
    }
    if sub.has_subcommands() {
        for nested in sub.get_subcommands().filter(|s| !s.is_hide_set()) {
            subcommand(page, nested, &format!("{path} {}", nested.get_name()))?;
        }
        return Ok(());
    }
    writeln!(page, ".SH \"{}\"", path.to_uppercase())?;
    let named = sub
        .clone()
        .name(path.to_string())
        .bin_name(path.to_string());
    let man = Man::new(named);
    let mut body = Vec::new();
    man.render_description_section(&mut body)?;
    man.render_synopsis_section(&mut body)?;
    let has_options = sub
        .get_arguments()
        .any(|a| !a.is_positional() && !a.is_hide_set());
    if has_options {
        man.render_options_section(&mut body)?;
    }
    // The pieces come with section headings of their own; inside this section they are
    // paragraphs.
    let body = String::from_utf8_lossy(&body)
        .replace(".SH DESCRIPTION\n", "")
        .replace(".SH SYNOPSIS\n", ".PP\n")
        .replace(".SH OPTIONS\n", ".PP\nOptions:\n");
    page.extend_from_slice(body.as_bytes());
    Ok(())
}

/// Text safe as a roff text line: no leading dot or quote, backslashes and hyphens escaped.
fn roff_text(text: &str) -> String {
    let text = text.replace('\\', "\\e").replace('-', "\\-");
    match text.chars().next() {
        Some('.' | '\'') => format!("\\&{text}"),
        _ => text,
    }
}

/// What the clap definitions do not hold: exit codes, environment, files.
const TAIL: &str = r#".SH "EXIT STATUS"
.TP
0
success
.TP
1
the device reported an error status, a script assertion failed or a script hit one of its limits;
\fBparams\fR: no parameter matches
.TP
2
input refused before anything was sent: validation, usage, a script that does not compile, a
configuration file with an unknown key or a bad value
.TP
3
connection failure, timeout or lost link
.TP
130
interrupted (Ctrl\-C)
.TP
143, 129
ended by SIGTERM or SIGHUP (or the interactive shell's terminal went away); the motors the
session set moving were stopped first
.TP
101
internal error; the motors the session set moving were stopped first
.SH ENVIRONMENT
.TP
\fBTMCLSH_PORT\fR, \fBTMCLSH_BAUD\fR, \fBTMCLSH_PROTOCOL\fR, \fBTMCLSH_PROFILE\fR, \fBTMCLSH_MODULE\fR, \fBTMCLSH_TIMEOUT\fR
the value of the option of the same name, below the command line and above the configuration
files; an empty variable counts as unset
.TP
\fBNO_COLOR\fR
plain output in the interactive shell
.TP
\fBXDG_CONFIG_HOME\fR, \fBXDG_DATA_HOME\fR
where the user's configuration file and the shell's history are
.SH FILES
.TP
\fBtmclsh.toml\fR
the project's configuration file, in the working directory or the nearest directory above it;
used only when it is the user's (or root's) and nobody else may write it, otherwise ignored with a
note
.TP
\fB$XDG_CONFIG_HOME/tmclsh/config.toml\fR (\fB~/.config/tmclsh/config.toml\fR)
the user's configuration file; keys port, baud, protocol, profile, module, timeout, echo,
log_dir, dtr, rts, rs485, rs485_delay and keep_latency; \fBtmclsh config\fR shows each setting and where it came from
.TP
\fB$XDG_DATA_HOME/tmclsh/history\-tmcl\fR, \fBhistory\-smd4\fR
the interactive shell's history, one file per protocol
"#;
