
use builtin;
use str;

set edit:completion:arg-completer[tmclsh] = {|@words|
    fn spaces {|n|
        builtin:repeat $n ' ' | str:join ''
    }
    fn cand {|text desc|
        edit:complex-candidate $text &display=$text' '(spaces (- 14 (wcswidth $text)))$desc
    }
    var command = 'tmclsh'
    for word $words[1..-1] {
        if (str:has-prefix $word '-') {
            break
        }
        set command = $command';'$word
    }
    var completions = [
        &'tmclsh'= {
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand -h 'Print help'
            cand --help 'Print help'
            cand -V 'Print version'
            cand --version 'Print version'
            cand params 'Print the module''s axis and global parameters (those matching FILTER)'
            cand ports 'List the serial ports of this machine'
            cand completions 'Print a shell completion script'
            cand sim 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;params'= {
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;ports'= {
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;completions'= {
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;sim'= {
            cand --listen 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed'
            cand --modules 'Module addresses on the simulated RS-485 bus'
            cand --baud 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)'
            cand --state 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts'
            cand --left-switch 'Position of the left limit switch (microsteps); not connected by default'
            cand --right-switch 'Position of the right limit switch'
            cand --home-switch 'Position of the reference (home) switch, active at and right of it'
            cand --reply-end 'Ending of ASCII replies: none, cr, lf or crlf'
            cand --echo-end 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)'
            cand --backspace-echo 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)'
            cand --drop-rate 'Drop replies with this probability (0..1)'
            cand --corrupt-rate 'Corrupt one byte of a reply with this probability'
            cand --delay-rate 'Delay replies with this probability, by --delay-ms'
            cand --delay-ms 'How long a delayed reply is held back'
            cand --silent-after 'Answer nothing after N replies (commands still execute)'
            cand --hangup-after 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)'
            cand --fault-seed 'Seed of the fault decisions (same seed, same faults)'
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand --pty 'Serve on a new pseudo-terminal (the default); its path is the first line printed'
            cand -v 'Log every frame and line received and sent, decoded, to stderr'
            cand --verbose 'Log every frame and line received and sent, decoded, to stderr'
            cand --manual-clock 'Let simulation time pass only on the console command `advance` (deterministic tests)'
            cand --no-reply-to-139 'Switch to ASCII mode on command 139 without a binary reply'
            cand --no-reply-to-bin 'Switch back to binary mode on BIN without an ASCII reply'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;help'= {
            cand params 'Print the module''s axis and global parameters (those matching FILTER)'
            cand ports 'List the serial ports of this machine'
            cand completions 'Print a shell completion script'
            cand sim 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;help;params'= {
        }
        &'tmclsh;help;ports'= {
        }
        &'tmclsh;help;completions'= {
        }
        &'tmclsh;help;sim'= {
        }
        &'tmclsh;help;help'= {
        }
    ]
    $completions[$command]
}
