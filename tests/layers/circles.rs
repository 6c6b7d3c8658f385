//! No circles between the files of a folder: the file a `crate::…` or `super::…` path names is
//! used by the file naming it, and following those uses must never lead back to where it began.
//! A circle makes a group of files one file in all but name: none of them can be read, tested or
//! moved without the others. Checked across the whole library; a parent's `mod.rs` is reached
//! by its children (its relative paths to them are not read), so it closes no circle.

use std::collections::BTreeMap;
use std::path::PathBuf;

use super::paths::{Source, used_paths};
use super::{library, made_up};

/// The files of `sources` that use each other in a circle, each circle once, in path order.
fn circles(sources: &[Source]) -> Vec<Vec<PathBuf>> {
    let files: Vec<&Source> = sources.iter().filter(|s| !s.test_only).collect();
    let by_module: BTreeMap<&[String], usize> = files
        .iter()
        .enumerate()
        .map(|(i, s)| (s.module.as_slice(), i))
        .collect();
    // The file a path names: the longest module path it starts with.
    let file_of = |path: &[String]| {
        (1..=path.len())
            .rev()
            .find_map(|n| by_module.get(&path[..n]).copied())
    };
    let uses: Vec<Vec<usize>> = files
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let mut used: Vec<usize> = used_paths(s)
                .iter()
                .filter_map(|p| file_of(p))
                .filter(|&j| j != i)
                .collect();
            used.sort();
            used.dedup();
            used
        })
        .collect();
    let reaches = |from: usize| {
        let mut seen = vec![false; files.len()];
        let mut todo = vec![from];
        while let Some(i) = todo.pop() {
            for &j in &uses[i] {
                if !seen[j] {
                    seen[j] = true;
                    todo.push(j);
                }
            }
        }
        seen
    };
    let reach: Vec<Vec<bool>> = (0..files.len()).map(reaches).collect();
    let mut found: Vec<Vec<PathBuf>> = Vec::new();
    let mut placed = vec![false; files.len()];
    for i in 0..files.len() {
        if placed[i] || !reach[i][i] {
            continue;
        }
        let circle: Vec<usize> = (0..files.len())
            .filter(|&j| reach[i][j] && reach[j][i])
            .collect();
        for &j in &circle {
            placed[j] = true;
        }
        found.push(circle.iter().map(|&j| files[j].file.clone()).collect());
    }
    found
}

#[test]
fn the_librarys_files_use_each_other_in_no_circle() {
    let found = circles(&library());
    assert!(
        found.is_empty(),
        "files using each other in a circle (move what both need below both):\n{}",
        found
            .iter()
            .map(|c| format!("{c:?}"))
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn the_check_sees_a_circle_of_three_and_not_a_parent_reached_by_its_children() {
    let sim = |name: &str, code: &str| {
        made_up(
            &format!("src/sim/{name}.rs"),
            &["sim", name],
            &format!("{code}\n"),
        )
    };
    let parent = made_up("src/sim/mod.rs", &["sim"], "pub use a::Thing;");
    let sources = [
        sim("a", "use super::b::B;\nuse super::Device;"),
        sim("b", "use crate::sim::c::C;"),
        sim("c", "fn f() { super::a::g() }"),
        sim("d", "use super::a::A;"),
        parent,
    ];
    let found = circles(&sources);
    let names = |c: &Vec<PathBuf>| {
        c.iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
    };
    assert_eq!(
        found.iter().map(names).collect::<Vec<_>>(),
        [["src/sim/a.rs", "src/sim/b.rs", "src/sim/c.rs"]]
    );
}
