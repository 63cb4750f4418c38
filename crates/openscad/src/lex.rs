//! Tokens of the `.csg` text: numbers, names, strings, symbols, with 1-based positions.

use csgpix_scene::CsgError;
use std::fmt;

// ---------------------------------------------------------------------------------------------
// Tokens

/// A 1-based line and column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Pos {
    pub(crate) line: usize,
    pub(crate) col: usize,
}

impl fmt::Display for Pos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.col)
    }
}

/// An error before the file name is attached.
#[derive(Debug)]
pub(crate) struct Fail {
    pub(crate) pos: Pos,
    pub(crate) problem: csgpix_scene::Error,
}

/// `problem` at `pos`.
pub(crate) fn fail<T>(pos: Pos, problem: impl Into<csgpix_scene::Error>) -> Result<T, Fail> {
    Err(Fail {
        pos,
        problem: problem.into(),
    })
}

#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Tok {
    Ident(String),
    Num(f64),
    Str(String),
    /// One of `( ) [ ] { } , ; = - + % # ! *`.
    Sym(u8),
    Eof,
}

impl Tok {
    pub(crate) fn describe(&self) -> String {
        match self {
            Tok::Ident(name) => format!("`{name}`"),
            Tok::Num(_) => "a number".to_string(),
            Tok::Str(_) => "a string".to_string(),
            Tok::Sym(c) => format!("'{}'", *c as char),
            Tok::Eof => "end of file".to_string(),
        }
    }
}

#[derive(Clone, Debug)]
pub(crate) struct Token {
    pub(crate) tok: Tok,
    pub(crate) pos: Pos,
    /// Byte offsets of the token in the text: its first byte and the one after its last.
    pub(crate) span: (usize, usize),
}

/// Splits the text into tokens, skipping white space and comments.
pub(crate) struct Lexer<'a> {
    pub(crate) text: &'a str,
    pub(crate) at: usize,
    pub(crate) pos: Pos,
}

impl<'a> Lexer<'a> {
    pub(crate) fn new(text: &'a str) -> Self {
        let at = if text.starts_with('\u{feff}') { 3 } else { 0 };
        Lexer {
            text,
            at,
            pos: Pos { line: 1, col: 1 },
        }
    }

    pub(crate) fn byte(&self, ahead: usize) -> Option<u8> {
        self.text.as_bytes().get(self.at + ahead).copied()
    }

    /// Moves past one byte; columns count characters, not UTF-8 continuation bytes.
    pub(crate) fn bump(&mut self) {
        if let Some(b) = self.byte(0) {
            self.at += 1;
            if b == b'\n' {
                self.pos.line += 1;
                self.pos.col = 1;
            } else if b & 0xC0 != 0x80 {
                self.pos.col += 1;
            }
        }
    }

    pub(crate) fn bump_while(&mut self, pred: impl Fn(u8) -> bool) -> usize {
        let start = self.at;
        while self.byte(0).is_some_and(&pred) {
            self.bump();
        }
        self.at - start
    }

    pub(crate) fn next_token(&mut self) -> Result<Token, Fail> {
        self.skip_trivia()?;
        let pos = self.pos;
        let start = self.at;
        let tok = match self.byte(0) {
            None => Tok::Eof,
            Some(b) if b.is_ascii_alphabetic() || b == b'_' || b == b'$' => self.ident(),
            Some(_) if number_starts(self.text.as_bytes(), self.at) => self.number(pos)?,
            Some(b'"') => self.string(pos)?,
            Some(b) if b"()[]{},;=-+%#!*".contains(&b) => {
                self.bump();
                Tok::Sym(b)
            }
            Some(_) => {
                let c = self.text.get(self.at..).and_then(|s| s.chars().next());
                let found = c.unwrap_or('?');
                return fail(pos, CsgError::UnexpectedCharacter { found });
            }
        };
        Ok(Token {
            tok,
            pos,
            span: (start, self.at),
        })
    }

    pub(crate) fn skip_trivia(&mut self) -> Result<(), Fail> {
        loop {
            match (self.byte(0), self.byte(1)) {
                (Some(b' ' | b'\t' | b'\r' | b'\n' | 0x0c), _) => self.bump(),
                (Some(b'/'), Some(b'/')) => {
                    self.bump_while(|b| b != b'\n');
                }
                (Some(b'/'), Some(b'*')) => self.block_comment()?,
                _ => return Ok(()),
            }
        }
    }

    pub(crate) fn block_comment(&mut self) -> Result<(), Fail> {
        let start = self.pos;
        self.bump();
        self.bump();
        loop {
            match (self.byte(0), self.byte(1)) {
                (Some(b'*'), Some(b'/')) => {
                    self.bump();
                    self.bump();
                    return Ok(());
                }
                (Some(_), _) => self.bump(),
                (None, _) => return fail(start, CsgError::Unterminated { comment: true }),
            }
        }
    }

    /// The next token, taken, with its position, when it is one of the symbols `set`; else
    /// the lexer is left before it (past the white space and comments before it, which
    /// [`Lexer::next_token`] would skip the same).
    pub(crate) fn sym_among(&mut self, set: &[u8]) -> Option<(u8, Pos)> {
        let (at, pos) = (self.at, self.pos);
        if self.skip_trivia().is_err() {
            (self.at, self.pos) = (at, pos);
            return None;
        }
        let b = self.byte(0).filter(|b| set.contains(b))?;
        let pos = self.pos;
        self.bump();
        Some((b, pos))
    }

    /// Numbers, each perhaps right after a `-`, separated by commas (white space and
    /// comments around them), each given to `number` with where it starts, as the tokens `-`
    /// and a number make it; the lexer is left just after the last one read, or where it was
    /// when none is. A number whose text is bad is left for [`Lexer::next_token`] to refuse.
    pub(crate) fn numbers(&mut self, mut number: impl FnMut(f64, Pos)) {
        let mut after = (self.at, self.pos);
        while self.skip_trivia().is_ok() {
            let (start, pos) = (self.at, self.pos);
            let bytes = self.text.as_bytes();
            let negative = bytes.get(start) == Some(&b'-');
            if !number_starts(bytes, start + negative as usize) {
                break;
            }
            if negative {
                self.bump();
            }
            let Ok(Tok::Num(v)) = self.number(self.pos) else {
                break;
            };
            number(if negative { -v } else { v }, pos);
            after = (self.at, self.pos);
            if self.skip_trivia().is_err() || self.byte(0) != Some(b',') {
                break;
            }
            self.bump();
        }
        (self.at, self.pos) = after;
    }

    pub(crate) fn ident(&mut self) -> Tok {
        let start = self.at;
        self.bump();
        self.bump_while(|b| b.is_ascii_alphanumeric() || b == b'_');
        Tok::Ident(self.text[start..self.at].to_string())
    }

    /// `12`, `-` is a separate token, `1.5`, `.5`, `5.`, `1e-3`, `2.5E+10`.
    pub(crate) fn number(&mut self, pos: Pos) -> Result<Tok, Fail> {
        let start = self.at;
        self.bump_while(|b| b.is_ascii_digit());
        if self.byte(0) == Some(b'.') {
            self.bump();
            self.bump_while(|b| b.is_ascii_digit());
        }
        if matches!(self.byte(0), Some(b'e' | b'E')) {
            self.bump();
            if matches!(self.byte(0), Some(b'+' | b'-')) {
                self.bump();
            }
            if self.bump_while(|b| b.is_ascii_digit()) == 0 {
                return self.bad_number(start, pos);
            }
        }
        if self.byte(0).is_some_and(continues_number) {
            return self.bad_number(start, pos);
        }
        let text = &self.text[start..self.at];
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Tok::Num(v)),
            Ok(_) => fail(pos, bad_number(text, true)),
            Err(_) => self.bad_number(start, pos),
        }
    }

    pub(crate) fn bad_number(&mut self, start: usize, pos: Pos) -> Result<Tok, Fail> {
        self.bump_while(continues_number);
        fail(pos, bad_number(&self.text[start..self.at], false))
    }

    pub(crate) fn string(&mut self, pos: Pos) -> Result<Tok, Fail> {
        self.bump();
        let mut bytes = Vec::new();
        loop {
            let Some(b) = self.byte(0) else {
                return fail(pos, CsgError::Unterminated { comment: false });
            };
            self.bump();
            match b {
                b'"' => return Ok(Tok::Str(String::from_utf8_lossy(&bytes).into_owned())),
                b'\\' => {
                    let escaped = self.byte(0).unwrap_or(b'\\');
                    self.bump();
                    bytes.push(match escaped {
                        b'n' => b'\n',
                        b't' => b'\t',
                        b'r' => b'\r',
                        other => other,
                    });
                }
                other => bytes.push(other),
            }
        }
    }
}

/// A number token that does not parse, or parses to an infinity (`out_of_range`).
fn bad_number(text: &str, out_of_range: bool) -> CsgError {
    CsgError::BadNumber {
        text: text.to_string(),
        out_of_range,
    }
}

/// Whether a number token starts at `at`: a digit, or a `.` followed by a digit (`.5`).
fn number_starts(bytes: &[u8], at: usize) -> bool {
    match bytes.get(at) {
        Some(b) if b.is_ascii_digit() => true,
        Some(b'.') => bytes.get(at + 1).is_some_and(u8::is_ascii_digit),
        _ => false,
    }
}

pub(crate) fn continues_number(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'_' | b'.' | b'$')
}

// ---------------------------------------------------------------------------------------------
// Values and arguments
