//! CSG expressions over named primitives, e.g. the tree of the thesis's Figure 4.4,
//! `(A+B)-((C+(D-E)).(F+G))`, parsed into a [`CsgNode`].
//!
//! Syntax: `+` union, `.` intersection, `-` difference, `!` prefix complement, parentheses.
//! Names are ASCII identifiers (letters, digits and `_`, starting with a letter); `Solid(i)` is
//! the i-th distinct name in order of first appearance. `!` binds tightest, then `.`, then `+`
//! and `-` (one level, left-associative): `A+B-C` is `(A+B)-C`, `!A.B` is `(!A).B`.
//!
//! The tree keeps the shape written, because the Blist of §4.3.2 depends on it (left-heavy
//! rotation): only a chain of one operator without parentheses becomes one n-ary node
//! (`A+B+C` is `Union[A, B, C]`, `A-B-C` is `Difference[A, B, C]`), which every consumer reads
//! as the left-deep binary tree `(A+B)+C` the chain means. `A+(B+C)` stays nested.
//!
//! The grammar and its parser are [`crate::expr`]'s, shared with clipping functions; nesting
//! (open parentheses plus pending `!`) deeper than [`MAX_DEPTH`] is refused with the column
//! where it happens, and no input overflows the stack.

use std::collections::HashMap;

use crate::expr::{self, BinOp, Grammar, Node};
use crate::solid::CsgNode;
use crate::{Error, Result};

/// Parentheses and `!` nested deeper than this are refused.
pub const MAX_DEPTH: usize = 10_000;

/// A parsed expression: the tree and the primitive names, `names[i]` for `Solid(i)`.
#[derive(Debug)]
pub struct CsgExpr {
    /// The tree, in the shape written (§4.3.2).
    pub root: CsgNode,
    /// The primitive names in order of first appearance.
    pub names: Vec<String>,
    /// Where each name first appears: `columns[i]` is the column (1-based, in characters) of
    /// `names[i]`'s first occurrence, for errors about a name found after parsing.
    pub columns: Vec<usize>,
}

/// CSG expressions: every operator, messages naming primitives.
const GRAMMAR: Grammar = Grammar {
    difference: true,
    noun: "a primitive",
    max_nesting: MAX_DEPTH,
    max_depth: MAX_DEPTH,
    depth_at_operand: false,
    misplaced: |c, open| match (c, open) {
        (None, Some(col)) => Error::Unclosed { open: Some(col) },
        (Some(')'), None) => Error::Unmatched,
        (c, _) => Error::Expected {
            expected: "'+', '-', '.', ')' or the end".into(),
            found: expr::found(c),
        },
    },
};

/// Parse `text` into a tree and its primitive names.
///
/// # Errors
///
/// The first problem, located at its column in [`expr::INPUT`], line 1.
///
/// # Examples
///
/// The tree of Figure 4.4:
///
/// ```
/// use csgpix_scene::csg_expr::parse;
/// use csgpix_scene::solid::CsgNode::{Difference, Intersection, Solid, Union};
///
/// let e = parse("(A+B)-((C+(D-E)).(F+G))")?;
/// assert_eq!(e.names, ["A", "B", "C", "D", "E", "F", "G"]);
/// let Difference(sides) = &e.root else { panic!() };
/// assert_eq!(sides[0], Union(vec![Solid(0), Solid(1)]));
/// assert!(matches!(&sides[1], Intersection(c) if c.len() == 2));
///
/// let err = parse("A+(B.C").unwrap_err();
/// assert_eq!(
///     err.in_file("EXPR").to_string(),
///     "EXPR:1:7: expected ')' to close the '(' at column 3"
/// );
/// # Ok::<(), csgpix_scene::Error>(())
/// ```
pub fn parse(text: &str) -> Result<CsgExpr> {
    let mut names: Vec<String> = vec![];
    // Each name's index, found by hashing: a search of `names` for every name read made a
    // long expression of distinct names quadratic in its length.
    let mut index: HashMap<String, usize> = HashMap::new();
    let intern = |name: &str| {
        let i = *index.entry(name.to_string()).or_insert_with(|| {
            names.push(name.to_string());
            names.len() - 1
        });
        Ok::<_, crate::Error>(i)
    };
    let tree = expr::parse(text, &GRAMMAR, intern)?;
    let columns = first_columns(text, &index, names.len());
    let root = tree.lower(|node, kids| match node {
        Node::Name(i) => CsgNode::Solid(*i),
        Node::Not(_) => {
            CsgNode::Complement(Box::new(kids.into_iter().next().expect("one operand")))
        }
        Node::Chain(BinOp::Union, _) => CsgNode::Union(kids),
        Node::Chain(BinOp::Intersection, _) => CsgNode::Intersection(kids),
        Node::Chain(BinOp::Difference, _) => CsgNode::Difference(kids),
    });
    Ok(CsgExpr {
        root,
        names,
        columns,
    })
}

/// The column of the first occurrence of each of `count` names (`index` gives a name's
/// number) in a text that parsed: every word of it is a name.
fn first_columns(text: &str, index: &HashMap<String, usize>, count: usize) -> Vec<usize> {
    let mut columns = vec![0; count];
    let mut word = String::new();
    // One pass, the column counted along; a space after the text ends the last word.
    for (col, c) in text.chars().chain([' ']).enumerate() {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
            continue;
        }
        if let Some(&i) = index.get(&word) {
            if columns[i] == 0 {
                columns[i] = col + 1 - word.len();
            }
        }
        word.clear();
    }
    columns
}

#[cfg(test)]
mod tests {
    use super::*;
    use CsgNode::*;

    fn s(i: usize) -> CsgNode {
        Solid(i)
    }

    #[test]
    fn figure_4_4_tree() {
        let e = parse("(A+B)-((C+(D-E)).(F+G))").unwrap();
        assert_eq!(e.names, ["A", "B", "C", "D", "E", "F", "G"]);
        assert_eq!(
            e.root,
            Difference(vec![
                Union(vec![s(0), s(1)]),
                Intersection(vec![
                    Union(vec![s(2), Difference(vec![s(3), s(4)])]),
                    Union(vec![s(5), s(6)]),
                ]),
            ])
        );
    }

    #[test]
    fn precedence_associativity_and_chains() {
        assert_eq!(
            parse("A+B.C").unwrap().root,
            Union(vec![s(0), Intersection(vec![s(1), s(2)])])
        );
        assert_eq!(
            parse("A-B+C").unwrap().root,
            Union(vec![Difference(vec![s(0), s(1)]), s(2)])
        );
        assert_eq!(
            parse("A+B-C").unwrap().root,
            Difference(vec![Union(vec![s(0), s(1)]), s(2)])
        );
        assert_eq!(
            parse("A-B-C").unwrap().root,
            Difference(vec![s(0), s(1), s(2)])
        );
        assert_eq!(parse("A+B+C").unwrap().root, Union(vec![s(0), s(1), s(2)]));
        // Parentheses keep the shape written.
        assert_eq!(
            parse("(A+B)+C").unwrap().root,
            Union(vec![Union(vec![s(0), s(1)]), s(2)])
        );
        assert_eq!(
            parse("A+(B+C)").unwrap().root,
            Union(vec![s(0), Union(vec![s(1), s(2)])])
        );
        assert_eq!(
            parse("!A.B").unwrap().root,
            Intersection(vec![Complement(Box::new(s(0))), s(1)])
        );
        assert_eq!(
            parse("!(A+B)").unwrap().root,
            Complement(Box::new(Union(vec![s(0), s(1)])))
        );
        assert_eq!(
            parse(" !!x_1 . y2 ").unwrap().root,
            Intersection(vec![Complement(Box::new(Complement(Box::new(s(0))))), s(1)])
        );
        let e = parse("cube1+cube2-cube1").unwrap();
        assert_eq!(e.names, ["cube1", "cube2"]);
        assert_eq!(e.root, Difference(vec![Union(vec![s(0), s(1)]), s(0)]));
    }

    #[test]
    fn names_keep_the_column_of_their_first_occurrence() {
        let e = parse("  é_free+(B1.A)").unwrap_err();
        assert_eq!(e.location().unwrap().col, 3);
        let e = parse("  A+(B1.A)+\tc_2").unwrap();
        assert_eq!(e.names, ["A", "B1", "c_2"]);
        assert_eq!(e.columns, [3, 6, 13]);
    }

    #[test]
    fn errors_name_the_column() {
        let col = |t: &str| parse(t).unwrap_err().location().unwrap().col;
        assert_eq!(col(""), 1);
        assert_eq!(col("A..B"), 3);
        assert_eq!(col("(A.B"), 5);
        assert_eq!(col("A B"), 3);
        assert_eq!(col("A+B)"), 4);
        assert_eq!(col("A+1"), 3);
        assert_eq!(col("!"), 2);
        assert_eq!(col("()"), 2);
        assert_eq!(col("A!B"), 2);
        assert_eq!(col("_A"), 1);
        assert!(parse("(A.B")
            .unwrap_err()
            .problem()
            .to_string()
            .contains("column 1"));
    }

    #[test]
    fn deep_nesting_is_refused_without_overflow() {
        let deep = format!("{}A{}", "(".repeat(100_000), ")".repeat(100_000));
        let e = parse(&deep).unwrap_err();
        assert_eq!(e.location().unwrap().col, MAX_DEPTH + 1);
        assert!(e.problem().to_string().contains("deeper"));
        assert!(parse(&format!("{}A", "!".repeat(100_000))).is_err());
        // At the limit it parses; the tree is dropped without recursion.
        let ok = format!("{}A{}", "(".repeat(MAX_DEPTH), ")".repeat(MAX_DEPTH));
        assert_eq!(parse(&ok).unwrap().root, Solid(0));
        let nested = format!("{}A{}", "(B-".repeat(MAX_DEPTH), ")".repeat(MAX_DEPTH));
        assert_eq!(parse(&nested).unwrap().names, ["B", "A"]);
        // Long flat chains are one node, not a deep tree.
        let long = vec!["A"; 100_000].join("+");
        assert_eq!(parse(&long).unwrap().root.children().len(), 100_000);
    }
}

#[cfg(test)]
mod fuzz {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// Any text parses or gives an error with a column inside it (or just past its end).
        #[test]
        fn parser_never_panics(text in "[AB_1!().+\\- x]{0,40}|\\PC{0,40}") {
            match parse(&text) {
                Ok(e) => prop_assert!(!e.names.is_empty()),
                Err(err) => {
                    let col = err.location().expect("a located error").col;
                    prop_assert!(col >= 1 && col <= text.chars().count() + 1)
                }
            }
        }
    }
}
