#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| tmclsh::fuzz_entry::slcan(data));
