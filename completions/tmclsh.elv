
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
            cand -c 'Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from stdin when it is not a terminal'
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --value 'With -c or piped lines: print only each reply''s value (TMCL: -5000 of BA 100 -5000; SMD4: the data items), an empty line for a line that failed'
            cand --json 'With -c or piped lines: print one JSON object per line (status, value or items, raw reply, module, exit code)'
            cand --keep-going 'With -c or piped lines: go on past a failing line; the exit code is then the worst failure''s (130 before 3 before 1 before 2)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
            cand params 'Print the module''s axis and global parameters (those matching FILTER)'
            cand profiles 'List the built-in TMCL module profiles with their sources, or show one in full'
            cand ports 'List the serial ports of this machine (--probe: and what module answers on each)'
            cand completions 'Print a shell completion script'
            cand man 'Print the manual page (roff; man/tmclsh.1 in the source)'
            cand run 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)'
            cand asm 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
            cand disasm 'Turn a program file back into TMCL source'
            cand download 'Store a program (source or program file) in the module, verify it, optionally run it'
            cand upload 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)'
            cand snapshot 'Save the module''s parameters to a TOML file, compare with one, or write one back'
            cand scan 'Find the modules on the bus, with firmware versions and echo settings'
            cand transcript 'Turn a --log transcript into a replayable Rhai script'
            cand sim 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
            cand config 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user''s config.toml, or built in'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;params'= {
            cand --motor 'With --values: only motor N''s axis parameters'
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --values 'Read the readable parameters (those whose name contains FILTER) from the module, with what each value means; the link is given as for any command (--port, --tcp, --sim)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;profiles'= {
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;ports'= {
            cand --baud 'With --probe: the bit rate to probe at (8N1)'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand -m 'With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N)'
            cand --module 'With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N)'
            cand --probe 'Ask each USB port (or each PORT named) which module is there: address --module at --baud in --protocol (TMCL: command 136 to address 1 at 9600 baud by default), each reply awaited 100 ms (a port in use by another program is reported, not waited for). Built-in ports are probed only when named: what is wired to them may not expect the bytes'
            cand --all 'List the placeholder ttyS ports too (reserved by the kernel, with no UART behind them)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;completions'= {
            cand --install 'Write the script where the shell loads it from (bash: bash-completion''s directory under $XDG_DATA_HOME; zsh: $XDG_DATA_HOME/zsh/site-functions; fish: $XDG_CONFIG_HOME/fish) instead of printing it, and say where'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;man'= {
            cand --install 'Write the page to $XDG_DATA_HOME/man/man1/tmclsh.1 (~/.local/share/man/man1) instead of printing it, and say where'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;run'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --max-operations 'Operations after which a runaway script is stopped (0: no limit)'
            cand --max-call-depth 'Deepest nesting of function calls'
            cand --max-memory 'Memory the script may hold, in MiB (0: no limit)'
            cand --max-time 'Wall-clock time after which the script is stopped, its motors too (exit code 1): 500ms, 30s, 2m, or milliseconds'
            cand --allow-dir 'A directory the script''s file functions may also reach (repeatable); by default they reach only the script''s directory and the working directory'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand --overwrite 'Let the script''s file functions replace existing files that are not tmclsh snapshots or recordings'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;asm'= {
            cand -o 'Write the program file (format in docs/programs.md); without it the source is only checked'
            cand --output 'Write the program file (format in docs/programs.md); without it the source is only checked'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand --list 'Print the listing: address, the 7 instruction bytes and the source line'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;disasm'= {
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;download'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --run 'Start the program after downloading it'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;upload'= {
            cand -o 'Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it'
            cand --output 'Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it'
            cand --max 'Read at most N instructions (default: the module''s program memory)'
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;snapshot'= {
            cand -h 'Print help'
            cand --help 'Print help'
            cand save 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
            cand diff 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
            cand restore 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;snapshot;save'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --force 'Replace FILE if it exists'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;snapshot;diff'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;snapshot;restore'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --store 'Afterwards make the written parameters permanent, after a confirmation: EEPROM (STAP/STGP) on TMCL modules; STORE on an SMD4, which saves its whole working configuration'
            cand --yes 'Confirm --store without asking (for scripts)'
            cand --dry-run 'Only print the lines that would be sent'
            cand --force 'Restore a file with problems that allow it: of another module type, with numbers that disagree with the names (written by name), with names, motors or banks the module lacks (skipped). Values the module would refuse are never forced'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;snapshot;help'= {
            cand save 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
            cand diff 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
            cand restore 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;snapshot;help;save'= {
        }
        &'tmclsh;snapshot;help;diff'= {
        }
        &'tmclsh;snapshot;help;restore'= {
        }
        &'tmclsh;snapshot;help;help'= {
        }
        &'tmclsh;scan'= {
            cand --addresses 'Addresses to try: numbers and (TMCL) letters A..Z, single or as ranges (1-26, A,C,30-40). TMCL: 1-26 by default; addresses above 26 have no ASCII character and are tried with binary frames. SMD4: 1-247 by default, one @N SYS:FW each. Each reply is awaited 100 ms unless --timeout is set'
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --first 'Stop at the first module found, trying the addresses in ascending order'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;transcript'= {
            cand -h 'Print help'
            cand --help 'Print help'
            cand to-rhai 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;transcript;to-rhai'= {
            cand -o 'Write the script to FILE instead of stdout'
            cand --output 'Write the script to FILE instead of stdout'
            cand --wait 'Milliseconds the script waits for a live value (position, switch) to reach the value the transcript saw'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;transcript;help'= {
            cand to-rhai 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;transcript;help;to-rhai'= {
        }
        &'tmclsh;transcript;help;help'= {
        }
        &'tmclsh;sim'= {
            cand --protocol 'The protocol of the simulated module: a bus of TMCL modules (tmcl) or an SMD4 drive (smd4)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand --link 'Keep the symlink PATH pointed at the current pseudo-terminal, as udev keeps /dev/serial/by-id names pointed at an adapter: after the console''s `unplug` it points at the new one (and is gone during the outage). An existing file that is not a symlink is refused'
            cand --listen 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed'
            cand --modules 'Modules on the simulated RS-485 bus: addresses, each optionally with its own profile (`1,2` or `1:tmcm-142,2:tmcm-6110`; a module without one is of `--profile`)'
            cand --boot-loader 'The modules run their boot loader: 136 answers with B for V (`6110B131`), every other command with invalid command; `--boot-loader=2,3` for the modules at those addresses only'
            cand --baud 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)'
            cand --latency 'Hold the bytes the simulator sends until MS milliseconds pass or 62 wait, as an FTDI adapter''s latency timer does (16 ms untouched; tmclsh lowers a real one where it can)'
            cand --state 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts'
            cand --left-switch 'Position of the left limit switch (microsteps) of every motor, or MOTOR:POS for one motor (repeatable); not connected by default'
            cand --right-switch 'Position of the right limit switch, of every motor or MOTOR:POS'
            cand --home-switch 'Position of the reference (home) switch, active at and right of it; of every motor or MOTOR:POS'
            cand --reply-end 'Ending of ASCII replies: none, cr, lf or crlf'
            cand --echo-end 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)'
            cand --backspace-echo 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)'
            cand --drop-rate 'Drop replies with this probability (0..1)'
            cand --corrupt-rate 'Corrupt one byte of a reply with this probability'
            cand --delay-rate 'Delay replies with this probability, by --delay-ms'
            cand --delay-ms 'How long a delayed reply is held back'
            cand --silent-after 'Answer nothing after N replies (commands still execute)'
            cand --hangup-after 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)'
            cand --seed 'Seed of the fault decisions: the same seed and traffic give the same faults, so a run replays exactly (also --fault-seed; the console''s `seed N` restarts them)'
            cand --fault-seed 'Seed of the fault decisions: the same seed and traffic give the same faults, so a run replays exactly (also --fault-seed; the console''s `seed N` restarts them)'
            cand --flag-case 'Hex case of the flag words: upper (0x088E, the text) or lower (0x088e, many examples)'
            cand --float-decimals 'Decimals of FLOAT replies: 4 (every example) or 5 (the type table)'
            cand --error-spelling 'Spelling of error items: paren (-103 (Invalid Mnemonic)), comma (-103,Invalid Mnemonic) or bare (-103)'
            cand --prefix-only 'Accept only one form of the address prefix: attached (@3MOTOR:STOP) or comma (@3,MOTOR:STOP)'
            cand --real-value-grid 'Put the real value of user/real pairs (VMAX, AMAX, VSTART …) on a grid of STEP Hz or Hz/s (the conversion is undocumented; 0.0027939677238464355 = 12 MHz/2^24/256 reproduces the VSTOP example). Without it the real value echoes the user value'
            cand --pty 'Serve on a new pseudo-terminal (the default); its path is the first line printed'
            cand --shared-line 'The modules hear each other''s replies, as on a real RS-485 bus: a module whose address equals the host address (GP 76, 2 by default) takes the others'' replies for commands and answers them. Every module drops a partial binary frame after 5 ms of quiet (the UART time-out of Trinamic''s firmware), shared line or not'
            cand --adapter-echo 'Hand every byte the host sends back to it, before the module''s answer, as a 2-wire RS-485 adapter without echo suppression does (tmclsh strips it: --local-echo)'
            cand -v 'Log every frame and line received and sent, decoded, to stderr'
            cand --verbose 'Log every frame and line received and sent, decoded, to stderr'
            cand --manual-clock 'Let simulation time pass only on the console command `advance` (deterministic tests)'
            cand --no-reply-to-139 'Switch to ASCII mode on command 139 without a binary reply'
            cand --no-reply-to-bin 'Switch back to binary mode on BIN without an ASCII reply'
            cand --no-ascii 'Answer 139 with invalid command and stay binary, as a module without the ASCII interface does (for a module whose interface is unconfirmed, such as the TMCM-3110)'
            cand --float-missing-e 'Leave the E out of floats (1.0000+01), as two examples do'
            cand --no-current-rounding 'Echo currents unrounded, as the examples do (the text rounds to 1.044/31 A steps)'
            cand --no-reply-prefix 'Send replies to addressed packets without the @N, prefix'
            cand --scientific-positions 'Report PACT/PREL in scientific notation like other FLOATs (examples: 1000.00)'
            cand --tzw-reply-ms 'Report MOTOR:TZW in milliseconds, as its example does (its argument is in seconds)'
            cand --flags-without-item 'Answer SYS:FLAGS without the trailing item `1` only its example shows (the document declares no return for it)'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;config'= {
            cand --port 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)'
            cand --baud 'Serial bit rate (8N1)'
            cand --tcp 'TCP address of the module or of a serial server (HOST:PORT)'
            cand --dtr 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)'
            cand --rts 'RTS on opening the port: on, off, or keep (as for --dtr)'
            cand --rs485-delay 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485'
            cand --protocol 'The protocol the module speaks (also selects the built-in simulated module)'
            cand --profile 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)'
            cand -m 'Address of the target module (1 = address character A)'
            cand --module 'Address of the target module (1 = address character A)'
            cand --timeout 'Milliseconds to wait for a reply before giving up (exit code 3)'
            cand --echo 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)'
            cand --log 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date'
            cand --local-echo 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips'
            cand --reconnect 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never'
            cand --address 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)'
            cand --quiet-gap 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)'
            cand --sim 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
            cand --rs485 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
            cand --keep-latency 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
            cand --no-validate 'Send lines the validator would refuse (still canonicalised where they parse)'
            cand --no-enter 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
            cand --stay-ascii 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
            cand --binary 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
            cand -v 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --verbose 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
            cand --prefix-comma 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
        }
        &'tmclsh;help'= {
            cand params 'Print the module''s axis and global parameters (those matching FILTER)'
            cand profiles 'List the built-in TMCL module profiles with their sources, or show one in full'
            cand ports 'List the serial ports of this machine (--probe: and what module answers on each)'
            cand completions 'Print a shell completion script'
            cand man 'Print the manual page (roff; man/tmclsh.1 in the source)'
            cand run 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)'
            cand asm 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
            cand disasm 'Turn a program file back into TMCL source'
            cand download 'Store a program (source or program file) in the module, verify it, optionally run it'
            cand upload 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)'
            cand snapshot 'Save the module''s parameters to a TOML file, compare with one, or write one back'
            cand scan 'Find the modules on the bus, with firmware versions and echo settings'
            cand transcript 'Turn a --log transcript into a replayable Rhai script'
            cand sim 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
            cand config 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user''s config.toml, or built in'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;help;params'= {
        }
        &'tmclsh;help;profiles'= {
        }
        &'tmclsh;help;ports'= {
        }
        &'tmclsh;help;completions'= {
        }
        &'tmclsh;help;man'= {
        }
        &'tmclsh;help;run'= {
        }
        &'tmclsh;help;asm'= {
        }
        &'tmclsh;help;disasm'= {
        }
        &'tmclsh;help;download'= {
        }
        &'tmclsh;help;upload'= {
        }
        &'tmclsh;help;snapshot'= {
            cand save 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
            cand diff 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
            cand restore 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
        }
        &'tmclsh;help;snapshot;save'= {
        }
        &'tmclsh;help;snapshot;diff'= {
        }
        &'tmclsh;help;snapshot;restore'= {
        }
        &'tmclsh;help;scan'= {
        }
        &'tmclsh;help;transcript'= {
            cand to-rhai 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
        }
        &'tmclsh;help;transcript;to-rhai'= {
        }
        &'tmclsh;help;sim'= {
        }
        &'tmclsh;help;config'= {
        }
        &'tmclsh;help;help'= {
        }
    ]
    $completions[$command]
}
