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
}

impl<'a> Parser<'a> {
    pub(crate) fn new(text: &'a str) -> Self {
        Parser {
            lexer: Lexer::new(text),
            ahead: VecDeque::new(),
            last_end: 0,
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

    /// A value, vectors included; nested vectors are read with an explicit stack.
    pub(crate) fn value(&mut self) -> Result<Value, Fail> {
        let mut open: Vec<(Pos, Vec<Value>)> = Vec::new();
        loop {
            let token = self.next()?;
            if token.tok == Tok::Sym(b'[') && !self.at_sym(b']')? {
                if open.len() >= MAX_VECTOR_NESTING {
                    let problem = CsgError::NestedTooDeep {
                        what: "vectors",
                        limit: MAX_VECTOR_NESTING,
                    };
                    return fail(token.pos, problem);
                }
                open.push((token.pos, Vec::new()));
                continue;
            }
            let element = self.scalar_or_empty(token)?;
            if let Some(value) = self.attach(&mut open, element)? {
                return Ok(value);
            }
        }
    }

    /// Adds a finished element to the innermost open vector, closing the vectors that end after
    /// it; returns the whole value once nothing is left open.
    pub(crate) fn attach(
        &mut self,
        open: &mut Vec<(Pos, Vec<Value>)>,
        mut done: Value,
    ) -> Result<Option<Value>, Fail> {
        while let Some((pos, mut items)) = open.pop() {
            items.push(done);
            let token = self.next()?;
            let closed = match token.tok {
                Tok::Sym(b',') => self.eat_sym(b']')?.is_some(),
                Tok::Sym(b']') => true,
                other => {
                    let expected = "',' or ']' in a vector";
                    return fail(token.pos, expected_found(expected, &other));
                }
            };
            if !closed {
                open.push((pos, items));
                return Ok(None);
            }
            done = Value {
                kind: Kind::List(items),
                pos,
            };
        }
        Ok(Some(done))
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
