//! Clipping functions over named objects (§5.2.1): `A.!B`, with `.` (intersection), `+`
//! (union), `!` (complement) and parentheses; `.` binds tighter than `+`, `!` tightest.
//!
//! The thesis evaluates an expression by drawing each object and clipping it by the rest:
//! @(A.!B) = @(A).!B + @(!B).A. In general the expression is put in sum-of-products form; for
//! every literal of every product the literal's object is drawn (first stage), clipped by the
//! product of the other literals (the clipping stack) and composed into the scene (second
//! stage), so the union of products is the nearest surface at each pixel.

use crate::expr::{self, BinOp, Grammar, Node};
use crate::{Error, Result};

/// A parsed clipping function; objects are numbered by their position in the scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Clip {
    /// Object i.
    Obj(usize),
    /// The complement `!e`.
    Not(Box<Clip>),
    /// The intersection `a.b`.
    And(Box<Clip>, Box<Clip>),
    /// The union `a+b`.
    Or(Box<Clip>, Box<Clip>),
}

/// A literal: object index and whether it is complemented.
pub type Literal = (usize, bool);

/// Nesting deeper than this is refused rather than risking the stack (the whole expression
/// is the first level; [`Clip::products`] and [`Clip::eval`] recurse).
pub const MAX_DEPTH: usize = 200;

/// Products in the sum-of-products form beyond this are refused.
pub const MAX_PRODUCTS: usize = 4096;

/// Clipping functions: no difference, and no `)` expected where none is open.
const GRAMMAR: Grammar = Grammar {
    difference: false,
    noun: "an object",
    max_nesting: MAX_DEPTH - 1,
    max_depth: MAX_DEPTH,
    depth_at_operand: true,
    misplaced: |c, open| match open {
        Some(_) => Error::Unclosed { open: None },
        None => Error::Expected {
            expected: "'+', '.' or the end".into(),
            found: expr::found(c),
        },
    },
};

impl Clip {
    /// Parse `text` over the object names `names` (e.g. A, B, …).
    ///
    /// # Errors
    ///
    /// The first problem, located at its column in [`expr::INPUT`], line 1.
    ///
    /// # Examples
    ///
    /// The thesis's `A.!B`, drawn as one product of two literals:
    ///
    /// ```
    /// use csgpix_scene::clip_expr::Clip;
    ///
    /// let names = ["A".to_string(), "B".to_string()];
    /// let clip = Clip::parse("A.!B", &names)?;
    /// assert_eq!(clip.products()?, vec![vec![(0, false), (1, true)]]);
    /// assert!(clip.eval(&[true, false]) && !clip.eval(&[true, true]));
    ///
    /// let err = Clip::parse("A-B", &names).unwrap_err();
    /// assert_eq!(err.to_string(), "<expr>:1:2: expected '+', '.' or the end, found '-'");
    /// # Ok::<(), csgpix_scene::Error>(())
    /// ```
    pub fn parse(text: &str, names: &[String]) -> Result<Clip> {
        let known = |name: &str| {
            names
                .iter()
                .position(|n| n == name)
                .ok_or_else(|| Error::UnknownObject {
                    name: name.to_string(),
                    known: names.to_vec(),
                })
        };
        let tree = expr::parse(text, &GRAMMAR, known)?;
        Ok(tree.lower(|node, kids| match node {
            Node::Name(i) => Clip::Obj(*i),
            Node::Not(_) => Clip::Not(Box::new(kids.into_iter().next().expect("one operand"))),
            Node::Chain(op, _) => {
                let join = match op {
                    BinOp::Union => Clip::Or,
                    BinOp::Intersection => Clip::And,
                    BinOp::Difference => unreachable!("clipping functions have no difference"),
                };
                // A chain means the left-deep tree: `A+B+C` is `(A+B)+C`.
                let mut kids = kids.into_iter();
                let first = kids.next().expect("a chain has operands");
                kids.fold(first, |a, b| join(Box::new(a), Box::new(b)))
            }
        }))
    }

    /// Sum-of-products form: a list of products, each a list of distinct literals; products
    /// that contain a literal and its complement are dropped (they are empty volumes).
    ///
    /// # Errors
    ///
    /// When the form has more than [`MAX_PRODUCTS`] products.
    pub fn products(&self) -> Result<Vec<Vec<Literal>>> {
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

    fn nnf_products(&self, neg: bool) -> Result<Vec<Vec<Literal>>> {
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
            return Err(Error::TooManyProducts {
                limit: MAX_PRODUCTS,
            });
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

    fn col(e: crate::Error) -> usize {
        e.location().expect("a located error").col
    }

    #[test]
    fn errors_name_the_column() {
        let n = names(2);
        assert_eq!(col(Clip::parse("A.!C", &n).unwrap_err()), 4);
        assert_eq!(col(Clip::parse("A..B", &n).unwrap_err()), 3);
        assert_eq!(col(Clip::parse("(A.B", &n).unwrap_err()), 5);
        assert_eq!(col(Clip::parse("A B", &n).unwrap_err()), 3);
        let deep = format!("{}A{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(Clip::parse(&deep, &n)
            .unwrap_err()
            .problem()
            .to_string()
            .contains("deeper"));
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
                Err(err) => {
                    let col = err.location().expect("a located error").col;
                    prop_assert!(col >= 1 && col <= text.chars().count() + 1)
                }
            }
        }
    }
}
