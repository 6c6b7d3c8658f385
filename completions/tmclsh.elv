
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
            cand asm 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
            cand disasm 'Turn a program file back into TMCL source'
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
        &'tmclsh;asm'= {
            cand -o 'Write the program file (format in the README); without it the source is only checked'
            cand --output 'Write the program file (format in the README); without it the source is only checked'
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand --list 'Print the listing: address, the 7 instruction bytes and the source line'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;disasm'= {
            cand --profile 'Module profile (TOML, schema in the README) instead of the built-in TMCM-142 tables'
            cand -h 'Print help'
            cand --help 'Print help'
        }
        &'tmclsh;help'= {
            cand params 'Print the module''s axis and global parameters (those matching FILTER)'
            cand ports 'List the serial ports of this machine'
            cand completions 'Print a shell completion script'
            cand asm 'Assemble a stand-alone TMCL program (check it, list it, write FILE.bin)'
            cand disasm 'Turn a program file back into TMCL source'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'tmclsh;help;params'= {
        }
        &'tmclsh;help;ports'= {
        }
        &'tmclsh;help;completions'= {
        }
        &'tmclsh;help;asm'= {
        }
        &'tmclsh;help;disasm'= {
        }
        &'tmclsh;help;help'= {
        }
    ]
    $completions[$command]
}
