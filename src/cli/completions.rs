//! `tmclsh completions SHELL`: completion scripts generated from the clap definition, with what
//! clap_complete's generators cannot say added for bash, zsh and fish: after `run` only `*.rhai`
//! files, after `download` `*.tmc` and `*.bin`, after `asm` `*.tmc`, after `disasm` `*.bin`, and
//! serial devices after `--port`. (clap's value hints reach no further: bash's generator offers
//! every file for any path, zsh's `_files` and fish's `-F` take no pattern; the elvish and
//! PowerShell generators complete options and subcommands only, and so do their scripts here.)

use std::io::{self, Write};

use clap::Command;
use clap_complete::Shell;

/// Arguments of `completions`.
#[derive(Debug, clap::Args)]
pub(super) struct CompletionsArgs {
    /// The shell to generate for.
    pub shell: Shell,
    /// Write the script where the shell loads it from (bash: bash-completion's directory under
    /// $XDG_DATA_HOME; zsh: $XDG_DATA_HOME/zsh/site-functions; fish: $XDG_CONFIG_HOME/fish)
    /// instead of printing it, and say where.
    #[arg(long)]
    pub install: bool,
}

pub(super) fn run(args: &CompletionsArgs, out: &mut dyn Write) -> io::Result<()> {
    out.write_all(&generate(args.shell))
}

/// The files a subcommand's file argument takes: (subcommand, argument id, extensions).
const FILES: &[(&str, &str, &[&str])] = &[
    ("run", "script", &["rhai"]),
    ("download", "file", &["tmc", "bin"]),
    ("asm", "file", &["tmc"]),
    ("disasm", "file", &["bin"]),
];

/// Where serial devices are found, as shell globs.
const SERIAL_GLOBS: &[&str] = &[
    "/dev/ttyUSB*",
    "/dev/ttyACM*",
    "/dev/ttyAMA*",
    "/dev/serial/by-id/*",
    "/dev/cu.*",
];

/// The completion script for `shell`.
pub(super) fn generate(shell: Shell) -> Vec<u8> {
    let mut cmd = super::command();
    let mut buf = Vec::new();
    clap_complete::generate(shell, &mut cmd, "tmclsh", &mut buf);
    let script = String::from_utf8(buf).expect("clap_complete writes UTF-8");
    let script = match shell {
        Shell::Bash => bash(script, &cmd),
        Shell::Zsh => zsh(script),
        Shell::Fish => fish(script),
        _ => script,
    };
    script.into_bytes()
}

/// Bash: a function in front of clap's that completes `--port` and the file arguments, handing
/// everything else to clap's.
fn bash(script: String, cmd: &Command) -> String {
    let registration = script
        .find("if [[ \"${BASH_VERSINFO[0]}\" -eq 4")
        .expect("clap_complete's bash script ends by registering _tmclsh");
    let (body, tail) = script.split_at(registration);
    let mut cases = String::new();
    for (sub, _, extensions) in FILES {
        let globs: Vec<String> = extensions.iter().map(|e| format!("'*.{e}'")).collect();
        cases.push_str(&format!(
            "            {sub}) extensions=({}) ;;\n",
            globs.join(" ")
        ));
    }
    let with_values = options_with_values(cmd).join("|");
    let globs = SERIAL_GLOBS.join(" ");
    let added = format!(
        r#"# Added to clap's script: serial devices after --port, and only the files a subcommand
# takes (run: *.rhai, download: *.tmc and *.bin, asm: *.tmc, disasm: *.bin).
_tmclsh_with_files() {{
    local cur="${{COMP_WORDS[COMP_CWORD]}}" prev="${{COMP_WORDS[COMP_CWORD-1]}}"
    local word port extension
    local -a extensions=()
    if [[ "$prev" == "--port" ]]; then
        COMPREPLY=()
        for port in {globs}; do
            [[ -e "$port" && "$port" == "$cur"* ]] && COMPREPLY+=("$port")
        done
        return 0
    fi
    for word in "${{COMP_WORDS[@]:1:COMP_CWORD-1}}"; do
        case "$word" in
            --) extensions=(); break ;;
{cases}        esac
    done
    case "$prev" in
        {with_values}) extensions=() ;;
    esac
    if [[ ${{#extensions[@]}} -gt 0 && "$cur" != -* ]]; then
        compopt -o filenames 2>/dev/null
        COMPREPLY=( $(compgen -d -- "$cur") )
        for extension in "${{extensions[@]}}"; do
            COMPREPLY+=( $(compgen -f -X "!$extension" -- "$cur") )
        done
        return 0
    fi
    _tmclsh "$@"
}}

"#
    );
    let tail = tail.replace("complete -F _tmclsh ", "complete -F _tmclsh_with_files ");
    format!("{body}{added}{tail}")
}

/// Zsh: `_files -g` patterns for the file arguments and a device list for `--port`.
fn zsh(mut script: String) -> String {
    for (sub, id, extensions) in FILES {
        let start = script
            .find(&format!("\n({sub})\n"))
            .unwrap_or_else(|| panic!("zsh script has a case for {sub}"));
        let end = start
            + script[start..]
                .find("\n;;")
                .expect("a zsh case ends with ;;");
        let block = &script[start..end];
        let spec_start = block
            .find(&format!("\n':{id} -- "))
            .unwrap_or_else(|| panic!("zsh case {sub} completes {id}"));
        let spec_end = spec_start
            + block[spec_start..]
                .find(":_files'")
                .expect("a file argument");
        let at = start + spec_end;
        let pattern = match extensions {
            [one] => format!("*.{one}"),
            many => format!("*.({})", many.join("|")),
        };
        script.replace_range(
            at..at + ":_files'".len(),
            &format!(":_files -g \"{pattern}\"'"),
        );
    }
    let script = script.replace(":PATH:_default'", ":PATH:_tmclsh_serial_ports'");
    let globs: Vec<String> = SERIAL_GLOBS.iter().map(|g| format!("{g}(N)")).collect();
    let function = format!(
        "# Added to clap's script: the serial devices of this machine, for --port.\n\
         (( $+functions[_tmclsh_serial_ports] )) ||\n\
         _tmclsh_serial_ports() {{\n    local -a ports\n    ports=({})\n    compadd -a ports\n}}\n\n",
        globs.join(" ")
    );
    let registration = script
        .rfind("if [ \"$funcstack[1]\" = \"_tmclsh\" ]; then")
        .expect("clap_complete's zsh script ends by registering _tmclsh");
    let (body, tail) = script.split_at(registration);
    format!("{body}{function}{tail}")
}

/// Fish: only the files a subcommand takes, and the serial devices after `--port`.
fn fish(mut script: String) -> String {
    script.push_str("# Added to clap's script: serial devices after --port, and only the files a subcommand\n# takes.\n");
    let globs = SERIAL_GLOBS.join(" ");
    script.push_str(&format!(
        "function __fish_tmclsh_serial_ports\n    for port in {globs}\n        test -e $port; and echo $port\n    end\nend\n"
    ));
    script.push_str(
        "complete -c tmclsh -l port -x -a \"(__fish_tmclsh_serial_ports)\" -d 'serial port'\n",
    );
    for (sub, _, extensions) in FILES {
        let suffixes: Vec<String> = extensions
            .iter()
            .map(|e| format!("__fish_complete_suffix .{e}"))
            .collect();
        script.push_str(&format!(
            "complete -c tmclsh -n \"__fish_tmclsh_using_subcommand {sub}\" -f -a \"({})\"\n",
            suffixes.join("; ")
        ));
    }
    script
}

/// Every option of `cmd` and its subcommands that takes a value, as bash case patterns.
fn options_with_values(cmd: &Command) -> Vec<String> {
    let mut found = Vec::new();
    collect_options(cmd, &mut found);
    found.sort();
    found.dedup();
    found
}

fn collect_options(cmd: &Command, found: &mut Vec<String>) {
    for arg in cmd.get_arguments() {
        if arg.is_positional() || !arg.get_action().takes_values() {
            continue;
        }
        if let Some(long) = arg.get_long() {
            found.push(format!("--{long}"));
        }
        if let Some(short) = arg.get_short() {
            found.push(format!("-{short}"));
        }
    }
    for sub in cmd.get_subcommands() {
        collect_options(sub, found);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_file_argument_of_the_table_exists() {
        let cmd = super::super::command();
        for (sub, id, _) in FILES {
            let sub = cmd.find_subcommand(sub).expect("the subcommand exists");
            assert!(
                sub.get_arguments()
                    .any(|a| a.get_id() == id && a.is_positional()),
                "{id}"
            );
        }
    }

    #[test]
    fn the_additions_reach_every_shell_that_can_take_them() {
        let zsh = String::from_utf8(generate(Shell::Zsh)).unwrap();
        assert!(zsh.contains(":_files -g \"*.rhai\"'"), "{zsh}");
        assert!(zsh.contains(":_files -g \"*.(tmc|bin)\"'"));
        assert!(zsh.contains(":PATH:_tmclsh_serial_ports'"));
        assert!(!zsh.contains(":PATH:_default'"));
        let fish = String::from_utf8(generate(Shell::Fish)).unwrap();
        assert!(fish.contains("__fish_complete_suffix .rhai"));
        let bash = String::from_utf8(generate(Shell::Bash)).unwrap();
        assert!(bash.contains("complete -F _tmclsh_with_files -o nosort"));
        assert!(bash.contains("run) extensions=('*.rhai') ;;"));
    }
}
