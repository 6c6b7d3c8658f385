use crate::dialect::tmcl::profile::{BUILTIN_TOML, Profile};

/// A small valid profile; `row` is spliced in as a third axis parameter starting on line 14.
fn with_row(row: &str) -> String {
    format!(
        "[meta]\n\
         module = \"TMCM-9\"\n\
         axes = 2\n\
         [[axis_parameter]]\n\
         number = 4\n\
         name = \"Max speed\"\n\
         ident = \"max_speed\"\n\
         access = \"RW\"\n\
         range = [0, 100]\n\
         [[axis_parameter]]\n\
         number = 5\n\
         name = \"Max acceleration\"\n\
         ident = \"max_acceleration\"\n\
         [[axis_parameter]]\n\
         {row}"
    )
}

fn refused(text: &str) -> String {
    let builtin = Profile::builtin();
    Profile::from_toml(text, Some(&builtin.commands)).unwrap_err()
}

#[test]
fn the_builtin_profile_passes_every_check() {
    let file = super::ProfileFile::parse(BUILTIN_TOML).unwrap();
    assert_eq!(super::check(&file, None), Vec::new());
}

#[test]
fn each_bad_row_is_refused_on_its_own_line() {
    let cases = [
        (
            "number = 6\nname = \"a\"\nident = \"a\"\nrange = [10, 1]\n",
            18,
            "reversed",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"a\"\naccess = \"RX\"\n",
            18,
            "unknown letter 'X'",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"\"\n",
            17,
            "must not be empty",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"max pos\"\n",
            17,
            "no spaces",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"max_speed\"\n",
            17,
            "'max_speed' is defined twice (first on line 7)",
        ),
        (
            "number = 4\nname = \"a\"\nident = \"a\"\n",
            15,
            "axis parameter 4 is defined twice (first on line 5)",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"a\"\nrange = [0, 9]\ndefault = 10\n",
            19,
            "default 10 lies outside the range 0..9",
        ),
        (
            "number = 300\nname = \"a\"\nident = \"a\"\n",
            15,
            "outside 0..255",
        ),
        (
            "number = 6\nnumber_last = 2\nname = \"a\"\nident = \"a\"\n",
            16,
            "number_last 2",
        ),
        (
            "number = 6\nname = \"a\"\nident = \"a\"\nrange = [0, 4294967295]\n",
            18,
            "beyond 32-bit",
        ),
    ];
    for (row, line, message) in cases {
        let error = refused(&with_row(row));
        assert!(
            error.starts_with(&format!("line {line}: ")) && error.contains(message),
            "{row}: {error}"
        );
    }
}

#[test]
fn zero_axes_and_schema_errors_name_their_line() {
    let error = refused("[meta]\nmodule = \"X\"\naxes = 0\n");
    assert!(
        error.starts_with("line 3: axes must be at least 1"),
        "{error}"
    );
    let error = refused("[meta]\nmodule = \"X\"\naxes = 300\n");
    assert!(error.starts_with("line 3: invalid value"), "{error}");
    let error = refused("[meta]\nmodule = \"X\"\n[[axis_parameter]]\nnumber = 1\n");
    assert!(error.starts_with("line 3: missing field"), "{error}");
    let error = refused("[meta]\nmodule = \"X\"\nbroken = [\n");
    assert!(
        error.starts_with("line 3: ") || error.starts_with("line 4: "),
        "{error}"
    );
}

#[test]
fn every_problem_is_listed_in_file_order() {
    let text = "[meta]\nmodule = \"\"\naxes = 0\n[[axis_parameter]]\nnumber = 1\nname = \"a\"\n\
                ident = \"a b\"\naccess = \"Q\"\n";
    let error = refused(text);
    let lines: Vec<&str> = error
        .lines()
        .map(|l| l.split(':').next().unwrap())
        .collect();
    assert_eq!(lines, ["line 2", "line 3", "line 7", "line 8"], "{error}");
}

#[test]
fn spanning_rows_collide_with_the_identifiers_they_make() {
    let text = "[meta]\nmodule = \"X\"\n\
                [[global_parameter]]\nbank = 2\nnumber = 0\nnumber_last = 3\nname = \"v\"\nident = \"var\"\n\
                [[global_parameter]]\nbank = 2\nnumber = 9\nname = \"v2\"\nident = \"VAR_2\"\n";
    let error = refused(text);
    assert!(
        error.starts_with(
            "line 13: global parameter identifier 'var_2' is defined twice (first on line 8)"
        ),
        "{error}"
    );
    let text = "[meta]\nmodule = \"X\"\n\
                [[global_parameter]]\nbank = 0\nnumber = 5\nname = \"a\"\nident = \"a\"\n\
                [[global_parameter]]\nbank = 2\nnumber = 5\nname = \"b\"\nident = \"b\"\n";
    assert!(Profile::from_toml(text, Some(&Profile::builtin().commands)).is_ok());
}

#[test]
fn command_rows_are_checked_too() {
    let row = |extra: &str| {
        format!(
            "[meta]\nmodule = \"X\"\n\
             [[command]]\nnumber = 1\nmnemonic = \"ROR\"\nname = \"r\"\n\
             [[command]]\nnumber = 2\nmnemonic = \"ROL\"\nname = \"l\"\n{extra}"
        )
    };
    let error = Profile::from_toml(&row("value_range = [5, 0]\n"), None).unwrap_err();
    assert!(
        error.starts_with("line 11: value_range [5, 0] is reversed"),
        "{error}"
    );
    let error =
        Profile::from_toml(&row("operands = [\"motor\", \"nonsense\"]\n"), None).unwrap_err();
    assert!(
        error.starts_with("line 7: command 2: unknown operand kind"),
        "{error}"
    );
    let text = row("").replace("\"ROL\"", "\"ror\"");
    let error = Profile::from_toml(&text, None).unwrap_err();
    assert!(
        error.contains("line 9: mnemonic ROR is defined twice (first on line 5)"),
        "{error}"
    );
    let text = row(
        "[[command.types]]\nvalue = 0\nname = \"A\"\n[[command.types]]\nvalue = 0\nname = \"B C\"\n",
    );
    let error = Profile::from_toml(&text, None).unwrap_err();
    assert!(error.contains("line 16: keyword \"B C\""), "{error}");
}

#[test]
fn simulation_constants_must_be_usable() {
    let error = refused(
        "[meta]\nmodule = \"X\"\n[simulation]\ntick_ms = 0\nvelocity_pps_per_unit = -1.0\n",
    );
    assert!(
        error.contains("line 4: tick_ms must be at least 1"),
        "{error}"
    );
    assert!(
        error.contains("line 5: velocity_pps_per_unit must be a positive number"),
        "{error}"
    );
}

#[test]
fn decoding_tables_must_decode_each_value_one_way() {
    let row =
        |tables: &str| format!("number = 6\nname = \"a\"\nident = \"a\"\nrange = [0, 3]\n{tables}");
    let cases = [
        (
            "values = [\n  [0, \"off\"],\n  [4, \"beyond\"],\n]\n",
            21,
            "values: code 4 lies outside the range 0..3",
        ),
        (
            "values = [\n  [1, \"on\"],\n  [1, \"again\"],\n]\n",
            21,
            "values: code 1 is given twice (first on line 20)",
        ),
        (
            "values = [[2, \" \"]]\n",
            19,
            "values: code 2 has no meaning",
        ),
        (
            "bits = [{ bit = 32, name = \"x\" }]\n",
            19,
            "bit 32 is beyond bit 31",
        ),
        (
            "bits = [\n  { bit = 3, name = \"x\" },\n  { bit = 3, meaning = \"y\" },\n]\n",
            21,
            "bits: bit 3 is given twice (first on line 20)",
        ),
        (
            "bits = [{ bit = 1 }]\n",
            19,
            "bit 1 has neither a name nor a meaning",
        ),
        (
            "fields = [{ name = \"echo\", bits = [5, 4] }]\n",
            19,
            "'echo' has bits [5, 4]",
        ),
        (
            "fields = [{ name = \"echo\", bits = [4, 5], values = [[4, \"x\"]] }]\n",
            19,
            "fields: 'echo': code 4 lies outside the range 0..3",
        ),
        (
            "fields = [\n  { name = \"a\", bits = [0, 2] },\n  { name = \"b\", bits = [2, 3] },\n]\n",
            21,
            "'b' and 'a' both hold bit 2",
        ),
        (
            "bits = [{ bit = 4, name = \"x\" }]\nfields = [{ name = \"f\", bits = [4, 5] }]\n",
            20,
            "bit 4 is in 'f' and in `bits`",
        ),
    ];
    for (tables, line, message) in cases {
        let error = refused(&with_row(&row(tables)));
        assert!(
            error.starts_with(&format!("line {line}: ")) && error.contains(message),
            "{tables}: {error}"
        );
    }
    // Without a range any 32-bit code may be named; a negative one too.
    let fine = "number = 6\nname = \"a\"\nident = \"a\"\nvalues = [[-1, \"permanent\"], [2048, \"off\"]]\n";
    let builtin = Profile::builtin();
    Profile::from_toml(&with_row(fine), Some(&builtin.commands)).unwrap();
}

#[test]
fn a_parameter_has_a_name_and_a_default_it_can_take() {
    let error = refused(&with_row("number = 6\nname = \" \"\nident = \"a\"\n"));
    assert!(
        error.starts_with("line 16: name must not be empty"),
        "{error}"
    );
    // A spanning row names its numbers through its identifier.
    let text = with_row("number = 6\nnumber_last = 7\nname = \"\"\nident = \"a\"\n");
    assert!(Profile::from_toml(&text, Some(&Profile::builtin().commands)).is_ok());
    let error = refused(&with_row(
        "number = 6\nname = \"a\"\nident = \"a\"\ndefault = 4294967296\n",
    ));
    assert!(
        error.starts_with("line 18: default 4294967296 is not a 32-bit value"),
        "{error}"
    );
    // A placeholder row defines nothing, not even a number that could collide.
    let text = with_row("number = -1\nname = \"\"\nident = \"\"\n");
    assert!(Profile::from_toml(&text, Some(&Profile::builtin().commands)).is_ok());
}

#[test]
fn command_numbers_param_use_and_keywords_are_checked() {
    let row = |extra: &str| {
        format!(
            "[meta]\nmodule = \"X\"\n\
             [[command]]\nnumber = 1\nmnemonic = \"ROR\"\nname = \"r\"\n\
             [[command]]\nnumber = 2\nmnemonic = \"ROL\"\nname = \"l\"\n{extra}"
        )
    };
    let error = Profile::from_toml(&row("").replace("number = 2", "number = 1"), None).unwrap_err();
    assert!(
        error.contains("line 8: command 1 is defined twice (first on line 4)"),
        "{error}"
    );
    let error = Profile::from_toml(&row("").replace("\"ROL\"", "\"RO L\""), None).unwrap_err();
    assert!(
        error.starts_with(
            "line 9: mnemonic \"RO L\" must be letters and digits (empty for control functions)"
        ),
        "{error}"
    );
    let error = Profile::from_toml(&row("param_use = \"erase\"\n"), None).unwrap_err();
    assert!(
        error.starts_with("line 11: param_use \"erase\" is not read, write or store"),
        "{error}"
    );
    let keywords = |second: &str| {
        row(&format!(
            "[[command.types]]\nvalue = 0\nname = \"A\"\n[[command.types]]\n{second}"
        ))
    };
    let error = Profile::from_toml(&keywords("value = 0\nname = \"B\"\n"), None).unwrap_err();
    assert!(
        error.contains("line 15: command 2: type 0 has two keywords (first on line 12)"),
        "{error}"
    );
    let error = Profile::from_toml(&keywords("value = 1\nname = \"a\"\n"), None).unwrap_err();
    assert!(
        error.contains("line 16: command 2: keyword A is defined twice (first on line 13)"),
        "{error}"
    );
    let error = Profile::from_toml(&keywords("value = 1\nname = \"\"\n"), None).unwrap_err();
    assert!(
        error.contains("line 16: keyword \"\" of command 2 must be letters, digits and _"),
        "{error}"
    );
}
