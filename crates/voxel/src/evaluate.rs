//! The two baseline evaluators of a CSG tree over the primitive slices (§3.4.1, §4.2), the
//! reference membership test [`direct`], and the colour rule every evaluator shares
//! ([`colour_labels`]). See `docs/evaluators.md`.
//!
//! Trees read from files can be 100,000 levels deep, so nothing here recurses: a tree is
//! flattened once, with an explicit stack, into a postfix [`Postfix`] program (the "inverse
//! Polish notation" of §4.2, the "postfix expression of the VST" of §3.4.1), and both evaluators
//! run that program.
//!
//! * [`TreeEval`] (§4.2, Procedure ClassifyAgainstTree): voxel by voxel, a stack of binary
//!   values; optionally with the short-circuit §4.2 describes.
//! * [`StackEval`] (§3.4.1, slice sweeping): the whole slice at once, a stack of slices
//!   ([`Mask`]s), 64 pixels per word operation.
//!
//! N-ary nodes are read as left-deep chains of binary operators (`A ∪ B ∪ C` is `A B ∪ C ∪`,
//! `A − B − C` is `A B − C −`), so a tree with T operands has the T − 1 binary operators §5.5
//! counts, whatever its arity.

use std::collections::HashMap;

use crate::slice::{self, slice_len, Labels, Mask, OpCounts, SliceEval};
use csgpix_scene::solid::CsgNode;

// ---------------------------------------------------------------------------------------------
// Reference evaluation and tree measures

/// Is the point inside `tree`, given `inside(i)` for primitive i (the tree's `Solid(i)`)?
///
/// The reference every evaluator is tested against: n-ary operators read literally (union: any
/// child; intersection: all children; difference: the first child and none of the others),
/// `Empty` and operators without children are nothing, `Complement` is everything outside its
/// child. Walked with an explicit stack, without short-circuit, so it is simple to trust.
pub fn direct(tree: &CsgNode, inside: impl Fn(usize) -> bool) -> bool {
    /// A node being evaluated: the next child to visit, and the value of the children so far.
    struct Frame<'a> {
        node: &'a CsgNode,
        next: usize,
        acc: bool,
    }
    let mut stack = vec![Frame {
        node: tree,
        next: 0,
        acc: false,
    }];
    // The value of the last node finished.
    let mut ret = false;
    while let Some(f) = stack.last_mut() {
        let children = f.node.children();
        if f.next > 0 {
            // `ret` is the value of child `next - 1`.
            f.acc = if f.next == 1 {
                ret
            } else {
                match f.node {
                    CsgNode::Union(_) => f.acc | ret,
                    CsgNode::Intersection(_) => f.acc & ret,
                    _ => f.acc & !ret, // Difference: the first minus the others
                }
            };
        }
        if f.next < children.len() {
            f.next += 1;
            let child = &children[f.next - 1];
            stack.push(Frame {
                node: child,
                next: 0,
                acc: false,
            });
            continue;
        }
        ret = match f.node {
            CsgNode::Solid(i) => inside(*i),
            CsgNode::Empty => false,
            CsgNode::Complement(_) => !f.acc,
            // Operators: the combined children, nothing when there are none.
            _ => f.next > 0 && f.acc,
        };
        stack.pop();
    }
    ret
}

/// Levels of the tree: 1 for a leaf (`Solid` or `Empty`), 1 + the deepest child otherwise.
/// This is the n-ary height; §4.2's H is the height of the binary tree the n-ary nodes stand
/// for, which is larger for wide nodes.
pub fn tree_depth(tree: &CsgNode) -> usize {
    let mut deepest = 0;
    let mut stack = vec![(tree, 1usize)];
    while let Some((node, level)) = stack.pop() {
        deepest = deepest.max(level);
        stack.extend(node.children().iter().map(|c| (c, level + 1)));
    }
    deepest
}

/// Operands of the tree: the number of `Solid` leaves (§5.5's T), repeats counted.
pub fn leaf_count(tree: &CsgNode) -> usize {
    let mut count = 0;
    let mut stack = vec![tree];
    while let Some(node) = stack.pop() {
        if matches!(node, CsgNode::Solid(_)) {
            count += 1;
        }
        stack.extend(node.children());
    }
    count
}

// ---------------------------------------------------------------------------------------------
// The colour rule

/// The leaves of a tree in the order the colour rule reads them (see [`colour_labels`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LeafOrder {
    /// Primitives with a positive occurrence, in the order of their first positive occurrence.
    positive: Vec<usize>,
    /// The first leaf of the tree, positive or not.
    first: Option<usize>,
}

impl LeafOrder {
    /// Walk the leaves left to right. A leaf is positive when it lies under an even number of
    /// complements, counting both `Complement` nodes and the subtracted operands of a
    /// `Difference` (A − B = A ∩ B', the positive form of §4.3): it is then a positive literal
    /// of the tree's positive form.
    pub fn new(tree: &CsgNode) -> LeafOrder {
        let mut order = LeafOrder::default();
        let mut seen = std::collections::HashSet::new();
        // (node, odd number of complements above it)
        let mut stack = vec![(tree, false)];
        while let Some((node, negated)) = stack.pop() {
            match node {
                CsgNode::Solid(i) => {
                    order.first.get_or_insert(*i);
                    if !negated && seen.insert(*i) {
                        order.positive.push(*i);
                    }
                }
                CsgNode::Complement(c) => stack.push((c, !negated)),
                CsgNode::Difference(cs) => {
                    // Reversed so that the first child is popped first.
                    for (k, c) in cs.iter().enumerate().rev() {
                        stack.push((c, negated ^ (k > 0)));
                    }
                }
                _ => stack.extend(node.children().iter().rev().map(|c| (c, negated))),
            }
        }
        order
    }

    /// Primitives with a positive occurrence, in order of their first one.
    pub fn positive(&self) -> &[usize] {
        &self.positive
    }

    /// The first leaf of the tree (None for a tree without `Solid` leaves).
    pub fn first_leaf(&self) -> Option<usize> {
        self.first
    }
}

/// Colour the voxels of `inside` (the scene's membership in this slice).
///
/// Rule: a voxel inside the scene takes the colour of the first primitive, in the tree's leaf
/// order, that contains it and occurs as a positive literal ([`LeafOrder::new`]). When none
/// does (the voxel is inside only through complements, as everywhere in `!A` outside A), it
/// takes the colour of the first leaf of the tree. A tree without leaves that is inside
/// somewhere (`!Empty`) labels those voxels 1 (primitive 0): there is nothing better to say.
/// Voxels outside are 0; a label is 1 + the primitive's index.
///
/// Works 64 voxels at a time: each word looks at the positive primitives in order until all
/// its voxels are coloured. A primitive without a mask in `prims` contains nothing.
pub fn colour_labels(order: &LeafOrder, prims: &[Mask], inside: &Mask) -> Labels {
    let mut labels = vec![0u32; inside.len()];
    let fallback = order.first.map_or(1, label_of);
    for (w, &word) in inside.words().iter().enumerate() {
        let mut rest = word;
        for &p in &order.positive {
            if rest == 0 {
                break;
            }
            let hit = rest & slice::prim_word(prims, p, w);
            write_bits(&mut labels, w, hit, label_of(p));
            rest &= !hit;
        }
        write_bits(&mut labels, w, rest, fallback);
    }
    labels
}

/// The label of primitive `p`, saturating for indices no scene can have.
fn label_of(p: usize) -> u32 {
    u32::try_from(p).map_or(u32::MAX, |p| p.saturating_add(1))
}

/// `labels[64·w + b] = label` for every set bit b of `bits`.
fn write_bits(labels: &mut [u32], w: usize, mut bits: u64, label: u32) {
    while bits != 0 {
        let b = bits.trailing_zeros() as usize;
        if let Some(l) = labels.get_mut(w * 64 + b) {
            *l = label;
        }
        bits &= bits - 1;
    }
}

// ---------------------------------------------------------------------------------------------
// The postfix program

/// One instruction of a [`Postfix`] program over a stack of values (bits or slices).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Push primitive i's classification (§4.2 InPrimitive; §3.4.1 "push slices of leaf
    /// nodes").
    Leaf(usize),
    /// Push a constant: false for `Empty` and childless operators.
    Const(bool),
    /// Replace the top by its complement (a one-operand operator: pop 1, push 1).
    Not,
    /// Pop b, pop a, push a ∩ b.
    And,
    /// Pop b, pop a, push a ∪ b.
    Or,
    /// Pop b, pop a, push a − b (AND NOT, §4.2).
    AndNot,
    /// Short-circuit (§4.2): if the top equals `absorb`, the rest of the chain cannot change it,
    /// so jump to instruction `to` leaving the top as the chain's value. Only in programs
    /// compiled with [`Compile::short_circuit`].
    Guard {
        /// The value that decides the chain (false for ∩ and −, true for ∪).
        absorb: bool,
        /// The instruction after the chain.
        to: usize,
    },
}

/// How to flatten a tree into a [`Postfix`] program.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Compile {
    /// Insert [`Op::Guard`]s so that a chain stops once its value is decided (§4.2's improved
    /// ClassifyAgainstTree). Meaningful per voxel only.
    pub short_circuit: bool,
    /// Evaluate the operand that needs the deepest stack first in unions and intersections
    /// (Sethi–Ullman order; the first operand of a difference stays first). Lowers the peak
    /// stack depth of right-heavy trees without changing any count; the left-heavy rotation of
    /// §4.3 has the same aim for the Blist. Off by default: §3.4.1 takes operands as written.
    pub deepest_first: bool,
}

/// A tree flattened into postfix (§4.2 "inverse Polish notation", §3.4.1 postfix VST), and the
/// peak stack depth it needs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Postfix {
    ops: Vec<Op>,
    peak: usize,
}

/// A node being flattened: the next child to emit and where its guards start in the pending
/// guard list.
struct EmitFrame<'a> {
    node: &'a CsgNode,
    /// Children in evaluation order (as written, or deepest first).
    order: Vec<&'a CsgNode>,
    next: usize,
    guard_base: usize,
}

impl Postfix {
    /// Flatten `tree` iteratively (no recursion, any depth).
    pub fn compile(tree: &CsgNode, opts: Compile) -> Postfix {
        let needs = if opts.deepest_first {
            stack_needs(tree)
        } else {
            HashMap::new()
        };
        let mut ops = Vec::new();
        // Guards waiting for the end of their chain.
        let mut guards: Vec<usize> = Vec::new();
        let mut stack = vec![EmitFrame::new(tree, &needs, 0)];
        while let Some(f) = stack.last_mut() {
            match f.node {
                CsgNode::Solid(i) => ops.push(Op::Leaf(*i)),
                CsgNode::Empty => ops.push(Op::Const(false)),
                CsgNode::Complement(c) if f.next == 0 => {
                    f.next = 1;
                    stack.push(EmitFrame::new(c, &needs, guards.len()));
                    continue;
                }
                CsgNode::Complement(_) => ops.push(Op::Not),
                _ if f.order.is_empty() => ops.push(Op::Const(false)),
                op => {
                    // Child `next - 1` has just been emitted; it closes a binary operator
                    // unless it was the first operand.
                    if f.next >= 2 {
                        ops.push(binary_op(op));
                    }
                    if f.next < f.order.len() {
                        if f.next >= 1 && opts.short_circuit {
                            guards.push(ops.len());
                            ops.push(Op::Guard {
                                absorb: matches!(op, CsgNode::Union(_)),
                                to: 0, // patched at the end of the chain
                            });
                        }
                        let child = f.order[f.next];
                        f.next += 1;
                        stack.push(EmitFrame::new(child, &needs, guards.len()));
                        continue;
                    }
                    // End of the chain: its guards jump here.
                    let end = ops.len();
                    for &g in &guards[f.guard_base..] {
                        if let Op::Guard { to, .. } = &mut ops[g] {
                            *to = end;
                        }
                    }
                    guards.truncate(f.guard_base);
                }
            }
            stack.pop();
        }
        let peak = peak_depth(&ops);
        Postfix { ops, peak }
    }

    /// The instructions, in execution order.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// The deepest the stack gets (with guards, the deepest it can get).
    pub fn peak_depth(&self) -> usize {
        self.peak
    }

    /// What one run of the whole program costs (§5.5 units, see [`StackEval`]): a comparison
    /// per instruction (is it an operand or an operator?), a push per operand and per operator
    /// result, a pop per operand an operator takes. The final read of the result is not a pop,
    /// as in §5.5's 2(T − 1). Guards, which only per-voxel programs have, count nothing.
    pub fn static_counts(&self) -> OpCounts {
        let mut c = OpCounts::default();
        for op in &self.ops {
            let (pops, pushes) = match op {
                Op::Leaf(_) | Op::Const(_) => (0, 1),
                Op::Not => (1, 1),
                Op::And | Op::Or | Op::AndNot => (2, 1),
                Op::Guard { .. } => continue,
            };
            c.comparisons += 1;
            c.pops += pops;
            c.pushes += pushes;
        }
        c
    }
}

impl<'a> EmitFrame<'a> {
    /// `guard_base`: guards pending when the node starts; those after it are the node's own.
    fn new(
        node: &'a CsgNode,
        needs: &HashMap<*const CsgNode, usize>,
        guard_base: usize,
    ) -> EmitFrame<'a> {
        let mut order: Vec<&CsgNode> = node.children().iter().collect();
        let commutative = matches!(node, CsgNode::Union(_) | CsgNode::Intersection(_));
        if commutative && !needs.is_empty() && !order.is_empty() {
            // The first child needing the deepest stack goes first; the rest keep their order.
            let need = |c: &CsgNode| needs.get(&(c as *const CsgNode)).copied().unwrap_or(1);
            let mut best = 0;
            for (k, c) in order.iter().enumerate() {
                if need(c) > need(order[best]) {
                    best = k;
                }
            }
            let deepest = order.remove(best);
            order.insert(0, deepest);
        }
        EmitFrame {
            node,
            order,
            next: 0,
            guard_base,
        }
    }
}

/// The binary operator a chain node applies between operands.
fn binary_op(node: &CsgNode) -> Op {
    match node {
        CsgNode::Union(_) => Op::Or,
        CsgNode::Intersection(_) => Op::And,
        _ => Op::AndNot,
    }
}

/// Stack depth each node needs when its operands are taken deepest first, by node address,
/// computed bottom-up with an explicit stack. A chain c0 c1 op c2 op … needs
/// max(need(c0), 1 + need(cj) for j ≥ 1).
fn stack_needs(tree: &CsgNode) -> HashMap<*const CsgNode, usize> {
    let mut needs: HashMap<*const CsgNode, usize> = HashMap::new();
    let mut stack = vec![(tree, false)];
    while let Some((node, expanded)) = stack.pop() {
        let children = node.children();
        if !expanded && !children.is_empty() {
            stack.push((node, true));
            stack.extend(children.iter().map(|c| (c, false)));
            continue;
        }
        let child_needs: Vec<usize> = children
            .iter()
            .map(|c| needs.get(&(c as *const CsgNode)).copied().unwrap_or(1))
            .collect();
        let need = match node {
            CsgNode::Complement(_) => child_needs.first().copied().unwrap_or(1),
            CsgNode::Difference(_) => chain_need(&child_needs),
            _ if child_needs.is_empty() => 1,
            _ => {
                // Deepest first: the maximum goes first, the others ride one level up.
                let mut sorted = child_needs.clone();
                sorted.sort_unstable_by(|a, b| b.cmp(a));
                chain_need(&sorted)
            }
        };
        needs.insert(node as *const CsgNode, need);
    }
    needs
}

/// Stack depth of the chain c0 c1 op c2 op … given each operand's own need.
fn chain_need(needs: &[usize]) -> usize {
    let mut need = needs.first().copied().unwrap_or(1);
    for &n in needs.iter().skip(1) {
        need = need.max(n + 1);
    }
    need
}

/// The deepest the stack gets running `ops` straight through (guards never taken).
fn peak_depth(ops: &[Op]) -> usize {
    let (mut depth, mut peak) = (0usize, 0usize);
    for op in ops {
        match op {
            Op::Leaf(_) | Op::Const(_) => depth += 1,
            Op::And | Op::Or | Op::AndNot => depth = depth.saturating_sub(1),
            Op::Not | Op::Guard { .. } => {}
        }
        peak = peak.max(depth);
    }
    peak
}

// ---------------------------------------------------------------------------------------------
// Baseline 1: the tree, voxel by voxel (§4.2)

/// §4.2 Procedure ClassifyAgainstTree, run voxel by voxel on the postfix form of the tree
/// ("could be evaluated without recursion … would use a stack").
///
/// Counts per voxel: a comparison per leaf classification looked up (InPrimitive), a push per
/// operand and per operator result, two pops per binary operator and one per complement.
/// Without short-circuit that is T comparisons, 2T − 1 pushes and 2(T − 1) pops per voxel for
/// T operands; with it, what the voxel actually needed.
#[derive(Clone, Debug)]
pub struct TreeEval {
    prog: Postfix,
    order: LeafOrder,
}

impl TreeEval {
    /// The procedure as printed: every leaf visited.
    pub fn new(tree: &CsgNode) -> TreeEval {
        TreeEval::with(tree, Compile::default())
    }

    /// With §4.2's improvement: skip an operand whose value cannot change the result (A false
    /// in A ∩ B or A − B, A true in A ∪ B).
    pub fn short_circuit(tree: &CsgNode) -> TreeEval {
        TreeEval::with(
            tree,
            Compile {
                short_circuit: true,
                ..Compile::default()
            },
        )
    }

    /// Any compile options.
    pub fn with(tree: &CsgNode, opts: Compile) -> TreeEval {
        TreeEval {
            prog: Postfix::compile(tree, opts),
            order: LeafOrder::new(tree),
        }
    }

    /// The postfix program run at every voxel.
    pub fn program(&self) -> &Postfix {
        &self.prog
    }

    /// The scene's membership in this slice, voxel by voxel.
    pub fn inside(&self, prims: &[Mask], counts: &mut OpCounts) -> Mask {
        let n = slice_len(prims);
        let mut inside = Mask::new(n);
        let mut stack = Vec::with_capacity(self.prog.peak);
        let mut tally = OpCounts::default();
        for i in 0..n {
            let bit = |p: usize| prims.get(p).is_some_and(|m| i < m.len() && m.get(i));
            if run_voxel(&self.prog.ops, bit, &mut stack, &mut tally) {
                inside.set(i, true);
            }
        }
        *counts += tally;
        inside
    }
}

/// Run the program for one voxel on a stack of binary values.
fn run_voxel(
    ops: &[Op],
    bit: impl Fn(usize) -> bool,
    stack: &mut Vec<bool>,
    tally: &mut OpCounts,
) -> bool {
    stack.clear();
    let mut pc = 0;
    while let Some(&op) = ops.get(pc) {
        pc += 1;
        match op {
            Op::Leaf(p) => {
                tally.comparisons += 1;
                tally.pushes += 1;
                stack.push(bit(p));
            }
            Op::Const(v) => {
                tally.pushes += 1;
                stack.push(v);
            }
            Op::Not => {
                tally.pops += 1;
                tally.pushes += 1;
                if let Some(top) = stack.last_mut() {
                    *top = !*top;
                }
            }
            Op::And | Op::Or | Op::AndNot => {
                tally.pops += 2;
                tally.pushes += 1;
                let b = stack.pop().unwrap_or(false);
                if let Some(a) = stack.last_mut() {
                    *a = match op {
                        Op::And => *a & b,
                        Op::Or => *a | b,
                        _ => *a & !b,
                    };
                }
            }
            Op::Guard { absorb, to } => {
                if stack.last() == Some(&absorb) {
                    pc = to;
                }
            }
        }
    }
    stack.last().copied().unwrap_or(false)
}

impl SliceEval for TreeEval {
    fn eval(&self, prims: &[Mask], counts: &mut OpCounts) -> Labels {
        let inside = self.inside(prims, counts);
        colour_labels(&self.order, prims, &inside)
    }

    /// A stack of peak-depth bits per voxel: what every pixel processor would hold to run the
    /// tree in parallel (the software loop reuses one). §4.2's recursive procedure needs H bits,
    /// the height of the binary tree; the postfix form needs its peak depth, never more.
    fn state_bytes(&self, pixels: usize) -> usize {
        pixels.saturating_mul(self.prog.peak).div_ceil(8)
    }
}

// ---------------------------------------------------------------------------------------------
// Baseline 2: the slice stack (§3.4.1)

/// What one push, pop or comparison of [`StackEval`] stands for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum StackUnit {
    /// One per whole-slice operation, as §3.4.1 and §5.5 count (push(S), pop()).
    #[default]
    Slice,
    /// One per 64-pixel word the operation touches.
    Word,
    /// One per voxel of the slice, to set beside the per-voxel counts of the other evaluators.
    Voxel,
}

/// §3.4.1 slice sweeping: the postfix program run once per slice over a stack of whole slices,
/// 64 pixels per word operation (AND, OR, AND NOT, NOT).
///
/// Counts (§5.5) per slice, in [`StackUnit`]s: a comparison per postfix node read (operator or
/// operand?), a push per operand slice and per operator result, a pop per operand an operator
/// takes. For T operands: 2T − 1 comparisons, 2T − 1 pushes, 2(T − 1) pops.
#[derive(Clone, Debug)]
pub struct StackEval {
    prog: Postfix,
    order: LeafOrder,
    unit: StackUnit,
    per_run: OpCounts,
}

impl StackEval {
    /// Operands as written, counts per slice.
    pub fn new(tree: &CsgNode) -> StackEval {
        StackEval::with(tree, Compile::default())
    }

    /// Any compile options (guards are ignored: a slice has no single value to test).
    pub fn with(tree: &CsgNode, opts: Compile) -> StackEval {
        let prog = Postfix::compile(
            tree,
            Compile {
                short_circuit: false,
                ..opts
            },
        );
        StackEval {
            per_run: prog.static_counts(),
            prog,
            order: LeafOrder::new(tree),
            unit: StackUnit::Slice,
        }
    }

    /// Count in another unit.
    pub fn with_unit(mut self, unit: StackUnit) -> StackEval {
        self.unit = unit;
        self
    }

    /// The postfix program swept over whole slices.
    pub fn program(&self) -> &Postfix {
        &self.prog
    }

    /// The scene's membership in this slice.
    pub fn inside(&self, prims: &[Mask], counts: &mut OpCounts) -> Mask {
        let n = slice_len(prims);
        let mut stack: Vec<Mask> = (0..self.prog.peak).map(|_| Mask::new(n)).collect();
        let mut sp = 0;
        for &op in &self.prog.ops {
            sp = apply(&mut stack, sp, op, prims);
        }
        *counts += self.scaled(n);
        match sp.checked_sub(1).and_then(|top| stack.get(top)) {
            Some(result) => result.clone(),
            None => Mask::new(n),
        }
    }

    /// One slice's counts in the chosen unit.
    fn scaled(&self, pixels: usize) -> OpCounts {
        let k = match self.unit {
            StackUnit::Slice => 1,
            StackUnit::Word => pixels.div_ceil(64) as u64,
            StackUnit::Voxel => pixels as u64,
        };
        let c = self.per_run;
        OpCounts {
            comparisons: c.comparisons * k,
            pushes: c.pushes * k,
            pops: c.pops * k,
            label_writes: 0,
        }
    }
}

/// Apply one instruction to the slice stack whose top is `sp - 1`; return the new `sp`.
fn apply(stack: &mut [Mask], sp: usize, op: Op, prims: &[Mask]) -> usize {
    match op {
        Op::Leaf(p) => {
            if let Some(dst) = stack.get_mut(sp) {
                load(dst, prims.get(p));
            }
            sp + 1
        }
        Op::Const(v) => {
            if let Some(dst) = stack.get_mut(sp) {
                dst.words_mut().fill(if v { !0 } else { 0 });
                dst.clear_tail();
            }
            sp + 1
        }
        Op::Not => {
            if let Some(top) = sp.checked_sub(1).and_then(|t| stack.get_mut(t)) {
                top.words_mut().iter_mut().for_each(|w| *w = !*w);
                top.clear_tail();
            }
            sp
        }
        Op::And | Op::Or | Op::AndNot => {
            if sp >= 2 {
                let (lo, hi) = stack.split_at_mut(sp - 1);
                let (a, b) = (&mut lo[sp - 2], &hi[0]);
                combine(a, b, op);
            }
            sp.saturating_sub(1)
        }
        Op::Guard { .. } => sp,
    }
}

/// a = a op b, word by word.
fn combine(a: &mut Mask, b: &Mask, op: Op) {
    let words = a.words_mut().iter_mut().zip(b.words());
    match op {
        Op::And => words.for_each(|(x, y)| *x &= y),
        Op::Or => words.for_each(|(x, y)| *x |= y),
        _ => words.for_each(|(x, y)| *x &= !y),
    }
}

/// Copy a primitive's mask into a stack slot; a missing mask is empty, a short one is padded.
fn load(dst: &mut Mask, src: Option<&Mask>) {
    let src = src.map_or(&[][..], Mask::words);
    for (w, d) in dst.words_mut().iter_mut().enumerate() {
        *d = src.get(w).copied().unwrap_or(0);
    }
    dst.clear_tail();
}

impl SliceEval for StackEval {
    fn eval(&self, prims: &[Mask], counts: &mut OpCounts) -> Labels {
        let inside = self.inside(prims, counts);
        colour_labels(&self.order, prims, &inside)
    }

    /// Peak stack depth × the bytes of one slice mask (one bit per pixel, whole words).
    fn state_bytes(&self, pixels: usize) -> usize {
        self.prog.peak.saturating_mul(pixels.div_ceil(64) * 8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use CsgNode::{Complement, Difference, Empty, Intersection, Solid, Union};

    fn prims(bits: &[&[bool]]) -> Vec<Mask> {
        bits.iter()
            .map(|b| Mask::from_fn(b.len(), |i| b[i]))
            .collect()
    }

    #[test]
    fn section_4_2_example_postfix() {
        // (A ∩ (B ∪ C)) − (D ∪ (E ∩ F)) − G  →  # # # ∪ ∩ # # # ∩ ∪ − # −
        let t = Difference(vec![
            Intersection(vec![Solid(0), Union(vec![Solid(1), Solid(2)])]),
            Union(vec![Solid(3), Intersection(vec![Solid(4), Solid(5)])]),
            Solid(6),
        ]);
        let p = Postfix::compile(&t, Compile::default());
        use Op::*;
        assert_eq!(
            p.ops(),
            &[
                Leaf(0),
                Leaf(1),
                Leaf(2),
                Or,
                And,
                Leaf(3),
                Leaf(4),
                Leaf(5),
                And,
                Or,
                AndNot,
                Leaf(6),
                AndNot
            ]
        );
        assert_eq!(p.peak_depth(), 4);
    }

    #[test]
    fn direct_reads_empty_and_degenerate_nodes() {
        let none = |_| true;
        assert!(!direct(&Empty, none));
        assert!(direct(&Complement(Box::new(Empty)), none));
        assert!(!direct(&Union(vec![]), none));
        assert!(!direct(&Intersection(vec![]), none));
        assert!(!direct(&Difference(vec![]), none));
        assert!(direct(&Difference(vec![Solid(0)]), |i| i == 0));
    }

    #[test]
    fn colour_rule_prefers_positive_literals() {
        // !(B − C) ∪ A = B' ∪ C ∪ A: C and A positive, B negative.
        let t = Union(vec![
            Complement(Box::new(Difference(vec![Solid(1), Solid(2)]))),
            Solid(0),
        ]);
        let order = LeafOrder::new(&t);
        assert_eq!(order.positive(), &[2, 0]);
        assert_eq!(order.first_leaf(), Some(1));
        // pixel 0: in A, B, C → C; pixel 1: in A, B → A; pixel 2: in nothing → via B' → B;
        // pixel 3: in B only → outside.
        let m = prims(&[
            &[true, true, false, false],
            &[true, true, false, true],
            &[true, false, false, false],
        ]);
        let mut c = OpCounts::default();
        assert_eq!(TreeEval::new(&t).eval(&m, &mut c), vec![3, 1, 2, 0]);
        assert_eq!(StackEval::new(&t).eval(&m, &mut c), vec![3, 1, 2, 0]);
    }

    #[test]
    fn short_circuit_skips_decided_operands() {
        let t = Intersection(vec![Solid(0), Solid(1), Solid(2)]);
        let m = prims(&[&[false, true], &[true, true], &[true, false]]);
        let mut c = OpCounts::default();
        let inside = TreeEval::short_circuit(&t).inside(&m, &mut c);
        assert_eq!(inside.ones().collect::<Vec<_>>(), Vec::<usize>::new());
        // pixel 0: A false, stop (1 leaf, 1 push); pixel 1: all three (3 leaves, 5 pushes,
        // 4 pops).
        assert_eq!((c.comparisons, c.pushes, c.pops), (4, 6, 4));
    }

    #[test]
    fn deepest_first_lowers_the_peak() {
        let mut t = Solid(0);
        for i in 1..50 {
            t = Union(vec![Solid(i), t]);
        }
        assert_eq!(StackEval::new(&t).program().peak_depth(), 50);
        let opts = Compile {
            deepest_first: true,
            ..Compile::default()
        };
        let s = StackEval::with(&t, opts);
        assert_eq!(s.program().peak_depth(), 2);
        assert_eq!(s.program().static_counts().pushes, 99);
        assert_eq!(tree_depth(&t), 50);
        assert_eq!(leaf_count(&t), 50);
    }

    // The tests every evaluator passes, for each evaluator and each way of compiling it.
    crate::slice::suite::slice_eval_suite!(tree, TreeEval::new);
    crate::slice::suite::slice_eval_suite!(tree_short_circuit, TreeEval::short_circuit);
    crate::slice::suite::slice_eval_suite!(stack, StackEval::new);
    crate::slice::suite::slice_eval_suite!(stack_deepest_first, |t| StackEval::with(
        t,
        Compile {
            deepest_first: true,
            ..Compile::default()
        }
    ));
}
