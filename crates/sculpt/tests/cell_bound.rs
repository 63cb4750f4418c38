//! The bound of an octree's nodes from the scene (`csgpix_voxel::cells::cell_counts`) against
//! the nodes of the volume the voxelizer makes (`octree::estimate::volume_counts`): at every
//! level, for random rotated boxes, spheres, cylinders and cones under union, difference and
//! intersection, on grids cubic or not, under both samplings, with bounds that cut the
//! solids, and for the bundled scenes (a dataset among them) up to 512³.

use csgpix_scene::grid::{Grid, GridSpec};
use csgpix_scene::solid::CsgScene;
use csgpix_sculpt::estimate::triangles;
use csgpix_sculpt::octree::depth_for;
use csgpix_sculpt::octree::estimate::volume_counts;
use csgpix_testkit::{primitive_or_unturned as primitive, scene_of};
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::cells::cell_counts;
use csgpix_voxel::sampled::Sampled;
use csgpix_voxel::{voxelize, Route, Sampling, Slicer, SlicerOptions};
use glam::{DVec3, Vec3Swizzles};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use std::f64::consts::PI;

/// Voxelizes as `sculpt` and `voxelize --store` do (the run route on the array's words) and
/// checks the bound level by level, and the triangles Marching Cubes makes. Returns the
/// bound's and the volume's internal nodes and triangles; None when the scene cannot be
/// voxelized on that grid (a plane past the depth word, which the commands refuse).
fn check(
    scene: &CsgScene,
    sampled: Vec<Sampled>,
    grid: Grid,
    sampling: Sampling,
    what: &str,
) -> Option<[(u64, u64); 2]> {
    let opts = SlicerOptions {
        sampling,
        sampled,
        ..SlicerOptions::default()
    };
    check_with(scene, opts, Route::Runs { float: false }, grid, what)
}

/// [`check`] with the slicer's options and the route given.
fn check_with(
    scene: &CsgScene,
    opts: SlicerOptions,
    route: Route,
    grid: Grid,
    what: &str,
) -> Option<[(u64, u64); 2]> {
    let slicer = Slicer::new(scene, grid, opts).ok()?;
    let depth = depth_for(grid.dims).unwrap();
    let bound = cell_counts(scene, &slicer, depth);
    let eval = BlistEval::new(&scene.root);
    let set = rtl_model::Equations::Derived.set();
    let (v, _) = voxelize(&slicer, route, set, &eval, &|| {}).ok()?;
    let actual = volume_counts(&v).unwrap();
    for l in 0..=depth as usize {
        assert!(
            actual.nonuniform[l] <= bound.nonuniform[l],
            "{what}: level {l}: {} nodes, bound {}\n{:?}\n{:?}",
            actual.nonuniform[l],
            bound.nonuniform[l],
            actual.nonuniform,
            bound.nonuniform
        );
    }
    let (ta, tb) = (triangles(&actual), triangles(&bound));
    assert!(ta <= tb, "{what}: {ta} triangles, bound {tb}");
    Some([(bound.internal(), actual.internal()), (tb, ta)])
}

/// One operation over one to three boxes, spheres, cylinders or cones, each rotated (or not:
/// faces along the axes) and shifted.
fn scene() -> impl Strategy<Value = String> {
    scene_of(primitive())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn no_level_has_more_nodes_than_the_bound(
        text in scene(),
        dims in prop::array::uniform3(4usize..40),
        slab in any::<bool>(),
        cut in prop::option::of(prop::array::uniform3(0.05..0.45f64)),
    ) {
        let scene = csgpix_openscad::parse_csg(&text, "r.csg").unwrap();
        let Ok((lo, hi)) = Grid::scene_bounds(&scene) else { return Ok(()) };
        // Bounds cutting through the solids: the grid's faces bound the volume too.
        let (lo, hi) = match cut {
            Some(f) => {
                let e = hi - lo;
                (lo + e * DVec3::from(f), hi - e * DVec3::from(f).yzx())
            }
            None => (lo, hi),
        };
        let Ok(grid) = Grid::new(dims, lo, hi) else { return Ok(()) };
        let sampling = if slab { Sampling::Slab } else { Sampling::Centre };
        check(&scene, vec![], grid, sampling, &text);
    }
}

/// A twisted extrusion of a star-shaped polygon (a closed mesh primitive), beside a box.
fn extrusion_scene() -> impl Strategy<Value = String> {
    let star = prop::collection::vec(1.0..6.0f64, 3..9);
    let op = prop_oneof![Just("union"), Just("difference"), Just("intersection")];
    (star, 0.0..120.0f64, 2.0..12.0f64, op, primitive()).prop_map(|(radii, twist, h, op, other)| {
        let n = radii.len();
        let pts: Vec<String> = radii
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let a = 2.0 * PI * i as f64 / n as f64;
                format!("[{:.4}, {:.4}]", r * a.cos(), r * a.sin())
            })
            .collect();
        format!(
            "{op}() {{\nmultmatrix([[0.8, -0.6, 0, 0.5], [0.6, 0.8, 0, -0.3], [0, 0, 1, -{:.3}], [0, 0, 0, 1]]) \
             linear_extrude(height = {h:.3}, twist = {twist:.2}, slices = 6) polygon([{}]);\n{other}\n}}\n",
            h / 2.0,
            pts.join(", ")
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn meshes_have_no_more_nodes_than_the_bound(
        text in extrusion_scene(),
        dims in prop::array::uniform3(4usize..64),
    ) {
        let scene = csgpix_openscad::parse_csg(&text, "e.csg").unwrap();
        let sampled = csgpix_voxel::sampled::load_imports(&scene, "e.csg", std::path::Path::new(".")).unwrap();
        prop_assert!(!sampled.is_empty(), "{}", text);
        let loaded = csgpix_voxel::sampled::Loaded { scene, sampled };
        let Ok((lo, hi)) = loaded.bounds() else { return Ok(()) };
        let Ok(grid) = Grid::new(dims, lo, hi) else { return Ok(()) };
        check(&loaded.scene, loaded.sampled.clone(), grid, Sampling::Centre, &text);
    }
}

/// The same scenes on finer grids, where the depth word's rounding moves faces by more.
#[test]
fn rotated_solids_on_fine_grids() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    for n in [96, 160, 256] {
        for _ in 0..3 {
            let text = scene().new_tree(&mut runner).unwrap().current();
            let scene = csgpix_openscad::parse_csg(&text, "r.csg").unwrap();
            let Ok((lo, hi)) = Grid::scene_bounds(&scene) else {
                continue;
            };
            let grid = Grid::new([n, n - 7, n + 5], lo, hi).unwrap();
            for sampling in [Sampling::Centre, Sampling::Slab] {
                check(&scene, vec![], grid, sampling, &text);
            }
        }
    }
}

/// The phantom dataset turned, scaled and cut by boxes, at a few iso values.
#[test]
fn turned_datasets() {
    let dir =
        std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../vectors/scenes"));
    for (t, n, turn) in [
        (300, 64, 0.3),
        (1000, 96, 1.1),
        (100, 80, 2.0),
        (300, 128, 0.0),
    ] {
        let (c, s) = (f64::cos(turn), f64::sin(turn));
        let text = format!(
            "difference() {{ multmatrix([[{c:.6}, 0, {s:.6}, 1], [0, 1.3, 0, 0], [{:.6}, 0, {c:.6}, -2], [0, 0, 0, 1]]) \
             import(file = \"phantom.nrrd\", threshold = {t}); cube(size = [6, 30, 6], center = true); }}",
            -s
        );
        let scene = csgpix_openscad::parse_csg(&text, "d.csg").unwrap();
        let sampled = csgpix_voxel::sampled::load_imports(&scene, "d.csg", &dir).unwrap();
        let loaded = csgpix_voxel::sampled::Loaded { scene, sampled };
        let (lo, hi) = loaded.bounds().unwrap();
        let grid = Grid::new([n, n + 3, n - 5], lo, hi).unwrap();
        check(
            &loaded.scene,
            loaded.sampled.clone(),
            grid,
            Sampling::Centre,
            &text,
        );
    }
}

/// CSG expressions with a complement (`!`, everything outside: the grid bounds it) over
/// scenes and a dataset, bound to names.
#[test]
fn expressions_with_a_complement() {
    use csgpix_voxel::sampled::{parse_binding, scene_from_expr};
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../vectors/scenes/");
    let bind = |s: &str| parse_binding(&s.replace('@', dir)).unwrap();
    let all = [
        bind("A=@csg-logo.csg"),
        bind("B=@cube-minus-cylinder.csg"),
        bind("H=@phantom.nrrd,threshold=300"),
    ];
    for expr in ["!A", "A.!B", "!(A+H)", "H-!B"] {
        let bindings: Vec<_> = all
            .iter()
            .filter(|b| expr.contains(b.name.as_str()))
            .cloned()
            .collect();
        let loaded = scene_from_expr(expr, &bindings).unwrap();
        let (lo, hi) = loaded.bounds().unwrap();
        for n in [24, 61] {
            let grid = Grid::new([n, n + 2, n - 3], lo, hi).unwrap();
            check(
                &loaded.scene,
                loaded.sampled.clone(),
                grid,
                Sampling::Centre,
                expr,
            )
            .expect(expr);
        }
    }
}

/// Blended datasets (`--blend`): a voxel's value is a blend of grey values, so a difference
/// of two datasets is empty where the first's value is not above the second's, inside both.
#[test]
fn blended_datasets() {
    use csgpix_voxel::blend::{BlendEval, Union};
    let dir =
        std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../vectors/scenes"));
    // Inside both, the first's grey value is above the second's here and not there.
    let text = "difference() { union() { import(file = \"phantom.nrrd\", threshold = 100); \
        cube(size = [4, 4, 30], center = true); } \
        multmatrix([[1, 0, 0, 0.7], [0, 1, 0, 0.4], [0, 0, 1, 0], [0, 0, 0, 1]]) \
        import(file = \"phantom.nrrd\", threshold = 100); }";
    let scene = csgpix_openscad::parse_csg(text, "b.csg").unwrap();
    for union in [Union::Max, Union::Sum { ks: 0.5, kd: 0.3 }] {
        let sampled = csgpix_voxel::sampled::load_imports(&scene, "b.csg", &dir).unwrap();
        let loaded = csgpix_voxel::sampled::Loaded {
            scene: scene.clone(),
            sampled,
        };
        let (lo, hi) = loaded.bounds().unwrap();
        let grid = Grid::new([40, 44, 48], lo, hi).unwrap();
        let opts = SlicerOptions {
            sampled: loaded.sampled.clone(),
            blend: Some(BlendEval::new(&scene.root, union)),
            ..SlicerOptions::default()
        };
        check_with(&scene, opts, Route::Intervals, grid, text).expect("voxelized");
    }
}

/// The bundled scenes as `sculpt` lays them (`--res N`: N voxels along the longest side).
#[test]
fn the_bundled_scenes() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../vectors/scenes/");
    let cases = [
        ("twelve.csg", 256),
        ("csg-logo.csg", 256),
        ("hollow-cube.csg", 128),
        ("cube-minus-cylinder.csg", 128),
        ("figure-5.2.csg", 128),
        ("figure-5.6.csg", 128),
        ("figure-5.6.csg", 256),
        ("extrusions.scad", 128),
        ("twelve.csg", 512),
    ];
    for (file, n) in cases {
        let path = std::path::PathBuf::from(dir).join(file);
        let loaded = csgpix_voxel::sampled::load_scene(&path).unwrap();
        let spec = GridSpec {
            longest: Some(n),
            ..GridSpec::default()
        };
        let grid = loaded.grid_over(&spec, None).unwrap();
        let [(ib, ia), (tb, ta)] = check(
            &loaded.scene,
            loaded.sampled.clone(),
            grid,
            Sampling::Centre,
            file,
        )
        .expect("voxelized");
        eprintln!("{file} at {n}: internal nodes {ia}, bound {ib}; triangles {ta}, bound {tb}");
    }
}
