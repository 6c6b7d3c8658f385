
using namespace System.Management.Automation
using namespace System.Management.Automation.Language

Register-ArgumentCompleter -Native -CommandName 'tmclsh' -ScriptBlock {
    param($wordToComplete, $commandAst, $cursorPosition)

    $commandElements = $commandAst.CommandElements
    $command = @(
        'tmclsh'
        for ($i = 1; $i -lt $commandElements.Count; $i++) {
            $element = $commandElements[$i]
            if ($element -isnot [StringConstantExpressionAst] -or
                $element.StringConstantType -ne [StringConstantType]::BareWord -or
                $element.Value.StartsWith('-') -or
                $element.Value -eq $wordToComplete) {
                break
        }
        $element.Value
    }) -join ';'

    $completions = @(switch ($command) {
        'tmclsh' {
            [CompletionResult]::new('-c', '-c', [CompletionResultType]::ParameterName, 'Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from stdin when it is not a terminal')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--value', '--value', [CompletionResultType]::ParameterName, 'With -c or piped lines: print only each reply''s value (TMCL: -5000 of BA 100 -5000; SMD4: the data items), an empty line for a line that failed')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'With -c or piped lines: print one JSON object per line (status, value or items, raw reply, module, exit code)')
            [CompletionResult]::new('--keep-going', '--keep-going', [CompletionResultType]::ParameterName, 'With -c or piped lines: go on past a failing line; the exit code is then the worst failure''s (130 before 3 before 1 before 2)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('params', 'params', [CompletionResultType]::ParameterValue, 'Print the module''s axis and global parameters (those matching FILTER)')
            [CompletionResult]::new('profiles', 'profiles', [CompletionResultType]::ParameterValue, 'List the built-in TMCL module profiles with their sources, or show one in full')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports of this machine (--probe: and what module answers on each)')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the manual page (roff; man/tmclsh.1 in the source)')
            [CompletionResult]::new('run', 'run', [CompletionResultType]::ParameterValue, 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)')
            [CompletionResult]::new('asm', 'asm', [CompletionResultType]::ParameterValue, 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)')
            [CompletionResult]::new('disasm', 'disasm', [CompletionResultType]::ParameterValue, 'Turn a program file back into TMCL source')
            [CompletionResult]::new('download', 'download', [CompletionResultType]::ParameterValue, 'Store a program (source or program file) in the module, verify it, optionally run it')
            [CompletionResult]::new('upload', 'upload', [CompletionResultType]::ParameterValue, 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)')
            [CompletionResult]::new('snapshot', 'snapshot', [CompletionResultType]::ParameterValue, 'Save the module''s parameters to a TOML file, compare with one, or write one back')
            [CompletionResult]::new('scan', 'scan', [CompletionResultType]::ParameterValue, 'Find the modules on the bus, with firmware versions and echo settings')
            [CompletionResult]::new('transcript', 'transcript', [CompletionResultType]::ParameterValue, 'Turn a --log transcript into a replayable Rhai script')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin')
            [CompletionResult]::new('config', 'config', [CompletionResultType]::ParameterValue, 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user''s config.toml, or built in')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;params' {
            [CompletionResult]::new('--motor', '--motor', [CompletionResultType]::ParameterName, 'With --values: only motor N''s axis parameters')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead of the table; not with --values (fields in docs/machine-output.md)')
            [CompletionResult]::new('--values', '--values', [CompletionResultType]::ParameterName, 'Read the readable parameters (those whose name contains FILTER) from the module, with what each value means; the link is given as for any command (--port, --tcp, --sim)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;profiles' {
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead (fields in docs/machine-output.md)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;ports' {
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'With --probe: the bit rate to probe at (8N1)')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'With --probe: the address to ask (TMCL: 1 = address character A; SMD4: @N)')
            [CompletionResult]::new('--probe', '--probe', [CompletionResultType]::ParameterName, 'Ask each USB port (or each PORT named) which module is there: address --module at --baud in --protocol (TMCL: command 136 to address 1 at 9600 baud by default), each reply awaited 100 ms (a port in use by another program is reported, not waited for). Built-in ports are probed only when named: what is wired to them may not expect the bytes')
            [CompletionResult]::new('--all', '--all', [CompletionResultType]::ParameterName, 'List the placeholder ttyS ports too (reserved by the kernel, with no UART behind them)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead (fields in docs/machine-output.md)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;completions' {
            [CompletionResult]::new('--install', '--install', [CompletionResultType]::ParameterName, 'Write the script where the shell loads it from (bash: bash-completion''s directory under $XDG_DATA_HOME; zsh: $XDG_DATA_HOME/zsh/site-functions; fish: $XDG_CONFIG_HOME/fish) instead of printing it, and say where')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;man' {
            [CompletionResult]::new('--install', '--install', [CompletionResultType]::ParameterName, 'Write the page to $XDG_DATA_HOME/man/man1/tmclsh.1 (~/.local/share/man/man1) instead of printing it, and say where')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;run' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--max-operations', '--max-operations', [CompletionResultType]::ParameterName, 'Operations after which a runaway script is stopped (0: no limit)')
            [CompletionResult]::new('--max-call-depth', '--max-call-depth', [CompletionResultType]::ParameterName, 'Deepest nesting of function calls')
            [CompletionResult]::new('--max-memory', '--max-memory', [CompletionResultType]::ParameterName, 'Memory the script may hold, in MiB (0: no limit)')
            [CompletionResult]::new('--max-time', '--max-time', [CompletionResultType]::ParameterName, 'Wall-clock time after which the script is stopped, its motors too (exit code 1): 500ms, 30s, 2m, or milliseconds')
            [CompletionResult]::new('--allow-dir', '--allow-dir', [CompletionResultType]::ParameterName, 'A directory the script''s file functions may also reach (repeatable); by default they reach only the script''s directory and the working directory')
            [CompletionResult]::new('--junit', '--junit', [CompletionResultType]::ParameterName, 'Write a JUnit XML report to FILE: one test case per `test("name", || …)` block of the script (the whole script as one case when it has none), failures with their message and script position. Written whatever the outcome; a failed block does not end the run')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--overwrite', '--overwrite', [CompletionResultType]::ParameterName, 'Let the script''s file functions replace existing files that are not tmclsh snapshots or recordings')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;asm' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the program file (format in docs/programs.md); without it the source is only checked')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the program file (format in docs/programs.md); without it the source is only checked')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('--list', '--list', [CompletionResultType]::ParameterName, 'Print the listing: address, the 7 instruction bytes and the source line')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;disasm' {
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;download' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--run', '--run', [CompletionResultType]::ParameterName, 'Start the program after downloading it')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;upload' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the program to FILE.tmc (source) or FILE.bin (a program file) instead of printing it')
            [CompletionResult]::new('--max', '--max', [CompletionResultType]::ParameterName, 'Read at most N instructions (default: the module''s program memory)')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;snapshot' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('save', 'save', [CompletionResultType]::ParameterValue, 'Read every readable parameter into FILE (TOML, keyed by parameter name)')
            [CompletionResult]::new('diff', 'diff', [CompletionResultType]::ParameterValue, 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)')
            [CompletionResult]::new('restore', 'restore', [CompletionResultType]::ParameterValue, 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;snapshot;save' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--force', '--force', [CompletionResultType]::ParameterName, 'Replace FILE if it exists')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;snapshot;diff' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead of the table (fields in docs/machine-output.md)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;snapshot;restore' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--store', '--store', [CompletionResultType]::ParameterName, 'Afterwards make the written parameters permanent, after a confirmation: EEPROM (STAP/STGP) on TMCL modules; STORE on an SMD4, which saves its whole working configuration')
            [CompletionResult]::new('--yes', '--yes', [CompletionResultType]::ParameterName, 'Confirm --store without asking (for scripts)')
            [CompletionResult]::new('--dry-run', '--dry-run', [CompletionResultType]::ParameterName, 'Only print the lines that would be sent')
            [CompletionResult]::new('--force', '--force', [CompletionResultType]::ParameterName, 'Restore a file with problems that allow it: of another module type, with numbers that disagree with the names (written by name), with names, motors or banks the module lacks (skipped). Values the module would refuse are never forced')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;snapshot;help' {
            [CompletionResult]::new('save', 'save', [CompletionResultType]::ParameterValue, 'Read every readable parameter into FILE (TOML, keyed by parameter name)')
            [CompletionResult]::new('diff', 'diff', [CompletionResultType]::ParameterValue, 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)')
            [CompletionResult]::new('restore', 'restore', [CompletionResultType]::ParameterValue, 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;snapshot;help;save' {
            break
        }
        'tmclsh;snapshot;help;diff' {
            break
        }
        'tmclsh;snapshot;help;restore' {
            break
        }
        'tmclsh;snapshot;help;help' {
            break
        }
        'tmclsh;scan' {
            [CompletionResult]::new('--addresses', '--addresses', [CompletionResultType]::ParameterName, 'Addresses to try: numbers and (TMCL) letters A..Z, single or as ranges (1-26, A,C,30-40). TMCL: 1-26 by default; addresses above 26 have no ASCII character and are tried with binary frames. SMD4: 1-247 by default, one @N SYS:FW each. Each reply is awaited 100 ms unless --timeout is set')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--first', '--first', [CompletionResultType]::ParameterName, 'Stop at the first module found, trying the addresses in ascending order')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead of the table (fields in docs/machine-output.md), also when nothing answered')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;transcript' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('to-rhai', 'to-rhai', [CompletionResultType]::ParameterValue, 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;transcript;to-rhai' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the script to FILE instead of stdout')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the script to FILE instead of stdout')
            [CompletionResult]::new('--wait', '--wait', [CompletionResultType]::ParameterName, 'Milliseconds the script waits for a live value (position, switch) to reach the value the transcript saw')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;transcript;help' {
            [CompletionResult]::new('to-rhai', 'to-rhai', [CompletionResultType]::ParameterValue, 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;transcript;help;to-rhai' {
            break
        }
        'tmclsh;transcript;help;help' {
            break
        }
        'tmclsh;sim' {
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol of the simulated module: a bus of TMCL modules (tmcl) or an SMD4 drive (smd4)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('--link', '--link', [CompletionResultType]::ParameterName, 'Keep the symlink PATH pointed at the current pseudo-terminal, as udev keeps /dev/serial/by-id names pointed at an adapter: after the console''s `unplug` it points at the new one (and is gone during the outage). An existing file that is not a symlink is refused')
            [CompletionResult]::new('--listen', '--listen', [CompletionResultType]::ParameterName, 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed')
            [CompletionResult]::new('--slcan-ack', '--slcan-ack', [CompletionResultType]::ParameterName, 'How the slcan adapter acknowledges a transmitted frame: z, Z, cr (a bare CR) or none')
            [CompletionResult]::new('--modules', '--modules', [CompletionResultType]::ParameterName, 'Modules on the simulated RS-485 bus: addresses, each optionally with its own profile (`1,2` or `1:tmcm-142,2:tmcm-6110`; a module without one is of `--profile`)')
            [CompletionResult]::new('--boot-loader', '--boot-loader', [CompletionResultType]::ParameterName, 'The modules run their boot loader: 136 answers with B for V (`6110B131`), every other command with invalid command; `--boot-loader=2,3` for the modules at those addresses only')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)')
            [CompletionResult]::new('--latency', '--latency', [CompletionResultType]::ParameterName, 'Hold the bytes the simulator sends until MS milliseconds pass or 62 wait, as an FTDI adapter''s latency timer does (16 ms untouched; tmclsh lowers a real one where it can)')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts')
            [CompletionResult]::new('--left-switch', '--left-switch', [CompletionResultType]::ParameterName, 'Position of the left limit switch (microsteps) of every motor, or MOTOR:POS for one motor (repeatable); not connected by default')
            [CompletionResult]::new('--right-switch', '--right-switch', [CompletionResultType]::ParameterName, 'Position of the right limit switch, of every motor or MOTOR:POS')
            [CompletionResult]::new('--home-switch', '--home-switch', [CompletionResultType]::ParameterName, 'Position of the reference (home) switch, active at and right of it; of every motor or MOTOR:POS')
            [CompletionResult]::new('--reply-end', '--reply-end', [CompletionResultType]::ParameterName, 'Ending of ASCII replies: none, cr, lf or crlf')
            [CompletionResult]::new('--echo-end', '--echo-end', [CompletionResultType]::ParameterName, 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)')
            [CompletionResult]::new('--backspace-echo', '--backspace-echo', [CompletionResultType]::ParameterName, 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)')
            [CompletionResult]::new('--drop-rate', '--drop-rate', [CompletionResultType]::ParameterName, 'Drop replies with this probability (0..1)')
            [CompletionResult]::new('--corrupt-rate', '--corrupt-rate', [CompletionResultType]::ParameterName, 'Corrupt one byte of a reply with this probability')
            [CompletionResult]::new('--delay-rate', '--delay-rate', [CompletionResultType]::ParameterName, 'Delay replies with this probability, by --delay-ms')
            [CompletionResult]::new('--delay-ms', '--delay-ms', [CompletionResultType]::ParameterName, 'How long a delayed reply is held back')
            [CompletionResult]::new('--silent-after', '--silent-after', [CompletionResultType]::ParameterName, 'Answer nothing after N replies (commands still execute)')
            [CompletionResult]::new('--hangup-after', '--hangup-after', [CompletionResultType]::ParameterName, 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)')
            [CompletionResult]::new('--seed', '--seed', [CompletionResultType]::ParameterName, 'Seed of the fault decisions: the same seed and traffic give the same faults, so a run replays exactly (also --fault-seed; the console''s `seed N` restarts them)')
            [CompletionResult]::new('--fault-seed', '--fault-seed', [CompletionResultType]::ParameterName, 'Seed of the fault decisions: the same seed and traffic give the same faults, so a run replays exactly (also --fault-seed; the console''s `seed N` restarts them)')
            [CompletionResult]::new('--flag-case', '--flag-case', [CompletionResultType]::ParameterName, 'Hex case of the flag words: upper (0x088E, the text) or lower (0x088e, many examples)')
            [CompletionResult]::new('--float-decimals', '--float-decimals', [CompletionResultType]::ParameterName, 'Decimals of FLOAT replies: 4 (every example) or 5 (the type table)')
            [CompletionResult]::new('--error-spelling', '--error-spelling', [CompletionResultType]::ParameterName, 'Spelling of error items: paren (-103 (Invalid Mnemonic)), comma (-103,Invalid Mnemonic) or bare (-103)')
            [CompletionResult]::new('--prefix-only', '--prefix-only', [CompletionResultType]::ParameterName, 'Accept only one form of the address prefix: attached (@3MOTOR:STOP) or comma (@3,MOTOR:STOP)')
            [CompletionResult]::new('--real-value-grid', '--real-value-grid', [CompletionResultType]::ParameterName, 'Put the real value of user/real pairs (VMAX, AMAX, VSTART …) on a grid of STEP Hz or Hz/s (the conversion is undocumented; 0.0027939677238464355 = 12 MHz/2^24/256 reproduces the VSTOP example). Without it the real value echoes the user value. At most 1, so each pair stays within the 0.5 the reply check allows ([user_real] in data/smd4.toml)')
            [CompletionResult]::new('--pty', '--pty', [CompletionResultType]::ParameterName, 'Serve on a new pseudo-terminal (the default); its path is the first line printed')
            [CompletionResult]::new('--slcan', '--slcan', [CompletionResultType]::ParameterName, 'Serve the simulated bus as an slcan (serial-line CAN) adapter: requests and replies are TMCL''s CAN frames (`--can slcan:PATH` on the other side)')
            [CompletionResult]::new('--foreign-frames', '--foreign-frames', [CompletionResultType]::ParameterName, 'Put another node''s frame on the CAN bus (a CANopen heartbeat, ID 0x705) before each reply, as on a bus the modules share with other nodes')
            [CompletionResult]::new('--shared-line', '--shared-line', [CompletionResultType]::ParameterName, 'The modules hear each other''s replies, as on a real RS-485 bus: a module whose address equals the host address (GP 76, 2 by default) takes the others'' replies for commands and answers them. Every module drops a partial binary frame after 5 ms of quiet (the UART time-out of Trinamic''s firmware), shared line or not')
            [CompletionResult]::new('--adapter-echo', '--adapter-echo', [CompletionResultType]::ParameterName, 'Hand every byte the host sends back to it, before the module''s answer, as a 2-wire RS-485 adapter without echo suppression does (tmclsh strips it: --local-echo)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Log every frame and line received and sent, decoded, to stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Log every frame and line received and sent, decoded, to stderr')
            [CompletionResult]::new('--manual-clock', '--manual-clock', [CompletionResultType]::ParameterName, 'Let simulation time pass only on the console command `advance` (deterministic tests)')
            [CompletionResult]::new('--no-reply-to-139', '--no-reply-to-139', [CompletionResultType]::ParameterName, 'Switch to ASCII mode on command 139 without a binary reply')
            [CompletionResult]::new('--no-reply-to-bin', '--no-reply-to-bin', [CompletionResultType]::ParameterName, 'Switch back to binary mode on BIN without an ASCII reply')
            [CompletionResult]::new('--no-ascii', '--no-ascii', [CompletionResultType]::ParameterName, 'Answer 139 with invalid command and stay binary, as a module without the ASCII interface does (for a module whose interface is unconfirmed, such as the TMCM-3110)')
            [CompletionResult]::new('--float-missing-e', '--float-missing-e', [CompletionResultType]::ParameterName, 'Leave the E out of floats (1.0000+01), as two examples do')
            [CompletionResult]::new('--no-current-rounding', '--no-current-rounding', [CompletionResultType]::ParameterName, 'Echo currents unrounded, as the examples do (the text rounds to 1.044/31 A steps)')
            [CompletionResult]::new('--no-reply-prefix', '--no-reply-prefix', [CompletionResultType]::ParameterName, 'Send replies to addressed packets without the @N, prefix')
            [CompletionResult]::new('--scientific-positions', '--scientific-positions', [CompletionResultType]::ParameterName, 'Report PACT/PREL in scientific notation like other FLOATs (examples: 1000.00)')
            [CompletionResult]::new('--tzw-reply-ms', '--tzw-reply-ms', [CompletionResultType]::ParameterName, 'Report MOTOR:TZW in milliseconds, as its example does (its argument is in seconds)')
            [CompletionResult]::new('--flags-without-item', '--flags-without-item', [CompletionResultType]::ParameterName, 'Answer SYS:FLAGS without the trailing item `1` only its example shows (the document declares no return for it)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;config' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Serial port of the module (e.g. /dev/ttyUSB0, usb:0403:6001); without a link, only the interactive shell starts (on the built-in simulated module)')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial bit rate (8N1)')
            [CompletionResult]::new('--tcp', '--tcp', [CompletionResultType]::ParameterName, 'TCP address of the module or of a serial server (HOST:PORT)')
            [CompletionResult]::new('--can', '--can', [CompletionResultType]::ParameterName, 'CAN adapter of the modules'' bus: slcan:PATH (a serial-line CAN adapter: CANable, USBtin, CANUSB) or socketcan:IFACE (Linux: can0, vcan0). The module''s CAN ID is --module')
            [CompletionResult]::new('--can-bitrate', '--can-bitrate', [CompletionResultType]::ParameterName, 'The CAN bus''s bit rate, set on an slcan adapter (10000 to 1000000; SocketCAN''s is set with `ip link`) [default: 1000000, the modules'' default]')
            [CompletionResult]::new('--can-reply-id', '--can-reply-id', [CompletionResultType]::ParameterName, 'The CAN ID the modules send their replies to (the modules'' reply ID setting)')
            [CompletionResult]::new('--dtr', '--dtr', [CompletionResultType]::ParameterName, 'DTR on opening the port: on, off, or keep (as found, and left so on closing: a board that resets on DTR is not reset by tmclsh starting or ending)')
            [CompletionResult]::new('--rts', '--rts', [CompletionResultType]::ParameterName, 'RTS on opening the port: on, off, or keep (as for --dtr)')
            [CompletionResult]::new('--rs485-delay', '--rs485-delay', [CompletionResultType]::ParameterName, 'RTS raised MS milliseconds before sending and held MS after (BEFORE,AFTER to give them apart); implies --rs485')
            [CompletionResult]::new('--protocol', '--protocol', [CompletionResultType]::ParameterName, 'The protocol the module speaks (also selects the built-in simulated module)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile instead of the TMCM-142''s: a built-in name, alias or module number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) or a TOML file (schema in docs/profiles.md)')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--module', '--module', [CompletionResultType]::ParameterName, 'Address of the target module (1 = address character A)')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Milliseconds to wait for a reply before giving up (exit code 3)')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Append every byte sent and received, timestamped and decoded, to FILE; given a directory (or a path ending in /), write a new file there named by device and date')
            [CompletionResult]::new('--local-echo', '--local-echo', [CompletionResultType]::ParameterName, 'Whether the adapter hands back every byte sent (a 2-wire RS-485 converter without echo suppression): on strips exactly those bytes from what comes back, comparing them; auto (the default) finds out at open and says so; off never strips')
            [CompletionResult]::new('--reconnect', '--reconnect', [CompletionResultType]::ParameterName, 'Wait up to WAIT (30s, 2m; a bare number is ms) for a lost link to come back instead of ending the run with exit 3 (`-c`, piped lines, `run`, the subcommands; the REPL always waits): the port is found again by the name given (a symlink or usb: name follows an adapter plugged back under another device name); an interrupted read is sent again, a motion or write never')
            [CompletionResult]::new('--echo', '--echo', [CompletionResultType]::ParameterName, 'Set the target module''s echo on opening: char, line (every reply attributed to its request) or none (global parameter 67 in RAM; it stays after tmclsh ends)')
            [CompletionResult]::new('--address', '--address', [CompletionResultType]::ParameterName, 'SMD4: send requests with the @N address prefix (0 broadcasts and gets no replies)')
            [CompletionResult]::new('--quiet-gap', '--quiet-gap', [CompletionResultType]::ParameterName, 'SMD4: milliseconds of silence that end a multi-line reply (SYS:FLAGSV, COMS:NET:IPCONF have no end marker)')
            [CompletionResult]::new('--sim', '--sim', [CompletionResultType]::ParameterName, 'Talk to the built-in simulated module: the explicit choice a command run without a terminal needs, so that no script passes against the simulator by accident')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction: RTS high while tmclsh sends, low to receive (the driver''s RS-485 mode where it has one, else tmclsh raises RTS around each write and waits until it has left)')
            [CompletionResult]::new('--keep-latency', '--keep-latency', [CompletionResultType]::ParameterName, 'Leave an FTDI adapter''s latency timer as it is (tmclsh otherwise sets the low-latency flag, which lowers a 16 ms timer to 1 ms where the driver honours it)')
            [CompletionResult]::new('--no-validate', '--no-validate', [CompletionResultType]::ParameterName, 'Send lines the validator would refuse (still canonicalised where they parse)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Say on stderr which module answered and the profile used (TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in))')
            [CompletionResult]::new('--no-enter', '--no-enter', [CompletionResultType]::ParameterName, 'Do not send the enter-ASCII-mode frame (the module is already in ASCII mode)')
            [CompletionResult]::new('--stay-ascii', '--stay-ascii', [CompletionResultType]::ParameterName, 'Leave the modules in ASCII mode on exit instead of restoring the mode they were found in')
            [CompletionResult]::new('--binary', '--binary', [CompletionResultType]::ParameterName, 'Talk to the modules in binary direct mode (typed lines go out as binary frames), whether or not they have the ASCII interface')
            [CompletionResult]::new('--prefix-comma', '--prefix-comma', [CompletionResultType]::ParameterName, 'SMD4: put a comma after the address prefix (@3,MOTOR:STOP) instead of the manual''s @3MOTOR:STOP')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'Print one JSON document instead (fields in docs/machine-output.md)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;help' {
            [CompletionResult]::new('params', 'params', [CompletionResultType]::ParameterValue, 'Print the module''s axis and global parameters (those matching FILTER)')
            [CompletionResult]::new('profiles', 'profiles', [CompletionResultType]::ParameterValue, 'List the built-in TMCL module profiles with their sources, or show one in full')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports of this machine (--probe: and what module answers on each)')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the manual page (roff; man/tmclsh.1 in the source)')
            [CompletionResult]::new('run', 'run', [CompletionResultType]::ParameterValue, 'Run a Rhai script against the module (exit code: 0 passed, 1 failed, 2 refused, 3 link)')
            [CompletionResult]::new('asm', 'asm', [CompletionResultType]::ParameterValue, 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)')
            [CompletionResult]::new('disasm', 'disasm', [CompletionResultType]::ParameterValue, 'Turn a program file back into TMCL source')
            [CompletionResult]::new('download', 'download', [CompletionResultType]::ParameterValue, 'Store a program (source or program file) in the module, verify it, optionally run it')
            [CompletionResult]::new('upload', 'upload', [CompletionResultType]::ParameterValue, 'Read the stored program back and print it as source (or write FILE.tmc / FILE.bin)')
            [CompletionResult]::new('snapshot', 'snapshot', [CompletionResultType]::ParameterValue, 'Save the module''s parameters to a TOML file, compare with one, or write one back')
            [CompletionResult]::new('scan', 'scan', [CompletionResultType]::ParameterValue, 'Find the modules on the bus, with firmware versions and echo settings')
            [CompletionResult]::new('transcript', 'transcript', [CompletionResultType]::ParameterValue, 'Turn a --log transcript into a replayable Rhai script')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin')
            [CompletionResult]::new('config', 'config', [CompletionResultType]::ParameterValue, 'Show the settings in effect (port, baud, protocol, …) and where each comes from: the command line, the environment, tmclsh.toml, the user''s config.toml, or built in')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;help;params' {
            break
        }
        'tmclsh;help;profiles' {
            break
        }
        'tmclsh;help;ports' {
            break
        }
        'tmclsh;help;completions' {
            break
        }
        'tmclsh;help;man' {
            break
        }
        'tmclsh;help;run' {
            break
        }
        'tmclsh;help;asm' {
            break
        }
        'tmclsh;help;disasm' {
            break
        }
        'tmclsh;help;download' {
            break
        }
        'tmclsh;help;upload' {
            break
        }
        'tmclsh;help;snapshot' {
            [CompletionResult]::new('save', 'save', [CompletionResultType]::ParameterValue, 'Read every readable parameter into FILE (TOML, keyed by parameter name)')
            [CompletionResult]::new('diff', 'diff', [CompletionResultType]::ParameterValue, 'Show the settings that differ between FILE and the module, or between FILE and FILE2 (exit code 1 when they differ)')
            [CompletionResult]::new('restore', 'restore', [CompletionResultType]::ParameterValue, 'Write FILE''s settings back (unit mode and limits first; SMD4: resolution, currents and frequencies first, the mode last, only while the motor stands still), verifying each by reading it back; read-only, live and link settings are skipped and listed')
            break
        }
        'tmclsh;help;snapshot;save' {
            break
        }
        'tmclsh;help;snapshot;diff' {
            break
        }
        'tmclsh;help;snapshot;restore' {
            break
        }
        'tmclsh;help;scan' {
            break
        }
        'tmclsh;help;transcript' {
            [CompletionResult]::new('to-rhai', 'to-rhai', [CompletionResultType]::ParameterValue, 'Write a Rhai script replaying the commands of LOG, with assert_eq on the values received')
            break
        }
        'tmclsh;help;transcript;to-rhai' {
            break
        }
        'tmclsh;help;sim' {
            break
        }
        'tmclsh;help;config' {
            break
        }
        'tmclsh;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
