//! `tmclsh upload` and `:upload`: the stored program read back (command 134) to its end and shown
//! as source with labels, or written as source or a program file; a download → upload round trip
//! gives the same program. `download` checks a program against the module identified, so an
//! interrupt program goes to a TMCM-1140 on the bus without --profile.

use super::{bus_sim, on};
use crate::util::{code, repo, run, run_with_stdin, stderr, stdout, tempdir};

/// Timer 0 counts in user variable 0; its handler lies past the main loop's JA, reached by VECT.
const TIMER_PROGRAM: &str = "\
      VECT 0, Tick
      SGP 0, 3, 100
      EI 0
      EI 255
Loop: JA Loop

Tick: GGP 0, 2
      CALC ADD, 1
      AGP 0, 2
      RETI
";

#[test]
fn download_then_upload_gives_the_same_program_with_its_interrupt_handler() {
    let sim = bus_sim(&[]);
    let dir = tempdir();
    let source = dir.join("timer.tmc");
    std::fs::write(&source, TIMER_PROGRAM).unwrap();
    let source = source.to_str().unwrap();
    // No --profile: the TMCM-1140 identified has EI, VECT and RETI.
    let out = on(&sim, &["-m", "1", "download", source]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).starts_with("downloaded 9 instructions"),
        "{}",
        stdout(&out)
    );
    // Printed: labels where the program jumps, the handler after the loop, the end said.
    let out = on(&sim, &["-m", "1", "upload"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.contains("9 instructions, ending at address 8"),
        "{text}"
    );
    for line in ["VECT 0, L5", "JA L4", "L5:", "RETI"] {
        assert!(text.contains(line), "{line}: {text}");
    }
    // Written as a program file and as source: both the program the assembler makes.
    let expected = dir.join("expected.bin");
    let asm = |file: &str, to: &std::path::Path| {
        let out = run(&[
            "--profile",
            "tmcm-1140",
            "asm",
            file,
            "-o",
            to.to_str().unwrap(),
        ]);
        assert_eq!(code(&out), 0, "{}", stderr(&out));
    };
    asm(source, &expected);
    let bin = dir.join("up.bin");
    let out = on(&sim, &["-m", "1", "upload", "-o", bin.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(stdout(&out).contains("written to"), "{}", stdout(&out));
    assert_eq!(
        std::fs::read(&bin).unwrap(),
        std::fs::read(&expected).unwrap()
    );
    let tmc = dir.join("up.tmc");
    let out = on(&sim, &["-m", "1", "upload", "-o", tmc.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let again = dir.join("again.bin");
    asm(tmc.to_str().unwrap(), &again);
    assert_eq!(
        std::fs::read(&again).unwrap(),
        std::fs::read(&expected).unwrap()
    );
    // The uploaded source goes back down and up unchanged.
    let out = on(&sim, &["-m", "1", "download", tmc.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = on(&sim, &["-m", "1", "upload"]);
    assert_eq!(stdout(&out), text);
}

#[test]
fn an_upload_says_when_it_stopped_at_the_bound_and_refuses_other_file_names() {
    let sim = bus_sim(&[]);
    let program = repo().join("scripts/test2.tmc");
    let out = on(&sim, &["-m", "3", "download", program.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let out = on(&sim, &["-m", "3", "upload", "--max", "3"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert!(
        stdout(&out).contains("3 instructions, stopped at the bound of 3"),
        "{}",
        stdout(&out)
    );
    let out = on(&sim, &["-m", "3", "upload", "-o", "program.txt"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("FILE.tmc"), "{}", stderr(&out));
}

#[test]
fn upload_in_the_shell_prints_what_download_stored() {
    let program = repo().join("scripts/test2.tmc");
    let input = format!(":download {}\n:upload\n", program.display());
    let out = run_with_stdin(&["--sim"], &input);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.contains("13 instructions, ending at address 12"),
        "{text}"
    );
    assert!(text.contains("L8:") && text.contains("JA L8"), "{text}");
}
