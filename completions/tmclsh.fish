# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_tmclsh_global_optspecs
    string join \n profile= h/help V/version
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

complete -c tmclsh -n "__fish_tmclsh_needs_command" -l profile -d 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables' -r -F
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -s V -l version -d 'Print version'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "params" -d 'Print the module\'s axis and global parameters (those matching FILTER)'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "ports" -d 'List the serial ports of this machine'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "completions" -d 'Print a shell completion script'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "sim" -d 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
complete -c tmclsh -n "__fish_tmclsh_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -l profile -d 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand params" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -l profile -d 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand ports" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand completions" -l profile -d 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand completions" -s h -l help -d 'Print help'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l listen -d 'Serve on TCP at ADDR (HOST:PORT, loopback unless said otherwise; port 0 picks a free one); the bound address is the first line printed' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l modules -d 'Module addresses on the simulated RS-485 bus' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l baud -d 'Pace bytes like a serial line at N baud (10 bits per byte, both directions)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l state -d 'Keep the simulated EEPROM (stored parameters, programs) in FILE across restarts' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l left-switch -d 'Position of the left limit switch (microsteps); not connected by default' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l right-switch -d 'Position of the right limit switch' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l home-switch -d 'Position of the reference (home) switch, active at and right of it' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l reply-end -d 'Ending of ASCII replies: none, cr, lf or crlf' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l echo-end -d 'What follows an echoed line: none, cr, lf or crlf (stands for the typed CR in character echo mode)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l backspace-echo -d 'Echo of a backspace in character echo mode: erase (BS SP BS) or plain (BS)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l drop-rate -d 'Drop replies with this probability (0..1)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l corrupt-rate -d 'Corrupt one byte of a reply with this probability' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l delay-rate -d 'Delay replies with this probability, by --delay-ms' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l delay-ms -d 'How long a delayed reply is held back' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l silent-after -d 'Answer nothing after N replies (commands still execute)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l hangup-after -d 'Hang up after N replies (pty: a new one appears, its path printed; TCP: the connection closes and the next client is served)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l fault-seed -d 'Seed of the fault decisions (same seed, same faults)' -r
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l profile -d 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables' -r -F
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l pty -d 'Serve on a new pseudo-terminal (the default); its path is the first line printed'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -s v -l verbose -d 'Log every frame and line received and sent, decoded, to stderr'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l manual-clock -d 'Let simulation time pass only on the console command `advance` (deterministic tests)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-reply-to-139 -d 'Switch to ASCII mode on command 139 without a binary reply'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -l no-reply-to-bin -d 'Switch back to binary mode on BIN without an ASCII reply'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand sim" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params ports completions sim help" -f -a "params" -d 'Print the module\'s axis and global parameters (those matching FILTER)'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params ports completions sim help" -f -a "ports" -d 'List the serial ports of this machine'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params ports completions sim help" -f -a "completions" -d 'Print a shell completion script'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params ports completions sim help" -f -a "sim" -d 'Serve the simulated module on a pseudo-terminal or TCP, with a control console on stdin'
complete -c tmclsh -n "__fish_tmclsh_using_subcommand help; and not __fish_seen_subcommand_from params ports completions sim help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
