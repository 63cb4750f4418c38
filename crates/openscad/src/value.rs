//! Values (numbers, booleans, strings, vectors) and argument lists.

use std::collections::VecDeque;

use csgpix_scene::error::{CsgError, Rule};
use csgpix_scene::Error;

use crate::{consts_::*, lex::*, linalg::*};

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Kind {
    Num(f64),
    Bool(bool),
    Undef,
    Str(String),
    List(Vec<Value>),
}

/// A value and where it starts.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Value {
    pub(crate) kind: Kind,
    pub(crate) pos: Pos,
}

impl Value {
    pub(crate) fn number(&self, what: &str) -> Result<f64, Fail> {
        match self.kind {
            Kind::Num(v) => Ok(v),
            _ => fail(self.pos, must(what, Rule::Number)),
        }
    }

    pub(crate) fn list(&self, what: &str) -> Result<&[Value], Fail> {
        match &self.kind {
            Kind::List(items) => Ok(items),
            _ => fail(self.pos, must(what, Rule::Vector)),
        }
    }

    /// A number for both, or `[x, y]` (`scale`, a square's `size`).
    pub(crate) fn pair(&self, what: &str) -> Result<[f64; 2], Fail> {
        match &self.kind {
            Kind::Num(s) => Ok([*s, *s]),
            _ => match self.list(what)? {
                [x, y] => Ok([x.number(what)?, y.number(what)?]),
                _ => fail(self.pos, must(what, Rule::NumberOrXy)),
            },
        }
    }

    pub(crate) fn vec3(&self, what: &str) -> Result<Vec3, Fail> {
        match self.list(what)? {
            [x, y, z] => Ok([x.number(what)?, y.number(what)?, z.number(what)?]),
            _ => fail(self.pos, must(what, Rule::Xyz)),
        }
    }
}

/// One argument of a node: `name = value` or a positional value.
pub(crate) struct Arg {
    pub(crate) name: Option<(String, Pos)>,
    pub(crate) value: Value,
}

/// Tokens with look-ahead, and the values and argument lists made of them.
pub(crate) struct Parser<'a> {
    pub(crate) lexer: Lexer<'a>,
    pub(crate) ahead: VecDeque<Token>,
    /// The byte after the last token taken.
    pub(crate) last_end: usize,
    /// Whether runs of plain numbers are read straight from the text ([`Parser::numbers`]);
    /// the tests turn it off to read them token by token.
    pub(crate) numbers_from_text: bool,
}

impl<'a> Parser<'a> {
    pub(crate) fn new(text: &'a str) -> Self {
        Parser {
            lexer: Lexer::new(text),
            ahead: VecDeque::new(),
            last_end: 0,
            numbers_from_text: true,
        }
    }

    pub(crate) fn peek_nth(&mut self, n: usize) -> Result<&Token, Fail> {
        while self.ahead.len() <= n {
            let token = self.lexer.next_token()?;
            self.ahead.push_back(token);
        }
        Ok(&self.ahead[n])
    }

    pub(crate) fn peek(&mut self) -> Result<&Token, Fail> {
        self.peek_nth(0)
    }

    pub(crate) fn next(&mut self) -> Result<Token, Fail> {
        let token = match self.ahead.pop_front() {
            Some(token) => token,
            None => self.lexer.next_token()?,
        };
        self.last_end = token.span.1;
        Ok(token)
    }

    pub(crate) fn at_sym(&mut self, c: u8) -> Result<bool, Fail> {
        Ok(self.peek()?.tok == Tok::Sym(c))
    }

    /// Consumes the symbol `c` if it comes next; returns its position.
    pub(crate) fn eat_sym(&mut self, c: u8) -> Result<Option<Pos>, Fail> {
        if self.at_sym(c)? {
            Ok(Some(self.next()?.pos))
        } else {
            Ok(None)
        }
    }

    pub(crate) fn expect_sym(&mut self, c: u8, context: &str) -> Result<Pos, Fail> {
        let token = self.next()?;
        if token.tok == Tok::Sym(c) {
            Ok(token.pos)
        } else {
            let expected = format!("'{}' {context}", c as char);
            fail(token.pos, expected_found(expected, &token.tok))
        }
    }

    /// `( [name =] value, … )`
    pub(crate) fn args(&mut self, node: &str) -> Result<Vec<Arg>, Fail> {
        self.expect_sym(b'(', &format!("after `{node}`"))?;
        let mut args = Vec::new();
        loop {
            if self.eat_sym(b')')?.is_some() {
                return Ok(args);
            }
            let name = self.arg_name()?;
            let value = self.value()?;
            args.push(Arg { name, value });
            let token = self.next()?;
            match token.tok {
                Tok::Sym(b',') => {}
                Tok::Sym(b')') => return Ok(args),
                other => {
                    let expected = format!("',' or ')' in the arguments of `{node}`");
                    return fail(token.pos, expected_found(expected, &other));
                }
            }
        }
    }

    /// The `name =` of a named argument, if the next two tokens are one.
    pub(crate) fn arg_name(&mut self) -> Result<Option<(String, Pos)>, Fail> {
        let Tok::Ident(name) = &self.peek()?.tok else {
            return Ok(None);
        };
        let name = name.clone();
        if self.peek_nth(1)?.tok != Tok::Sym(b'=') {
            return Ok(None);
        }
        let pos = self.next()?.pos;
        self.next()?;
        Ok(Some((name, pos)))
    }

    /// A value, vectors included; nested vectors are read with an explicit stack. Runs of
    /// plain numbers in a vector are read straight from the text ([`Parser::numbers`]).
    pub(crate) fn value(&mut self) -> Result<Value, Fail> {
        let mut open: Vec<(Pos, Vec<Value>)> = Vec::new();
        loop {
            let token = self.next()?;
            if token.tok == Tok::Sym(b'[') {
                let mut items = Vec::new();
                let read = self.numbers(&mut items);
                if read > 0 || !self.at_sym(b']')? {
                    open_vector(&mut open, token.pos, items)?;
                    if read > 0 {
                        if let Some(value) = self.separators(&mut open)? {
                            return Ok(value);
                        }
                    }
                    continue;
                }
            }
            let element = self.scalar_or_empty(token)?;
            if let Some(value) = self.attach(&mut open, element)? {
                return Ok(value);
            }
        }
    }

    /// Adds a finished element to the innermost open vector and reads what follows it
    /// ([`Parser::separators`]); returns the whole value once nothing is left open.
    pub(crate) fn attach(
        &mut self,
        open: &mut Vec<(Pos, Vec<Value>)>,
        done: Value,
    ) -> Result<Option<Value>, Fail> {
        match open.last_mut() {
            None => Ok(Some(done)),
            Some((_, items)) => {
                items.push(done);
                self.separators(open)
            }
        }
    }

    /// After an element of the innermost open vector: the `,` or `]` that follows, and the
    /// runs of numbers after a `,`, closing the vectors that end (each an element of the one
    /// around it); the whole value once nothing is left open, None where an element that is
    /// not a plain number comes next.
    fn separators(&mut self, open: &mut Vec<(Pos, Vec<Value>)>) -> Result<Option<Value>, Fail> {
        loop {
            let sym = match self.take_sym(b",]") {
                Some(sym) => sym,
                None => {
                    let token = self.next()?;
                    match token.tok {
                        Tok::Sym(c @ (b',' | b']')) => c,
                        other => {
                            let expected = "',' or ']' in a vector";
                            return fail(token.pos, expected_found(expected, &other));
                        }
                    }
                }
            };
            let closed = match sym {
                b',' => {
                    if let Some((_, items)) = open.last_mut() {
                        if self.numbers(items) > 0 {
                            continue;
                        }
                    }
                    if let Some((pos, items)) = self.vector_of_numbers() {
                        open_vector(open, pos, items)?;
                        continue;
                    }
                    self.take_sym(b"]").is_some() || self.eat_sym(b']')?.is_some()
                }
                _ => true,
            };
            if !closed {
                return Ok(None);
            }
            let Some((pos, items)) = open.pop() else {
                return Ok(None);
            };
            let done = Value {
                kind: Kind::List(items),
                pos,
            };
            match open.last_mut() {
                None => return Ok(Some(done)),
                Some((_, outer)) => outer.push(done),
            }
        }
    }

    /// Whether the next item may be read straight from the text: no token has been looked at
    /// ahead (the lexer stands where the parser does) and the tests have not turned it off.
    fn reads_straight(&self) -> bool {
        self.ahead.is_empty() && self.numbers_from_text
    }

    /// The next token, taken, when it is one of the symbols `set` and no token has been
    /// looked at ahead: as [`Parser::next`] would take it, without making the token.
    fn take_sym(&mut self, set: &[u8]) -> Option<u8> {
        if !self.reads_straight() {
            return None;
        }
        let (sym, _) = self.lexer.sym_among(set)?;
        self.last_end = self.lexer.at;
        Some(sym)
    }

    /// A `[` and the plain numbers after it ([`Parser::numbers`], at least one), taken when
    /// no token has been looked at ahead; the `[`'s position and the numbers. Nothing is
    /// taken otherwise.
    fn vector_of_numbers(&mut self) -> Option<(Pos, Vec<Value>)> {
        if !self.reads_straight() {
            return None;
        }
        let before = (self.lexer.at, self.lexer.pos);
        let (_, pos) = self.lexer.sym_among(b"[")?;
        let mut items = Vec::new();
        if self.numbers(&mut items) == 0 {
            (self.lexer.at, self.lexer.pos) = before;
            return None;
        }
        Some((pos, items))
    }

    /// Reads into `items` the plain numbers that come next (each perhaps after a `-`), with
    /// the commas between them, when no token has been looked at ahead; stops after a number
    /// (the token after it is left unread) or where anything else comes. Each value is the
    /// one the tokens would make ([`Parser::scalar_or_empty`]), at the same position: a
    /// polyhedron's points and faces are most of a large `.csg`, and this skips a token and
    /// its look-ahead per number. Returns how many were read.
    fn numbers(&mut self, items: &mut Vec<Value>) -> usize {
        if !self.reads_straight() {
            return 0;
        }
        let before = items.len();
        self.lexer.numbers(|v, pos| {
            let kind = Kind::Num(v);
            items.push(Value { kind, pos })
        });
        let read = items.len() - before;
        if read > 0 {
            self.last_end = self.lexer.at;
        }
        read
    }

    /// A number, boolean, `undef`, string or `[]`, starting with `token`.
    pub(crate) fn scalar_or_empty(&mut self, token: Token) -> Result<Value, Fail> {
        let pos = token.pos;
        let kind = match token.tok {
            Tok::Num(v) => Kind::Num(v),
            Tok::Str(s) => Kind::Str(s),
            Tok::Sym(b'[') => {
                self.next()?; // the ']'
                Kind::List(Vec::new())
            }
            Tok::Sym(sign @ (b'-' | b'+')) => {
                let token = self.next()?;
                let v = match &token.tok {
                    Tok::Num(v) => Some(*v),
                    Tok::Ident(name) => non_finite(name),
                    _ => None,
                };
                match token.tok {
                    _ if v.is_some() && sign == b'-' => Kind::Num(-v.unwrap_or_default()),
                    _ if v.is_some() => Kind::Num(v.unwrap_or_default()),
                    other => {
                        let expected = format!("a number after '{}'", sign as char);
                        return fail(token.pos, expected_found(expected, &other));
                    }
                }
            }
            Tok::Ident(name) => match name.as_str() {
                "true" => Kind::Bool(true),
                "false" => Kind::Bool(false),
                "undef" => Kind::Undef,
                "inf" | "nan" => Kind::Num(non_finite(name.as_str()).unwrap_or(f64::NAN)),
                _ => return fail(pos, CsgError::NotAValue { name }),
            },
            other => return fail(pos, expected_found("a value", &other)),
        };
        Ok(Value { kind, pos })
    }
}

// ---------------------------------------------------------------------------------------------

/// A vector opened at `pos` with its first `items`, inside those `open`; an error when that
/// nests vectors deeper than [`MAX_VECTOR_NESTING`].
fn open_vector(open: &mut Vec<(Pos, Vec<Value>)>, pos: Pos, items: Vec<Value>) -> Result<(), Fail> {
    if open.len() >= MAX_VECTOR_NESTING {
        let problem = CsgError::NestedTooDeep {
            what: "vectors",
            limit: MAX_VECTOR_NESTING,
        };
        return fail(pos, problem);
    }
    open.push((pos, items));
    Ok(())
}

/// `what must rule`.
pub(crate) fn must(what: &str, rule: Rule) -> CsgError {
    CsgError::Must {
        what: what.to_string(),
        rule,
    }
}

/// `expected EXPECTED, found` the token.
pub(crate) fn expected_found(expected: impl Into<String>, found: &Tok) -> Error {
    Error::Expected {
        expected: expected.into(),
        found: found.describe(),
    }
}

/// `inf` and `nan` as OpenSCAD's CSG export writes an infinite or undefined number (its
/// `Value::toString` of a double): the nodes that take them decide, as OpenSCAD does, what
/// such a number makes (mostly an empty object with a warning).
fn non_finite(name: &str) -> Option<f64> {
    match name {
        "inf" => Some(f64::INFINITY),
        "nan" => Some(f64::NAN),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// What reading a value gives: the value, or the error and where; then where the reading
    /// left off (the last token's end and the next token).
    fn read(text: &str, from_text: bool) -> String {
        let mut p = Parser::new(text);
        p.numbers_from_text = from_text;
        let value = match p.value() {
            Ok(v) => format!("{v:?}"),
            Err(e) => return format!("{} at {}", e.problem, e.pos),
        };
        let end = p.last_end;
        let next = match p.next() {
            Ok(t) => format!("{:?} at {}", t.tok, t.pos),
            Err(e) => format!("{} at {}", e.problem, e.pos),
        };
        format!("{value}; last end {end}; next {next}")
    }

    /// White space and comments between tokens.
    fn trivia() -> impl Strategy<Value = String> {
        prop_oneof![
            4 => Just(String::new()),
            4 => Just(" ".to_string()),
            1 => Just("\n  ".to_string()),
            1 => Just("/* c */".to_string()),
            1 => Just("// x\n".to_string()),
            1 => Just("\t\r\n".to_string()),
        ]
    }

    fn number() -> impl Strategy<Value = String> {
        prop_oneof![
            (-1e6f64..1e6).prop_map(|v| format!("{v}")),
            (-1e-3f64..1e-3).prop_map(|v| format!("{v:e}")),
            (0u32..1000).prop_map(|v| format!("{v}")),
            Just(".5".to_string()),
            Just("5.".to_string()),
            Just("- 3".to_string()),
            Just("+2".to_string()),
            Just("-inf".to_string()),
            Just("1e400".to_string()),
            Just("2.5E+10".to_string()),
            Just("1.2.3".to_string()),
            Just("7x".to_string()),
            Just("true".to_string()),
            Just("\"s\"".to_string()),
        ]
    }

    /// Nested vectors of numbers (and now and then something else), trailing commas and
    /// trivia included.
    fn value_text() -> impl Strategy<Value = String> {
        let leaf = (trivia(), number()).prop_map(|(t, n)| format!("{t}{n}"));
        leaf.prop_recursive(5, 200, 8, |inner| {
            (
                proptest::collection::vec((inner, trivia()), 0..8),
                any::<bool>(),
                trivia(),
            )
                .prop_map(|(items, trailing, t)| {
                    let body: Vec<String> = items.iter().map(|(v, t)| format!("{v}{t}")).collect();
                    let comma = if trailing && !body.is_empty() {
                        ","
                    } else {
                        ""
                    };
                    format!("{t}[{}{comma}]", body.join(","))
                })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(600))]

        /// Numbers read straight from the text give the values, positions, errors and the
        /// place reading left off that reading every token gives, also in damaged text.
        #[test]
        fn numbers_from_the_text_are_those_of_the_tokens(
            text in value_text(),
            cut in any::<proptest::sample::Index>(),
            damage in proptest::sample::select(vec!["", "]", ",", "[", ";", "-", "/*", "é", ")"]),
            tail in proptest::sample::select(vec!["", ";", ")", ", 5", "]"]),
        ) {
            let at = cut.index(text.len() + 1);
            let at = (0..=at).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
            let damaged = format!("{}{damage}{}{tail}", &text[..at], &text[at..]);
            prop_assert_eq!(read(&damaged, true), read(&damaged, false), "{}", damaged);
        }
    }
}
