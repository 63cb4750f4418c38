//! Clipping functions over named objects (§5.2.1): `A.!B`, with `.` (intersection), `+`
//! (union), `!` (complement) and parentheses; `.` binds tighter than `+`, `!` tightest.
//!
//! The thesis evaluates an expression by drawing each object and clipping it by the rest:
//! @(A.!B) = @(A).!B + @(!B).A. In general the expression is put in sum-of-products form; for
//! every literal of every product the literal's object is drawn (first stage), clipped by the
//! product of the other literals (the clipping stack) and composed into the scene (second
//! stage), so the union of products is the nearest surface at each pixel.

use std::fmt;

/// A parsed clipping function; objects are numbered by their position in the scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Clip {
    Obj(usize),
    Not(Box<Clip>),
    And(Box<Clip>, Box<Clip>),
    Or(Box<Clip>, Box<Clip>),
}

/// A literal: object index and whether it is complemented.
pub type Literal = (usize, bool);

/// Why an expression was refused, with its 1-based column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ClipError {
    pub col: usize,
    pub msg: String,
}

impl fmt::Display for ClipError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.col, self.msg)
    }
}

impl std::error::Error for ClipError {}

/// Nesting deeper than this is refused rather than risking the stack.
pub const MAX_DEPTH: usize = 200;

/// Products in the sum-of-products form beyond this are refused.
pub const MAX_PRODUCTS: usize = 4096;

struct Parser<'a> {
    chars: Vec<(usize, char)>,
    pos: usize,
    names: &'a [String],
    depth: usize,
}

impl Parser<'_> {
    /// The next non-blank character (blanks are skipped for good).
    fn peek(&mut self) -> Option<char> {
        while self
            .chars
            .get(self.pos)
            .is_some_and(|c| c.1.is_whitespace())
        {
            self.pos += 1;
        }
        self.chars.get(self.pos).map(|c| c.1)
    }

    fn col(&self) -> usize {
        self.chars
            .get(self.pos)
            .map_or_else(|| self.chars.last().map_or(1, |c| c.0 + 2), |c| c.0 + 1)
    }

    fn err<T>(&mut self, msg: String) -> Result<T, ClipError> {
        self.peek();
        Err(ClipError {
            col: self.col(),
            msg,
        })
    }

    fn enter(&mut self) -> Result<(), ClipError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return self.err(format!("expression nested deeper than {MAX_DEPTH}"));
        }
        Ok(())
    }

    fn expr(&mut self) -> Result<Clip, ClipError> {
        self.enter()?;
        let mut e = self.term()?;
        while self.peek() == Some('+') {
            self.pos += 1;
            e = Clip::Or(Box::new(e), Box::new(self.term()?));
        }
        self.depth -= 1;
        Ok(e)
    }

    fn term(&mut self) -> Result<Clip, ClipError> {
        let mut e = self.factor()?;
        while self.peek() == Some('.') {
            self.pos += 1;
            e = Clip::And(Box::new(e), Box::new(self.factor()?));
        }
        Ok(e)
    }

    fn factor(&mut self) -> Result<Clip, ClipError> {
        match self.peek() {
            Some('!') => {
                self.pos += 1;
                self.enter()?;
                let f = self.factor()?;
                self.depth -= 1;
                Ok(Clip::Not(Box::new(f)))
            }
            Some('(') => {
                self.pos += 1;
                let e = self.expr()?;
                if self.peek() != Some(')') {
                    return self.err("expected ')'".into());
                }
                self.pos += 1;
                Ok(e)
            }
            Some(c) if c.is_ascii_alphabetic() => self.name(),
            Some(c) => self.err(format!("expected an object name, '!' or '(', found {c:?}")),
            None => self.err("expected an object name, '!' or '(', found the end".into()),
        }
    }

    fn name(&mut self) -> Result<Clip, ClipError> {
        let start = self.pos;
        let word = |c: &(usize, char)| c.1.is_ascii_alphanumeric() || c.1 == '_';
        while self.chars.get(self.pos).is_some_and(word) {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().map(|c| c.1).collect();
        match self.names.iter().position(|n| *n == name) {
            Some(i) => Ok(Clip::Obj(i)),
            None => Err(ClipError {
                col: self.chars[start].0 + 1,
                msg: format!(
                    "unknown object {name:?}; the scene names {}",
                    self.names.join(", ")
                ),
            }),
        }
    }
}

impl Clip {
    /// Parse `text` over the object names `names` (e.g. A, B, …).
    pub fn parse(text: &str, names: &[String]) -> Result<Clip, ClipError> {
        let chars: Vec<(usize, char)> = text.chars().enumerate().collect();
        let mut p = Parser {
            chars,
            pos: 0,
            names,
            depth: 0,
        };
        let e = p.expr()?;
        if let Some(c) = p.peek() {
            return p.err(format!("expected '+', '.' or the end, found {c:?}"));
        }
        Ok(e)
    }

    /// Sum-of-products form: a list of products, each a list of distinct literals; products
    /// that contain a literal and its complement are dropped (they are empty volumes).
    pub fn products(&self) -> Result<Vec<Vec<Literal>>, String> {
        let mut out = self.nnf_products(false)?;
        for p in &mut out {
            p.sort();
            p.dedup();
        }
        out.retain(|p| !p.windows(2).any(|w| w[0].0 == w[1].0));
        out.sort();
        out.dedup();
        Ok(out)
    }

    fn nnf_products(&self, neg: bool) -> Result<Vec<Vec<Literal>>, String> {
        let (both, is_and) = match (self, neg) {
            (Clip::Obj(i), _) => return Ok(vec![vec![(*i, neg)]]),
            (Clip::Not(e), _) => return e.nnf_products(!neg),
            (Clip::And(a, b), false) | (Clip::Or(a, b), true) => ((a, b), true),
            (Clip::Or(a, b), false) | (Clip::And(a, b), true) => ((a, b), false),
        };
        let (pa, pb) = (both.0.nnf_products(neg)?, both.1.nnf_products(neg)?);
        let n = if is_and {
            pa.len() * pb.len()
        } else {
            pa.len() + pb.len()
        };
        if n > MAX_PRODUCTS {
            return Err(format!(
                "the expression expands to more than {MAX_PRODUCTS} products"
            ));
        }
        Ok(if is_and {
            pa.iter()
                .flat_map(|x| pb.iter().map(move |y| [x.as_slice(), y].concat()))
                .collect()
        } else {
            [pa, pb].concat()
        })
    }

    /// Evaluate on a point: `inside[i]` says whether the point is inside object i.
    pub fn eval(&self, inside: &[bool]) -> bool {
        match self {
            Clip::Obj(i) => inside[*i],
            Clip::Not(e) => !e.eval(inside),
            Clip::And(a, b) => a.eval(inside) && b.eval(inside),
            Clip::Or(a, b) => a.eval(inside) || b.eval(inside),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(n: usize) -> Vec<String> {
        (0..n)
            .map(|i| ((b'A' + i as u8) as char).to_string())
            .collect()
    }

    #[test]
    fn thesis_expression_parses_to_a_and_not_b() {
        let e = Clip::parse("A.!B", &names(2)).unwrap();
        assert_eq!(
            e,
            Clip::And(
                Box::new(Clip::Obj(0)),
                Box::new(Clip::Not(Box::new(Clip::Obj(1))))
            )
        );
        assert_eq!(e.products().unwrap(), vec![vec![(0, false), (1, true)]]);
    }

    #[test]
    fn precedence_and_parentheses() {
        let n = names(3);
        let e = Clip::parse("A+B.C", &n).unwrap();
        assert_eq!(
            e.products().unwrap(),
            vec![vec![(0, false)], vec![(1, false), (2, false)]]
        );
        let e = Clip::parse("!(A+B).C", &n).unwrap();
        assert_eq!(
            e.products().unwrap(),
            vec![vec![(0, true), (1, true), (2, false)]]
        );
        assert_eq!(
            Clip::parse("A.!A", &n).unwrap().products().unwrap(),
            Vec::<Vec<Literal>>::new()
        );
    }

    #[test]
    fn errors_name_the_column() {
        let n = names(2);
        assert_eq!(Clip::parse("A.!C", &n).unwrap_err().col, 4);
        assert_eq!(Clip::parse("A..B", &n).unwrap_err().col, 3);
        assert_eq!(Clip::parse("(A.B", &n).unwrap_err().col, 5);
        assert_eq!(Clip::parse("A B", &n).unwrap_err().col, 3);
        let deep = format!("{}A{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(Clip::parse(&deep, &n).unwrap_err().msg.contains("deeper"));
        let nots = format!("{}A", "!".repeat(10_000));
        assert!(Clip::parse(&nots, &n).is_err());
    }

    #[test]
    fn products_agree_with_the_expression_on_every_point() {
        let n = names(4);
        for text in ["A.!B+C", "!(A.(B+!C))+D.A", "(A+B).(C+D)", "!(!A+!B)"] {
            let e = Clip::parse(text, &n).unwrap();
            let prods = e.products().unwrap();
            for m in 0..16u32 {
                let inside: Vec<bool> = (0..4).map(|i| m >> i & 1 == 1).collect();
                let sop = prods
                    .iter()
                    .any(|p| p.iter().all(|&(i, neg)| inside[i] != neg));
                assert_eq!(e.eval(&inside), sop, "{text} at {m:04b}");
            }
        }
    }
}

#[cfg(test)]
mod fuzz {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Any text either parses or gives an error with a column inside it (or just past it).
        #[test]
        fn parser_never_panics(text in "[AB!().+ x]{0,40}|\\PC{0,40}") {
            let names = vec!["A".to_string(), "B".to_string()];
            match Clip::parse(&text, &names) {
                Ok(e) => { e.products().ok(); }
                Err(err) => prop_assert!(err.col >= 1 && err.col <= text.chars().count() + 1),
            }
        }
    }
}
