//! `tmclsh man`: the manual page (roff), generated from the same clap definitions as `--help` and
//! the completions, so the three cannot disagree. `man/tmclsh.1` is its output, kept current by a
//! test. One page: the shell's options, then a section per subcommand with its synopsis and
//! options, then examples, exit status, environment and files. The synopses are written here:
//! clap_mangen's name no values (`[-c ]`, `[--port]`).

use std::io::{self, Write};

use clap::{Arg, ArgAction, Command};
use clap_mangen::Man;

/// An example of the EXAMPLES section: the command line and what it does.
pub struct Example {
    /// The command line, starting with `tmclsh`.
    pub command: &'static str,
    /// What it does, one sentence.
    pub what: &'static str,
    /// Whether it runs to its end without a terminal (the test suite runs those given `--sim`).
    pub batch: bool,
}

/// The EXAMPLES section: every one on the built-in simulator (`--sim`) or a placeholder port.
pub const EXAMPLES: &[Example] = &[
    Example {
        command: "tmclsh --sim",
        what: "The interactive shell on the built-in simulated TMCM-142 (:help lists the helpers).",
        batch: false,
    },
    Example {
        command: "tmclsh --port /dev/ttyUSB0 --baud 115200",
        what: "The interactive shell on the module at a serial port.",
        batch: false,
    },
    Example {
        command: "tmclsh --sim -c 'ROR 0, 1000' -c 'GAP 3, 0'",
        what: "Send two lines and print each reply; the exit code says whether all went well.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim --value -c 'GAP 1, 0'",
        what: "Print only the value of a reply, for a shell script.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim --protocol smd4 -c 'SYS:FW'",
        what: "Talk to the simulated AML SMD4 drive instead.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim scan",
        what: "Find the modules on the bus, with firmware versions.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim params --values --motor 0 speed",
        what: "Read motor 0's parameters whose names contain speed from the module.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim run scripts/back_and_forth.rhai -- 2 2000 200000 4000000",
        what: "Run a Rhai script; exit code 0 when it passed, 1 when an assertion failed.",
        batch: true,
    },
    Example {
        command: "tmclsh --sim snapshot save rig.toml",
        what: "Save the module's parameters to a TOML file (snapshot diff and restore use it).",
        batch: true,
    },
    Example {
        command: "tmclsh --port /dev/ttyUSB0 download scripts/test2.tmc --run",
        what: "Assemble a TMCL program, store it in the module, verify it and start it.",
        batch: false,
    },
    Example {
        command: "tmclsh ports --probe --baud 115200",
        what: "List the serial ports and ask each USB port which module answers at 115200 baud.",
        batch: false,
    },
];

/// The whole page.
pub fn render() -> io::Result<Vec<u8>> {
    let mut cmd = super::command();
    cmd.build();
    let mut page = Vec::new();
    let man = Man::new(cmd.clone()).manual("tmclsh manual");
    man.render_title(&mut page)?;
    man.render_name_section(&mut page)?;
    writeln!(page, ".SH SYNOPSIS\n{}", synopsis(&cmd, "tmclsh"))?;
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
    examples(&mut page)?;
    page.extend_from_slice(EXIT_STATUS.as_bytes());
    environment(&mut page, &cmd)?;
    files(&mut page)?;
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
    writeln!(body, ".PP\n{}", synopsis(sub, path))?;
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
        .replace(".SH OPTIONS\n", ".PP\nOptions:\n");
    page.extend_from_slice(body.as_bytes());
    Ok(())
}

/// The synopsis of `cmd` called `name`: each visible option with its value (`[-c LINE]...`,
/// `[--port PATH]`), the arguments, then `[COMMAND]` where it has subcommands.
fn synopsis(cmd: &Command, name: &str) -> String {
    let mut line = format!("\\fB{}\\fR", roff_text(name));
    let options = cmd
        .get_arguments()
        .filter(|a| !a.is_positional() && !a.is_hide_set());
    for arg in options {
        let flag = match (arg.get_short(), arg.get_long()) {
            (Some(short), Some(long)) => format!("\\fB-{short}\\fR|\\fB--{long}\\fR"),
            (Some(short), None) => format!("\\fB-{short}\\fR"),
            (None, Some(long)) => format!("\\fB--{long}\\fR"),
            (None, None) => continue,
        };
        let value = match value_name(arg) {
            Some(value) if optional_value(arg) => format!("[=\\fI{value}\\fR]"),
            Some(value) => format!(" \\fI{value}\\fR"),
            None => String::new(),
        };
        let repeated = matches!(arg.get_action(), ArgAction::Append | ArgAction::Count);
        let dots = if repeated { "..." } else { "" };
        line.push_str(&format!(" [{}{value}]{dots}", flag.replace('-', "\\-")));
    }
    for arg in cmd.get_positionals().filter(|a| !a.is_hide_set()) {
        let value = format!("\\fI{}\\fR", value_name(arg).unwrap_or_default());
        let many = arg.get_num_args().is_some_and(|n| n.max_values() > 1);
        let dots = if many { "..." } else { "" };
        if arg.is_required_set() {
            line.push_str(&format!(" {value}{dots}"));
        } else {
            line.push_str(&format!(" [{value}]{dots}"));
        }
    }
    if cmd.has_subcommands() {
        line.push_str(" [\\fICOMMAND\\fR]");
    }
    line
}

/// The value an option or argument takes, as its help names it (`PATH`, `NAME|FILE`), escaped.
fn value_name(arg: &Arg) -> Option<String> {
    if !arg.get_action().takes_values() {
        return None;
    }
    let names = match arg.get_value_names() {
        Some(names) => names.iter().map(|n| n.to_string()).collect::<Vec<_>>(),
        None => vec![arg.get_id().as_str().to_uppercase()],
    };
    Some(roff_text(&names.join(" ")))
}

/// Whether the option's value may be left out (`--local-echo` alone means on).
fn optional_value(arg: &Arg) -> bool {
    arg.get_num_args().is_some_and(|n| n.min_values() == 0)
}

/// The EXAMPLES section, from [`EXAMPLES`].
fn examples(page: &mut Vec<u8>) -> io::Result<()> {
    writeln!(page, ".SH EXAMPLES")?;
    for example in EXAMPLES {
        writeln!(
            page,
            ".TP\n\\fB{}\\fR\n{}",
            roff_text(example.command),
            roff_text(example.what)
        )?;
    }
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

/// The exit codes (`exit::Exit`), which the clap definitions do not hold.
const EXIT_STATUS: &str = r#".SH "EXIT STATUS"
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
"#;

/// The ENVIRONMENT section: the options' variables, as the clap definitions name them, then the
/// variables tmclsh reads besides.
fn environment(page: &mut Vec<u8>, cmd: &Command) -> io::Result<()> {
    let mut names = Vec::new();
    option_variables(cmd, &mut names);
    let names: Vec<String> = names
        .iter()
        .map(|name| format!("\\fB{}\\fR", roff_text(name)))
        .collect();
    writeln!(page, ".SH ENVIRONMENT\n.TP\n{}", names.join(", "))?;
    page.extend_from_slice(OTHER_VARIABLES.as_bytes());
    Ok(())
}

/// The variables of `cmd`'s options and its subcommands', each once, in the order of the help.
fn option_variables(cmd: &Command, names: &mut Vec<String>) {
    for arg in cmd.get_arguments() {
        let Some(name) = arg.get_env() else { continue };
        let name = name.to_string_lossy().into_owned();
        if !names.contains(&name) {
            names.push(name);
        }
    }
    for sub in cmd.get_subcommands() {
        option_variables(sub, names);
    }
}

/// What the options' variables mean, and the variables that belong to no option.
const OTHER_VARIABLES: &str = r#"the value of the option of the same name, below the command line and above the configuration
files; an empty variable counts as unset
.TP
\fBNO_COLOR\fR
plain output in the interactive shell
.TP
\fBXDG_CONFIG_HOME\fR, \fBXDG_DATA_HOME\fR
where the user's configuration file and the shell's history are
"#;

/// The FILES section, the keys of the configuration files from their table (`config::KEYS`).
fn files(page: &mut Vec<u8>) -> io::Result<()> {
    let keys: Vec<&str> = super::config::KEYS.iter().map(|key| key.name).collect();
    let (last, rest) = keys.split_last().expect("configuration files have keys");
    let keys = roff_text(&format!("{} and {last}", rest.join(", ")));
    write!(
        page,
        r#".SH FILES
.TP
\fBtmclsh.toml\fR
the project's configuration file, in the working directory or the nearest directory above it;
used only when it is the user's (or root's) and nobody else may write it, otherwise ignored with a
note
.TP
\fB$XDG_CONFIG_HOME/tmclsh/config.toml\fR (\fB~/.config/tmclsh/config.toml\fR)
the user's configuration file; keys {keys}; \fBtmclsh config\fR shows each setting and where it came from
.TP
\fB$XDG_DATA_HOME/tmclsh/history\-tmcl\fR, \fBhistory\-smd4\fR
the interactive shell's history, one file per protocol
"#
    )
}
