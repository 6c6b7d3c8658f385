
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
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('params', 'params', [CompletionResultType]::ParameterValue, 'Print the module''s axis and global parameters (those matching FILTER)')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports of this machine')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;params' {
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;ports' {
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;completions' {
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            break
        }
        'tmclsh;sim' {
            [CompletionResult]::new('--listen', '--listen', [CompletionResultType]::ParameterName, 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed')
            [CompletionResult]::new('--modules', '--modules', [CompletionResultType]::ParameterName, 'Module addresses on the simulated RS-485 bus')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)')
            [CompletionResult]::new('--state', '--state', [CompletionResultType]::ParameterName, 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts')
            [CompletionResult]::new('--left-switch', '--left-switch', [CompletionResultType]::ParameterName, 'Position of the left limit switch (microsteps); not connected by default')
            [CompletionResult]::new('--right-switch', '--right-switch', [CompletionResultType]::ParameterName, 'Position of the right limit switch')
            [CompletionResult]::new('--home-switch', '--home-switch', [CompletionResultType]::ParameterName, 'Position of the reference (home) switch, active at and right of it')
            [CompletionResult]::new('--reply-end', '--reply-end', [CompletionResultType]::ParameterName, 'Ending of ASCII replies: none, cr, lf or crlf')
            [CompletionResult]::new('--echo-end', '--echo-end', [CompletionResultType]::ParameterName, 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)')
            [CompletionResult]::new('--backspace-echo', '--backspace-echo', [CompletionResultType]::ParameterName, 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)')
            [CompletionResult]::new('--drop-rate', '--drop-rate', [CompletionResultType]::ParameterName, 'Drop replies with this probability (0..1)')
            [CompletionResult]::new('--corrupt-rate', '--corrupt-rate', [CompletionResultType]::ParameterName, 'Corrupt one byte of a reply with this probability')
            [CompletionResult]::new('--delay-rate', '--delay-rate', [CompletionResultType]::ParameterName, 'Delay replies with this probability, by --delay-ms')
            [CompletionResult]::new('--delay-ms', '--delay-ms', [CompletionResultType]::ParameterName, 'How long a delayed reply is held back')
            [CompletionResult]::new('--silent-after', '--silent-after', [CompletionResultType]::ParameterName, 'Answer nothing after N replies (commands still execute)')
            [CompletionResult]::new('--hangup-after', '--hangup-after', [CompletionResultType]::ParameterName, 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)')
            [CompletionResult]::new('--fault-seed', '--fault-seed', [CompletionResultType]::ParameterName, 'Seed of the fault decisions (same seed, same faults)')
            [CompletionResult]::new('--profile', '--profile', [CompletionResultType]::ParameterName, 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables')
            [CompletionResult]::new('--pty', '--pty', [CompletionResultType]::ParameterName, 'Serve on a new pseudo-terminal (the default); its path is the first line printed')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Log every frame and line received and sent, decoded, to stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Log every frame and line received and sent, decoded, to stderr')
            [CompletionResult]::new('--manual-clock', '--manual-clock', [CompletionResultType]::ParameterName, 'Let simulation time pass only on the console command `advance` (deterministic tests)')
            [CompletionResult]::new('--no-reply-to-139', '--no-reply-to-139', [CompletionResultType]::ParameterName, 'Switch to ASCII mode on command 139 without a binary reply')
            [CompletionResult]::new('--no-reply-to-bin', '--no-reply-to-bin', [CompletionResultType]::ParameterName, 'Switch back to binary mode on BIN without an ASCII reply')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            break
        }
        'tmclsh;help' {
            [CompletionResult]::new('params', 'params', [CompletionResultType]::ParameterValue, 'Print the module''s axis and global parameters (those matching FILTER)')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'List the serial ports of this machine')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('sim', 'sim', [CompletionResultType]::ParameterValue, 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'tmclsh;help;params' {
            break
        }
        'tmclsh;help;ports' {
            break
        }
        'tmclsh;help;completions' {
            break
        }
        'tmclsh;help;sim' {
            break
        }
        'tmclsh;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
