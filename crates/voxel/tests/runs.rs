//! The run route (`crates/voxel/src/runs.rs`) against the slab routes it takes its depths
//! from: the same volume voxel for voxel, on the word and the float model, either sampling,
//! every evaluator, any panel size, convex solids, meshes and datasets; the same slices when
//! handed on slab by slab; and every primitive's footprint inside the outline it is visited on.

use std::path::PathBuf;

use csgpix_openscad::parse_csg;
use csgpix_scene::solid::{CsgNode, CsgScene};
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::evaluate::{StackEval, TreeEval};
use csgpix_voxel::sampled::load_scene;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{
    float_ranges, voxelize, voxelize_slabs, word_ranges, Error, Grid, Route, Sampling, Slicer,
    SlicerOptions, Volume, Work,
};
use proptest::prelude::*;
use rtl_model::Equations;

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn run(slicer: &Slicer, route: Route, eval: &dyn SliceEval) -> (Volume, Work) {
    voxelize(slicer, route, Equations::Derived.set(), eval, &|| {}).unwrap()
}

/// The run route of either model equals its slab route: volume, filled voxels, frames and
/// clocks (the evaluator's counts differ: per segment, not per voxel).
fn check_equal(slicer: &Slicer, eval: &dyn SliceEval) {
    for float in [false, true] {
        let route = Route::Runs { float };
        let set = Equations::Derived.set();
        let by_slab = voxelize(slicer, route.by_slab(), set.clone(), eval, &|| {});
        let by_runs = voxelize(slicer, route, set, eval, &|| {});
        let ((a, wa), (b, wb)) = match (by_runs, by_slab) {
            (Ok(a), Ok(b)) => (a, b),
            (a, b) => {
                // A plane the word cannot hold fails both routes alike.
                assert_eq!(a.err(), b.err());
                continue;
            }
        };
        let differ = a
            .voxels
            .iter()
            .zip(&b.voxels)
            .filter(|(x, y)| x != y)
            .count();
        assert_eq!(
            differ,
            0,
            "{route:?}: {differ} voxels differ from {:?}",
            route.by_slab()
        );
        assert_eq!(
            (wa.filled, wa.cycles, wa.frames, wa.full_pixel_clocks),
            (wb.filled, wb.cycles, wb.frames, wb.full_pixel_clocks)
        );
    }
}

fn evaluator(i: usize, root: &CsgNode) -> Box<dyn SliceEval> {
    match i {
        0 => Box::new(BlistEval::new(root)),
        1 => Box::new(TreeEval::new(root)),
        _ => Box::new(StackEval::new(root)),
    }
}

/// A random tree over a scene's primitives: the file's tree, wrapped in a complement or
/// differences with its own leaves, so inside-through-complement and repeated leaves occur.
fn reshape(root: CsgNode, how: usize, prims: usize) -> CsgNode {
    use CsgNode::*;
    match how {
        0 => root,
        1 => Complement(Box::new(root)),
        2 => Difference(vec![Complement(Box::new(Solid(0))), root]),
        _ => Union(vec![
            Difference(vec![Solid(prims - 1), root.clone()]),
            Intersection(vec![root, Complement(Box::new(Solid(0)))]),
        ]),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn runs_are_the_slab_routes_voxels(
        text in csgpix_testkit::random_scene(),
        dims in prop::array::uniform3(1usize..19),
        slab in any::<bool>(),
        e in 0usize..3,
        how in 0usize..4,
        panel in prop::option::of(prop::array::uniform2(1usize..9)),
    ) {
        let mut scene = parse_csg(&text, "random").unwrap();
        scene.root = reshape(scene.root.clone(), how, scene.solids.len());
        let opts = SlicerOptions {
            sampling: if slab { Sampling::Slab } else { Sampling::Centre },
            panel,
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&scene, Grid::of_scene(&scene, dims).unwrap(), opts).unwrap();
        check_equal(&slicer, evaluator(e, &scene.root).as_ref());
    }

    #[test]
    fn footprints_lie_inside_the_outlines(
        text in csgpix_testkit::random_scene(),
        dims in prop::array::uniform3(1usize..40),
        slab in any::<bool>(),
    ) {
        let scene = parse_csg(&text, "random").unwrap();
        let opts = SlicerOptions {
            sampling: if slab { Sampling::Slab } else { Sampling::Centre },
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&scene, Grid::of_scene(&scene, dims).unwrap(), opts).unwrap();
        check_outlines(&slicer);
    }

    #[test]
    fn run_slices_are_the_whole_runs(
        text in csgpix_testkit::random_scene(),
        cuts in prop::collection::vec(0usize..20, 0..3),
        float in any::<bool>(),
    ) {
        let scene = parse_csg(&text, "random").unwrap();
        let grid = Grid::of_scene(&scene, [13, 11, 17]).unwrap();
        let slicer = Slicer::new(&scene, grid, SlicerOptions::default()).unwrap();
        check_slices(&slicer, float, &BlistEval::new(&scene.root), &cuts);
    }
}

/// Every pixel where a solid fills some slab lies in its outline.
fn check_outlines(slicer: &Slicer) {
    let w = slicer.grid.dims[0];
    for p in 0..slicer.lists.len() {
        // A plane the word cannot hold fails the word route: the float ranges remain.
        let word = word_ranges(slicer, p).ok();
        for r in word.iter().chain([&float_ranges(slicer, p)]) {
            for (i, &(a, b)) in r.0.iter().enumerate() {
                if a > b {
                    continue;
                }
                let (x, y) = (i % w, i / w);
                let o = slicer.outlines[p].unwrap_or_else(|| panic!("solid {p} has no outline"));
                assert!(
                    (o.x0..o.x1).contains(&x) && (o.y0..o.y1).contains(&y),
                    "solid {p} fills pixel ({x}, {y}) outside its outline {o:?}"
                );
            }
        }
    }
}

/// Slices of slab ranges cut at `cuts` are the whole run's, in order.
fn check_slices(slicer: &Slicer, float: bool, eval: &dyn SliceEval, cuts: &[usize]) {
    let route = Route::Runs { float };
    let (whole, work) = run(slicer, route, eval);
    let nz = slicer.grid.dims[2];
    let len = slicer.grid.slice_len();
    let mut bounds: Vec<usize> = cuts.iter().map(|c| c % (nz + 1)).collect();
    bounds.extend([0, nz]);
    bounds.sort_unstable();
    let mut filled = 0;
    for w in bounds.windows(2) {
        let mut next = w[0];
        let set = Equations::Derived.set();
        let part =
            voxelize_slabs::<Error>(slicer, route, set, eval, &|| {}, w[0]..w[1], &mut |k, s| {
                assert_eq!(k, next);
                assert_eq!(s, &whole.voxels[k * len..(k + 1) * len], "slice {k}");
                next += 1;
                Ok(())
            })
            .unwrap();
        assert_eq!(next, w[1]);
        filled += part.filled;
    }
    assert_eq!(filled, work.filled);
}

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(ROOT).join("vectors/scenes").join(name)
}

/// A loaded scene on `dims` with its imports.
fn loaded_slicer(name: &str, dims: [usize; 3], panel: Option<[usize; 2]>) -> (CsgScene, Slicer) {
    let l = load_scene(&scene_path(name)).unwrap();
    let grid = Grid::of_scene(&l.scene, dims).unwrap();
    let grid = match l.sampled.is_empty() {
        true => grid,
        false => l.grid(dims).unwrap(),
    };
    let opts = SlicerOptions {
        sampled: l.sampled,
        panel,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
    (l.scene, slicer)
}

#[test]
fn the_bundled_scenes_by_runs() {
    for (name, dims) in [
        ("csg-logo.csg", [40, 36, 33]),
        ("twelve.csg", [33, 35, 31]),
        ("figure-5.2.csg", [30, 30, 30]),
        ("figure-5.6.csg", [28, 26, 24]),
        ("hollow-cube.csg", [21, 22, 23]),
    ] {
        for panel in [None, Some([7, 5])] {
            let (scene, slicer) = loaded_slicer(name, dims, panel);
            for e in 0..3 {
                check_equal(&slicer, evaluator(e, &scene.root).as_ref());
            }
            check_outlines(&slicer);
        }
    }
}

/// Figure 5.6's head goes a lattice cell at a time on the run route (`dataset_runs`): on a
/// finer grid than the bundled scenes' test, and placed flipped, stretched and shifted (the
/// index z falling along the columns), still the slab route's voxels.
#[test]
fn a_dataset_by_cells_by_runs() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(scene_path("phantom.nrrd"), dir.path().join("phantom.nrrd")).unwrap();
    let placed = "difference() {\n\
        multmatrix([[-1, 0, 0, 1], [0, 1.5, 0, 0.25], [0, 0, -0.75, 2], [0, 0, 0, 1]]) import(file = \"phantom.nrrd\", threshold = 400);\n\
        cube(size = [6, 30, 30], center = true);\n}\n";
    let file = dir.path().join("placed.csg");
    std::fs::write(&file, placed).unwrap();
    let cases = [
        (scene_path("figure-5.6.csg"), [96, 90, 131]),
        (file, [45, 70, 83]),
    ];
    for (path, dims) in cases {
        let l = load_scene(&path).unwrap();
        let grid = l.grid(dims).unwrap();
        let opts = SlicerOptions {
            sampled: l.sampled,
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
        let columns = csgpix_voxel::dataset_runs::DatasetColumns::new(&slicer.sampled[0], &grid);
        assert!(columns.unwrap().by_cells(), "{path:?}");
        check_equal(&slicer, &BlistEval::new(&l.scene.root));
    }
}

/// A dataset's runs are counted for the estimate, and a task that computes some tiles counts
/// only theirs: each tile's estimate holds the runs its brick keeps (were its dataset left
/// uncounted, a panel would be taken as one run a column, under them), no tile's is above
/// the whole grid's, and the tiles away from the head cost less than the whole.
#[test]
fn a_tiles_estimate_counts_its_datasets_runs() {
    use csgpix_voxel::runs::{memory_estimate_bricks, Columns, Run};
    use csgpix_voxel::PixelBox;
    let (scene, slicer) = loaded_slicer("figure-5.6.csg", [96, 96, 96], Some([16, 16]));
    let eval = BlistEval::new(&scene.root);
    let tile = [32, 32];
    let whole = memory_estimate_bricks(&slicer, &eval, 1, tile, None);
    let grid = PixelBox::new(0, 0, 96, 96);
    assert_eq!(
        memory_estimate_bricks(&slicer, &eval, 1, tile, Some(grid)),
        whole
    );
    let columns = Columns::new(&slicer, false, &|| ()).unwrap();
    let mut least = u64::MAX;
    for (x, y) in (0..3).flat_map(|j| (0..3).map(move |i| (i * 32, j * 32))) {
        let t = PixelBox::new(x, y, x + 32, y + 32);
        let est = memory_estimate_bricks(&slicer, &eval, 1, tile, Some(t));
        let brick = columns.brick(&eval, t);
        let runs: usize = brick.bands.iter().map(|b| b.runs.len()).sum();
        let kept = (runs * std::mem::size_of::<Run>() + t.pixels() * 8) as u64;
        assert!(
            kept <= est && est <= whole,
            "{t:?}: {kept} kept, {est}, {whole}"
        );
        least = least.min(est);
    }
    assert!(least < whole, "{least} and {whole}");
}

/// Concave extrusions and a rotate_extrude become closed mesh primitives: their runs come
/// from crossings kept over their outline only.
#[test]
fn mesh_primitives_by_runs() {
    let text = "difference() {\n\
        linear_extrude(height = 6, twist = 40, slices = 4) polygon(points = [[0, 0], [8, 0], [8, 8], [4, 3], [0, 8]]);\n\
        multmatrix([[1, 0, 0, 4], [0, 1, 0, 4], [0, 0, 1, 3], [0, 0, 0, 1]]) sphere($fn = 10, r = 2.5);\n\
        }\n\
        multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) rotate_extrude(angle = 200, $fn = 12) polygon(points = [[1, 0], [3, 0], [3, 2], [2, 1], [1, 2]]);\n";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("meshes.csg");
    std::fs::write(&path, text).unwrap();
    let l = load_scene(&path).unwrap();
    assert!(l.sampled.len() >= 2, "the extrusions are mesh primitives");
    for dims in [[31, 17, 12], [8, 40, 21]] {
        let grid = l.grid(dims).unwrap();
        let opts = SlicerOptions {
            sampled: l.sampled.clone(),
            panel: Some([6, 4]),
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
        check_equal(&slicer, &BlistEval::new(&l.scene.root));
        check_slices(&slicer, false, &StackEval::new(&l.scene.root), &[5, 9]);
    }
}

/// Polyhedra that are not closed (a box without its top, turned; a cube's soup missing a
/// triangle) go by their winding number at the voxel centres: the same voxels by runs as by
/// slabs, and as slices handed on.
#[test]
fn open_meshes_by_runs() {
    let open_box =
        std::fs::read_to_string(format!("{ROOT}/vectors/openmesh/open-box.csg")).unwrap();
    let soup = std::fs::read_to_string(format!("{ROOT}/vectors/openmesh/soup-open.csg")).unwrap();
    let text = format!(
        "difference() {{\n\
         multmatrix([[0.8, -0.6, 0, 2], [0.6, 0.8, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) {{\n{open_box}}}\n\
         multmatrix([[1, 0, 0, 4], [0, 1, 0, 4], [0, 0, 1, 7], [0, 0, 0, 1]]) sphere($fn = 10, r = 4);\n\
         }}\n\
         multmatrix([[0.5, 0, 0, 12], [0, 0.5, 0, 0], [0, 0, -0.5, 6], [0, 0, 0, 1]]) {{\n{soup}}}\n"
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("open.csg");
    std::fs::write(&path, text).unwrap();
    let l = load_scene(&path).unwrap();
    let open = l
        .sampled
        .iter()
        .filter(|s| matches!(s.shape, csgpix_voxel::sampled::Shape::OpenMesh(..)))
        .count();
    assert_eq!(open, 2);
    for dims in [[31, 17, 12], [8, 40, 21]] {
        let grid = l.grid(dims).unwrap();
        let opts = SlicerOptions {
            sampled: l.sampled.clone(),
            panel: Some([6, 4]),
            ..SlicerOptions::default()
        };
        let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
        check_equal(&slicer, &BlistEval::new(&l.scene.root));
        check_slices(&slicer, false, &StackEval::new(&l.scene.root), &[5, 9]);
        check_outlines(&slicer);
    }
}

/// Where voxels take a dataset's grey values the run route hands over to the slab route.
#[test]
fn grey_datasets_go_by_slab() {
    let l = load_scene(&scene_path("figure-5.6.csg")).unwrap();
    let grid = l.grid([20, 20, 20]).unwrap();
    let opts = SlicerOptions {
        sampled: l.sampled,
        grey: true,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
    assert!(!csgpix_voxel::runs::applies(&slicer));
    check_equal(&slicer, &BlistEval::new(&l.scene.root));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    /// A brick (any box of columns × any slab range) is that part of the whole volume.
    #[test]
    fn bricks_are_parts_of_the_whole_volume(
        text in csgpix_testkit::random_scene(),
        corner in prop::array::uniform3(0usize..17),
        size in prop::array::uniform3(0usize..17),
        float in any::<bool>(),
    ) {
        let scene = parse_csg(&text, "random").unwrap();
        let dims = [15, 13, 16];
        let grid = Grid::of_scene(&scene, dims).unwrap();
        let opts = SlicerOptions { panel: Some([4, 3]), ..SlicerOptions::default() };
        let slicer = Slicer::new(&scene, grid, opts).unwrap();
        let eval = BlistEval::new(&scene.root);
        let (whole, _) = run(&slicer, Route::Runs { float }, &eval);
        let lo = [0, 1, 2].map(|a| corner[a] % dims[a]);
        let hi = [0, 1, 2].map(|a| (lo[a] + size[a]).min(dims[a]));
        let b = csgpix_voxel::PixelBox { x0: lo[0], y0: lo[1], x1: hi[0].max(lo[0] + 1), y1: hi[1].max(lo[1] + 1) };
        let (brick, filled) =
            csgpix_voxel::runs::voxelize_brick(&slicer, float, &eval, b, lo[2]..hi[2]).unwrap();
        let mut want = vec![];
        for k in lo[2]..hi[2] {
            for y in b.y0..b.y1 {
                let at = (k * dims[1] + y) * dims[0];
                want.extend_from_slice(&whole.voxels[at + b.x0..at + b.x1]);
            }
        }
        prop_assert_eq!(filled, want.iter().filter(|&&v| v != 0).count());
        prop_assert_eq!(brick, want);
    }
}

#[test]
fn a_brick_outside_the_grid_is_refused() {
    let scene = parse_csg("cube(size = [2, 2, 2]);", "cube").unwrap();
    let slicer = Slicer::new(
        &scene,
        Grid::of_scene(&scene, [4, 4, 4]).unwrap(),
        SlicerOptions::default(),
    )
    .unwrap();
    let eval = BlistEval::new(&scene.root);
    let b = csgpix_voxel::PixelBox {
        x0: 0,
        y0: 0,
        x1: 5,
        y1: 4,
    };
    let err = csgpix_voxel::runs::voxelize_brick(&slicer, false, &eval, b, 0..4).unwrap_err();
    assert!(
        err.to_string().contains("not inside the grid 4x4x4"),
        "{err}"
    );
}
