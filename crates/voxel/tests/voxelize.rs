//! Voxelizing: every route gives the processor's voxels, the result does not depend on
//! threads, `word` differs from `float` only where the rounding bound allows, hidden cavities
//! survive (§5.9).

use csgpix_draw::float::rounding_bound;
use csgpix_openscad::parse_csg;
use csgpix_scene::solid::CsgScene;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::evaluate::{direct, StackEval, TreeEval};
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{
    float_interval, float_ranges, voxelize, word_ranges, Grid, Route, Slicer, SlicerOptions, Volume,
};
use rtl_model::Equations;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn scene(name: &str) -> CsgScene {
    let path = format!("{ROOT}/vectors/scenes/{name}.csg");
    parse_csg(&std::fs::read_to_string(path).unwrap(), name).unwrap()
}

fn run(s: &CsgScene, n: usize, route: Route, threads: usize) -> Volume {
    run_with(s, n, route, threads, &TreeEval::new(&s.root))
}

fn run_with(s: &CsgScene, n: usize, route: Route, threads: usize, eval: &dyn SliceEval) -> Volume {
    let slicer = Slicer::new(
        s,
        Grid::of_scene(s, [n, n, n]).unwrap(),
        SlicerOptions::default(),
    )
    .unwrap();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| voxelize(&slicer, route, Equations::Derived.set(), eval, &|| {}))
        .unwrap()
        .0
}

#[test]
fn every_route_gives_the_processors_voxels_on_every_example() {
    for name in ["figure-5.2", "hollow-cube", "cube-minus-cylinder"] {
        let s = scene(name);
        let fast = run(&s, 12, Route::Intervals, 2);
        let word = run(&s, 12, Route::Array { cycle: false }, 2);
        let cycle = run(&s, 12, Route::Array { cycle: true }, 1);
        assert_eq!(fast, word, "{name}: intervals and word array differ");
        assert_eq!(word, cycle, "{name}: word and cycle arrays differ");
        assert!(fast.voxels.iter().any(|&v| v != 0), "{name}: empty");
    }
}

const EXAMPLES: [&str; 5] = [
    "figure-5.2",
    "hollow-cube",
    "cube-minus-cylinder",
    "twelve",
    "csg-logo",
];

/// `--eval blist|tree|stack` fill the same voxels on every example scene (the cycle model's
/// slices at 16³, the fast route's at 48³); tree and stack also colour them alike, the Blist
/// by §4.5 (docs/blist.md), so only membership is compared with it.
#[test]
fn the_three_evaluators_fill_the_same_voxels_on_every_example() {
    for name in EXAMPLES {
        let s = scene(name);
        for (n, route) in [(16, Route::Array { cycle: true }), (48, Route::Intervals)] {
            let tree = run_with(&s, n, route, 2, &TreeEval::new(&s.root));
            let stack = run_with(&s, n, route, 2, &StackEval::new(&s.root));
            let blist = run_with(&s, n, route, 2, &BlistEval::new(&s.root));
            assert_eq!(tree, stack, "{name} {n}³: tree and stack differ");
            let filled = |v: &Volume| v.voxels.iter().map(|&c| c != 0).collect::<Vec<_>>();
            assert_eq!(
                filled(&blist),
                filled(&tree),
                "{name} {n}³: blist and tree differ"
            );
            assert!(filled(&tree).contains(&true), "{name} {n}³: empty");
        }
    }
}

#[test]
fn output_does_not_depend_on_threads() {
    let s = scene("twelve");
    let one = run(&s, 40, Route::Intervals, 1);
    for t in [2, 3, 8] {
        assert_eq!(one, run(&s, 40, Route::Intervals, t), "{t} threads");
    }
}

#[test]
fn the_hidden_cavity_survives() {
    let s = scene("hollow-cube");
    let v = run(&s, 32, Route::Intervals, 2);
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * 32 + j) * 32 + i];
    // The cube spans the grid; the cavity is its middle half.
    assert_eq!(at(16, 16, 16), 0, "cavity filled");
    assert_ne!(at(16, 16, 2), 0, "front wall missing");
    assert_ne!(at(16, 16, 29), 0, "back wall missing");
    assert_ne!(at(2, 16, 16), 0, "side wall missing");
    let empty = v.voxels.iter().filter(|&&c| c == 0).count();
    // 16³ cavity voxels, within one layer either way of the half-open slab convention.
    assert!(
        (16 * 16 * 15..=16 * 16 * 17).contains(&empty),
        "{empty} empty voxels"
    );
}

/// Voxels (membership) of the whole tree evaluated directly on the float intervals.
#[test]
fn word_differs_from_float_only_within_the_rounding_bound() {
    for name in ["figure-5.2", "twelve", "cube-minus-cylinder"] {
        let s = scene(name);
        let n = 48;
        let slicer = Slicer::new(
            &s,
            Grid::of_scene(&s, [n, n, n]).unwrap(),
            SlicerOptions::default(),
        )
        .unwrap();
        let (mut differ, mut total) = (0, 0);
        for p in 0..s.solids.len() {
            let (w, f) = (word_ranges(&slicer, p).unwrap(), float_ranges(&slicer, p));
            for i in 0..n * n {
                total += 1;
                if w.0[i] == f.0[i] {
                    continue;
                }
                differ += 1;
                let (x, y) = (i % n, i / n);
                let e = 2.0 * rounding_bound(&slicer.fmt, x, y);
                let (lo, hi) = float_interval(&slicer, p, x, y).unwrap_or((f64::NAN, f64::NAN));
                // Some exact endpoint (or a perpendicular plane's K) is within the bound of a
                // slab plane, so the word may put it on the other side.
                let near_slab = |z: f64| {
                    (0..=n).any(|k| {
                        let plane = slicer.fmt.to_real(slicer.z_plane(k));
                        (z - plane).abs() <= e || (z - (plane - slicer.fmt.to_real(1))).abs() <= e
                    })
                };
                let near_edge = slicer.lists[p]
                    .planes
                    .iter()
                    .filter(|pl| pl.y)
                    .any(|pl| (pl.z0 + x as f64 * pl.dzx + y as f64 * pl.dzy).abs() <= e);
                let near_crossing = slicer.lists[p].planes.iter().filter(|pl| !pl.y).any(|a| {
                    slicer.lists[p]
                        .planes
                        .iter()
                        .filter(|pl| !pl.y && pl.h != a.h)
                        .any(|b| {
                            let va = a.z0 + x as f64 * a.dzx + y as f64 * a.dzy;
                            let vb = b.z0 + x as f64 * b.dzx + y as f64 * b.dzy;
                            (va - vb).abs() <= 2.0 * e
                        })
                });
                assert!(
                    near_slab(lo) || near_slab(hi) || near_edge || near_crossing,
                    "{name}: solid {p} pixel ({x}, {y}): word {:?} float {:?}, interval {lo}..{hi}",
                    w.0[i],
                    f.0[i]
                );
            }
        }
        println!("{name} {n}³: {differ} of {total} (solid, pixel) slab ranges differ from float, all within the bound");
    }
}

#[test]
fn tree_evaluation_matches_direct_evaluation_of_the_masks() {
    let s = scene("figure-5.2");
    let n = 20;
    let slicer = Slicer::new(
        &s,
        Grid::of_scene(&s, [n, n, n]).unwrap(),
        SlicerOptions::default(),
    )
    .unwrap();
    let v = run(&s, n, Route::Intervals, 2);
    let ranges: Vec<_> = (0..s.solids.len())
        .map(|p| word_ranges(&slicer, p).unwrap())
        .collect();
    for k in 0..n {
        let masks: Vec<_> = ranges.iter().map(|r| r.mask(k)).collect();
        for i in 0..n * n {
            let want = direct(&s.root, |p| masks[p].get(i));
            assert_eq!(v.voxels[k * n * n + i] != 0, want, "slab {k} pixel {i}");
        }
    }
}
