//! Centre sampling against the geometry: the centre-sampled CSG volume is the point membership
//! of the CSG solid at every voxel centre, evaluated here directly from the solids' faces (no
//! display list, no depth word, no slab), apart from centres within one depth unit of a face;
//! and the thesis's slab sampling is not (it dilates subtracted solids).

use csgpix_openscad::parse_csg;
use csgpix_scene::solid::CsgScene;
use csgpix_testkit::{face_planes as planes, random_scene};
use csgpix_voxel::evaluate::direct;
use csgpix_voxel::slice::SliceEval;
use csgpix_voxel::{voxelize, Grid, Route, Sampling, Slicer, SlicerOptions, Volume};
use glam::DVec3;
use proptest::prelude::*;
use rtl_model::Equations;

/// Signed distance-like value of p to a convex solid: the largest signed distance to its face
/// planes (≤ 0 inside; within t of 0 exactly when p is within t of the boundary, up to the
/// solid's corners, where it is smaller than the true distance).
fn signed(planes: &[(DVec3, f64)], p: DVec3) -> f64 {
    planes
        .iter()
        .map(|(n, d)| n.dot(p) - d)
        .fold(f64::NEG_INFINITY, f64::max)
}

fn run(scene: &CsgScene, grid: Grid, sampling: Sampling, route: Route) -> (Slicer, Volume) {
    let slicer = Slicer::new(
        scene,
        grid,
        SlicerOptions {
            sampling,
            ..SlicerOptions::default()
        },
    )
    .unwrap();
    let eval = csgpix_voxel::blist::BlistEval::new(&scene.root);
    let eval: &dyn SliceEval = &eval;
    let (v, _) = voxelize(&slicer, route, Equations::Derived.set(), eval, &|| {}).unwrap();
    (slicer, v)
}

/// Compares a volume with direct point membership at the voxel centres. Returns the number of
/// disagreeing voxels and the largest distance (scene units) from such a centre to a solid's
/// boundary.
fn against_direct(scene: &CsgScene, grid: &Grid, v: &Volume) -> (usize, f64) {
    let planes: Vec<_> = scene.solids.iter().map(planes).collect();
    let [nx, ny, nz] = grid.dims;
    let (mut bad, mut worst) = (0, 0.0f64);
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let c = grid.centre(i, j, k);
                let d: Vec<f64> = planes.iter().map(|p| signed(p, c)).collect();
                let want = direct(&scene.root, |p| d[p] <= 0.0);
                let got = v.voxels[(k * ny + j) * nx + i] != 0;
                if want != got {
                    bad += 1;
                    let near = d.iter().map(|x| x.abs()).fold(f64::INFINITY, f64::min);
                    worst = worst.max(near);
                }
            }
        }
    }
    (bad, worst)
}

/// One depth unit of the word along Z, in scene units: a voxel is q depth units deep.
fn depth_unit(s: &Slicer) -> f64 {
    s.grid.voxel().z / s.fmt.to_real(s.slab_raw)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Every route's centre-sampled volume is the CSG solid's point membership at every voxel
    /// centre, except at centres within one depth unit of some solid's boundary (counted, and
    /// bounded: the word's plane error is far below a depth unit on these grids).
    #[test]
    fn centre_sampling_is_point_membership(text in random_scene(), n in 8usize..20) {
        let scene = parse_csg(&text, "scene.csg").unwrap();
        let grid = Grid::of_scene(&scene, [n, n + 1, n + 2]).unwrap();
        for route in [Route::Float, Route::Intervals] {
            let (slicer, v) = run(&scene, grid, Sampling::Centre, route);
            let (bad, worst) = against_direct(&scene, &grid, &v);
            let unit = depth_unit(&slicer);
            prop_assert!(
                worst <= unit,
                "{route:?}: {bad} voxels differ, one {worst} from a face (> {unit})\n{text}"
            );
            // At most a thin shell: no more than the voxels of one layer per solid face.
            prop_assert!(bad <= grid.slice_len(), "{route:?}: {bad} voxels differ\n{text}");
        }
    }
}

/// Over a fixed batch of random scenes: how many centres disagree with direct evaluation, and
/// how far from a face the farthest lies (printed with --nocapture; asserted ≤ a depth unit).
#[test]
fn centre_sampling_disagreements_are_counted_and_bounded() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        proptest::test_runner::TestRng::deterministic_rng(
            proptest::test_runner::RngAlgorithm::ChaCha,
        ),
    );
    let (mut voxels, mut bad, mut worst, mut unit_min) = (0usize, 0usize, 0.0f64, f64::MAX);
    for _ in 0..40 {
        let text = random_scene().new_tree(&mut runner).unwrap().current();
        let scene = parse_csg(&text, "scene.csg").unwrap();
        let grid = Grid::of_scene(&scene, [24; 3]).unwrap();
        let (slicer, v) = run(&scene, grid, Sampling::Centre, Route::Intervals);
        let (b, w) = against_direct(&scene, &grid, &v);
        voxels += v.voxels.len();
        bad += b;
        worst = worst.max(w / depth_unit(&slicer));
        unit_min = unit_min.min(depth_unit(&slicer));
    }
    println!(
        "40 random scenes at 24^3: {bad} of {voxels} centres differ from direct evaluation, \
         the farthest {worst:.4} depth units from a face"
    );
    assert!(worst <= 1.0);
    assert!(bad * 1000 <= voxels, "{bad} of {voxels}");
    assert!(unit_min > 0.0);
}

/// `cube([b − a, …])` placed at a on an integer grid: exactly b − a voxels along each axis
/// under centre sampling, on every route; the slab convention adds the layer behind the far
/// face (the face lies on a Z-plane, which belongs to the slab behind it).
#[test]
fn a_cube_on_grid_planes_is_exactly_its_size() {
    let text = "multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]) \
                { cube(size = [14, 9, 11], center = false); }";
    let scene = parse_csg(text, "cube.csg").unwrap();
    let grid = Grid::new([16; 3], DVec3::ZERO, DVec3::splat(16.0)).unwrap();
    let extent = |v: &Volume| {
        let mut lo = [usize::MAX; 3];
        let mut hi = [0usize; 3];
        let mut n = 0;
        for (idx, _) in v.voxels.iter().enumerate().filter(|(_, &c)| c != 0) {
            let p = [idx % 16, idx / 16 % 16, idx / 256];
            for a in 0..3 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
            n += 1;
        }
        (lo, hi.map(|h| h + 1), n)
    };
    let routes = [
        Route::Float,
        Route::Intervals,
        Route::Array { cycle: false },
        Route::Array { cycle: true },
    ];
    for route in routes {
        let (_, v) = run(&scene, grid, Sampling::Centre, route);
        assert_eq!(
            extent(&v),
            ([1, 2, 3], [15, 11, 14], 14 * 9 * 11),
            "{route:?}"
        );
        let (_, v) = run(&scene, grid, Sampling::Slab, route);
        assert_eq!(
            extent(&v),
            ([1, 2, 3], [15, 11, 15], 14 * 9 * 12),
            "{route:?} slab"
        );
    }
}

/// A cube minus a sphere inside it: centre sampling matches direct evaluation, slab sampling
/// carves the sphere dilated along Z (every voxel whose segment touches it).
#[test]
fn slab_sampling_dilates_subtracted_solids_centre_does_not() {
    let text = "difference() { cube(size = [20, 20, 20], center = true); \
                multmatrix([[1, 0, 0, 2], [0, 1, 0, 1], [0, 0, 1, 0.5], [0, 0, 0, 1]]) \
                { sphere($fn = 24, r = 7); } }";
    let scene = parse_csg(text, "cube-minus-sphere.csg").unwrap();
    let grid = Grid::new([32; 3], DVec3::splat(-10.0), DVec3::splat(10.0)).unwrap();
    let (slicer, centre) = run(&scene, grid, Sampling::Centre, Route::Intervals);
    let (_, slab) = run(&scene, grid, Sampling::Slab, Route::Intervals);
    let (bad_c, worst_c) = against_direct(&scene, &grid, &centre);
    let (bad_s, _) = against_direct(&scene, &grid, &slab);
    let filled = |v: &Volume| v.voxels.iter().filter(|&&c| c != 0).count();
    println!(
        "cube minus sphere 32^3: centre {} filled, {bad_c} differ from direct; slab {} filled, {bad_s} differ",
        filled(&centre),
        filled(&slab)
    );
    // Only centres on a face (within a depth unit) may go either way.
    assert!(
        bad_c <= 4 && worst_c <= depth_unit(&slicer),
        "{bad_c} {worst_c}"
    );
    assert!(bad_s > 100, "slab differs in only {bad_s} voxels");
    assert!(filled(&slab) < filled(&centre));
}
