//! The committed fuzz corpus (`fuzz/corpus/NAME/`, minimised with `cargo fuzz cmin`) replayed
//! through the same entry points the fuzz targets call (`tmclsh::fuzz_entry`), on stable, so a
//! parser change that crashes on an input the fuzzer once reached fails here. TESTING.md says
//! how to run the fuzzer and grow the corpus.

use std::path::{Path, PathBuf};

use tmclsh::fuzz_entry::TARGETS;

use crate::util::repo;

fn fuzz_dir() -> PathBuf {
    repo().join("fuzz")
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.is_file())
        .collect();
    files.sort();
    files
}

#[test]
fn every_fuzz_target_has_an_entry_point_and_a_corpus() {
    let mut on_disk: Vec<String> = files(&fuzz_dir().join("fuzz_targets"))
        .iter()
        .filter_map(|p| Some(p.file_stem()?.to_str()?.to_string()))
        .collect();
    on_disk.sort();
    let mut entries: Vec<String> = TARGETS.iter().map(|(name, _)| name.to_string()).collect();
    entries.sort();
    assert_eq!(
        on_disk, entries,
        "fuzz/fuzz_targets/ and fuzz_entry::TARGETS"
    );
    let manifest = std::fs::read_to_string(fuzz_dir().join("Cargo.toml")).unwrap();
    for name in &entries {
        assert!(
            manifest.contains(&format!("path = \"fuzz_targets/{name}.rs\"")),
            "{name} is a [[bin]] of fuzz/Cargo.toml"
        );
        let corpus = files(&fuzz_dir().join("corpus").join(name));
        assert!(!corpus.is_empty(), "fuzz/corpus/{name} holds inputs");
    }
}

#[test]
fn the_fuzz_corpus_replays_through_every_entry_point() {
    // The fuzzer runs on the main thread (8 MiB of stack); test threads get 2 MiB, and a debug
    // build's frames are larger than a release build's.
    let replay = std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(|| {
            let mut count = 0;
            for (name, entry) in TARGETS {
                for file in files(&fuzz_dir().join("corpus").join(name)) {
                    let data = std::fs::read(&file).unwrap();
                    let outcome = std::panic::catch_unwind(|| entry(&data));
                    assert!(outcome.is_ok(), "{name}: {} fails", file.display());
                    count += 1;
                }
            }
            count
        })
        .unwrap();
    let count = replay.join().expect("the replay finished");
    assert!(count > TARGETS.len(), "{count} inputs replayed");
}
