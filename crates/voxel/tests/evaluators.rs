//! The two baseline evaluators (§4.2 tree per voxel, §3.4.1 slice stack) against each other,
//! against their colour rule and the reference `direct`, on trees as deep as files can make,
//! and against the operation counts of §5.5. What every evaluator, the Blist (§4.5) included,
//! must do is the shared suite's (`slice_eval_suite!`, crates/voxel/src/slice/suite.rs).

use csgpix_scene::solid::CsgNode;
use csgpix_voxel::evaluate::{
    direct, leaf_count, tree_depth, Compile, StackEval, StackUnit, TreeEval,
};
use csgpix_voxel::slice::{Labels, Mask, OpCounts, SliceEval};
use proptest::prelude::*;

use CsgNode::{Complement, Difference, Empty, Intersection, Solid, Union};

// ---------------------------------------------------------------------------------------------
// Helpers

/// Masks for `count` primitives over `len` pixels from a seed: each primitive gets its own
/// density (some empty, some full) so that every operator meets both values.
fn masks(count: usize, len: usize, seed: u64) -> Vec<Mask> {
    let mut state = seed | 1;
    let mut next = move || {
        // xorshift64*
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        state.wrapping_mul(0x2545_F491_4F6C_DD1D)
    };
    (0..count)
        .map(|_| {
            let density = next() % 9; // in eighths; 0 = empty, 8 = full
            Mask::from_fn(len, |_| next() % 8 < density)
        })
        .collect()
}

/// The colour rule, written out per pixel from its definition (docs/evaluators.md): the first
/// leaf in tree order that is a positive literal and contains the pixel, else the first leaf.
fn colour_by_definition(tree: &CsgNode, prims: &[Mask], inside: &Mask) -> Labels {
    // Leaves in order with their parity (odd = under an odd number of complements, where a
    // subtracted operand of a difference counts as one).
    let mut leaves = vec![];
    let mut stack = vec![(tree, false)];
    while let Some((node, odd)) = stack.pop() {
        match node {
            Solid(i) => leaves.push((*i, odd)),
            Complement(c) => stack.push((c, !odd)),
            Difference(cs) => {
                for (k, c) in cs.iter().enumerate().rev() {
                    stack.push((c, odd ^ (k > 0)));
                }
            }
            _ => stack.extend(node.children().iter().rev().map(|c| (c, odd))),
        }
    }
    (0..inside.len())
        .map(|px| {
            if !inside.get(px) {
                return 0;
            }
            let positive = leaves
                .iter()
                .find(|&&(p, odd)| !odd && prims[p].get(px))
                .map(|&(p, _)| p);
            let first = leaves.first().map(|&(p, _)| p);
            positive.or(first).map_or(1, |p| p as u32 + 1)
        })
        .collect()
}

/// The baselines on `tree`, every way of compiling them, checked against the colour
/// definition. Membership alone, the Blist's included, is the shared suite's
/// (`slice_eval_suite!` in crates/voxel/src/slice/suite.rs).
fn check_all(tree: &CsgNode, prims: &[Mask]) {
    let n = prims.first().map_or(0, Mask::len);
    let expect = Mask::from_fn(n, |px| direct(tree, |p| prims[p].get(px)));
    let want = colour_by_definition(tree, prims, &expect);
    let deepest = Compile {
        deepest_first: true,
        ..Compile::default()
    };
    let evals: Vec<(&str, Box<dyn SliceEval>)> = vec![
        ("tree", Box::new(TreeEval::new(tree))),
        (
            "tree short-circuit",
            Box::new(TreeEval::short_circuit(tree)),
        ),
        ("stack", Box::new(StackEval::new(tree))),
        (
            "stack deepest-first",
            Box::new(StackEval::with(tree, deepest)),
        ),
    ];
    for (name, e) in &evals {
        let got = e.eval(prims, &mut OpCounts::default());
        assert_eq!(got, want, "{name} labels");
    }
    let mut c = OpCounts::default();
    assert_eq!(TreeEval::new(tree).inside(prims, &mut c), expect);
    assert_eq!(StackEval::new(tree).inside(prims, &mut c), expect);
}

// ---------------------------------------------------------------------------------------------
// Random trees

/// Trees over up to 64 primitives with every node kind, n-ary nodes from 0 to 4 children.
fn tree() -> impl Strategy<Value = CsgNode> {
    let leaf = prop_oneof![
        10 => (0usize..64).prop_map(Solid),
        1 => Just(Empty),
    ];
    leaf.prop_recursive(7, 80, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..5).prop_map(Union),
            prop::collection::vec(inner.clone(), 0..5).prop_map(Intersection),
            prop::collection::vec(inner.clone(), 0..5).prop_map(Difference),
            inner.prop_map(|c| Complement(Box::new(c))),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// TreeEval and StackEval give the same labels, membership is `direct`'s, colours follow
    /// the rule; slice sizes include ones that are not a multiple of 64.
    #[test]
    fn evaluators_agree(t in tree(), len in 1usize..300, seed in any::<u64>()) {
        let prims = masks(64, len, seed);
        check_all(&t, &prims);
    }

    /// Counts per slice and per voxel follow from the program, whatever the tree.
    #[test]
    fn counts_follow_the_program(t in tree(), len in 1usize..300, seed in any::<u64>()) {
        let prims = masks(64, len, seed);
        let stack = StackEval::new(&t);
        let per_slice = stack.program().static_counts();
        let mut c = OpCounts::default();
        stack.eval(&prims, &mut c);
        prop_assert_eq!(c, per_slice);

        let mut c = OpCounts::default();
        stack.clone().with_unit(StackUnit::Word).eval(&prims, &mut c);
        prop_assert_eq!(c.pushes, per_slice.pushes * len.div_ceil(64) as u64);

        // The tree, without short-circuit, does the same pushes and pops for every voxel, and
        // looks up every leaf; short-circuit never does more.
        let mut full = OpCounts::default();
        TreeEval::new(&t).eval(&prims, &mut full);
        let n = len as u64;
        prop_assert_eq!(full.pushes, per_slice.pushes * n);
        prop_assert_eq!(full.pops, per_slice.pops * n);
        prop_assert_eq!(full.comparisons, leaf_count(&t) as u64 * n);
        let mut short = OpCounts::default();
        TreeEval::short_circuit(&t).eval(&prims, &mut short);
        prop_assert!(short.comparisons <= full.comparisons);
        prop_assert!(short.pushes <= full.pushes && short.pops <= full.pops);
    }
}

// ---------------------------------------------------------------------------------------------
// Deep trees: no recursion anywhere (this runs on the test harness's small thread stack)

const DEEP: usize = 100_000;

/// `make(previous, level)` applied DEEP times to `Solid(0)`.
fn deep(make: impl Fn(CsgNode, usize) -> CsgNode) -> CsgNode {
    (1..=DEEP).fold(Solid(0), make)
}

fn deep_check(t: &CsgNode, depth: usize) {
    assert_eq!(tree_depth(t), depth);
    let prims = masks(8, 70, 0xdee9);
    check_all(t, &prims);
    let stack = StackEval::new(t);
    assert_eq!(
        stack.state_bytes(70),
        stack.program().peak_depth() * 16,
        "two words per mask"
    );
}

#[test]
fn deep_unions_left_and_right() {
    // Left-nested: ((A ∪ B) ∪ C) ∪ …, peak depth 2.
    let left = deep(|t, i| Union(vec![t, Solid(i % 8)]));
    deep_check(&left, DEEP + 1);
    assert_eq!(StackEval::new(&left).program().peak_depth(), 2);
    // Right-nested: A ∪ (B ∪ (C ∪ …)), peak depth DEEP + 1 as written, 2 deepest first.
    let right = deep(|t, i| Union(vec![Solid(i % 8), t]));
    deep_check(&right, DEEP + 1);
    assert_eq!(StackEval::new(&right).program().peak_depth(), DEEP + 1);
    let opts = Compile {
        deepest_first: true,
        ..Compile::default()
    };
    assert_eq!(StackEval::with(&right, opts).program().peak_depth(), 2);
    assert_eq!(leaf_count(&right), DEEP + 1);
}

#[test]
fn deep_difference_intersection_and_complement_chains() {
    let diff = deep(|t, i| Difference(vec![t, Solid(i % 8)]));
    deep_check(&diff, DEEP + 1);
    let sub = deep(|t, i| Difference(vec![Solid(i % 8), t]));
    deep_check(&sub, DEEP + 1);
    let inter = deep(|t, i| Intersection(vec![Solid(i % 8), t]));
    deep_check(&inter, DEEP + 1);
    let not = deep(|t, _| Complement(Box::new(t)));
    deep_check(&not, DEEP + 1);
    let mixed = deep(|t, i| match i % 4 {
        0 => Union(vec![Solid(i % 8), t]),
        1 => Complement(Box::new(t)),
        2 => Difference(vec![t, Solid(i % 8), Empty]),
        _ => Intersection(vec![Solid(i % 8), t, Complement(Box::new(Solid(3)))]),
    });
    deep_check(&mixed, DEEP + 1);
}

// ---------------------------------------------------------------------------------------------
// §5.5 operation counts

/// A binary tree over T operands of a shape picked by `shape` (0: left chain, 1: right chain,
/// 2: balanced), operators cycling through ∪ ∩ −.
fn binary_tree(t: usize, shape: u8) -> CsgNode {
    fn op(k: usize, a: CsgNode, b: CsgNode) -> CsgNode {
        match k % 3 {
            0 => Union(vec![a, b]),
            1 => Intersection(vec![a, b]),
            _ => Difference(vec![a, b]),
        }
    }
    let mut level: Vec<CsgNode> = (0..t).map(Solid).collect();
    match shape {
        0 => {
            let mut it = level.into_iter();
            let first = it.next().unwrap_or(Empty);
            it.enumerate().fold(first, |acc, (k, b)| op(k, acc, b))
        }
        1 => {
            let last = level.pop().unwrap_or(Empty);
            level
                .into_iter()
                .rev()
                .enumerate()
                .fold(last, |acc, (k, a)| op(k, a, acc))
        }
        _ => {
            let mut k = 0;
            while level.len() > 1 {
                let mut next = vec![];
                let mut it = level.into_iter();
                while let Some(a) = it.next() {
                    match it.next() {
                        Some(b) => {
                            next.push(op(k, a, b));
                            k += 1;
                        }
                        None => next.push(a),
                    }
                }
                level = next;
            }
            level.pop().unwrap_or(Empty)
        }
    }
}

/// §5.5: "if there are T operands, there will be T−1 operators … the number of required push
/// operations is 2T−1 and the number of required pop operations is 2(T−1), and the number of
/// required comparisons is 2T−1" (slice sweeping, per slice). The tree per voxel does the same
/// pushes and pops and T leaf look-ups.
#[test]
fn section_5_5_formulas() {
    for t in 1..=64u64 {
        for shape in 0..3 {
            let tree = binary_tree(t as usize, shape);
            assert_eq!(leaf_count(&tree) as u64, t);
            let prims = masks(64, 100, t * 7 + shape as u64);

            let mut c = OpCounts::default();
            StackEval::new(&tree).eval(&prims, &mut c);
            assert_eq!(
                (c.comparisons, c.pushes, c.pops),
                (2 * t - 1, 2 * t - 1, 2 * (t - 1)),
                "slice stack, T = {t}, shape {shape}"
            );

            let mut c = OpCounts::default();
            TreeEval::new(&tree).eval(&prims, &mut c);
            assert_eq!(
                (c.comparisons, c.pushes, c.pops),
                (t * 100, (2 * t - 1) * 100, 2 * (t - 1) * 100),
                "tree per voxel, T = {t}, shape {shape}"
            );
        }
    }
}

/// N-ary nodes count as their chains of binary operators: the same formulas hold.
#[test]
fn section_5_5_formulas_n_ary() {
    let tree = Difference(vec![
        Union(vec![Solid(0), Solid(1), Solid(2)]),
        Intersection(vec![Solid(3), Solid(4)]),
        Solid(5),
    ]);
    let t = 6;
    let mut c = OpCounts::default();
    StackEval::new(&tree).eval(&masks(6, 10, 1), &mut c);
    assert_eq!(
        (c.comparisons, c.pushes, c.pops),
        (2 * t - 1, 2 * t - 1, 2 * (t - 1))
    );
}

/// Figure 5.6 (five primitives: cube1, cube2, cylinder1, cylinder2, CT head): "9 comparisons
/// … 17 pop, push operations". Any binary tree over five operands gives those counts.
#[test]
fn figure_5_6_counts() {
    for shape in 0..3 {
        let tree = binary_tree(5, shape);
        let mut c = OpCounts::default();
        StackEval::new(&tree).eval(&masks(5, 64, 3), &mut c);
        assert_eq!(c.comparisons, 9);
        assert_eq!(c.pushes + c.pops, 17);
    }
}

/// Bytes of intermediate state: peak depth bits per voxel for both.
#[test]
fn state_bytes() {
    let tree = binary_tree(8, 2); // balanced: peak depth 4
    let stack = StackEval::new(&tree);
    assert_eq!(stack.program().peak_depth(), 4);
    assert_eq!(stack.state_bytes(64), 4 * 8);
    assert_eq!(stack.state_bytes(65), 4 * 16);
    let per_voxel = TreeEval::new(&tree);
    assert_eq!(per_voxel.state_bytes(64), 4 * 8);
    assert_eq!(per_voxel.state_bytes(3), 2); // 12 bits
}
