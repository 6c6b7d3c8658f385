use super::super::error::Diagnostics;
use super::super::lex::tokenize;
use super::*;

fn parse(text: &str) -> Result<ParsedLine, SyntaxError> {
    let mut diags = Diagnostics::new("t.tmc");
    let lines = tokenize(text, &mut diags);
    assert!(diags.finish().is_ok(), "lexes: {text}");
    parse_line(1, &lines[0].1)
}

fn name(name: &str, column: usize) -> Expr {
    Expr::Name {
        name: name.into(),
        column,
    }
}

fn number(value: i64) -> Expr {
    Expr::Number { value, hex: false }
}

#[test]
fn labels_then_an_instruction_with_its_operands() {
    let line = parse("A: B : MVP ABS, 0, 5").unwrap();
    assert_eq!(line.labels, [("A".to_string(), 1), ("B".to_string(), 4)]);
    let Body::Instruction(statement) = line.body else {
        panic!("an instruction")
    };
    assert_eq!(statement.head, Head::Mnemonic("MVP".into()));
    assert_eq!(statement.at, Position { line: 1, column: 8 });
    let columns: Vec<usize> = statement.operands.iter().map(|o| o.column).collect();
    assert_eq!(columns, [12, 17, 20]);
    assert_eq!(statement.operands[0].expr, name("ABS", 12));
}

#[test]
fn constants_in_both_spellings() {
    for text in ["Speed = 10", "#define Speed 10", "# DEFINE Speed 10"] {
        let Body::Constant { name, expr, .. } = parse(text).unwrap().body else {
            panic!("a constant: {text}")
        };
        assert_eq!((name.as_str(), expr), ("Speed", number(10)), "{text}");
    }
}

#[test]
fn expressions_follow_the_usual_precedence() {
    let Body::Constant { expr, .. } = parse("X = 1 + 2 * -(3 - A)").unwrap().body else {
        panic!("a constant")
    };
    let expected = Expr::Binary {
        op: '+',
        left: Box::new(number(1)),
        right: Box::new(Expr::Binary {
            op: '*',
            left: Box::new(number(2)),
            right: Box::new(Expr::Negate {
                inner: Box::new(Expr::Binary {
                    op: '-',
                    left: Box::new(number(3)),
                    right: Box::new(name("A", 19)),
                    column: 17,
                }),
                column: 13,
            }),
            column: 11,
        }),
        column: 7,
    };
    assert_eq!(expr, expected);
}

#[test]
fn a_line_may_be_only_labels_or_a_command_number() {
    let line = parse("End:").unwrap();
    assert_eq!(line.body, Body::Empty);
    let Body::Instruction(statement) = parse("136 1").unwrap().body else {
        panic!("an instruction")
    };
    assert_eq!(statement.head, Head::Number(136));
    assert_eq!(statement.operands.len(), 1);
}

#[test]
fn syntax_errors_point_at_the_problem() {
    let cases = [
        (": MST 0", (1, "label name missing before ':'")),
        ("ROL , 5", (5, "operand missing before ','")),
        ("ROL 0,, 5", (7, "operand missing before ','")),
        ("X = ", (4, "value missing")),
        ("X = 1 2", (7, "unexpected '2' after the value")),
        ("CALC ADD, (1 + 2", (11, "'(' is never closed")),
        ("CALC ADD, (1 + 2 3)", (18, "expected ')', found '3'")),
        ("CALC ADD, 1 +", (14, "value missing after '+'")),
        (
            "CALC ADD, *2",
            (11, "expected a number or a name, found '*'"),
        ),
        ("#define", (2, "#define needs a name and a value")),
        ("#define X", (9, "#define X needs a value")),
        ("# 5", (1, "expected 'define' after '#'")),
        (
            "= 5",
            (1, "expected a command, a label or a constant, found '='"),
        ),
    ];
    for (text, (column, message)) in cases {
        assert_eq!(parse(text), Err((column, message.to_string())), "{text}");
    }
}
