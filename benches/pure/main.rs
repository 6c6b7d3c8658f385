//! `cargo bench --bench pure`: the pure protocol code, timed in-process (see `cases.rs`).

mod cases;

fn main() {
    println!("{:<66} {:>12}", "pure part", "ns/op");
    for case in cases::run() {
        println!("{:<66} {:>12.1}", case.name, case.ns);
    }
}
