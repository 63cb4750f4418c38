//! The expression grammar shared by clipping functions (§5.2.1, [`crate::clip_expr`]) and CSG
//! expressions over named primitives (§4.3, [`crate::csg_expr`]): names, `+` union, `.`
//! intersection, `-` difference (CSG expressions only), prefix `!` complement and
//! parentheses. `!` binds tightest, then `.`, then `+` and `-` (one level, left-associative).
//!
//! Names are ASCII identifiers (letters, digits and `_`, starting with a letter); blanks
//! between tokens are skipped. Each language resolves its names as they are read, so an
//! unknown name is reported before anything after it.
//!
//! The syntax tree keeps the shape written: only a chain of one operator without parentheses
//! becomes one n-ary node (`A+B+C` is one union of three, meaning the left-deep `(A+B)+C`),
//! while `A+(B+C)` stays nested. Its nodes are stored children first, so a front end lowers it
//! in one pass without recursion.
//!
//! The parser is an operator-precedence (shunting-yard) loop over explicit stacks: no input can
//! overflow the call stack, and nesting (open parentheses plus pending `!`) deeper than the
//! language's limit is refused with the column where it happens.

use crate::{Error, Result};

/// The name expressions are located in by their errors (line 1, the column in characters);
/// callers rename it after the input the expression came from ([`Error::in_file`]).
pub const INPUT: &str = "<expr>";

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `+`, union.
    Union,
    /// `.`, intersection.
    Intersection,
    /// `-`, difference.
    Difference,
}

impl BinOp {
    fn of(c: char, difference: bool) -> Option<BinOp> {
        match c {
            '+' => Some(BinOp::Union),
            '.' => Some(BinOp::Intersection),
            '-' if difference => Some(BinOp::Difference),
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
}

/// A node of the syntax tree; its children are indices of earlier nodes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Node {
    /// A name, by the index its language resolved it to.
    Name(usize),
    /// `!` of a node.
    Not(usize),
    /// Two or more operands joined by one operator, left to right.
    Chain(BinOp, Vec<usize>),
}

/// A parsed expression: its nodes, every child before its parent, the root last.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expr {
    /// The nodes in postfix order.
    pub nodes: Vec<Node>,
}

impl Expr {
    /// Builds the language's own tree bottom-up: `lower` gets each node with its children
    /// already built (in order), and the root's result is returned. No recursion, however deep
    /// the tree.
    pub fn lower<T>(self, mut lower: impl FnMut(&Node, Vec<T>) -> T) -> T {
        let mut built: Vec<Option<T>> = Vec::with_capacity(self.nodes.len());
        for node in &self.nodes {
            let mut take = |i: &usize| built[*i].take().expect("each node has one parent");
            let children = match node {
                Node::Name(_) => vec![],
                Node::Not(c) => vec![take(c)],
                Node::Chain(_, cs) => cs.iter().map(take).collect(),
            };
            built.push(Some(lower(node, children)));
        }
        built
            .pop()
            .flatten()
            .expect("a parsed expression has a root")
    }
}

/// What sets one language apart: its operators, its limits and its messages.
pub struct Grammar {
    /// Whether `-` (difference) is an operator.
    pub difference: bool,
    /// What a name names, with its article, in messages ("an object", "a primitive").
    pub noun: &'static str,
    /// Open parentheses plus pending `!` beyond this many are refused.
    pub max_nesting: usize,
    /// The depth the refusal names: "expression nested deeper than `max_depth`".
    pub max_depth: usize,
    /// Whether too deep a nesting is reported at the operand after the `(` or `!` that goes
    /// too deep (the next token) rather than at that `(` or `!` itself.
    pub depth_at_operand: bool,
    /// The message where an operator, `)` or the end was expected: given what was found
    /// (`None` at the end) and the column of the innermost `(` still open, if any.
    pub misplaced: fn(found: Option<char>, open: Option<usize>) -> Error,
}

/// `'c'`, or "the end".
pub fn found(c: Option<char>) -> String {
    c.map_or_else(|| "the end".to_string(), |c| format!("{c:?}"))
}

/// Parses `text` in `grammar`; `name` resolves each name as it is read (to its index, or the
/// reason it is refused, reported at the name's column).
///
/// # Errors
///
/// The first problem, located at line 1 and its column (in characters) in [`INPUT`].
pub fn parse(
    text: &str,
    grammar: &Grammar,
    name: impl FnMut(&str) -> Result<usize>,
) -> Result<Expr> {
    let mut p = Parser {
        chars: text.chars().collect(),
        pos: 0,
        grammar,
        resolve: name,
        ops: vec![],
        operands: vec![],
        nodes: vec![],
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
    let root = p.operands.pop().expect("the parser ends with one operand");
    debug_assert!(p.operands.is_empty() && p.ops.is_empty());
    p.seal(root);
    Ok(Expr { nodes: p.nodes })
}

/// What waits on the operator stack.
#[derive(Clone, Copy, Debug)]
enum Pending {
    Not,
    /// An open parenthesis and its column.
    Open(usize),
    Bin(BinOp),
}

/// An operand on the stack.
enum Operand {
    /// A finished node: a name, a complement or a parenthesized expression, never extended
    /// (so that `(A+B)+C` and `A+(B+C)` keep their shapes).
    Node(usize),
    /// An unparenthesized chain, still open to more operands of its operator; it becomes a
    /// node once finished, after all of its children.
    Chain(BinOp, Vec<usize>),
}

/// What [`Parser::operator`] read.
enum After {
    /// A binary operator: an operand is expected next.
    Operator,
    /// `)`: still an operator, `)` or the end next.
    Close,
    End,
}

struct Parser<'g, F> {
    chars: Vec<char>,
    pos: usize,
    grammar: &'g Grammar,
    resolve: F,
    ops: Vec<Pending>,
    operands: Vec<Operand>,
    nodes: Vec<Node>,
    /// Open parentheses and pending `!` on `ops`.
    depth: usize,
}

impl<F: FnMut(&str) -> Result<usize>> Parser<'_, F> {
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

    fn err<T>(&self, col: usize, problem: Error) -> Result<T> {
        Err(Error::at(INPUT, 1, col, problem))
    }

    /// Push `!` or `(` (at the current character), refusing nesting past the limit.
    fn nest(&mut self, p: Pending) -> Result<()> {
        self.depth += 1;
        self.pos += 1;
        if self.depth > self.grammar.max_nesting {
            let col = match self.grammar.depth_at_operand {
                true => {
                    self.peek();
                    self.col()
                }
                false => self.col() - 1,
            };
            let limit = self.grammar.max_depth;
            return self.err(col, Error::ExpressionTooDeep { limit });
        }
        self.ops.push(p);
        Ok(())
    }

    /// Where an operand is expected: `!`, `(` or a name. True when an operand is complete.
    fn operand(&mut self) -> Result<bool> {
        match self.peek() {
            Some('!') => self.nest(Pending::Not).map(|_| false),
            Some('(') => {
                let col = self.col();
                self.nest(Pending::Open(col)).map(|_| false)
            }
            Some(c) if c.is_ascii_alphabetic() => {
                let node = self.name()?;
                self.push_operand(node);
                Ok(true)
            }
            c => {
                let noun = self.grammar.noun;
                let e = Error::Expected {
                    expected: format!("{noun} name, '!' or '('"),
                    found: found(c),
                };
                self.err(self.col(), e)
            }
        }
    }

    /// Read a name and resolve it to a node.
    fn name(&mut self) -> Result<usize> {
        let start = self.pos;
        let word = |c: &char| c.is_ascii_alphanumeric() || *c == '_';
        while self.chars.get(self.pos).is_some_and(word) {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().collect();
        match (self.resolve)(&name) {
            Ok(i) => Ok(self.add(Node::Name(i))),
            Err(e) => Err(e.located(INPUT, 1, start + 1)),
        }
    }

    fn add(&mut self, node: Node) -> usize {
        self.nodes.push(node);
        self.nodes.len() - 1
    }

    /// The node of a finished operand.
    fn seal(&mut self, o: Operand) -> usize {
        match o {
            Operand::Node(node) => node,
            Operand::Chain(op, children) => self.add(Node::Chain(op, children)),
        }
    }

    /// A complete operand: the `!`s waiting right before it apply to it first (tightest).
    fn push_operand(&mut self, mut node: usize) {
        while let Some(Pending::Not) = self.ops.last() {
            self.ops.pop();
            self.depth -= 1;
            node = self.add(Node::Not(node));
        }
        self.operands.push(Operand::Node(node));
    }

    /// Combine the two top operands with `op`, extending an unparenthesized chain of `op`.
    fn reduce(&mut self, op: BinOp) {
        let (Some(right), Some(left)) = (self.operands.pop(), self.operands.pop()) else {
            unreachable!("a binary operator always has two operands below it");
        };
        let right = self.seal(right);
        let chain = match left {
            Operand::Chain(o, mut children) if o == op => {
                children.push(right);
                children
            }
            left => vec![self.seal(left), right],
        };
        self.operands.push(Operand::Chain(op, chain));
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

    /// The column of the innermost `(` still open.
    fn open(&self) -> Option<usize> {
        self.ops.iter().rev().find_map(|p| match p {
            Pending::Open(col) => Some(*col),
            _ => None,
        })
    }

    /// Where an operator, `)` or the end is expected.
    fn operator(&mut self) -> Result<After> {
        let c = self.peek();
        if let Some(op) = c.and_then(|c| BinOp::of(c, self.grammar.difference)) {
            // Left-associative: reduce everything of the same or higher precedence first.
            self.reduce_while(|top| top.precedence() >= op.precedence());
            self.ops.push(Pending::Bin(op));
            self.pos += 1;
            return Ok(After::Operator);
        }
        match c {
            Some(')') if self.open().is_some() => {
                self.reduce_while(|_| true);
                let Some(Pending::Open(_)) = self.ops.pop() else {
                    unreachable!("only binary operators are above the innermost '('");
                };
                self.depth -= 1;
                self.pos += 1;
                let inner = self
                    .operands
                    .pop()
                    .expect("a closed parenthesis holds an operand");
                let node = self.seal(inner);
                self.push_operand(node);
                Ok(After::Close)
            }
            None if self.open().is_none() => {
                self.reduce_while(|_| true);
                Ok(After::End)
            }
            c => self.err(self.col(), (self.grammar.misplaced)(c, self.open())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grammar() -> Grammar {
        Grammar {
            difference: true,
            noun: "a",
            max_nesting: 3,
            max_depth: 3,
            depth_at_operand: false,
            misplaced: |c, _| Error::Expected {
                expected: "an operator".into(),
                found: found(c),
            },
        }
    }

    fn nodes(text: &str) -> Vec<Node> {
        let mut names: Vec<String> = vec![];
        let intern = |n: &str| {
            Ok(names.iter().position(|m| m == n).unwrap_or_else(|| {
                names.push(n.to_string());
                names.len() - 1
            }))
        };
        parse(text, &grammar(), intern).unwrap().nodes
    }

    #[test]
    fn chains_are_flat_until_parenthesized_and_children_come_first() {
        use Node::*;
        assert_eq!(
            nodes("A+B+C"),
            [
                Name(0),
                Name(1),
                Name(2),
                Chain(BinOp::Union, vec![0, 1, 2])
            ]
        );
        assert_eq!(
            nodes("(A+B)+C"),
            [
                Name(0),
                Name(1),
                Chain(BinOp::Union, vec![0, 1]),
                Name(2),
                Chain(BinOp::Union, vec![2, 3])
            ]
        );
        // A chain becomes a node when finished: after the operand read next.
        assert_eq!(
            nodes("!A.B-C"),
            [
                Name(0),
                Not(0),
                Name(1),
                Name(2),
                Chain(BinOp::Intersection, vec![1, 2]),
                Chain(BinOp::Difference, vec![4, 3])
            ]
        );
    }

    #[test]
    fn lowering_sees_children_built() {
        let e = parse("A.(B+!A)", &grammar(), |n| Ok(n.len())).unwrap();
        let text = e.lower(|n, kids: Vec<String>| match n {
            Node::Name(i) => i.to_string(),
            Node::Not(_) => format!("!{}", kids[0]),
            Node::Chain(op, _) => format!("{op:?}({})", kids.join(",")),
        });
        assert_eq!(text, "Intersection(1,Union(1,!1))");
    }

    #[test]
    fn errors_are_located() {
        let err = |t: &str| parse(t, &grammar(), |_| Ok(0)).unwrap_err();
        let e = err("A B");
        assert_eq!(e.to_string(), "<expr>:1:3: expected an operator, found 'B'");
        assert_eq!(
            err("((((A").to_string(),
            "<expr>:1:4: expression nested deeper than 3"
        );
        let e = parse("A+Bad", &grammar(), |n| match n {
            "A" => Ok(0),
            _ => Err(Error::UnknownObject {
                name: n.to_string(),
                known: vec!["A".to_string()],
            }),
        });
        assert_eq!(
            e.unwrap_err().to_string(),
            "<expr>:1:3: unknown object \"Bad\"; the scene names A"
        );
    }
}
