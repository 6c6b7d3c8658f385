//! The checks of a parameter's decoding tables (`values`, `bits`, `fields`): a table that names a
//! code twice, a code the parameter cannot hold or a bit beyond 32 would decode a reading wrongly
//! or never, and nobody would notice until a value on a real module read as something it is not.

use std::collections::HashMap;

use super::{Problem, Step};
use crate::dialect::tmcl::profile::decode::{BitRow, FieldRow};
use crate::dialect::tmcl::profile::load::ParamRow;

/// The highest bit a 32-bit value has.
const TOP_BIT: u8 = 31;

/// Every problem of the decoding tables of row `i` of `table`.
pub(super) fn check(table: &'static str, i: usize, row: &ParamRow, problems: &mut Vec<Problem>) {
    let at = |key: &'static str| vec![Step::Key(table), Step::Row(i), Step::Key(key)];
    let range = row.range.filter(|[lo, hi]| lo <= hi);
    check_codes(
        &row.decoding.values,
        range,
        at("values"),
        "values",
        problems,
    );
    check_bits(&row.decoding.bits, at("bits"), problems);
    check_fields(
        &row.decoding.fields,
        &row.decoding.bits,
        at("fields"),
        problems,
    );
}

/// `[[code, "meaning"], …]`: each code once, inside `range`, with a meaning.
fn check_codes(
    codes: &[(i64, String)],
    range: Option<[i64; 2]>,
    at: Vec<Step>,
    what: &str,
    problems: &mut Vec<Problem>,
) {
    let mut seen: HashMap<i64, Vec<Step>> = HashMap::new();
    for (j, (code, meaning)) in codes.iter().enumerate() {
        let here = [at.clone(), vec![Step::Row(j)]].concat();
        if meaning.trim().is_empty() {
            problems.push(Problem::at(
                here.clone(),
                format!("{what}: code {code} has no meaning"),
            ));
        }
        if let Some([lo, hi]) = range {
            if !(lo..=hi).contains(code) {
                problems.push(Problem::at(
                    here.clone(),
                    format!("{what}: code {code} lies outside the range {lo}..{hi}"),
                ));
            }
        }
        match seen.get(code) {
            Some(first) => problems.push(
                Problem::at(here, format!("{what}: code {code} is given twice"))
                    .also(first.clone()),
            ),
            None => {
                seen.insert(*code, here);
            }
        }
    }
}

/// Single bits: each once, 0..31, with a name or a meaning.
fn check_bits(bits: &[BitRow], at: Vec<Step>, problems: &mut Vec<Problem>) {
    let mut seen: HashMap<u8, Vec<Step>> = HashMap::new();
    for (j, bit) in bits.iter().enumerate() {
        let here = [at.clone(), vec![Step::Row(j)]].concat();
        if bit.bit > TOP_BIT {
            problems.push(Problem::at(
                here.clone(),
                format!(
                    "bits: bit {} is beyond bit {TOP_BIT} of a 32-bit value",
                    bit.bit
                ),
            ));
        }
        let named = bit.name.as_deref().is_some_and(|n| !n.trim().is_empty());
        if !named && bit.meaning.trim().is_empty() {
            problems.push(Problem::at(
                here.clone(),
                format!("bits: bit {} has neither a name nor a meaning", bit.bit),
            ));
        }
        match seen.get(&bit.bit) {
            Some(first) => problems.push(
                Problem::at(here, format!("bits: bit {} is given twice", bit.bit))
                    .also(first.clone()),
            ),
            None => {
                seen.insert(bit.bit, here);
            }
        }
    }
}

/// Fields of bits: ordered bits within 0..31, apart from each other and from the single bits,
/// their codes each once and small enough for their width.
fn check_fields(fields: &[FieldRow], bits: &[BitRow], at: Vec<Step>, problems: &mut Vec<Problem>) {
    let mut owner: HashMap<u8, &str> = HashMap::new();
    for (j, field) in fields.iter().enumerate() {
        let here = [at.clone(), vec![Step::Row(j)]].concat();
        let [low, high] = field.bits;
        if low > high || high > TOP_BIT {
            problems.push(Problem::at(
                here,
                format!(
                    "fields: '{}' has bits [{low}, {high}]; give [low, high] within 0..{TOP_BIT}",
                    field.name
                ),
            ));
            continue;
        }
        for bit in low..=high {
            if let Some(other) = owner.insert(bit, &field.name) {
                problems.push(Problem::at(
                    here.clone(),
                    format!("fields: '{}' and '{other}' both hold bit {bit}", field.name),
                ));
            }
            if bits.iter().any(|b| b.bit == bit) {
                problems.push(Problem::at(
                    here.clone(),
                    format!(
                        "fields: bit {bit} is in '{}' and in `bits`; a bit is one or the other",
                        field.name
                    ),
                ));
            }
        }
        let width = u32::from(high - low) + 1;
        let largest = (1i64 << width) - 1;
        check_codes(
            &field.values,
            Some([0, largest]),
            [here, vec![Step::Key("values")]].concat(),
            &format!("fields: '{}'", field.name),
            problems,
        );
    }
}
