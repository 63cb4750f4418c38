//! The Blist (Boolean list) of a CSG tree and its evaluation, thesis §4.3-4.5 (after Rossignac,
//! "Blist: a Boolean list formulation of CSG trees"). See `docs/blist.md`.
//!
//! [`BlistTable::compile`] is the CSG-to-Blist conversion of §4.3.2, step by step:
//!
//! 1. **Positive form** (§4.3.1): complements are pushed to the leaves with De Morgan's laws
//!    (`X−Y = X.Y'`, `(X+Y)' = X'.Y'`, `(X.Y)' = X'+Y'`, `X'' = X`); what is left is a binary
//!    tree of `+` and `.` whose leaves carry a sign (`+` the primitive, `−` its complement).
//! 2. **Left-heavy rotation** (§4.3.2): the children of a node are switched when the right one
//!    is strictly higher.
//! 3. **(T ∪ OUT) ∩ IN** (§4.3.2, Figure 4.3 (b)): the tree T is made the left-most leaf of a
//!    two-level tree with the special leaves OUT and IN; leaves get consecutive ids, left to right.
//! 4. **Procedure Match** (§4.3.2, lines (a)-(o)) for every leaf of T in that order: the sign,
//!    toggled when the first operator above is `.`; the match M; M's name, the lowest strictly
//!    positive integer not locked, locked until M's own turn releases it; the stamp = M's name.
//! 5. **IN renamed to 1** (§4.3.2): if IN's name is x ≠ 1, x and 1 are switched in all names
//!    and stamps.
//!
//! [`BlistTable::classify`] is Procedure ClassifyAgainstBlist (§4.3.3), [`BlistEval`] the slice
//! version of §4.5 (a label register per voxel, colour from §4.5).
//!
//! Nothing here recurses on the tree: trees 100,000 levels deep are compiled with explicit
//! stacks and index-ordered passes, and the walks of Match are precomputed per node.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use crate::slice::{self, Labels, Mask, OpCounts, SliceEval};
use csgpix_scene::solid::CsgNode;

/// One entry `BL[p]` of the Blist table (§4.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlistRow {
    /// `BL[p].primitiveReference`: the primitive (the tree's `Solid` index).
    pub prim: usize,
    /// `BL[p].name`: 0 for "no name"; a voxel whose label is this name (or 0) is classified
    /// against this primitive.
    pub name: u32,
    /// `BL[p].sign`: `true` is `+`. A voxel whose classification against the primitive equals
    /// the sign takes the stamp; otherwise its label becomes 0 ("the next primitive decides").
    pub sign: bool,
    /// `BL[p].stamp`: the name of the next primitive that must classify the voxel when its
    /// classification equals the sign (IN's name when the voxel is then known to be in).
    pub stamp: u32,
}

impl BlistRow {
    /// Whether the row classifies a voxel labelled `label` (§4.3.3): the label is 0 or the
    /// row's name.
    fn classifies(&self, label: u32) -> bool {
        label == 0 || label == self.name
    }

    /// The label the row writes for classification `c` against its primitive: the stamp when
    /// `c` equals the sign, else 0.
    fn write(&self, c: bool) -> u32 {
        if c == self.sign {
            self.stamp
        } else {
            0
        }
    }
}

/// The Blist table BL of a CSG tree (§4.3), ready for ClassifyAgainstBlist (§4.3.3).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BlistTable {
    /// BL[1..=|P|], in order (row p of the thesis is `rows[p - 1]`).
    pub rows: Vec<BlistRow>,
    /// IN's name: a voxel whose label ends equal to it is inside. 1 after the renaming of
    /// §4.3.2. Two degenerate trees that the thesis does not consider have no rows: a tree that
    /// is empty has `in_name` 1 (the label stays 0: every voxel is out) and a tree that is
    /// everything (`!Empty`) has `in_name` 0 (the label stays 0: every voxel is in).
    pub in_name: u32,
    /// Width of the label register: ceil(log2(largest name + 1)) bits, over the names, stamps
    /// and IN's name (§4.3.2: names are kept low to keep this small).
    pub label_bits: u32,
}

/// Work one voxel's classification does, counted per operation (§5.5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RowTests {
    /// `label = 0` tests: one per row.
    pub zero_tests: u64,
    /// `label = BL[p].name` tests: one per row whose `label = 0` test failed (the `OR` of
    /// §4.3.3 read as a short-circuit; without it there is one per row).
    pub name_tests: u64,
    /// `InPrimitive(...) = BL[p].sign` tests: one per row that classifies the voxel.
    pub sign_tests: u64,
    /// Label writes: one per row that classifies the voxel.
    pub label_writes: u64,
}

impl BlistTable {
    /// The CSG-to-Blist conversion of §4.3.2 (see the module documentation).
    ///
    /// N-ary nodes are read as left-deep binary chains (`A+B+C` is `(A+B)+C`, `A−B−C` is
    /// `(A−B)−C`). `Empty`, and operators without children, are nothing, as everywhere in the
    /// project (an empty intersection too); constants are folded away before step 2, since a
    /// Blist row needs a primitive.
    ///
    /// ```
    /// use csgpix_voxel::blist::BlistTable;
    /// use csgpix_voxel::evaluate::direct;
    ///
    /// // (A + B) − C: positive form (A + B)·C', one row per primitive, left to right.
    /// let e = csgpix_scene::csg_expr::parse("(A + B) - C").unwrap();
    /// let t = BlistTable::compile(&e.root);
    /// let rows: Vec<_> = t.rows.iter().map(|r| (r.prim, r.name, r.sign, r.stamp)).collect();
    /// // A: in → C decides (name 1); out → B decides. B: out → OUT (2). C: out → IN (1).
    /// assert_eq!(rows, [(0, 0, true, 1), (1, 0, false, 2), (2, 1, false, 1)]);
    /// assert_eq!((t.in_name, t.label_bits), (1, 2));
    /// // ClassifyAgainstBlist agrees with the tree at every combination of A, B and C.
    /// for bits in 0..8 {
    ///     let inside = |p: usize| bits >> p & 1 == 1;
    ///     assert_eq!(t.classify(inside, None), direct(&e.root, inside));
    /// }
    /// ```
    pub fn compile(root: &CsgNode) -> BlistTable {
        let mut tree = Tree::default();
        match tree.positive_form(root) {
            Val::Const(everything) => BlistTable {
                rows: vec![],
                in_name: u32::from(!everything),
                label_bits: u32::from(!everything),
            },
            Val::Node(t) => {
                tree.rotate_left_heavy();
                let wrapped = tree.wrap(t);
                let walks = wrapped.walks(&tree);
                wrapped.fill_table(&tree, |leaf| wrapped.find_match(&tree, &walks, leaf))
            }
        }
    }

    /// Procedure ClassifyAgainstBlist (§4.3.3) for one voxel: `inside(i)` is its classification
    /// against primitive i. The label starts at 0; row p classifies the voxel when the label is
    /// 0 or `BL[p].name`, and then writes `BL[p].stamp` if the classification equals
    /// `BL[p].sign`, else 0. The voxel is in when the final label is IN's name. `trace`
    /// receives the label after every row (the label column of Table 4.2).
    pub fn classify(&self, inside: impl Fn(usize) -> bool, trace: Option<&mut Vec<u32>>) -> bool {
        self.run(inside, trace, &mut RowTests::default()).0 == self.in_name
    }

    /// [`BlistTable::classify`], counting the work (§5.5).
    pub fn classify_counted(&self, inside: impl Fn(usize) -> bool) -> (bool, RowTests) {
        let mut t = RowTests::default();
        let label = self.run(inside, None, &mut t).0;
        (label == self.in_name, t)
    }

    /// The primitive whose colour the voxel takes (§4.5), None when it is out. See
    /// [`BlistEval`] for the rule.
    pub fn classify_colour(&self, inside: impl Fn(usize) -> bool) -> Option<usize> {
        let (label, colour) = self.run(inside, None, &mut RowTests::default());
        // Only a table without rows (`!Empty`) has voxels in that no row classified.
        (label == self.in_name).then(|| colour.unwrap_or(0))
    }

    /// The row loop: the final label and the colour register (§4.5, [`BlistEval`]).
    fn run(
        &self,
        inside: impl Fn(usize) -> bool,
        mut trace: Option<&mut Vec<u32>>,
        t: &mut RowTests,
    ) -> (u32, Option<usize>) {
        let mut label = 0;
        let mut colour = None;
        for row in &self.rows {
            t.zero_tests += 1;
            if label != 0 {
                t.name_tests += 1;
            }
            if row.classifies(label) {
                t.sign_tests += 1;
                t.label_writes += 1;
                let c = inside(row.prim);
                label = row.write(c);
                if c || (label == self.in_name && colour.is_none()) {
                    colour = Some(row.prim);
                }
            }
            if let Some(tr) = trace.as_deref_mut() {
                tr.push(label);
            }
        }
        (label, colour)
    }

    /// ceil(log2(n + 1)): bits to hold 0..=n.
    fn bits_for(n: u32) -> u32 {
        u32::BITS - n.leading_zeros()
    }
}

// ---------------------------------------------------------------------------------------------
// The binary tree the conversion works on

/// Node index meaning "none" (the root's parent).
const NONE: usize = usize::MAX;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Op {
    /// `+`, ∪.
    Union,
    /// `.`, ∩.
    Inter,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Leaf {
    Prim(usize),
    Out,
    In,
}

#[derive(Clone, Copy, Debug)]
enum Node {
    /// A leaf and its sign (`true`: the primitive, `false`: its complement).
    Leaf(Leaf, bool),
    Op(Op, usize, usize),
}

/// A value of the positive form under construction: a node, or a constant folded away.
#[derive(Clone, Copy, Debug)]
enum Val {
    Const(bool),
    Node(usize),
}

/// The positive binary tree (§4.2's node structure, as an arena). Nodes are created children
/// first, so a parent's index is always greater than its children's: passes in increasing
/// index order are bottom-up, in decreasing order top-down, and neither recurses.
#[derive(Default)]
struct Tree {
    nodes: Vec<Node>,
}

impl Tree {
    fn push(&mut self, n: Node) -> usize {
        self.nodes.push(n);
        self.nodes.len() - 1
    }

    /// Step 1 (§4.3.1): the positive form of `root`, built with an explicit stack. A node is
    /// visited with its polarity (`neg`: under an odd number of complements); De Morgan turns a
    /// negative `+` into `.` and back, a difference into `.` (positive: X.Y'.Z') or `+`
    /// (negative: X'+Y+Z), and a complement flips the polarity of its child and disappears.
    fn positive_form(&mut self, root: &CsgNode) -> Val {
        enum Task<'a> {
            Visit(&'a CsgNode, bool),
            Build(Op, usize),
        }
        let mut tasks = vec![Task::Visit(root, false)];
        let mut out: Vec<Val> = vec![];
        while let Some(task) = tasks.pop() {
            match task {
                Task::Visit(n, neg) => match n {
                    CsgNode::Solid(i) => {
                        let leaf = self.push(Node::Leaf(Leaf::Prim(*i), !neg));
                        out.push(Val::Node(leaf));
                    }
                    CsgNode::Empty => out.push(Val::Const(neg)),
                    CsgNode::Complement(c) => tasks.push(Task::Visit(c, !neg)),
                    _ if n.children().is_empty() => out.push(Val::Const(neg)),
                    _ => {
                        let kids = n.children();
                        let diff = matches!(n, CsgNode::Difference(_));
                        let op = positive_op(n, neg);
                        tasks.push(Task::Build(op, kids.len()));
                        for (k, child) in kids.iter().enumerate().rev() {
                            // The subtracted operands of a difference change polarity.
                            tasks.push(Task::Visit(child, neg ^ (diff && k > 0)));
                        }
                    }
                },
                Task::Build(op, k) => {
                    let kids = out.split_off(out.len() - k);
                    let folded = kids.into_iter().reduce(|a, b| self.combine(op, a, b));
                    out.push(folded.unwrap_or(Val::Const(false)));
                }
            }
        }
        out.pop().unwrap_or(Val::Const(false))
    }

    /// `a op b`, left-deep, with constants folded (∪ with nothing or ∩ with everything is the
    /// other operand; ∪ with everything is everything; ∩ with nothing is nothing).
    fn combine(&mut self, op: Op, a: Val, b: Val) -> Val {
        match (op, a, b) {
            (Op::Union, Val::Const(true), _) | (Op::Union, _, Val::Const(true)) => Val::Const(true),
            (Op::Inter, Val::Const(false), _) | (Op::Inter, _, Val::Const(false)) => {
                Val::Const(false)
            }
            (_, Val::Const(_), x) | (_, x, Val::Const(_)) => x,
            (_, Val::Node(l), Val::Node(r)) => Val::Node(self.push(Node::Op(op, l, r))),
        }
    }

    /// Step 2 (§4.3.2): switch the children of every node whose right child is strictly higher
    /// (greater maximum path length to a leaf). Heights are computed bottom-up; switching does
    /// not change a node's height, so one pass does it.
    fn rotate_left_heavy(&mut self) {
        let mut height = vec![0u32; self.nodes.len()];
        for i in 0..self.nodes.len() {
            if let Node::Op(op, l, r) = self.nodes[i] {
                height[i] = 1 + height[l].max(height[r]);
                if height[r] > height[l] {
                    self.nodes[i] = Node::Op(op, r, l);
                }
            }
        }
    }

    /// Step 3 (§4.3.2): (T ∪ OUT) ∩ IN, parents, and the leaves' ids in left-to-right order.
    fn wrap(&mut self, t: usize) -> Wrapped {
        let out = self.push(Node::Leaf(Leaf::Out, true));
        let t_out = self.push(Node::Op(Op::Union, t, out));
        let inn = self.push(Node::Leaf(Leaf::In, true));
        let root = self.push(Node::Op(Op::Inter, t_out, inn));
        let mut parent = vec![NONE; self.nodes.len()];
        for (i, n) in self.nodes.iter().enumerate() {
            if let Node::Op(_, l, r) = *n {
                parent[l] = i;
                parent[r] = i;
            }
        }
        // Leaves left to right: a depth-first walk with an explicit stack, left child first.
        let mut leaves = vec![];
        let mut stack = vec![root];
        while let Some(i) = stack.pop() {
            match self.nodes[i] {
                Node::Leaf(..) => leaves.push(i),
                Node::Op(_, l, r) => stack.extend([r, l]),
            }
        }
        let mut id = vec![0usize; self.nodes.len()];
        for (k, &leaf) in leaves.iter().enumerate() {
            id[leaf] = k + 1;
        }
        Wrapped {
            parent,
            leaves,
            id,
            out,
            inn,
        }
    }

    fn op(&self, i: usize) -> Op {
        match self.nodes[i] {
            Node::Op(op, ..) => op,
            Node::Leaf(..) => unreachable!("a parent is an operator"),
        }
    }
}

/// The `+`/`.` operator a node becomes in the positive form (§4.3.1): a difference is `.`
/// (X.Y') when positive and `+` (X'+Y) when negative; a negative node switches `+` and `.`.
fn positive_op(n: &CsgNode, neg: bool) -> Op {
    match (n, neg) {
        (CsgNode::Union(_), false) | (CsgNode::Intersection(_), true) => Op::Union,
        (CsgNode::Difference(_), true) => Op::Union,
        _ => Op::Inter,
    }
}

/// The tree after step 3.
struct Wrapped {
    parent: Vec<usize>,
    /// Leaf nodes in left-to-right order: T's leaves, then OUT, then IN.
    leaves: Vec<usize>,
    /// P.primitiveID: 1-based position of a leaf in `leaves`.
    id: Vec<usize>,
    out: usize,
    inn: usize,
}

/// The walks of Procedure Match, precomputed for every node so that the whole conversion is
/// linear in the tree (walking up from every leaf is quadratic on a chain 100,000 deep). Each
/// entry is the node where the corresponding WHILE loop of §4.3.2 stops when started there.
struct Walks {
    /// Line (f): first ancestor-or-self that is a left child.
    first_left: Vec<usize>,
    /// Line (j), for op = `+` and op = `.`: first ancestor-or-self M that is a left child of a
    /// node whose operator is not op.
    other_op: [Vec<usize>; 2],
    /// Line (l): the left-most leaf below a node.
    leftmost: Vec<usize>,
}

impl Wrapped {
    fn is_left(&self, tree: &Tree, i: usize) -> bool {
        let p = self.parent[i];
        p != NONE && matches!(tree.nodes[p], Node::Op(_, l, _) if l == i)
    }

    fn walks(&self, tree: &Tree) -> Walks {
        let n = tree.nodes.len();
        let mut w = Walks {
            first_left: vec![NONE; n],
            other_op: [vec![NONE; n], vec![NONE; n]],
            leftmost: vec![NONE; n],
        };
        // Top-down (parents have greater indices): the loops' "M := M.parent" steps.
        for i in (0..n).rev() {
            let p = self.parent[i];
            let left = self.is_left(tree, i);
            let up = |v: &Vec<usize>| if p == NONE { NONE } else { v[p] };
            w.first_left[i] = if left { i } else { up(&w.first_left) };
            for (k, op) in [Op::Union, Op::Inter].into_iter().enumerate() {
                w.other_op[k][i] = if left && tree.op(p) != op {
                    i
                } else {
                    up(&w.other_op[k])
                };
            }
        }
        // Bottom-up: line (l)'s walk down the left children.
        for i in 0..n {
            w.leftmost[i] = match tree.nodes[i] {
                Node::Leaf(..) => i,
                Node::Op(_, l, _) => w.leftmost[l],
            };
        }
        w
    }

    /// Lines (e)-(l) of Procedure Match for leaf `leaf`: the sign toggle and the match M.
    fn find_match(&self, tree: &Tree, w: &Walks, leaf: usize) -> (bool, usize) {
        let m = w.first_left[leaf]; // (e), (f)
        let op = tree.op(self.parent[m]); // (g)
        let toggle = op == Op::Inter; // (h)
        let m = self.parent[m]; // (i)
        let m = w.other_op[usize::from(op == Op::Inter)][m]; // (j)
        let Node::Op(_, _, right) = tree.nodes[self.parent[m]] else {
            unreachable!("(j) stops below an operator");
        };
        (toggle, w.leftmost[right]) // (k), (l)
    }

    /// Lines (e)-(l) as the thesis writes them, walking the tree (quadratic on deep chains);
    /// the tests check that [`Wrapped::find_match`] agrees.
    #[cfg(test)]
    fn find_match_literal(&self, tree: &Tree, leaf: usize) -> (bool, usize) {
        let mut m = leaf;
        while !self.is_left(tree, m) {
            m = self.parent[m];
        }
        let op = tree.op(self.parent[m]);
        m = self.parent[m];
        while !self.is_left(tree, m) || tree.op(self.parent[m]) == op {
            m = self.parent[m];
        }
        let Node::Op(_, _, mut m) = tree.nodes[self.parent[m]] else {
            unreachable!()
        };
        while let Node::Op(_, l, _) = tree.nodes[m] {
            m = l;
        }
        (op == Op::Inter, m)
    }

    /// Step 4 and 5: Procedure Match for every leaf of T in order, then IN renamed to 1.
    /// `find_match` gives lines (e)-(l) for a leaf: the sign toggle and the match M.
    fn fill_table(&self, tree: &Tree, find_match: impl Fn(usize) -> (bool, usize)) -> BlistTable {
        let mut names = Names::default();
        // BL[p].name for every leaf id (OUT and IN included), 0 = no name yet.
        let mut name = vec![0u32; self.leaves.len() + 1];
        let mut rows = Vec::with_capacity(self.leaves.len() - 2);
        for &leaf in &self.leaves[..self.leaves.len() - 2] {
            let p = self.id[leaf]; // (a)
            if name[p] != 0 {
                names.release(name[p]); // (b): P's turn frees the name that led here.
            }
            let Node::Leaf(Leaf::Prim(prim), sign) = tree.nodes[leaf] else {
                unreachable!("T's leaves are primitives");
            };
            let (toggle, m) = find_match(leaf);
            let m = self.id[m]; // (m)
            if name[m] == 0 {
                name[m] = names.lock_lowest(); // (n)
            }
            rows.push(BlistRow {
                prim,                // (d)
                name: name[p],       // named by an earlier Match, or 0
                sign: sign ^ toggle, // (c), (h)
                stamp: name[m],      // (o)
            });
        }
        let in_name = name[self.id[self.inn]];
        debug_assert_ne!(in_name, 0, "T's last leaf always matches IN");
        debug_assert!(name[self.id[self.out]] != in_name);
        rename_in(&mut rows, in_name);
        let largest = rows.iter().map(|r| r.name.max(r.stamp)).max().unwrap_or(0);
        BlistTable {
            rows,
            in_name: 1,
            label_bits: BlistTable::bits_for(largest.max(1)),
        }
    }
}

/// Step 5 (§4.3.2): "If the name attributed to the IN node was not 1, but x, we simply switch
/// all uses of x's and 1's in the names and stamps stored in BL".
fn rename_in(rows: &mut [BlistRow], x: u32) {
    let swap = |n: u32| match n {
        n if n == x => 1,
        1 => x,
        n => n,
    };
    for r in rows {
        r.name = swap(r.name);
        r.stamp = swap(r.stamp);
    }
}

/// lockLowestAvalibleIntegerName / releaseIntegerName (§4.3.2): the lowest strictly positive
/// integer not locked. Names below `next` are either locked or in `free`.
#[derive(Default)]
struct Names {
    next: u32,
    free: BinaryHeap<Reverse<u32>>,
}

impl Names {
    fn lock_lowest(&mut self) -> u32 {
        match self.free.pop() {
            Some(Reverse(n)) => n,
            None => {
                self.next += 1;
                self.next
            }
        }
    }

    fn release(&mut self, n: u32) {
        self.free.push(Reverse(n));
    }
}

// ---------------------------------------------------------------------------------------------
// §4.5 over slices

/// Blist evaluation of a slice (§4.5), 64 voxels per machine word.
///
/// Each voxel has a label register of [`BlistTable::label_bits`] bits, kept as bit-planes
/// (plane b holds bit b of 64 labels), so `label = 0`, `label = BL[p].name` and the write of the
/// stamp are a few word operations per row, as the per-pixel hardware would do them.
///
/// Colour (§4.5): `If (Inprimitive(BL[p]) && v.label = IN.name) v.color = BL[p].color`: the voxel
/// takes the colour of the row that moves its label to IN's name while it is inside that row's
/// primitive. IN's name is locked from the row that first stamps it to the end, so no later row
/// can classify the voxel again: that colour is final. The thesis leaves voxels that reach IN
/// from outside a complemented primitive (every voxel of A−B: the B row, sign −, sends them to
/// IN) without colour, which would show them as empty; here such a voxel takes the colour of
/// the last row that classified it while it was inside that row's primitive (A for A−B), or,
/// if there is none (`!A`), of the row that moved it to IN. Both rules are one colour register
/// written on classifying rows; where §4.5 gives a colour this rule gives the same one.
#[derive(Clone, Debug)]
pub struct BlistEval {
    /// The Blist of the tree (§4.3.2).
    pub table: BlistTable,
}

impl BlistEval {
    /// The evaluator of `tree`: its Blist compiled once.
    pub fn new(tree: &CsgNode) -> BlistEval {
        BlistEval {
            table: BlistTable::compile(tree),
        }
    }

    /// The slice's program: the table's rows, where a stretch of rows whose primitives hold
    /// no voxel of the slice is one [`Jump`] (see [`Step`]).
    fn program(&self, prims: &[Mask], words: usize) -> Vec<Step> {
        let t = &self.table;
        let labels = 1usize << t.label_bits.min(31);
        // A jump costs its labels to build once and a few operations per label and word to
        // apply; rows cost a few per word each.
        let jumps = labels <= JUMP_LABELS && labels <= 8 * words.max(1);
        let absent = |p: usize| {
            prims
                .get(p)
                .is_none_or(|m| m.words().iter().all(|&w| w == 0))
        };
        let mut steps = vec![];
        let mut stretch = 0..0;
        for (i, row) in t.rows.iter().enumerate() {
            if jumps && absent(row.prim) {
                stretch = if stretch.is_empty() {
                    i..i + 1
                } else {
                    stretch.start..i + 1
                };
                continue;
            }
            self.push_stretch(&mut steps, std::mem::replace(&mut stretch, 0..0), labels);
            steps.push(Step::Row(i));
        }
        self.push_stretch(&mut steps, stretch, labels);
        steps
    }

    /// Rows `rows` (primitives absent from the slice) as steps: one row as itself, more as
    /// one jump.
    fn push_stretch(&self, steps: &mut Vec<Step>, rows: std::ops::Range<usize>, labels: usize) {
        match rows.len() {
            0 => {}
            1 => steps.push(Step::Row(rows.start)),
            _ => steps.push(Step::Jump(Jump::over(&self.table, rows, labels))),
        }
    }

    /// One word of 64 voxels: `valid` marks the voxels that exist; returns the inside mask and
    /// writes the colours of the classifying rows into `colour`.
    fn eval_word(
        &self,
        (prims, steps): (&[Mask], &[Step]),
        w: usize,
        valid: u64,
        colour: &mut [u32; 64],
        counts: &mut OpCounts,
    ) -> u64 {
        let t = &self.table;
        // Names are u32, so a label never has more than 32 bits: no allocation per word.
        let bits = (t.label_bits as usize).min(32);
        let mut store = [0u64; 32];
        let planes = &mut store[..bits]; // label := 0
        for step in steps {
            match step {
                Step::Row(r) => {
                    self.row_word(&t.rows[*r], (prims, w), planes, valid, colour, counts)
                }
                Step::Jump(j) => j.apply(planes, valid, colour, counts),
            }
        }
        equals(planes, t.in_name) & valid
    }

    /// Row `row` of §4.3.3 on one word's label planes.
    fn row_word(
        &self,
        row: &BlistRow,
        (prims, w): (&[Mask], usize),
        planes: &mut [u64],
        valid: u64,
        colour: &mut [u32; 64],
        counts: &mut OpCounts,
    ) {
        let zero = !planes.iter().fold(0, |a, &p| a | p);
        let classify = (zero | equals(planes, row.name)) & valid;
        if classify == 0 {
            return;
        }
        let inside = slice::prim_word(prims, row.prim, w);
        let sign = if row.sign { !0 } else { 0 };
        let hit = classify & !(inside ^ sign);
        // label := stamp where the classification equals the sign, 0 elsewhere.
        for (b, plane) in planes.iter_mut().enumerate() {
            let stamp_bit = if row.stamp >> b & 1 == 1 { hit } else { 0 };
            *plane = (*plane & !classify) | stamp_bit;
        }
        let to_in = if row.stamp == self.table.in_name {
            hit
        } else {
            0
        };
        set_colour(colour, classify & inside, row.prim);
        let uncoloured = colour_missing(colour, to_in & !inside);
        set_colour(colour, uncoloured, row.prim);
        counts.comparisons += u64::from(classify.count_ones());
        counts.label_writes += u64::from(classify.count_ones());
    }
}

/// Largest label range (2^label_bits) for which stretches of absent rows become jumps.
const JUMP_LABELS: usize = 64;

/// A step of a slice's program: a row of the table, or a stretch of rows whose primitives
/// hold no voxel of the slice.
enum Step {
    Row(usize),
    Jump(Jump),
}

/// A stretch of rows whose primitives are absent from the slice (every voxel outside them).
/// A voxel outside a row's primitive classifies the same way whatever the voxel, so the
/// stretch is a function of the label alone: the label it leaves, the rows that classify
/// it (the counts), and the row, if any, that first sends it to IN's name (the colour an
/// uncoloured voxel takes there, [`BlistEval`]). Precomputed per label; labels the stretch
/// leaves alone, with no row classifying them, are not listed.
struct Jump {
    /// (label before, label after, classifying rows, the first row's primitive sending it to
    /// IN, if any).
    moves: Vec<(u32, u32, u64, Option<usize>)>,
}

impl Jump {
    /// The jump over `rows` of `t` for labels `0..labels`.
    fn over(t: &BlistTable, rows: std::ops::Range<usize>, labels: usize) -> Jump {
        let mut moves = vec![];
        for v in 0..labels as u32 {
            let (mut label, mut n, mut to_in) = (v, 0u64, None);
            for row in &t.rows[rows.clone()] {
                if row.classifies(label) {
                    n += 1;
                    // The voxel is outside the absent primitive; [`BlistTable::run`]'s colour
                    // rule for that case.
                    label = row.write(false);
                    if label == t.in_name && to_in.is_none() {
                        to_in = Some(row.prim);
                    }
                }
            }
            if label != v || n > 0 {
                moves.push((v, label, n, to_in));
            }
        }
        Jump { moves }
    }

    /// The stretch on one word's label planes.
    fn apply(&self, planes: &mut [u64], valid: u64, colour: &mut [u32; 64], counts: &mut OpCounts) {
        let mut set = [0u64; 32];
        let mut moved = 0u64;
        for &(from, to, n, to_in) in &self.moves {
            let lanes = equals(planes, from) & valid;
            if lanes == 0 {
                continue;
            }
            counts.comparisons += n * u64::from(lanes.count_ones());
            counts.label_writes += n * u64::from(lanes.count_ones());
            if let Some(prim) = to_in {
                let uncoloured = colour_missing(colour, lanes);
                set_colour(colour, uncoloured, prim);
            }
            if to != from {
                moved |= lanes;
                for (b, s) in set.iter_mut().enumerate().take(planes.len()) {
                    if to >> b & 1 == 1 {
                        *s |= lanes;
                    }
                }
            }
        }
        for (plane, s) in planes.iter_mut().zip(set) {
            *plane = (*plane & !moved) | s;
        }
    }
}

/// Voxels whose label (bit-planes) equals `name`.
fn equals(planes: &[u64], name: u32) -> u64 {
    planes.iter().enumerate().fold(!0, |acc, (b, &p)| {
        acc & if name >> b & 1 == 1 { p } else { !p }
    })
}

fn set_colour(colour: &mut [u32; 64], mut bits: u64, prim: usize) {
    let label = u32::try_from(prim).map_or(u32::MAX, |p| p.saturating_add(1));
    while bits != 0 {
        colour[bits.trailing_zeros() as usize] = label;
        bits &= bits - 1;
    }
}

/// The voxels of `bits` whose colour register is still empty.
fn colour_missing(colour: &[u32; 64], mut bits: u64) -> u64 {
    let mut out = 0;
    while bits != 0 {
        let b = bits.trailing_zeros();
        if colour[b as usize] == 0 {
            out |= 1 << b;
        }
        bits &= bits - 1;
    }
    out
}

impl SliceEval for BlistEval {
    /// §4.5: every voxel's label runs down the table; a voxel is in when its label ends equal
    /// to IN's name. `comparisons` counts the rows that classify a voxel (`label = 0` or
    /// `label = BL[p].name` holds) and `label_writes` the label writes they make (the same
    /// number: every classifying row writes the stamp or 0).
    fn eval(&self, prims: &[Mask], counts: &mut OpCounts) -> Labels {
        let len = slice::slice_len(prims);
        let steps = self.program(prims, len.div_ceil(64));
        let mut labels = vec![0u32; len];
        for (w, chunk) in labels.chunks_mut(64).enumerate() {
            let valid = if chunk.len() == 64 {
                !0
            } else {
                (1u64 << chunk.len()) - 1
            };
            let mut colour = [0u32; 64];
            let mut inside = self.eval_word((prims, &steps), w, valid, &mut colour, counts);
            // A voxel can be in without any row classifying it only in a table without rows
            // (`!Empty`); it takes primitive 0's colour then, there being no better one.
            while inside != 0 {
                let b = inside.trailing_zeros() as usize;
                chunk[b] = colour[b].max(1);
                inside &= inside - 1;
            }
        }
        labels
    }

    /// The label registers: `label_bits` bits per voxel.
    fn state_bytes(&self, pixels: usize) -> usize {
        (pixels * self.table.label_bits as usize).div_ceil(8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The conversion with the WHILE loops of Match walked as printed.
    fn compile_literal(root: &CsgNode) -> BlistTable {
        let mut tree = Tree::default();
        let Val::Node(t) = tree.positive_form(root) else {
            return BlistTable::compile(root);
        };
        tree.rotate_left_heavy();
        let wrapped = tree.wrap(t);
        wrapped.fill_table(&tree, |leaf| wrapped.find_match_literal(&tree, leaf))
    }

    fn tree() -> impl Strategy<Value = CsgNode> {
        let leaf =
            prop_oneof![9 => (0..12usize).prop_map(CsgNode::Solid), 1 => Just(CsgNode::Empty)];
        leaf.prop_recursive(8, 96, 4, |inner| {
            prop_oneof![
                prop::collection::vec(inner.clone(), 0..4).prop_map(CsgNode::Union),
                prop::collection::vec(inner.clone(), 0..4).prop_map(CsgNode::Intersection),
                prop::collection::vec(inner.clone(), 0..4).prop_map(CsgNode::Difference),
                inner.prop_map(|c| CsgNode::Complement(Box::new(c))),
            ]
        })
    }

    #[test]
    fn names_are_the_lowest_free() {
        let mut n = Names::default();
        assert_eq!(
            [n.lock_lowest(), n.lock_lowest(), n.lock_lowest()],
            [1, 2, 3]
        );
        n.release(2);
        n.release(1);
        assert_eq!(
            [n.lock_lowest(), n.lock_lowest(), n.lock_lowest()],
            [1, 2, 4]
        );
    }

    #[test]
    fn in_is_renamed_to_one() {
        let mut rows = [
            BlistRow {
                prim: 0,
                name: 0,
                sign: true,
                stamp: 1,
            },
            BlistRow {
                prim: 1,
                name: 1,
                sign: false,
                stamp: 3,
            },
        ];
        rename_in(&mut rows, 3);
        assert_eq!((rows[0].stamp, rows[1].name, rows[1].stamp), (3, 3, 1));
    }

    #[test]
    fn constants_have_no_rows() {
        use CsgNode::*;
        let none = BlistTable::compile(&Intersection(vec![Solid(0), Empty]));
        assert_eq!((none.rows.len(), none.in_name), (0, 1));
        assert!(!none.classify(|_| true, None));
        let all = BlistTable::compile(&Complement(Box::new(Empty)));
        assert_eq!((all.rows.len(), all.in_name, all.label_bits), (0, 0, 0));
        assert!(all.classify(|_| false, None));
        // A union with an empty operand is the other operand.
        let a = BlistTable::compile(&Union(vec![Empty, Solid(4)]));
        assert_eq!(
            a.rows,
            [BlistRow {
                prim: 4,
                name: 0,
                sign: true,
                stamp: 1
            }]
        );
        assert_eq!(a.label_bits, 1);
    }

    #[test]
    fn a_minus_b_interior_takes_a_colour() {
        use CsgNode::*;
        let t = BlistTable::compile(&Difference(vec![Solid(0), Solid(1)]));
        assert_eq!(t.classify_colour(|p| p == 0), Some(0));
        assert_eq!(t.classify_colour(|_| true), None);
        let not_a = BlistTable::compile(&Complement(Box::new(Solid(0))));
        assert_eq!(not_a.classify_colour(|_| false), Some(0));
        // Where §4.5 colours (inside the row that sends the voxel to IN), that colour.
        let u = BlistTable::compile(&Union(vec![Solid(0), Solid(1)]));
        assert_eq!(u.classify_colour(|p| p == 1), Some(1));
        assert_eq!(u.classify_colour(|_| true), Some(0));
    }

    /// A union of 1,000 primitives of which two hold voxels is five steps: the rows before,
    /// between and after them are one jump each, and the labels are the rows' own.
    #[test]
    fn absent_rows_are_jumped() {
        let tree = CsgNode::Union((0..1000).map(CsgNode::Solid).collect());
        let e = BlistEval::new(&tree);
        let mut prims: Vec<Mask> = (0..1000).map(|_| Mask::new(0)).collect();
        prims[10] = Mask::from_fn(100, |i| i % 3 == 0);
        prims[500] = Mask::from_fn(100, |i| i % 5 == 0);
        assert_eq!(e.program(&prims, 2).len(), 5);
        let mut counts = OpCounts::default();
        let labels = e.eval(&prims, &mut counts);
        for (i, &l) in labels.iter().enumerate() {
            let want = match (i % 3 == 0, i % 5 == 0) {
                (true, _) => 11,
                (false, true) => 501,
                _ => 0,
            };
            assert_eq!(l, want, "voxel {i}");
        }
        // Every row classifies a voxel still out: those in primitive 10 stop there.
        let (in10, in500) = (34, 20 - 7);
        let want = 11 * in10 + 501 * in500 + 1000 * (100 - in10 - in500);
        assert_eq!(counts.comparisons, want);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]
        /// The precomputed walks stop where the WHILE loops of Match stop.
        #[test]
        fn walks_agree_with_the_printed_loops(t in tree()) {
            prop_assert_eq!(BlistTable::compile(&t), compile_literal(&t));
        }

        /// The bit-sliced evaluator agrees with the per-voxel procedure, label and colour, and
        /// counts one comparison and one label write per classifying row.
        #[test]
        fn slice_eval_agrees_with_classify(
            t in tree(),
            len in 1usize..200,
            seed in prop::collection::vec(any::<u64>(), 12 * 4),
            absent in prop::collection::vec(0u8..4, 12),
        ) {
            // A quarter of the primitives hold no voxel (an empty mask, or one of zeros), so
            // that stretches of rows become jumps.
            let prims: Vec<Mask> = (0..12)
                .map(|p| match absent[p] {
                    0 if p % 2 == 0 => Mask::new(0),
                    0 => Mask::new(len),
                    _ => Mask::from_fn(len, |i| seed[p * 4 + i / 64] >> (i % 64) & 1 == 1),
                })
                .collect();
            let e = BlistEval::new(&t);
            let mut counts = OpCounts::default();
            let labels = e.eval(&prims, &mut counts);
            let mut classified = 0;
            for (i, &l) in labels.iter().enumerate() {
                let inside = |p: usize| i < prims[p].len() && prims[p].get(i);
                let want = e.table.classify_colour(inside).map_or(0, |p| p as u32 + 1);
                prop_assert_eq!(l, want, "voxel {}", i);
                prop_assert_eq!(l != 0, e.table.classify(inside, None));
                classified += e.table.classify_counted(inside).1.sign_tests;
            }
            prop_assert_eq!(counts.comparisons, classified);
            prop_assert_eq!(counts.label_writes, classified);
            prop_assert_eq!((counts.pushes, counts.pops), (0, 0));
        }
    }

    // The tests every evaluator passes.
    crate::slice::suite::slice_eval_suite!(blist, BlistEval::new);
}
