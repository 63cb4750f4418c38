//! The tests every [`SliceEval`] passes, whatever its method: [`slice_eval_suite!`] writes
//! them out once per evaluator, in the evaluator's own module, so that an evaluator added
//! later gets them by one line and a broken one fails under its own name. What only one
//! evaluator promises (its colour rule, its operation counts, its tables) stays in its own
//! tests.
//!
//! The reference is [`direct`], the recursive reading of the tree; colours are not compared
//! between evaluators (the Blist colours by §4.5, the baselines by their shared rule), only
//! that a voxel inside takes the colour of one of the tree's primitives.

use std::collections::BTreeSet;

use super::{slice_len, Labels, Mask, OpCounts, SliceEval};
use crate::evaluate::direct;
use csgpix_scene::solid::CsgNode;
use proptest::prelude::*;
use CsgNode::{Complement, Difference, Empty, Intersection, Solid, Union};

/// The shared tests of a [`SliceEval`] as a module `$name`; `$make` makes the evaluator of a
/// tree (`fn(&CsgNode) -> impl SliceEval`, a path or a closure).
macro_rules! slice_eval_suite {
    ($name:ident, $make:expr) => {
        mod $name {
            // The evaluator's own module's names, for `$make`; proptest's, which it may
            // already have.
            #[allow(unused_imports)]
            use super::*;
            use csgpix_scene::solid::CsgNode;
            #[allow(unused_imports)]
            use proptest::prelude::*;
            use $crate::slice::suite;

            fn make(tree: &CsgNode) -> impl $crate::slice::SliceEval {
                ($make)(tree)
            }

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(200))]

                /// Membership is `direct`'s on random trees and masks, slices of any length.
                #[test]
                fn membership_is_direct(
                    t in suite::tree(),
                    len in 1usize..300,
                    seed in any::<u64>(),
                ) {
                    suite::check(&make(&t), &t, &suite::masks(64, len, seed));
                }

                /// A short or missing mask is the same as one padded with empty pixels.
                #[test]
                fn short_masks_are_empty_past_their_end(
                    t in suite::tree(),
                    len in 1usize..300,
                    seed in any::<u64>(),
                    cuts in prop::collection::vec(0usize..300, 64),
                    kept in 0usize..=64,
                ) {
                    suite::check_short_masks(&make(&t), &t, len, seed, &cuts, kept);
                }

                /// The state grows with the slice, a whole word at a time.
                #[test]
                fn state_bytes_follow_the_slice(t in suite::tree()) {
                    suite::check_state_bytes(&make(&t));
                }
            }

            #[test]
            fn constant_trees() {
                suite::check_constants(make);
            }

            #[test]
            fn single_primitive_and_its_complement() {
                suite::check_single(make);
            }

            #[test]
            fn deep_union_and_intersection_chains() {
                for (what, t) in suite::deep_unions() {
                    suite::check_deep(&make(&t), &t, what);
                }
            }

            #[test]
            fn deep_difference_and_complement_chains() {
                for (what, t) in suite::deep_differences() {
                    suite::check_deep(&make(&t), &t, what);
                }
            }

            #[test]
            fn counts_add_up_and_labels_repeat() {
                suite::check_repeat(make);
            }
        }
    };
}
pub(crate) use slice_eval_suite;

/// Masks for `count` primitives over `len` pixels from a seed: each primitive gets its own
/// density (some empty, some full) so that every operator meets both values.
pub(crate) fn masks(count: usize, len: usize, seed: u64) -> Vec<Mask> {
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

/// Trees over up to 64 primitives with every node kind, n-ary nodes from 0 to 4 children.
pub(crate) fn tree() -> impl Strategy<Value = CsgNode> {
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

/// The primitives the tree names.
fn leaves(tree: &CsgNode) -> BTreeSet<usize> {
    let mut out = BTreeSet::new();
    let mut stack = vec![tree];
    while let Some(node) = stack.pop() {
        if let Solid(i) = node {
            out.insert(*i);
        }
        stack.extend(node.children());
    }
    out
}

/// Is pixel `px` in primitive `p` (a missing or short mask contains nothing past its end)?
fn in_prim(prims: &[Mask], p: usize, px: usize) -> bool {
    prims.get(p).is_some_and(|m| px < m.len() && m.get(px))
}

/// `e`'s labels of `tree` over `prims`: one per pixel of the slice, non-zero exactly where
/// `direct` puts the pixel inside, and then the colour of one of the tree's primitives, or of
/// primitive 0 where no primitive decides (a constant subtree).
pub(crate) fn check(e: &impl SliceEval, tree: &CsgNode, prims: &[Mask]) -> Labels {
    let labels = e.eval(prims, &mut OpCounts::default());
    assert_eq!(labels.len(), slice_len(prims), "one label per pixel");
    let named = leaves(tree);
    for (px, &label) in labels.iter().enumerate() {
        let inside = direct(tree, |p| in_prim(prims, p, px));
        assert_eq!(label != 0, inside, "pixel {px}: label {label}");
        if let Some(p) = (label as usize).checked_sub(1) {
            assert!(
                named.contains(&p) || p == 0,
                "pixel {px} takes the colour of primitive {p}, which the tree does not name"
            );
        }
    }
    labels
}

/// The masks cut short (mask p to `cuts[p]` pixels, at most `len`) and only the first `kept`
/// of them given: the labels are those of the same masks padded with empty pixels to the
/// slice's length.
pub(crate) fn check_short_masks(
    e: &impl SliceEval,
    tree: &CsgNode,
    len: usize,
    seed: u64,
    cuts: &[usize],
    kept: usize,
) {
    let full = masks(64, len, seed);
    let short: Vec<Mask> = full
        .iter()
        .zip(cuts)
        .take(kept)
        .map(|(m, &cut)| Mask::from_fn(cut.min(len), |i| m.get(i)))
        .collect();
    let n = slice_len(&short);
    let padded: Vec<Mask> = (0..64)
        .map(|p| Mask::from_fn(n, |px| in_prim(&short, p, px)))
        .collect();
    let got = check(e, tree, &short);
    assert_eq!(
        got,
        e.eval(&padded, &mut OpCounts::default()),
        "short masks"
    );
}

/// No state for no pixels, the same state for every whole word of 64 pixels, never less for
/// more pixels, and never more for a slice than for its two parts.
pub(crate) fn check_state_bytes(e: &impl SliceEval) {
    assert_eq!(e.state_bytes(0), 0, "no pixels");
    let word = e.state_bytes(64);
    for k in 1..=8 {
        assert_eq!(e.state_bytes(64 * k), k * word, "{k} words");
    }
    let mut last = 0;
    for n in 0..=200 {
        let b = e.state_bytes(n);
        assert!(b >= last, "{n} pixels: {b} bytes, {last} for one fewer");
        for m in [1, 7, 63, 64, 65] {
            assert!(
                e.state_bytes(n + m) <= b + e.state_bytes(m),
                "{n} + {m} pixels"
            );
        }
        last = b;
    }
    assert!(
        e.state_bytes(1 << 40) >= e.state_bytes(1 << 20),
        "large slices"
    );
}

/// Trees that are nothing, trees that are everything, on a slice and on no slice at all.
pub(crate) fn check_constants<E: SliceEval>(make: impl Fn(&CsgNode) -> E) {
    let prims = masks(3, 70, 7);
    let nothing = [
        Empty,
        Union(vec![]),
        Intersection(vec![]),
        Difference(vec![]),
        Intersection(vec![Solid(0), Empty]),
        Difference(vec![Empty, Solid(1)]),
        Complement(Box::new(Complement(Box::new(Empty)))),
    ];
    for t in &nothing {
        let labels = check(&make(t), t, &prims);
        assert_eq!(labels, vec![0; 70], "{t:?}");
    }
    let everything = [
        Complement(Box::new(Empty)),
        Complement(Box::new(Union(vec![]))),
        Complement(Box::new(Intersection(vec![Solid(1), Empty]))),
        Union(vec![Solid(0), Complement(Box::new(Solid(0)))]),
    ];
    for t in &everything {
        let labels = check(&make(t), t, &prims);
        assert!(labels.iter().all(|&l| l != 0), "{t:?}: {labels:?}");
    }
    for t in nothing.iter().chain(&everything) {
        assert_eq!(make(t).eval(&[], &mut OpCounts::default()), Labels::new());
    }
}

/// One primitive, alone, as the only child of an operator, complemented, and named past the
/// masks given (empty): its colour exactly where it is in (or out).
pub(crate) fn check_single<E: SliceEval>(make: impl Fn(&CsgNode) -> E) {
    let prims = masks(6, 130, 11);
    let a = || Solid(2);
    let mask = &prims[2];
    let inside: Labels = (0..130)
        .map(|px| if mask.get(px) { 3 } else { 0 })
        .collect();
    let outside: Labels = (0..130)
        .map(|px| if mask.get(px) { 0 } else { 3 })
        .collect();
    for t in [
        a(),
        Union(vec![a()]),
        Intersection(vec![a()]),
        Difference(vec![a()]),
        Union(vec![a(), a()]),
        Intersection(vec![a(), a()]),
    ] {
        assert_eq!(check(&make(&t), &t, &prims), inside, "{t:?}");
    }
    for t in [
        Complement(Box::new(a())),
        Difference(vec![Complement(Box::new(a())), Empty]),
    ] {
        assert_eq!(check(&make(&t), &t, &prims), outside, "{t:?}");
    }
    let absent = Solid(9);
    assert_eq!(check(&make(&absent), &absent, &prims), vec![0; 130]);
    let not_absent = Complement(Box::new(Solid(9)));
    let labels = check(&make(&not_absent), &not_absent, &prims);
    assert_eq!(labels, vec![10; 130], "the only primitive's colour");
}

/// Levels of the deep trees: as deep as files can make them. Nothing may recurse on them
/// (the test harness's threads have small stacks).
const DEEP: usize = 100_000;

/// `make(previous, level)` applied DEEP times to `Solid(0)`.
fn deep(make: impl Fn(CsgNode, usize) -> CsgNode) -> CsgNode {
    (1..=DEEP).fold(Solid(0), make)
}

/// Union and intersection chains, nested to the left and to the right.
pub(crate) fn deep_unions() -> Vec<(&'static str, CsgNode)> {
    vec![
        ("left union", deep(|t, i| Union(vec![t, Solid(i % 8)]))),
        ("right union", deep(|t, i| Union(vec![Solid(i % 8), t]))),
        (
            "right intersection",
            deep(|t, i| Intersection(vec![Solid(i % 8), t])),
        ),
    ]
}

/// Difference chains (the tree subtracted from, and subtracted), complement chains, and every
/// node kind mixed.
pub(crate) fn deep_differences() -> Vec<(&'static str, CsgNode)> {
    vec![
        (
            "left difference",
            deep(|t, i| Difference(vec![t, Solid(i % 8)])),
        ),
        (
            "right difference",
            deep(|t, i| Difference(vec![Solid(i % 8), t])),
        ),
        ("complements", deep(|t, _| Complement(Box::new(t)))),
        (
            "mixed",
            deep(|t, i| match i % 5 {
                0 => Union(vec![Solid(i % 8), t]),
                1 => Complement(Box::new(t)),
                2 => Difference(vec![t, Solid(i % 8), Empty]),
                3 => Difference(vec![Solid(i % 64), t]),
                _ => Intersection(vec![Solid(i % 8), t, Complement(Box::new(Solid(3)))]),
            }),
        ),
    ]
}

/// A deep tree over 64 primitives' masks of 70 pixels: the labels [`check`] asks for.
pub(crate) fn check_deep(e: &impl SliceEval, tree: &CsgNode, what: &str) {
    let labels = check(e, tree, &masks(64, 70, 0xdee9));
    assert_eq!(labels.len(), 70, "{what}");
}

/// The same slice twice: the same labels, and the counts of both (counts add, they are
/// never reset).
pub(crate) fn check_repeat<E: SliceEval>(make: impl Fn(&CsgNode) -> E) {
    let t = Difference(vec![
        Union(vec![Solid(0), Solid(1), Solid(2)]),
        Intersection(vec![Solid(3), Complement(Box::new(Solid(4)))]),
        Solid(5),
    ]);
    let e = make(&t);
    let prims = masks(6, 100, 5);
    let mut once = OpCounts::default();
    let first = e.eval(&prims, &mut once);
    assert!(
        once != OpCounts::default(),
        "a tree of leaves costs something"
    );
    let mut twice = once;
    let second = e.eval(&prims, &mut twice);
    assert_eq!(first, second);
    let mut sum = once;
    sum += once;
    assert_eq!(twice, sum);
}
