# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_tmclsh_global_optspecs
    string join \n c= value json keep-going port= baud= tcp= can= can-bitrate= can-reply-id= sim dtr= rts= rs485 rs485-delay= keep-latency protocol= profile= m/module= timeout= log= no-validate local-echo= reconnect= v/verbose echo= no-enter stay-ascii binary address= prefix-comma quiet-gap= h/help V/version
end

function __fish_tmclsh_needs_command
    # Figure out if the current invocation already has a command.
    set -l cmd (commandline -opc)
    set -e cmd[1]
    argparse -s (__fish_tmclsh_global_optspecs) -- $cmd 2>/dev/null
    or return
    if set -q argv[1]
        # Also print the command, so this can be used to figure out what it is.
        echo $argv[1]
        return 1
    end
    return 0
end

function __fish_tmclsh_using_subcommand
    set -l cmd (__fish_tmclsh_needs_command)
    test -z "$cmd"
    and return 1
    contains -- $cmd[1] $argv
end

complete -c tmclsh -n "__fish_tmclsh_needs_command" -s c -d 'Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from stdin when it is not a terminal' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l value -d 'With -c or piped lines: print only each reply\'s value (TMCL: -5000 of BA 100 -5000; SMD4: the data items), an empty line for a line that failed'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l json -d 'With -c or piped lines: print one JSON object per line (status, value or items, raw reply, module, exit code)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l keep-going -d 'With -c or piped lines: go on past a failing line; the exit code is then the worst failure\'s (130 before 3 before 1 before 2)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s V -l version -d 'Print version'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "params" -d 'Print the module\'s axis and global parameters (those matching FILTER)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "profiles" -d 'List the built-in TMCL module profiles with their sources, or show one in full'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "ports" -d 'List the serial ports of this machine (--probe: and what module answers on each)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "completions" -d 'Print a shell completion script'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "man" -d 'Print the manual page (roff; man/tmclsh.1 in the source)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "run" -d 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "asm" -d 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "disasm" -d 'Turn a program file back into TMCL source'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "download" -d 'Store a program (source or program file) in the module, verify it, optionally run it'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "upload" -d 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "snapshot" -d 'Save the module\'s parameters to a TOML file, compare with one, or write one back'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "scan" -d 'Find the modules on the bus, with firmware versions and echo settings'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "transcript" -d 'Turn a --log transcript into a replayable Rhai script'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "sim" -d 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "config" -d 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user\'s config.toml, or built in'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l motor -d 'With --values: only motor N\'s axis parameters' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l json -d 'Print one JSON document instead of the table; not with --values (fields in docs/machine-output.md)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l values -d 'Read the readable parameters (those whose name contains FILTER) from the module, with what each value means; the link is given as for any command (--port, --tcp, --sim)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand profiles" -l json -d 'Print one JSON document instead (fields in docs/machine-output.md)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand profiles" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l baud -d 'With --probe: the bit rate to probe at (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -s m -l module -d 'With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l probe -d 'Ask each USB port (or each PORT named) which module is there: address --module at --baud in --protocol (TMCL: command 136 to address 1 at 9600 baud by default), each reply awaited 100 ms (a port in use by another program is reported, not waited for). Built-in ports are probed only when named: what is wired to them may not expect the bytes'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l all -d 'List the placeholder ttyS ports too (reserved by the kernel, with no UART behind them)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l json -d 'Print one JSON document instead (fields in docs/machine-output.md)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand completions" -l install -d 'Write the script where the shell loads it from (bash: bash-completion\'s directory under $XDG_DATA_HOME; zsh: $XDG_DATA_HOME/zsh/site-functions; fish: $XDG_CONFIG_HOME/fish) instead of printing it, and say where'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand completions" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand man" -l install -d 'Write the page to $XDG_DATA_HOME/man/man1/tmclsh.1 (~/.local/share/man/man1) instead of printing it, and say where'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand man" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l max-operations -d 'Operations after which a runaway script is stopped (0: no limit)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l max-call-depth -d 'Deepest nesting of function calls' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l max-memory -d 'Memory the script may hold, in MiB (0: no limit)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l max-time -d 'Wall-clock time after which the script is stopped, its motors too (exit code 1): 500ms, 30s, 2m, or milliseconds' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l allow-dir -d 'A directory the script\'s file functions may also reach (repeatable); by default they reach only the script\'s directory and the working directory' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l junit -d 'Write a JUnit XML report to FILE: one test case per `test("name", || …)` block of the script (the whole script as one case when it has none), failures with their message and script position. Written whatever the outcome; a failed block does not end the run' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -l overwrite -d 'Let the script\'s file functions replace existing files that are not tmclsh snapshots or recordings'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand asm" -s o -l output -d 'Write the program file (format in docs/programs.md); without it the source is only checked' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand asm" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand asm" -l list -d 'Print the listing: address, the 7 instruction bytes and the source line'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand asm" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand disasm" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand disasm" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l run -d 'Start the program after downloading it'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -s o -l output -d 'Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l max -d 'Read at most N instructions (default: the module\'s program memory)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand upload" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and not __fish_seen_subcommand_from save diff restore help" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and not __fish_seen_subcommand_from save diff restore help" -f -a "save" -d 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and not __fish_seen_subcommand_from save diff restore help" -f -a "diff" -d 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and not __fish_seen_subcommand_from save diff restore help" -f -a "restore" -d 'Write FILE\'s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and not __fish_seen_subcommand_from save diff restore help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l force -d 'Replace FILE if it exists'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from save" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l json -d 'Print one JSON document instead of the table (fields in docs/machine-output.md)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from diff" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l store -d 'Afterwards make the written parameters permanent, after a confirmation: EEPROM (STAP/STGP) on TMCL modules; STORE on an SMD4, which saves its whole working configuration'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l yes -d 'Confirm --store without asking (for scripts)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l dry-run -d 'Only print the lines that would be sent'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l force -d 'Restore a file with problems that allow it: of another module type, with numbers that disagree with the names (written by name), with names, motors or banks the module lacks (skipped). Values the module would refuse are never forced'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from restore" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from help" -f -a "save" -d 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from help" -f -a "diff" -d 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from help" -f -a "restore" -d 'Write FILE\'s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand snapshot; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l addresses -d 'Addresses to try: numbers and (TMCL) letters A..Z, single or as ranges (1-26, A,C,30-40). TMCL: 1-26 by default; addresses above 26 have no ASCII character and are tried with binary frames. SMD4: 1-247 by default, one @N SYS:FW each. Each reply is awaited 100 ms unless --timeout is set' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l first -d 'Stop at the first module found, trying the addresses in ascending order'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l json -d 'Print one JSON document instead of the table (fields in docs/machine-output.md), also when nothing answered'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand scan" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and not __fish_seen_subcommand_from to-rhai help" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and not __fish_seen_subcommand_from to-rhai help" -f -a "to-rhai" -d 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and not __fish_seen_subcommand_from to-rhai help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from to-rhai" -s o -l output -d 'Write the script to FILE instead of stdout' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from to-rhai" -l wait -d 'Milliseconds the script waits for a live value (position, switch) to reach the value the transcript saw' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from to-rhai" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from to-rhai" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from help" -f -a "to-rhai" -d 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand transcript; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l protocol -d 'The protocol of the simulated module: a bus of TMCL modules (tmcl) or an SMD4 drive (smd4)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l link -d 'Keep the symlink PATH pointed at the current pseudo-terminal, as udev keeps /dev/serial/by-id names pointed at an adapter: after the console\'s `unplug` it points at the new one (and is gone during the outage). An existing file that is not a symlink is refused' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l listen -d 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l slcan-ack -d 'How the slcan adapter acknowledges a transmitted frame: z, Z, cr (a bare CR) or none' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l modules -d 'Modules on the simulated RS-485 bus: addresses, each optionally with its own profile (`1,2` or `1:tmcm-142,2:tmcm-6110`; a module without one is of `--profile`)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l boot-loader -d 'The modules run their boot loader: 136 answers with B for V (`6110B131`), every other command with invalid command; `--boot-loader=2,3` for the modules at those addresses only' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l baud -d 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l latency -d 'Hold the bytes the simulator sends until MS milliseconds pass or 62 wait, as an FTDI adapter\'s latency timer does (16 ms untouched; tmclsh lowers a real one where it can)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l state -d 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l left-switch -d 'Position of the left limit switch (microsteps) of every motor, or MOTOR:POS for one motor (repeatable); not connected by default' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l right-switch -d 'Position of the right limit switch, of every motor or MOTOR:POS' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l home-switch -d 'Position of the reference (home) switch, active at and right of it; of every motor or MOTOR:POS' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l reply-end -d 'Ending of ASCII replies: none, cr, lf or crlf' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l echo-end -d 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l backspace-echo -d 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l drop-rate -d 'Drop replies with this probability (0..1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l corrupt-rate -d 'Corrupt one byte of a reply with this probability' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l delay-rate -d 'Delay replies with this probability, by --delay-ms' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l delay-ms -d 'How long a delayed reply is held back' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l silent-after -d 'Answer nothing after N replies (commands still execute)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l hangup-after -d 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l seed -l fault-seed -d 'Seed of the fault decisions: the same seed and traffic give the same faults, so a run replays exactly (also --fault-seed; the console\'s `seed N` restarts them)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l flag-case -d 'Hex case of the flag words: upper (0x088E, the text) or lower (0x088e, many examples)' -r -f -a "upper\t''
lower\t''"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l float-decimals -d 'Decimals of FLOAT replies: 4 (every example) or 5 (the type table)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l error-spelling -d 'Spelling of error items: paren (-103 (Invalid Mnemonic)), comma (-103,Invalid Mnemonic) or bare (-103)' -r -f -a "paren\t''
comma\t''
bare\t''"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l prefix-only -d 'Accept only one form of the address prefix: attached (@3MOTOR:STOP) or comma (@3,MOTOR:STOP)' -r -f -a "attached\t''
comma\t''"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l real-value-grid -d 'Put the real value of user/real pairs (VMAX, AMAX, VSTART …) on a grid of STEP Hz or Hz/s (the conversion is undocumented; 0.0027939677238464355 = 12 MHz/2^24/256 reproduces the VSTOP example). Without it the real value echoes the user value. At most 1, so each pair stays within the 0.5 the reply check allows ([user_real] in data/smd4.toml)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l pty -d 'Serve on a new pseudo-terminal (the default); its path is the first line printed'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l slcan -d 'Serve the simulated bus as an slcan (serial-line CAN) adapter: requests and replies are TMCL\'s CAN frames (`--can slcan:PATH` on the other side)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l foreign-frames -d 'Put another node\'s frame on the CAN bus (a CANopen heartbeat, ID 0x705) before each reply, as on a bus the modules share with other nodes'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l shared-line -d 'The modules hear each other\'s replies, as on a real RS-485 bus: a module whose address equals the host address (GP 76, 2 by default) takes the others\' replies for commands and answers them. Every module drops a partial binary frame after 5 ms of quiet (the UART time-out of Trinamic\'s firmware), shared line or not'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l adapter-echo -d 'Hand every byte the host sends back to it, before the module\'s answer, as a 2-wire RS-485 adapter without echo suppression does (tmclsh strips it: --local-echo)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -s v -l verbose -d 'Log every frame and line received and sent, decoded, to stderr'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l manual-clock -d 'Let simulation time pass only on the console command `advance` (deterministic tests)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-reply-to-139 -d 'Switch to ASCII mode on command 139 without a binary reply'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-reply-to-bin -d 'Switch back to binary mode on BIN without an ASCII reply'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-ascii -d 'Answer 139 with invalid command and stay binary, as a module without the ASCII interface does (for a module whose interface is unconfirmed, such as the TMCM-3110)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l float-missing-e -d 'Leave the E out of floats (1.0000+01), as two examples do'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-current-rounding -d 'Echo currents unrounded, as the examples do (the text rounds to 1.044/31 A steps)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-reply-prefix -d 'Send replies to addressed packets without the @N, prefix'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l scientific-positions -d 'Report PACT/PREL in scientific notation like other FLOATs (examples: 1000.00)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l tzw-reply-ms -d 'Report MOTOR:TZW in milliseconds, as its example does (its argument is in seconds)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l flags-without-item -d 'Answer SYS:FLAGS without the trailing item `1` only its example shows (the document declares no return for it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l port -d 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l baud -d 'Serial bit rate (8N1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l tcp -d 'TCP address of the module or of a serial server (HOST:PORT)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l can -d 'CAN adapter of the modules\' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module\'s CAN ID is --module' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l can-bitrate -d 'The CAN bus\'s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN\'s is set with `ip link`) [default: 1000000, the modules\' default]' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l can-reply-id -d 'The CAN ID the modules send their replies to (the modules\' reply ID setting)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l dtr -d 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l rts -d 'RTS on opening the port: on, off, or keep (as for --dtr)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l rs485-delay -d 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l protocol -d 'The protocol the module speaks (also selects the built-in simulated module)' -r -f -a "tmcl\t'Trinamic TMCL: ASCII interface (manual §6.6), binary frames after `:bin`'
smd4\t'AML SMD4 text protocol'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l profile -d 'Module profile instead of the TMCM-142\'s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -s m -l module -d 'Address of the target module (1 = address character A)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l timeout -d 'Milliseconds to wait for a reply before giving up (exit code 3)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l log -d 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l local-echo -d 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips' -r -f -a "auto\t'Find out at open: the first request that comes straight back, byte for byte'
on\t'The adapter echoes: strip it'
off\t'It does not'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l reconnect -d 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l echo -d 'Set the target module\'s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)' -r -f -a "char\t'Every character echoed as it arrives'
line\t'The whole line echoed after its end'
none\t'No echo, only the reply'"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l address -d 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l quiet-gap -d 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l sim -d 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l rs485 -d 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver\'s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l keep-latency -d 'Leave an FTDI adapter\'s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l no-validate -d 'Send lines the validator would refuse (still canonicalised where they parse)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -s v -l verbose -d 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l no-enter -d 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l stay-ascii -d 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l binary -d 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l prefix-comma -d 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual\'s @3MOTOR:STOP'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -l json -d 'Print one JSON document instead (fields in docs/machine-output.md)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand config" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "params" -d 'Print the module\'s axis and global parameters (those matching FILTER)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "profiles" -d 'List the built-in TMCL module profiles with their sources, or show one in full'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "ports" -d 'List the serial ports of this machine (--probe: and what module answers on each)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "completions" -d 'Print a shell completion script'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "man" -d 'Print the manual page (roff; man/tmclsh.1 in the source)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "run" -d 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "asm" -d 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "disasm" -d 'Turn a program file back into TMCL source'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "download" -d 'Store a program (source or program file) in the module, verify it, optionally run it'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "upload" -d 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "snapshot" -d 'Save the module\'s parameters to a TOML file, compare with one, or write one back'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "scan" -d 'Find the modules on the bus, with firmware versions and echo settings'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "transcript" -d 'Turn a --log transcript into a replayable Rhai script'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "sim" -d 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "config" -d 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user\'s config.toml, or built in'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params profiles ports completions man run asm disasm download upload snapshot scan transcript sim config help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and __fish_seen_subcommand_from snapshot" -f -a "save" -d 'Read every readable parameter into FILE (TOML, keyed by parameter name)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and __fish_seen_subcommand_from snapshot" -f -a "diff" -d 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and __fish_seen_subcommand_from snapshot" -f -a "restore" -d 'Write FILE\'s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and __fish_seen_subcommand_from transcript" -f -a "to-rhai" -d 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received'
# Added to clap's script: serial devices after --port, and only the files a subcommand
# takes.
function __fish_tmclsh_serial_ports
    for port in /dev/ttyUSB* /dev/ttyACM* /dev/ttyAMA* /dev/serial/by-id/* /dev/cu.*
        test -e $port; and echo $port
    end
end
complete -c tmclsh -l port -x -a "(__fish_tmclsh_serial_ports)" -d 'serial port'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand run" -f -a "(__fish_complete_suffix .rhai)"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand download" -f -a "(__fish_complete_suffix .tmc; __fish_complete_suffix .bin)"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand asm" -f -a "(__fish_complete_suffix .tmc)"
complete -c tmclsh -n "__fish_tmclsh_using_subcommand disasm" -f -a "(__fish_complete_suffix .bin)"
