//! The family fields of a profile file, each with a good row and bad ones refused on their line.

use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::profile::{ParamKind, Profile};

/// A valid profile over the built-in command table, using every family field.
const GOOD: &str = r#"[meta]
module = "TMCM-1234"
module_number = 1234
version_prefix = "1234"
version_format = "NNNNVabc"
bootloader_format = "NNNNBabc"
aliases = ["PD-1234"]
ascii_interface = "yes"
parameter_generation = "A"
axes = 2
[[axis_parameter]]
number = 255
name = "Unit mode"
ident = "unit_mode"
access = "RW"
range = [0, 1]
[[axis_parameter]]
number = 4
name = "Max speed"
ident = "max_speed"
access = "RW"
range = [0, 2047]
range_when = [{ axis_parameter = 255, equals = 1, range = [0, 100000], unit = "pps" }]
[commands]
base = "builtin"
absent = [29]
absent_reason = "not in its manual"
[[extra_command]]
number = 25
mnemonic = "EI"
name = "enable interrupt"
operands = ["type"]
standalone = true
[ascii]
allowed_commands = ["GAP", "SAP", "SIO"]
[[io_port]]
bank = 0
port = 0
name = "IN0"
kind = "digital input"
pin = 7
[[io_port]]
bank = 1
port = 0
name = "AIN0"
range = [0, 4095]
[[io_port]]
bank = 2
port = 0
name = "OUT0"
pin = "X3.4"
uncertain = true
[[io_port]]
signal = "fault output"
kind = "hardware only"
[simulation]
version_string = "1234V100"
digital_inputs = [0]
analog_inputs = [0]
outputs = [0]
adc_max = 4095
"#;

fn load(text: &str) -> Result<Profile, String> {
    Profile::from_toml(text, Some(&Profile::builtin().commands))
}

/// The 1-based line of `text` that is `start`, or else the first that starts with it.
fn line(text: &str, start: &str) -> usize {
    let lines: Vec<&str> = text.lines().collect();
    lines
        .iter()
        .position(|l| *l == start)
        .or_else(|| lines.iter().position(|l| l.starts_with(start)))
        .unwrap_or_else(|| panic!("no line starts with {start:?}"))
        + 1
}

/// `GOOD` with the first line starting with `start` replaced by `with`: refused, with `message`
/// on that line.
fn refused_on_its_line(start: &str, with: &str, message: &str) {
    let at = line(GOOD, start);
    let text: String = GOOD
        .lines()
        .enumerate()
        .map(|(i, l)| if i + 1 == at { with } else { l })
        .collect::<Vec<_>>()
        .join("\n");
    let error = load(&text).expect_err(with);
    let wanted = format!("line {at}: {message}");
    assert!(
        error.lines().any(|l| l.starts_with(&wanted)),
        "{with}: wanted {wanted:?} in\n{error}"
    );
}

#[test]
fn a_profile_with_every_family_field_loads_them() {
    let p = load(GOOD).unwrap_or_else(|e| panic!("{e}"));
    let id = &p.identity;
    assert_eq!(id.module_number, Some(1234));
    assert_eq!(id.version_format.as_deref(), Some("NNNNVabc"));
    assert_eq!(id.bootloader_format.as_deref(), Some("NNNNBabc"));
    assert_eq!(id.aliases, ["PD-1234"]);
    assert_eq!(id.ascii_interface(), AsciiInterface::Yes);
    assert_eq!(id.generation.as_deref(), Some("A"));
    // [commands] absent and [[extra_command]]
    assert!(p.commands.by_mnemonic("SAC").is_none());
    let (sac, reason) = p.commands.absent("sac").unwrap();
    assert_eq!((sac.number, reason), (29, "not in its manual"));
    assert_eq!(p.commands.by_number(25).unwrap().mnemonic, "EI");
    // [ascii] allowed_commands replaces the flags of the built-in table
    let ascii: Vec<&str> = p.commands.ascii_mnemonics();
    assert_eq!(ascii, ["SAP", "GAP", "SIO"]);
    // range_when of a parameter; the built-in table's own on ROR names AP255, defined here
    let speed = p.axis_param(4).unwrap();
    assert_eq!(speed.range_when.len(), 1);
    assert_eq!(speed.range_when[0].range, (0, 100000));
    assert_eq!(speed.range_when[0].when.kind, ParamKind::Axis);
    assert_eq!(
        speed.range_when[0].describe(),
        "0..100000 pps when axis parameter 255 = 1"
    );
    assert_eq!(p.commands.by_mnemonic("ROR").unwrap().range_when.len(), 1);
    // banks and type_ignored come with the built-in table
    assert_eq!(p.commands.by_mnemonic("STGP").unwrap().banks, Some(vec![2]));
    assert!(p.commands.by_number(135).unwrap().type_ignored);
    // the I/O map: addressed rows only, by bank and port
    let ports: Vec<(u8, u8, &str)> = p
        .io_ports
        .iter()
        .map(|io| (io.bank, io.port, io.name.as_str()))
        .collect();
    assert_eq!(ports, [(0, 0, "IN0"), (1, 0, "AIN0"), (2, 0, "OUT0")]);
    assert_eq!(p.io_port(1, 0).unwrap().range, Some((0, 4095)));
    // pins as numbers or as printed; uncertain rows are marked
    assert_eq!(p.io_port(0, 0).unwrap().pin.as_deref(), Some("7"));
    assert_eq!(p.io_port(2, 0).unwrap().pin.as_deref(), Some("X3.4"));
    assert!(p.io_port(2, 0).unwrap().uncertain && !p.io_port(0, 0).unwrap().uncertain);
    assert!(p.io_port(2, 0).unwrap().is_output() && !p.io_port(1, 0).unwrap().is_output());
}

#[test]
fn a_condition_the_profile_cannot_have_is_dropped_from_the_builtin_table() {
    // Without axis parameter 255 the TMCM-142's pps range of ROR means nothing.
    let text = GOOD
        .replace("number = 255\n", "number = 254\n")
        .replace("axis_parameter = 255", "axis_parameter = 254");
    let p = load(&text).unwrap_or_else(|e| panic!("{e}"));
    assert!(p.commands.by_mnemonic("ROR").unwrap().range_when.is_empty());
}

#[test]
fn identification_fields_are_checked_on_their_lines() {
    refused_on_its_line(
        "module_number",
        "module_number = 12",
        "module_number 12: TMCL module numbers have three or four digits",
    );
    refused_on_its_line(
        "version_prefix",
        "version_prefix = \"1235\"",
        "version_prefix \"1235\" is not the module number 1234",
    );
    refused_on_its_line(
        "version_format",
        "version_format = \"NNNVa.bc\"",
        "version_format \"NNNVa.bc\" must be NNNNVabc",
    );
    refused_on_its_line(
        "bootloader_format",
        "bootloader_format = \"NNNNVabc\"",
        "bootloader_format \"NNNNVabc\" must be the version_format with B for V",
    );
    refused_on_its_line(
        "version_string",
        "version_string = \"1234V1.0\"",
        "version_string \"1234V1.0\" does not have the module's format NNNNVabc",
    );
    refused_on_its_line(
        "version_string",
        "version_string = \"4321V100\"",
        "version_string \"4321V100\" does not have the module's format NNNNVabc starting with 1234",
    );
    refused_on_its_line(
        "aliases",
        "aliases = [\"TMCM-1234\"]",
        "alias TMCM-1234 is the module's own name",
    );
    refused_on_its_line(
        "aliases",
        "aliases = [\"PD 1234\"]",
        "alias \"PD 1234\" must be a product name without spaces",
    );
    refused_on_its_line(
        "aliases",
        "aliases = [\"PD-1234\", \"pd-1234\"]",
        "alias pd-1234 is given twice",
    );
    refused_on_its_line(
        "ascii_interface",
        "ascii_interface = \"maybe\"",
        "ascii_interface \"maybe\" must be yes, no or unconfirmed",
    );
    refused_on_its_line(
        "parameter_generation",
        "parameter_generation = \"C\"",
        "parameter_generation \"C\" must be one of TMCM-142, A, B",
    );
}

#[test]
fn identification_fields_need_the_fields_they_derive_from() {
    // Without a module number the prefix has nothing to be the digits of, and either format fits.
    let text = GOOD.replace("module_number = 1234\n", "");
    let error = load(&text).unwrap_err();
    let at = line(&text, "version_prefix");
    assert_eq!(
        error,
        format!("line {at}: version_prefix needs the module_number it is the digits of")
    );
    let text = text
        .replace("version_prefix = \"1234\"\n", "")
        .replace("\"NNNNVabc\"", "\"NNNVabc\"");
    let error = load(&text).unwrap_err();
    assert!(
        error.contains("version_format \"NNNVabc\" must be NNNVa.bc or NNNNVabc"),
        "{error}"
    );
    // A boot loader format varies the version format: without one it cannot be checked.
    let text = GOOD.replace("version_format = \"NNNNVabc\"\n", "");
    let error = load(&text).unwrap_err();
    let at = line(&text, "bootloader_format");
    assert_eq!(
        error,
        format!("line {at}: bootloader_format needs the version_format it varies")
    );
}

#[test]
fn the_command_set_is_checked_against_the_builtin_table() {
    refused_on_its_line(
        "absent",
        "absent = [29, 29]",
        "absent command 29 is given twice",
    );
    refused_on_its_line(
        "absent",
        "absent = [200]",
        "absent command 200 is not in the built-in command table",
    );
    refused_on_its_line(
        "base",
        "base = \"mine\"",
        "base \"mine\" must be \"builtin\"",
    );
    refused_on_its_line(
        "number = 25",
        "number = 5",
        "command 5 (SAP) is in the built-in table already",
    );
    refused_on_its_line(
        "mnemonic = \"EI\"",
        "mnemonic = \"GAP\"",
        "mnemonic GAP is command 6 of the built-in table already",
    );
    // An unknown operand kind is reported on its row, as for [[command]] rows.
    let text = GOOD.replace("operands = [\"type\"]", "operands = [\"typo\"]");
    let error = load(&text).unwrap_err();
    let at = line(&text, "[[extra_command]]");
    assert!(
        error.starts_with(&format!(
            "line {at}: command 25: unknown operand kind 'typo'"
        )),
        "{error}"
    );
    // An absent command may come back as an extra one under its number.
    let text = GOOD.replace(
        "number = 25\nmnemonic = \"EI\"",
        "number = 29\nmnemonic = \"SAC\"",
    );
    assert!(load(&text).is_ok());
}

#[test]
fn the_ascii_list_names_commands_the_module_has() {
    refused_on_its_line(
        "allowed_commands",
        "allowed_commands = [\"GAP\", \"SAC\"]",
        "ASCII command SAC is marked absent in [commands]",
    );
    refused_on_its_line(
        "allowed_commands",
        "allowed_commands = [\"GAP\", \"GAPP\"]",
        "ASCII command GAPP is not a command of this profile",
    );
    refused_on_its_line(
        "allowed_commands",
        "allowed_commands = [\"GAP\", \"gap\"]",
        "ASCII command gap is listed twice",
    );
    // A module without the interface has no list.
    let text = GOOD.replace("ascii_interface = \"yes\"", "ascii_interface = \"no\"");
    let error = load(&text).unwrap_err();
    let at = line(&text, "allowed_commands");
    assert!(
        error.starts_with(&format!("line {at}: a module without the ASCII interface")),
        "{error}"
    );
    let text = text.replace("allowed_commands = [\"GAP\", \"SAP\", \"SIO\"]\n", "");
    let p = load(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.identity.ascii_interface(), AsciiInterface::No);
    assert!(p.commands.iter().all(|c| !c.ascii_allowed));
}

#[test]
fn the_io_map_is_checked_and_the_simulator_follows_it() {
    let at = line(GOOD, "port = 0");
    let text: String = GOOD
        .lines()
        .enumerate()
        .filter(|(i, _)| i + 1 != at)
        .map(|(_, l)| l)
        .collect::<Vec<_>>()
        .join("\n");
    let error = load(&text).unwrap_err();
    assert!(
        error.contains(&format!(
            "line {}: an I/O port with a bank needs its port",
            at - 1
        )),
        "{error}"
    );
    refused_on_its_line(
        "name = \"OUT0\"",
        "name = \"\"",
        "I/O port 0 of bank 2 needs a name",
    );
    // Text that help and hints print may not carry control characters.
    refused_on_its_line(
        "kind = \"digital input\"",
        "kind = \"digital\\u001b[2J input\"",
        "the kind of I/O port 0 of bank 0 has a control character",
    );
    refused_on_its_line(
        "pin = \"X3.4\"",
        "pin = \"X3\\u0007\"",
        "the pin of I/O port 0 of bank 2 has a control character",
    );
    refused_on_its_line(
        "range = [0, 4095]",
        "range = [0, 65535]",
        "analog port range up to 65535 is above the ADC's adc_max 4095",
    );
    refused_on_its_line(
        "outputs = [0]",
        "outputs = [0, 1]",
        "outputs [0, 1] are not the ports of bank 2 in [[io_port]] [0]",
    );
    let twice = GOOD.replace("port = 0\nname = \"OUT0\"", "port = 0\nname = \"IN0\"");
    let twice = twice.replacen("bank = 2\nport = 0", "bank = 0\nport = 0", 1);
    let error = load(&twice).unwrap_err();
    assert!(
        error.contains("I/O port 0 of bank 0 is defined twice (first on line"),
        "{error}"
    );
}

#[test]
fn range_when_names_a_parameter_of_the_profile() {
    refused_on_its_line(
        "range_when",
        "range_when = [{ axis_parameter = 254, equals = 1, range = [0, 100000] }]",
        "range_when depends on axis parameter 254, which this profile does not define",
    );
    refused_on_its_line(
        "range_when",
        "range_when = [{ axis_parameter = 255, equals = 1, range = [100000, 0] }]",
        "range_when range [100000, 0] is reversed",
    );
    refused_on_its_line(
        "range_when",
        "range_when = [{ equals = 1, range = [0, 1] }]",
        "range_when names one parameter",
    );
}

/// A profile with its own command rows, for the rules on commands.
fn own(extra: &str) -> String {
    format!(
        "[meta]\nmodule = \"X\"\n\
         [[axis_parameter]]\nnumber = 255\nname = \"u\"\nident = \"u\"\n\
         [[command]]\nnumber = 11\nmnemonic = \"STGP\"\nname = \"store\"\n\
         operands = [\"global_param\", \"bank\"]\n{extra}"
    )
}

#[test]
fn rules_on_commands_fit_their_operands() {
    let ok = own("banks = [2]\n");
    let p = Profile::from_toml(&ok, None).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.commands.by_number(11).unwrap().banks, Some(vec![2]));
    for (extra, message) in [
        (
            "banks = []\n",
            "line 12: command 11: banks must name at least one bank",
        ),
        (
            "banks = [2, 2]\n",
            "line 12: command 11: a bank is given twice",
        ),
        (
            "range_when = [{ axis_parameter = 255, equals = 1, range = [0, 1] }]\n",
            "line 12: command 11: range_when applies to a command with a value operand",
        ),
        (
            "type_ignored = true\ntypes = [{ value = 0, name = \"A\" }]\n",
            "line 12: command 11: type_ignored contradicts the keywords",
        ),
    ] {
        let error = Profile::from_toml(&own(extra), None).unwrap_err();
        assert!(error.starts_with(message), "{extra}: {error}");
    }
    let text = own("").replace("\"global_param\", \"bank\"", "\"global_param\"") + "banks = [2]\n";
    let error = Profile::from_toml(&text, None).unwrap_err();
    assert!(
        error.starts_with("line 12: command 11: banks apply to a command with a bank operand"),
        "{error}"
    );
}

#[test]
fn a_file_with_its_own_commands_changes_no_builtin_table() {
    let text = own("ascii_allowed = true\n[commands]\nabsent = [29]\n");
    let error = load(&text).unwrap_err();
    assert!(
        error.starts_with("line 13: [commands] changes the built-in"),
        "{error}"
    );
    let text = own("[[extra_command]]\nnumber = 25\nmnemonic = \"EI\"\nname = \"e\"\n");
    let error = load(&text).unwrap_err();
    assert!(
        error.starts_with("line 12: [[extra_command]] adds to"),
        "{error}"
    );
    // Its ASCII list and its flags must say the same.
    let text = own("ascii_allowed = true\n[ascii]\nallowed_commands = [\"STGP\"]\n");
    assert!(load(&text).is_ok());
    let text = own("[ascii]\nallowed_commands = [\"STGP\"]\n");
    let error = load(&text).unwrap_err();
    assert!(
        error.starts_with(
            "line 13: allowed_commands disagrees with the ascii_allowed flags of the [[command]] \
             rows (listed without ascii_allowed: STGP)"
        ),
        "{error}"
    );
    let text = own("ascii_allowed = true\n[ascii]\nallowed_commands = []\n");
    let error = load(&text).unwrap_err();
    assert!(
        error.starts_with(
            "line 14: allowed_commands disagrees with the ascii_allowed flags of the [[command]] \
             rows (ascii_allowed rows not listed: STGP)"
        ),
        "{error}"
    );
}

#[test]
fn a_generic_profile_has_no_parameters() {
    let text = "[meta]\nmodule = \"any\"\ngeneric = true\n\
                [[axis_parameter]]\nnumber = 1\nname = \"p\"\nident = \"p\"\n";
    let error = load(text).unwrap_err();
    assert!(
        error.starts_with("line 4: a generic profile knows parameters by number only"),
        "{error}"
    );
}

#[test]
fn an_io_port_is_addressed_by_bank_and_port_together() {
    let at = line(GOOD, "bank = 2");
    let text = GOOD.replace("bank = 2\n", "");
    let error = load(&text).unwrap_err();
    assert!(
        error.contains(&format!(
            "line {at}: an I/O port with a port needs its bank"
        )),
        "{error}"
    );
    refused_on_its_line(
        "kind = \"digital input\"",
        "unit = \"V\\u0007\"\nkind = \"digital input\"",
        "the unit of I/O port 0 of bank 0 has a control character",
    );
}

#[test]
fn a_command_range_gives_a_builtin_command_the_modules_own_range() {
    let row = "[[command_range]]\nnumber = 1\nmnemonic = \"ROR\"\nvalue_range = [-2047, 2047]\n";
    let p = load(&format!("{GOOD}{row}")).unwrap_or_else(|e| panic!("{e}"));
    let ror = p.commands.by_mnemonic("ROR").unwrap();
    assert_eq!(ror.value_range, Some((-2047, 2047)));
    // The TMCM-142's unit-mode range is the TMCM-142's: not this module's.
    assert!(ror.range_when.is_empty());
    assert_eq!(
        p.commands.by_mnemonic("ROL").unwrap().value_range,
        Some((0, 2147483647))
    );
    for (bad, message) in [
        (
            "mnemonic = \"ROR\"",
            "mnemonic = \"ROL\"",
            "command 1 is ROR, not ROL",
        ),
        (
            "number = 1",
            "number = 29",
            "command 29 is not in this module's table",
        ),
        (
            "value_range = [-2047, 2047]",
            "value_range = [2047, 0]",
            "value_range [2047, 0] runs backwards",
        ),
    ]
    .map(|(from, to, message)| (row.replace(from, to), message))
    {
        let error = load(&format!("{GOOD}{bad}")).expect_err(&bad);
        assert!(error.contains(message), "{bad}: {error}");
    }
}

#[test]
fn an_interrupt_has_a_known_kind_and_a_bank_3_parameter_of_the_file() {
    let config = "[[global_parameter]]\nbank = 3\nnumber = 0\nname = \"Timer 0 period\"\nident = \"timer_0\"\naccess = \"RW\"\n";
    let row = "[[interrupt]]\nnumber = 0\nname = \"Timer 0\"\nkind = \"timer\"\nconfig = 0\n";
    let p = load(&format!("{GOOD}{config}{row}")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.interrupts.len(), 1);
    assert_eq!(p.interrupts[0].config, Some(0));
    for (bad, message) in [
        (
            row.replace("\"timer\"", "\"alarm\""),
            "interrupt kind 'alarm' is none of",
        ),
        (
            row.replace("config = 0", "config = 9"),
            "no bank-3 global parameter 9",
        ),
        (
            row.replace("number = 0", "number = 255"),
            "is given twice or is 255",
        ),
    ] {
        let error = load(&format!("{GOOD}{config}{bad}")).expect_err(&bad);
        assert!(error.contains(message), "{bad}: {error}");
    }
}
