//! USB serial adapters known to run slcan firmware, from `data/can-adapters.toml`: `tmclsh
//! ports` marks them as CAN adapters.

use serde::Deserialize;

/// The table, built in.
const TABLE: &str = include_str!("../../../data/can-adapters.toml");

#[derive(Debug, Deserialize)]
struct Table {
    adapter: Vec<Adapter>,
}

/// One known adapter.
#[derive(Debug, Deserialize)]
struct Adapter {
    vid: u16,
    pid: u16,
    name: String,
    /// Where the id comes from: read only by people, required of every row.
    #[serde(rename = "source")]
    _source: String,
}

/// The name of the slcan adapter with these ids, if it is a known one.
pub(super) fn slcan_adapter(vid: u16, pid: u16) -> Option<String> {
    let table: Table = toml::from_str(TABLE).expect("data/can-adapters.toml is checked by a test");
    table
        .adapter
        .into_iter()
        .find(|a| a.vid == vid && a.pid == pid)
        .map(|a| a.name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_reads_and_names_known_adapters() {
        assert_eq!(
            slcan_adapter(0x16d0, 0x117e).as_deref(),
            Some("CANable 2.0 (slcan firmware)")
        );
        assert_eq!(slcan_adapter(0x0403, 0x6001), None);
    }
}
