//! The Blist of §4.3-4.5 against the thesis's printed tables (transcribed in `vectors/blist/`),
//! against direct evaluation of the tree, and on trees too deep for recursion.

use std::collections::BTreeMap;

use csgpix_scene::csg_expr::parse;
use csgpix_scene::solid::CsgNode;
use csgpix_voxel::blist::{BlistRow, BlistTable};
use proptest::prelude::*;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// The tree of Figure 4.4 (its text is garbled in the OCR).
const FIGURE_4_4: &str = "(A+B)-((C+(D-E)).(F+G))";

/// A tree whose table is Table 5.1 (docs/blist.md: how it was found).
const FIGURE_5_6: &str = "(A+B+C)-(D+E)";

/// A printed table: rows of whitespace-separated fields, header and `#` lines skipped.
fn printed(file: &str) -> Vec<Vec<String>> {
    let path = format!("{ROOT}/vectors/blist/{file}");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('P'))
        .map(|l| l.split('\t').map(str::to_string).collect())
        .collect()
}

/// The printed columns P, name, sign, reference, stamp as rows over `names`.
fn printed_rows(file: &str, names: &[String]) -> Vec<BlistRow> {
    printed(file)
        .iter()
        .enumerate()
        .map(|(k, f)| {
            assert_eq!(f[0], (k + 1).to_string(), "{file}: P column");
            BlistRow {
                name: f[1].parse().unwrap(),
                sign: match f[2].as_str() {
                    "+" => true,
                    "-" => false,
                    s => panic!("{file}: sign {s:?}"),
                },
                prim: names.iter().position(|n| *n == f[3]).unwrap(),
                stamp: f[4].parse().unwrap(),
            }
        })
        .collect()
}

/// Direct evaluation of a tree, with an explicit stack (the reference the Blist must equal):
/// n-ary operators literally, `Empty` and operators without operands are nothing.
fn direct(root: &CsgNode, inside: &impl Fn(usize) -> bool) -> bool {
    enum Task<'a> {
        Visit(&'a CsgNode),
        Build(&'a CsgNode, usize),
    }
    let mut tasks = vec![Task::Visit(root)];
    let mut vals: Vec<bool> = vec![];
    while let Some(t) = tasks.pop() {
        match t {
            Task::Visit(CsgNode::Solid(i)) => vals.push(inside(*i)),
            Task::Visit(n) => {
                tasks.push(Task::Build(n, n.children().len()));
                tasks.extend(n.children().iter().rev().map(Task::Visit));
            }
            Task::Build(n, k) => {
                let v = vals.split_off(vals.len() - k);
                vals.push(match n {
                    CsgNode::Union(_) => v.iter().any(|&b| b),
                    CsgNode::Intersection(_) => !v.is_empty() && v.iter().all(|&b| b),
                    CsgNode::Difference(_) => !v.is_empty() && v[0] && !v[1..].iter().any(|&b| b),
                    CsgNode::Complement(_) => !v[0],
                    _ => false,
                });
            }
        }
    }
    vals.pop().unwrap()
}

#[test]
fn figure_4_4_gives_table_4_1() {
    let e = parse(FIGURE_4_4).unwrap();
    let t = BlistTable::compile(&e.root);
    assert_eq!(t.rows, printed_rows("table-4.1.txt", &e.names));
    assert_eq!((t.in_name, t.label_bits), (1, 2));
}

#[test]
fn voxel_0100110_gives_the_labels_of_table_4_2() {
    let e = parse(FIGURE_4_4).unwrap();
    let t = BlistTable::compile(&e.root);
    let table = printed("table-4.2.txt");
    assert_eq!(t.rows, printed_rows("table-4.2.txt", &e.names));
    let bits = b"0100110"; // A..G
    let inside = |p: usize| bits[p] == b'1';
    let mut trace = vec![];
    assert!(t.classify(inside, Some(&mut trace)));
    assert!(direct(&e.root, &inside));
    for (k, f) in table.iter().enumerate() {
        let class = u8::from(inside(t.rows[k].prim)).to_string();
        assert_eq!(f[5], class, "Class column, row {}", k + 1);
        assert_eq!(f[6], trace[k].to_string(), "label column, row {}", k + 1);
    }
}

#[test]
fn figure_5_6_tree_gives_table_5_1() {
    let e = parse(FIGURE_5_6).unwrap();
    let t = BlistTable::compile(&e.root);
    assert_eq!(t.rows, printed_rows("table-5.1.txt", &e.names));
    assert_eq!((t.in_name, t.label_bits), (1, 2));
}

/// All binary trees over the leaves `0..n` in order, as (postfix shape) lists of operator slots.
fn shapes(n: usize) -> Vec<String> {
    if n == 1 {
        return vec!["x".into()];
    }
    let mut out = vec![];
    for k in 1..n {
        for l in shapes(k) {
            for r in shapes(n - k) {
                out.push(format!("({l}o{r})"));
            }
        }
    }
    out
}

/// Every permutation of `v`.
fn permutations(v: &[char]) -> Vec<Vec<char>> {
    if v.len() <= 1 {
        return vec![v.to_vec()];
    }
    let mut out = vec![];
    for i in 0..v.len() {
        let mut rest = v.to_vec();
        let c = rest.remove(i);
        for mut p in permutations(&rest) {
            p.insert(0, c);
            out.push(p);
        }
    }
    out
}

/// The search of docs/blist.md: every binary tree with the five leaves A..E in any order and
/// any of the operators ∪, ∩, − whose table is Table 5.1, grouped by the Boolean function.
#[test]
fn table_5_1_search() {
    let names: Vec<String> = "ABCDE".chars().map(String::from).collect();
    let want = printed_rows("table-5.1.txt", &names);
    let mut found: BTreeMap<u32, Vec<String>> = BTreeMap::new();
    let mut tried = 0;
    for shape in shapes(5) {
        for perm in permutations(&['A', 'B', 'C', 'D', 'E']) {
            for ops in 0..81u32 {
                let (mut leaf, mut op) = (perm.iter(), ops);
                let text: String = shape
                    .chars()
                    .map(|c| match c {
                        'x' => *leaf.next().unwrap(),
                        'o' => {
                            let s = ['+', '.', '-'][(op % 3) as usize];
                            op /= 3;
                            s
                        }
                        c => c,
                    })
                    .collect();
                tried += 1;
                let mut e = parse(&text).unwrap();
                // Solid(i) is primitive letter i, whatever the order in the text.
                let remap: Vec<usize> = e
                    .names
                    .iter()
                    .map(|n| names.iter().position(|m| m == n).unwrap())
                    .collect();
                relabel(&mut e.root, &remap);
                if BlistTable::compile(&e.root).rows == want {
                    let truth = (0..32u32)
                        .filter(|m| direct(&e.root, &|p| m >> p & 1 == 1))
                        .fold(0, |a, m| a | 1 << m);
                    found.entry(truth).or_default().push(text);
                }
            }
        }
    }
    assert_eq!(tried, 14 * 120 * 81);
    for (truth, trees) in &found {
        println!(
            "function {truth:#010x}: {} trees, e.g. {:?}",
            trees.len(),
            &trees[..trees.len().min(8)]
        );
    }
    let total: usize = found.values().map(Vec::len).sum();
    println!("{total} of {tried} trees give Table 5.1");
    // One Boolean function only: (A ∪ B ∪ C) − (D ∪ E).
    let e = parse(FIGURE_5_6).unwrap();
    let truth = (0..32u32)
        .filter(|m| direct(&e.root, &|p| m >> p & 1 == 1))
        .fold(0, |a, m| a | 1 << m);
    assert_eq!(found.keys().copied().collect::<Vec<_>>(), [truth]);
    assert!(found[&truth].contains(&"(((A+B)+C)-(D+E))".to_string()));
}

/// Renumber the solids of a (small) tree.
fn relabel(n: &mut CsgNode, map: &[usize]) {
    match n {
        CsgNode::Solid(i) => *i = map[*i],
        CsgNode::Union(c) | CsgNode::Intersection(c) | CsgNode::Difference(c) => {
            c.iter_mut().for_each(|c| relabel(c, map))
        }
        CsgNode::Complement(c) => relabel(c, map),
        CsgNode::Empty => {}
    }
}

/// Height of the binary positive form as the thesis counts it (n-ary chains left-deep).
fn height(root: &CsgNode) -> usize {
    let mut best = 0;
    let mut stack = vec![(root, 0usize)];
    while let Some((n, d)) = stack.pop() {
        match n {
            CsgNode::Complement(c) => stack.push((c, d)),
            _ => {
                let c = n.children();
                best = best.max(d);
                // Child k of an n-ary node sits at depth d + (len - k) in the left-deep chain
                // (the first child shares the deepest slot with the second).
                for (k, child) in c.iter().enumerate() {
                    stack.push((child, d + c.len() - k.max(1)));
                }
            }
        }
    }
    best
}

/// A tree built from a random postfix recipe: each step pushes a primitive (of 64) or combines
/// the top 1-4 trees with ∪, ∩, − or complements the top one; what is left is united.
fn tree_of(recipe: &[(u8, u8)]) -> CsgNode {
    let mut stack: Vec<CsgNode> = vec![];
    for &(a, b) in recipe {
        let k = (1 + usize::from(b % 4)).min(stack.len());
        let node = match a % 7 {
            _ if stack.is_empty() => CsgNode::Solid(usize::from(b % 64)),
            0..=2 => CsgNode::Solid(usize::from(b % 64)),
            3 => CsgNode::Union(stack.split_off(stack.len() - k)),
            4 => CsgNode::Intersection(stack.split_off(stack.len() - k)),
            5 => CsgNode::Difference(stack.split_off(stack.len() - k)),
            _ => CsgNode::Complement(Box::new(stack.pop().unwrap())),
        };
        stack.push(node);
    }
    match stack.len() {
        1 => stack.pop().unwrap(),
        _ => CsgNode::Union(stack),
    }
}

fn random_tree() -> impl Strategy<Value = CsgNode> {
    prop::collection::vec(any::<(u8, u8)>(), 1..300).prop_map(|r| tree_of(&r))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// ClassifyAgainstBlist equals direct evaluation of the tree, for random trees over up to
    /// 64 primitives with every node kind, on random classifications. The label fits
    /// ceil(log2(H + 1)) bits (§4.2, §4.3.2) when H counts the levels of the binary tree (nodes
    /// on its longest path); counting edges it can take one bit more (docs/blist.md).
    #[test]
    fn blist_equals_the_tree(t in random_tree(), points in prop::collection::vec(any::<u64>(), 32)) {
        let table = BlistTable::compile(&t);
        for m in points {
            let inside = |p: usize| m >> p & 1 == 1;
            prop_assert_eq!(table.classify(inside, None), direct(&t, &inside), "at {:#x}", m);
        }
        let levels = height(&t) as u32 + 1;
        let largest = table.rows.iter().map(|r| r.name.max(r.stamp)).max().unwrap_or(0);
        prop_assert!(largest <= levels, "name {} for {} levels", largest, levels);
        prop_assert!(table.label_bits <= u32::BITS - levels.leading_zeros());
    }

    /// Expressions parse to trees whose Blist equals them.
    #[test]
    fn parsed_expressions(
        e in "(\\(?!?[A-F]\\)?[+.\\-]){0,7}!?[A-F]\\)?".prop_filter_map("parses", |t| parse(&t).ok()),
        m in any::<u64>(),
    ) {
        let table = BlistTable::compile(&e.root);
        let inside = |p: usize| m >> p & 1 == 1;
        prop_assert_eq!(table.classify(inside, None), direct(&e.root, &inside));
    }
}

/// A tree 100,000 levels deep, every node kind, built the way a file reader would.
fn deep_tree(levels: usize) -> CsgNode {
    let mut t = CsgNode::Solid(0);
    for k in 1..levels {
        let leaf = CsgNode::Solid(k % 64);
        t = match k % 5 {
            0 => CsgNode::Difference(vec![leaf, t]),
            1 => CsgNode::Union(vec![t, leaf]),
            2 => CsgNode::Intersection(vec![leaf, CsgNode::Complement(Box::new(t))]),
            3 => CsgNode::Union(vec![leaf, t]),
            _ => CsgNode::Difference(vec![t, leaf, CsgNode::Solid((k * 7) % 64)]),
        };
    }
    t
}

#[test]
fn trees_100000_levels_deep_compile_and_classify() {
    let t = deep_tree(100_000);
    let table = BlistTable::compile(&t);
    assert!(table.rows.len() > 100_000);
    for seed in [
        0u64,
        !0,
        0x5555_5555_5555_5555,
        0x0123_4567_89ab_cdef,
        0xdead_beef_f00d_cafe,
    ] {
        let inside = |p: usize| seed.rotate_left(p as u32 * 7) & 1 == 1;
        assert_eq!(table.classify(inside, None), direct(&t, &inside));
    }
    // A left-deep chain, the worst case for the walks of Match.
    let mut chain = CsgNode::Solid(0);
    for k in 1..100_000 {
        chain = CsgNode::Union(vec![chain, CsgNode::Solid(k % 64)]);
    }
    let table = BlistTable::compile(&chain);
    assert!(table.rows.iter().all(|r| r.stamp == 1 && r.sign));
    // And from an expression nested as deep as the parser allows.
    let text = format!("{}A{}", "(B-".repeat(10_000), ")".repeat(10_000));
    let e = parse(&text).unwrap();
    let table = BlistTable::compile(&e.root);
    assert_eq!(table.rows.len(), 10_001);
    for m in 0..4u64 {
        let inside = |p: usize| m >> p & 1 == 1;
        assert_eq!(table.classify(inside, None), direct(&e.root, &inside));
    }
}

/// §5.5: "For the Blist approach ... only 3T comparisons at most required"; for Figure 5.6
/// (T = 5) "only 10 comparisons between the contents of the label and the name". Per voxel and
/// row: `label = 0`, `label = name` (2T in all without short-circuit: 10 for T = 5), and the
/// classification against the sign on the rows that classify (at most T): at most 3T.
#[test]
fn section_5_5_counts() {
    for (text, t_operands) in [(FIGURE_5_6, 5u64), (FIGURE_4_4, 7)] {
        let e = parse(text).unwrap();
        let table = BlistTable::compile(&e.root);
        let (mut lo, mut hi, mut sum) = ((u64::MAX, u64::MAX), (0, 0), (0, 0));
        for m in 0..1u32 << t_operands {
            let (_, c) = table.classify_counted(|p| m >> p & 1 == 1);
            assert_eq!(c.zero_tests, t_operands);
            assert_eq!(c.label_writes, c.sign_tests);
            assert!(c.sign_tests >= 1 && c.sign_tests <= t_operands);
            // Without the short-circuit of the OR: exactly 2T label comparisons.
            let label_tests = 2 * t_operands;
            assert!(label_tests + c.sign_tests <= 3 * t_operands);
            let short = c.zero_tests + c.name_tests;
            lo = (lo.0.min(short), lo.1.min(c.sign_tests));
            hi = (hi.0.max(short), hi.1.max(c.sign_tests));
            sum = (sum.0 + short, sum.1 + c.sign_tests);
        }
        let n = f64::from(1u32 << t_operands);
        println!(
            "{text}: T = {t_operands}; label tests 2T = {}; short-circuit label tests {}..{} \
             (mean {:.2}); rows classifying {}..{} (mean {:.2})",
            2 * t_operands,
            lo.0,
            hi.0,
            sum.0 as f64 / n,
            lo.1,
            hi.1,
            sum.1 as f64 / n
        );
    }
}
