//! A run split by slab ranges (`voxelize_slabs`, docs/scale-out.md): every range's slices are
//! the whole run's, whatever the route, the scene or where the ranges cut, and the ranges'
//! work adds up to the whole run's.

use csgpix_openscad::parse_csg;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::sampled::load_scene;
use csgpix_voxel::{
    voxelize, voxelize_slabs, Error, Grid, Route, Slicer, SlicerOptions, Volume, Work,
};
use proptest::prelude::*;
use rtl_model::Equations;
use std::path::PathBuf;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

const ROUTES: [Route; 4] = [
    Route::Intervals,
    Route::Float,
    Route::Array { cycle: false },
    Route::Array { cycle: true },
];

/// The slices of slabs `a..b` and their work.
fn slabs(slicer: &Slicer, route: Route, eval: &BlistEval, a: usize, b: usize) -> (Vec<u8>, Work) {
    let set = Equations::Derived.set();
    let mut out = vec![];
    let mut next = a;
    let work = voxelize_slabs::<Error>(slicer, route, set, eval, &|| {}, a..b, &mut |k, s| {
        assert_eq!(k, next, "slices come in order of k");
        next += 1;
        out.extend_from_slice(s);
        Ok(())
    })
    .unwrap();
    assert_eq!(next, b, "every slab of the range is handed on");
    (out, work)
}

/// Split the grid at `cuts` and check every piece against `whole`, and the work's sum.
fn check_split(slicer: &Slicer, route: Route, eval: &BlistEval, cuts: &[usize]) {
    let set = Equations::Derived.set();
    let (whole, work): (Volume, Work) = voxelize(slicer, route, set, eval, &|| {}).unwrap();
    let nz = slicer.grid.dims[2];
    let slice = slicer.grid.slice_len();
    let mut bounds: Vec<usize> = cuts.iter().map(|c| c % (nz + 1)).collect();
    bounds.extend([0, nz]);
    bounds.sort_unstable();
    let mut sum = Work::default();
    for w in bounds.windows(2) {
        let (s, part) = slabs(slicer, route, eval, w[0], w[1]);
        assert_eq!(
            s,
            whole.voxels[w[0] * slice..w[1] * slice],
            "{route:?} {w:?}"
        );
        sum.filled += part.filled;
        sum.cycles += part.cycles;
        sum.frames += part.frames;
        sum.ops += part.ops;
        sum.simulated_pixel_clocks += part.simulated_pixel_clocks;
        sum.full_pixel_clocks += part.full_pixel_clocks;
    }
    assert_eq!(
        sum, work,
        "{route:?}: the ranges' work adds up to the run's"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn slab_ranges_are_the_whole_runs_slices(
        text in csgpix_testkit::random_scene(),
        cuts in prop::collection::vec(0usize..40, 0..4),
        route in 0usize..4,
    ) {
        let scene = parse_csg(&text, "random").unwrap();
        let slicer = Slicer::new(
            &scene,
            Grid::of_scene(&scene, [14, 12, 11]).unwrap(),
            SlicerOptions::default(),
        )
        .unwrap();
        check_split(&slicer, ROUTES[route], &BlistEval::new(&scene.root), &cuts);
    }
}

#[test]
fn slab_ranges_of_a_scene_with_a_dataset() {
    let path = PathBuf::from(ROOT).join("vectors/scenes/figure-5.6.csg");
    let l = load_scene(&path).unwrap();
    let grid = Grid::of_scene(&l.scene, [24, 24, 20]).unwrap();
    let opts = SlicerOptions {
        sampled: l.sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
    let eval = BlistEval::new(&l.scene.root);
    check_split(&slicer, Route::Intervals, &eval, &[3, 7, 19]);
}

#[test]
fn a_range_past_the_grid_is_refused() {
    let scene = parse_csg("cube(size = [2, 2, 2]);", "cube").unwrap();
    let slicer = Slicer::new(
        &scene,
        Grid::of_scene(&scene, [4, 4, 4]).unwrap(),
        SlicerOptions::default(),
    )
    .unwrap();
    let eval = BlistEval::new(&scene.root);
    let set = Equations::Derived.set();
    for (a, b) in [(0, 5), (3, 2)] {
        let r = voxelize_slabs::<Error>(
            &slicer,
            Route::Intervals,
            set.clone(),
            &eval,
            &|| {},
            a..b,
            &mut |_, _| Ok(()),
        );
        assert_eq!(
            r.unwrap_err().to_string(),
            format!("slabs {a}..{b}: the grid has slabs 0..4")
        );
    }
}
