//! Meshes that are not closed, voxelized by their generalized winding number
//! (`csgpix_scene::winding`): polyhedra that OpenSCAD 2021.01's render drops
//! (`vectors/openmesh/`, its own `.csg` exports and logs), a welded soup against OpenSCAD's own
//! render of it, an open STL import with its located warning, and closed meshes left on the
//! parity path.

use std::path::PathBuf;

use csgpix_scene::grid::Grid;
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::sampled::{load_scene, scene_from_expr, Binding, Loaded, Shape};
use csgpix_voxel::{voxelize, Route, Slicer, SlicerOptions, Volume};
use glam::DVec3;
use rtl_model::Equations;

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn vector(name: &str) -> PathBuf {
    PathBuf::from(ROOT).join("vectors/openmesh").join(name)
}

/// The scene on `n`³ voxels over `[lo, hi]³` by `route`.
fn volume(l: &Loaded, n: usize, (lo, hi): (f64, f64), route: Route) -> Volume {
    let grid = Grid::new([n; 3], DVec3::splat(lo), DVec3::splat(hi)).unwrap();
    let opts = SlicerOptions {
        sampled: l.sampled.clone(),
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
    let eval = BlistEval::new(&l.scene.root);
    voxelize(&slicer, route, Equations::Derived.set(), &eval, &|| {})
        .unwrap()
        .0
}

fn filled(v: &Volume) -> usize {
    v.voxels.iter().filter(|&&c| c != 0).count()
}

#[test]
fn polyhedra_openscad_drops_are_voxelized() {
    for (name, open) in [
        ("open-box", true),
        ("soup-open", true),
        ("soup-flipped", false),
        ("one-face-wrong", false),
    ] {
        // OpenSCAD's render refuses each of them and writes nothing.
        let log = std::fs::read_to_string(vector(&format!("{name}.log"))).unwrap();
        assert!(log.contains("The given mesh is not closed!"), "{name}");
        let l = load_scene(&vector(&format!("{name}.csg"))).unwrap();
        let warned: Vec<String> = l.scene.warnings.iter().map(|w| w.to_string()).collect();
        match open {
            true => {
                assert!(
                    matches!(l.sampled[0].shape, Shape::OpenMesh(_, None)),
                    "{name}"
                );
                assert_eq!(warned.len(), 1, "{name}: {warned:?}");
                let w = &warned[0];
                assert!(w.contains(":2:2: polyhedron is not closed"), "{w}");
                assert!(warned[0].contains("edges belong to one triangle (first from"));
            }
            // Closed once its corners are welded, whatever the winding: parity, no warning.
            false => {
                assert!(matches!(l.sampled[0].shape, Shape::Mesh(_)), "{name}");
                assert!(warned.is_empty(), "{name}: {warned:?}");
            }
        }
        // The cube [0, 10]³ on voxels of 1 centred at −0.5 … 10.5: 10³ inside.
        for route in [Route::Intervals, Route::Runs { float: false }] {
            let v = volume(&l, 12, (-1.0, 11.0), route);
            assert_eq!(filled(&v), 1000, "{name} {route:?}");
        }
    }
}

/// A soup of a cube's triangles, each with its own corners: OpenSCAD welds it and renders the
/// cube (`soup.stl`); csgpix welds it closed and slices it by parity, voxel for voxel the
/// same as OpenSCAD's render imported.
#[test]
fn a_welded_soup_is_openscads_cube() {
    let soup = load_scene(&vector("soup.csg")).unwrap();
    assert!(matches!(soup.sampled[0].shape, Shape::Mesh(_)));
    assert!(soup.scene.warnings.is_empty());
    let b = Binding {
        name: "A".into(),
        file: vector("soup.stl"),
        threshold: None,
    };
    let rendered = scene_from_expr("A", &[b]).unwrap();
    for n in [7, 16] {
        let a = volume(&soup, n, (-0.7, 10.9), Route::Float);
        let b = volume(&rendered, n, (-0.7, 10.9), Route::Float);
        let occupied = |v: &Volume| v.voxels.iter().map(|&c| c != 0).collect::<Vec<bool>>();
        assert_eq!(occupied(&a), occupied(&b), "{n}");
        assert!(filled(&a) > 0);
    }
}

/// An STL without its top face, imported: voxelized as the box it was, its warning located
/// at the `import` in the scene and naming the open edges.
#[test]
fn an_open_stl_import_carries_its_warning() {
    let dir = tempfile::tempdir().unwrap();
    let stl = csgpix_testkit::box_stl(4.0, true);
    std::fs::write(dir.path().join("open.stl"), stl).unwrap();
    let scene = dir.path().join("s.csg");
    std::fs::write(&scene, "group() {\n  import(file = \"open.stl\");\n}\n").unwrap();
    let l = load_scene(&scene).unwrap();
    let w = l.scene.warnings.last().expect("a warning").to_string();
    let at = format!(
        "{}:2:3: `open.stl`: mesh is not closed: 4 edges",
        scene.display()
    );
    assert!(w.starts_with(&at), "{w}");
    let v = volume(&l, 8, (-0.5, 4.5), Route::Runs { float: true });
    // Voxel centres at −0.1875 + 0.625·i: 0.4375 … 3.5625 inside, 6 a side.
    assert_eq!(filled(&v), 6 * 6 * 6);
}

/// The run route's progress counts an open mesh's winding numbers: both of its whole-volume
/// and streamed sweeps tick as often as `runs::ticks` says, once a band of rows and once a
/// row of each open mesh's outline.
#[test]
fn the_run_routes_ticks_count_an_open_meshs_rows() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let l = load_scene(&vector("open-box.csg")).unwrap();
    let n = 24;
    let (lo, hi) = (-1.0, 11.0);
    let grid = Grid::new([n; 3], DVec3::splat(lo), DVec3::splat(hi)).unwrap();
    let opts = SlicerOptions {
        sampled: l.sampled.clone(),
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&l.scene, grid, opts).unwrap();
    let rows = csgpix_voxel::runs::open_mesh_ticks(&slicer);
    let want = csgpix_voxel::runs::ticks(&slicer);
    assert!(rows > n / 2 && want > rows, "{rows} rows of {want} ticks");
    let eval = BlistEval::new(&l.scene.root);
    let route = Route::Runs { float: false };
    let ticked = AtomicUsize::new(0);
    let tick = || {
        ticked.fetch_add(1, Ordering::Relaxed);
    };
    let (whole, _) = voxelize(&slicer, route, Equations::Derived.set(), &eval, &tick).unwrap();
    assert_eq!(ticked.swap(0, Ordering::Relaxed), want);
    assert!(filled(&whole) > 0);
    let mut sink = |_: usize, _: &[u8]| -> Result<(), csgpix_voxel::Error> { Ok(()) };
    let set = Equations::Derived.set();
    csgpix_voxel::voxelize_streaming(&slicer, route, set, &eval, &tick, &mut sink).unwrap();
    assert_eq!(ticked.load(Ordering::Relaxed), want);
}
