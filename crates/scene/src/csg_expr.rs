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
//! The parser is an operator-precedence (shunting-yard) loop over explicit stacks: no input can
//! overflow the call stack, and nesting (open parentheses plus pending `!`) deeper than
//! [`MAX_DEPTH`] is refused with the column where it happens.

use std::fmt;

use crate::solid::CsgNode;

/// Parentheses and `!` nested deeper than this are refused.
pub const MAX_DEPTH: usize = 10_000;

/// A parsed expression: the tree and the primitive names, `names[i]` for `Solid(i)`.
#[derive(Debug)]
pub struct CsgExpr {
    pub root: CsgNode,
    pub names: Vec<String>,
}

/// Why an expression was refused, with the 1-based column (in characters) where it was seen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CsgExprError {
    pub col: usize,
    pub msg: String,
}

impl fmt::Display for CsgExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.col, self.msg)
    }
}

impl std::error::Error for CsgExprError {}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BinOp {
    Union,
    Intersection,
    Difference,
}

impl BinOp {
    fn of(c: char) -> Option<BinOp> {
        match c {
            '+' => Some(BinOp::Union),
            '.' => Some(BinOp::Intersection),
            '-' => Some(BinOp::Difference),
            _ => None,
        }
    }

    /// `.` above `+` and `-`.
    fn precedence(self) -> u8 {
        match self {
            BinOp::Intersection => 2,
            BinOp::Union | BinOp::Difference => 1,
        }
    }

    fn node(self, children: Vec<CsgNode>) -> CsgNode {
        match self {
            BinOp::Union => CsgNode::Union(children),
            BinOp::Intersection => CsgNode::Intersection(children),
            BinOp::Difference => CsgNode::Difference(children),
        }
    }

    /// The children of `n` if it is this operator's node.
    fn chain(self, n: &mut CsgNode) -> Option<&mut Vec<CsgNode>> {
        match (self, n) {
            (BinOp::Union, CsgNode::Union(c))
            | (BinOp::Intersection, CsgNode::Intersection(c))
            | (BinOp::Difference, CsgNode::Difference(c)) => Some(c),
            _ => None,
        }
    }
}

/// What waits on the operator stack.
#[derive(Clone, Copy, Debug)]
enum Pending {
    Not,
    /// An open parenthesis and its column.
    Open(usize),
    Bin(BinOp),
}

/// An operand and whether it was written in parentheses (then it is never flattened into a
/// chain, so that `(A+B)+C` and `A+(B+C)` keep their shapes).
struct Operand {
    node: CsgNode,
    closed: bool,
}

/// What [`Parser::operator`] read.
enum After {
    /// A binary operator: an operand is expected next.
    Operator,
    /// `)`: still an operator, `)` or the end next.
    Close,
    End,
}

struct Parser {
    chars: Vec<char>,
    pos: usize,
    ops: Vec<Pending>,
    operands: Vec<Operand>,
    names: Vec<String>,
    /// Open parentheses and pending `!` on `ops`.
    depth: usize,
}

impl Parser {
    /// The next non-blank character, or None at the end.
    fn peek(&mut self) -> Option<char> {
        while self.chars.get(self.pos).is_some_and(|c| c.is_whitespace()) {
            self.pos += 1;
        }
        self.chars.get(self.pos).copied()
    }

    fn col(&self) -> usize {
        self.pos + 1
    }

    fn err<T>(&self, col: usize, msg: impl Into<String>) -> Result<T, CsgExprError> {
        Err(CsgExprError {
            col,
            msg: msg.into(),
        })
    }

    fn found(c: Option<char>) -> String {
        c.map_or_else(|| "the end".to_string(), |c| format!("{c:?}"))
    }

    fn nest(&mut self, p: Pending) -> Result<(), CsgExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return self.err(
                self.col(),
                format!("expression nested deeper than {MAX_DEPTH}"),
            );
        }
        self.ops.push(p);
        self.pos += 1;
        Ok(())
    }

    /// Where an operand is expected: `!`, `(` or a name. True when an operand is complete.
    fn operand(&mut self) -> Result<bool, CsgExprError> {
        match self.peek() {
            Some('!') => self.nest(Pending::Not).map(|_| false),
            Some('(') => {
                let col = self.col();
                self.nest(Pending::Open(col)).map(|_| false)
            }
            Some(c) if c.is_ascii_alphabetic() => {
                let node = CsgNode::Solid(self.name());
                self.push_operand(node, false);
                Ok(true)
            }
            c => self.err(
                self.col(),
                format!(
                    "expected a primitive name, '!' or '(', found {}",
                    Self::found(c)
                ),
            ),
        }
    }

    /// Read a name; its index, new names appended.
    fn name(&mut self) -> usize {
        let start = self.pos;
        let word = |c: &char| c.is_ascii_alphanumeric() || *c == '_';
        while self.chars.get(self.pos).is_some_and(word) {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().collect();
        match self.names.iter().position(|n| *n == name) {
            Some(i) => i,
            None => {
                self.names.push(name);
                self.names.len() - 1
            }
        }
    }

    /// A complete operand: the `!`s waiting right before it apply to it first (tightest).
    fn push_operand(&mut self, mut node: CsgNode, mut closed: bool) {
        while let Some(Pending::Not) = self.ops.last() {
            self.ops.pop();
            self.depth -= 1;
            node = CsgNode::Complement(Box::new(node));
            closed = true;
        }
        self.operands.push(Operand { node, closed });
    }

    /// Combine the two top operands with `op`, extending an unparenthesized chain of `op`.
    fn reduce(&mut self, op: BinOp) {
        let (Some(right), Some(mut left)) = (self.operands.pop(), self.operands.pop()) else {
            unreachable!("a binary operator always has two operands below it");
        };
        let node = match op.chain(&mut left.node) {
            Some(children) if !left.closed => {
                children.push(right.node);
                left.node
            }
            _ => op.node(vec![left.node, right.node]),
        };
        self.operands.push(Operand {
            node,
            closed: false,
        });
    }

    /// Reduce the binary operators on top of the stack while `keep_going` says so.
    fn reduce_while(&mut self, keep_going: impl Fn(BinOp) -> bool) {
        while let Some(&Pending::Bin(op)) = self.ops.last() {
            if !keep_going(op) {
                break;
            }
            self.ops.pop();
            self.reduce(op);
        }
    }

    /// Where an operator, `)` or the end is expected.
    fn operator(&mut self) -> Result<After, CsgExprError> {
        let c = self.peek();
        if let Some(op) = c.and_then(BinOp::of) {
            // Left-associative: reduce everything of the same or higher precedence first.
            self.reduce_while(|top| top.precedence() >= op.precedence());
            self.ops.push(Pending::Bin(op));
            self.pos += 1;
            return Ok(After::Operator);
        }
        match c {
            Some(')') => {
                self.reduce_while(|_| true);
                if !matches!(self.ops.pop(), Some(Pending::Open(_))) {
                    return self.err(self.col(), "')' without a matching '('");
                }
                self.depth -= 1;
                self.pos += 1;
                let Some(inner) = self.operands.pop() else {
                    unreachable!("a closed parenthesis holds an operand");
                };
                self.push_operand(inner.node, true);
                Ok(After::Close)
            }
            None => {
                self.reduce_while(|_| true);
                if let Some(&Pending::Open(col)) = self.ops.last() {
                    return self.err(
                        self.col(),
                        format!("expected ')' to close the '(' at column {col}"),
                    );
                }
                Ok(After::End)
            }
            c => self.err(
                self.col(),
                format!(
                    "expected '+', '-', '.', ')' or the end, found {}",
                    Self::found(c)
                ),
            ),
        }
    }
}

/// Parse `text` into a tree and its primitive names.
pub fn parse(text: &str) -> Result<CsgExpr, CsgExprError> {
    let mut p = Parser {
        chars: text.chars().collect(),
        pos: 0,
        ops: vec![],
        operands: vec![],
        names: vec![],
        depth: 0,
    };
    // Two states: an operand is expected (at the start, after an operator, `!` or `(`), or an
    // operator, `)` or the end is (after a name or `)`).
    let mut want_operand = true;
    loop {
        if want_operand {
            want_operand = !p.operand()?;
        } else {
            match p.operator()? {
                After::Operator => want_operand = true,
                After::Close => {}
                After::End => break,
            }
        }
    }
    let root = p.operands.pop().map(|o| o.node);
    match root {
        Some(root) if p.operands.is_empty() && p.ops.is_empty() => Ok(CsgExpr {
            root,
            names: p.names,
        }),
        _ => unreachable!("the parser ends with exactly one operand"),
    }
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
    fn errors_name_the_column() {
        let col = |t: &str| parse(t).unwrap_err().col;
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
        assert!(parse("(A.B").unwrap_err().msg.contains("column 1"));
    }

    #[test]
    fn deep_nesting_is_refused_without_overflow() {
        let deep = format!("{}A{}", "(".repeat(100_000), ")".repeat(100_000));
        let e = parse(&deep).unwrap_err();
        assert_eq!(e.col, MAX_DEPTH + 1);
        assert!(e.msg.contains("deeper"));
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
                Err(err) => prop_assert!(err.col >= 1 && err.col <= text.chars().count() + 1),
            }
        }
    }
}
