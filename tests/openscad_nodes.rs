//! OpenSCAD's 2D shapes, extrusions, `hull()` and `offset()` in `.csg` scenes: what each
//! becomes (a convex solid the array draws, or a closed mesh primitive), checked against
//! independently built solids voxel for voxel, and the refusals with line and column.

mod common;

use common::csgpix;
use csgpix::openscad::parse_csg;
use csgpix::scene::solid::{CsgNode, CsgScene};
use csgpix::voxel::blist::BlistEval;
use csgpix::voxel::sampled::load_imports;
use csgpix::voxel::{voxelize, Grid, Route, Slicer, SlicerOptions, Volume};
use glam::DVec3;
use rtl_model::Equations;

fn parse(text: &str) -> CsgScene {
    parse_csg(text, "t.csg").unwrap_or_else(|e| panic!("{e}"))
}

/// Voxels of a scene (imports loaded) on a fixed grid, centre sampling, float route.
fn voxels(text: &str, lo: f64, hi: f64, n: usize) -> Volume {
    let scene = parse(text);
    let sampled = load_imports(&scene, "t.csg", std::path::Path::new(".")).unwrap();
    let grid = Grid::new([n; 3], DVec3::splat(lo), DVec3::splat(hi)).unwrap();
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(&scene, grid, opts).unwrap();
    let eval = BlistEval::new(&scene.root);
    voxelize(
        &slicer,
        Route::Float,
        Equations::Derived.set(),
        &eval,
        &|| {},
    )
    .unwrap()
    .0
}

fn filled(v: &Volume) -> Vec<bool> {
    v.voxels.iter().map(|&c| c != 0).collect()
}

fn err(text: &str) -> String {
    parse_csg(text, "t.csg").unwrap_err().to_string()
}

#[test]
fn a_square_extruded_is_the_cube() {
    let s = parse(
        "linear_extrude(height = 3, center = false) { square(size = [1, 2], center = false); }",
    );
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0), "a convex solid");
    assert_eq!(s.solids[0].faces.len(), 6);
    let a = voxels(
        "linear_extrude(height = 3) square(size = [1, 2]);",
        -1.0,
        4.0,
        20,
    );
    let b = voxels("cube(size = [1, 2, 3]);", -1.0, 4.0, 20);
    assert_eq!(filled(&a), filled(&b));
    assert_eq!(filled(&a).iter().filter(|&&x| x).count(), 4 * 8 * 12);
}

#[test]
fn a_scaled_extrusion_is_a_convex_frustum() {
    // A square pyramid frustum: at half height the outline is scaled by 0.75.
    let s = parse("linear_extrude(height = 4, scale = 0.5) square(size = 4, center = true);");
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
    let v = voxels(
        "linear_extrude(height = 4, scale = 0.5) square(size = 4, center = true);",
        -2.0,
        2.0,
        16,
    );
    // The solid spans z 0..4, the grid -2..2 in 16 layers: layer 15 has its centres at
    // z = 1.875, where the half-width is 2·(1 − 0.5·1.875/4) = 1.53, so 12 of 16 centres
    // across (±0.125 … ±1.375) are inside.
    let layer: usize = (0..16 * 16).filter(|i| v.voxels[15 * 256 + i] != 0).count();
    assert_eq!(layer, 12 * 12);
}

#[test]
fn a_2d_difference_extruded_is_the_difference_of_extrusions() {
    let text = "linear_extrude(height = 2) difference() { square(size = 10, center = true); \
                circle(r = 3, $fn = 16); }";
    let s = parse(text);
    assert_eq!(
        (s.solids.len(), s.imports.len()),
        (2, 0),
        "two convex prisms"
    );
    assert!(matches!(s.root, CsgNode::Difference(_)));
    let a = voxels(text, -5.0, 5.0, 20);
    let b = voxels(
        "difference() { multmatrix([[1,0,0,-5],[0,1,0,-5],[0,0,1,0],[0,0,0,1]]) cube(size = [10, 10, 2]); \
         cylinder(h = 2, r = 3, $fn = 16); }",
        -5.0,
        5.0,
        20,
    );
    assert_eq!(filled(&a), filled(&b));
}

#[test]
fn a_holed_polygon_becomes_a_closed_mesh_with_its_hole() {
    let text = "linear_extrude(height = 4, twist = 30, slices = 3) polygon(points = [[-5,-5],[5,-5],[5,5],[-5,5],[-2,-2],[2,-2],[2,2],[-2,2]], paths = [[0,1,2,3],[4,5,6,7]]);";
    let s = parse(text);
    assert_eq!(
        (s.solids.len(), s.imports.len()),
        (0, 1),
        "a mesh primitive"
    );
    let v = voxels(text, -6.0, 6.0, 24);
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * 24 + j) * 24 + i] != 0;
    assert!(!at(12, 12, 13), "the hole");
    assert!(at(3, 12, 13), "the wall");
    assert!(!at(12, 12, 5), "below the extrusion");
}

#[test]
fn rotate_extrude_of_a_circle_is_a_torus() {
    let text = "rotate_extrude(angle = 360, $fn = 12) multmatrix([[1,0,0,4],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) circle(r = 1, $fn = 8);";
    let s = parse(text);
    assert_eq!(s.imports.len(), 1);
    let mesh = s.imports[0].mesh.as_ref().unwrap();
    assert_eq!(mesh.len(), 2 * 8 * 12);
    let v = voxels(text, -6.0, 6.0, 24);
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * 24 + j) * 24 + i] != 0;
    assert!(!at(12, 12, 12), "the hole of the torus");
    assert!(
        at(20, 12, 12) && at(4, 12, 12) && at(12, 20, 12),
        "the ring"
    );
    // A part turn from +X counter-clockwise: the quarter at -Y is empty.
    let part = "rotate_extrude(angle = 270) multmatrix([[1,0,0,4],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) circle(r = 1, $fn = 8);";
    let v = voxels(part, -6.0, 6.0, 24);
    let at = |i: usize, j: usize, k: usize| v.voxels[(k * 24 + j) * 24 + i] != 0;
    assert!(at(12, 20, 12) && at(4, 12, 12) && !at(12, 4, 12));
}

#[test]
fn hull_of_solids_is_one_convex_solid() {
    let text = "hull() { cube(size = 2); multmatrix([[1,0,0,5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(size = 2); }";
    let s = parse(text);
    assert_eq!(s.solids.len(), 1, "the hulled cubes leave the scene");
    assert_eq!(s.solids[0].faces.len(), 6);
    let a = voxels(text, -1.0, 8.0, 18);
    let b = voxels("cube(size = [7, 2, 2]);", -1.0, 8.0, 18);
    assert_eq!(filled(&a), filled(&b));
    // Beside another solid, which keeps its place and number.
    let s = parse(&format!("sphere(r = 1, $fn = 6); {text}"));
    assert_eq!(s.solids.len(), 2);
    assert_eq!(
        s.root,
        CsgNode::Union(vec![CsgNode::Solid(0), CsgNode::Solid(1)])
    );
    // Of 2D shapes, extruded.
    let s = parse("linear_extrude(height = 1) hull() { square(size = 1); multmatrix([[1,0,0,3],[0,1,0,3],[0,0,1,0],[0,0,0,1]]) circle(r = 1, $fn = 4); }");
    assert_eq!((s.solids.len(), s.imports.len()), (1, 0));
}

#[test]
fn offsets_of_a_square_extruded() {
    let grown = voxels(
        "linear_extrude(height = 2) offset(delta = 1) square(size = 2);",
        -2.0,
        4.0,
        24,
    );
    let cube = voxels(
        "multmatrix([[1,0,0,-1],[0,1,0,-1],[0,0,1,0],[0,0,0,1]]) cube(size = [4, 4, 2]);",
        -2.0,
        4.0,
        24,
    );
    assert_eq!(filled(&grown), filled(&cube));
    let shrunk = voxels(
        "linear_extrude(height = 2) offset(r = -0.5) square(size = 2);",
        -2.0,
        4.0,
        24,
    );
    let inner = voxels(
        "multmatrix([[1,0,0,0.5],[0,1,0,0.5],[0,0,1,0],[0,0,0,1]]) cube(size = [1, 1, 2]);",
        -2.0,
        4.0,
        24,
    );
    assert_eq!(filled(&shrunk), filled(&inner));
}

#[test]
fn offset_of_a_holed_square_extruded() {
    // [0, 4]² minus [1, 3]², its edges moved in by 0.25: the frame [0.25, 3.75]² minus
    // [0.75, 3.25]².
    let frame = voxels(
        "linear_extrude(height = 2) offset(delta = -0.25) difference() { square(size = 4); multmatrix([[1,0,0,1],[0,1,0,1],[0,0,1,0],[0,0,0,1]]) square(size = 2); }",
        -1.0,
        5.0,
        24,
    );
    let cubes = voxels(
        "difference() { multmatrix([[1,0,0,0.25],[0,1,0,0.25],[0,0,1,0],[0,0,0,1]]) cube(size = [3.5, 3.5, 2]); multmatrix([[1,0,0,0.75],[0,1,0,0.75],[0,0,1,-1],[0,0,0,1]]) cube(size = [2.5, 2.5, 4]); }",
        -1.0,
        5.0,
        24,
    );
    assert!(filled(&frame).iter().any(|&b| b));
    assert_eq!(filled(&frame), filled(&cubes));
}

#[test]
fn unsupported_uses_are_refused_with_line_and_column() {
    assert!(err("group() {\n  square(size = 1);\n}").starts_with("t.csg:2:3: a 2D shape outside"));
    // A 2D child beside 3D ones is ignored with OpenSCAD's warning (no longer refused).
    let s = parse("union() { cube(size = 1);\n square(size = 1); }");
    assert!(s
        .warnings
        .iter()
        .any(|w| w.to_string().contains("Ignoring 2D child object")));
    let e = err(
        "hull() { difference() { cube(size = 2); import(file = \"d.nrrd\", threshold = 1); } }",
    );
    assert!(
        e.starts_with("t.csg:1:1: hull(): `import(\"d.nrrd\")` has no geometry"),
        "{e}"
    );
    let e = err("minkowski() {\n cube(size = 2); import(file = \"m.stl\"); }");
    assert!(
        e.starts_with("t.csg:1:1: minkowski(): `import(\"m.stl\")` has no geometry"),
        "{e}"
    );
    // A shape across the axis: nothing drawn, with OpenSCAD's words as a warning.
    let s = parse("rotate_extrude() square(size = 2, center = true);");
    assert_eq!(s.root, CsgNode::Empty);
    let w = s.warnings[0].to_string();
    assert!(
        w.starts_with("t.csg:1:1: all points for rotate_extrude()"),
        "{w}"
    );
    let e = err("linear_extrude(height = 1, scale = -1) square(size = 1);");
    assert!(
        e.starts_with("t.csg:1:36: `scale` must not be negative"),
        "{e}"
    );
    // A 3D child of an extrusion is ignored with OpenSCAD's warning.
    let s = parse("linear_extrude(height = 1) cube(size = 1);");
    assert!(s
        .warnings
        .iter()
        .any(|w| w.to_string().contains("Ignoring 3D child object")));
}

#[test]
fn render_names_an_extrusion_it_cannot_draw() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("t.csg");
    std::fs::write(
        &scene,
        "cube(size = 1);\nrotate_extrude($fn = 8) square(size = 1);\n",
    )
    .unwrap();
    let out = dir.path().join("t.png");
    let o = csgpix(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(
        e.contains("t.csg:2:1: `rotate_extrude at 2:1` (not a convex solid)"),
        "{e}"
    );
    assert!(!out.exists());
}

/// A `.scad` file goes through `openscad -o x.csg`; without openscad a one-line error says so.
#[test]
fn scad_files_are_read_through_openscad() {
    let dir = tempfile::tempdir().unwrap();
    let scad = dir.path().join("t.scad");
    std::fs::write(
        &scad,
        "difference() { cube(10, center = true); sphere(4); }\n",
    )
    .unwrap();
    let out = dir.path().join("t.nrrd");
    let args = [
        "voxelize",
        scad.to_str().unwrap(),
        "--res",
        "16x16x16",
        "-o",
        out.to_str().unwrap(),
    ];
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .env("PATH", "")
        .output()
        .unwrap();
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("reading .scad needs openscad on PATH"), "{e}");
    assert_eq!(e.trim().lines().count(), 1);
    assert!(!out.exists());
    let have = std::process::Command::new("openscad")
        .arg("--version")
        .output()
        .is_ok();
    if !have {
        assert_ne!(std::env::var("CSGPIX_OPENSCAD").as_deref(), Ok("require"));
        eprintln!("openscad is not on PATH: the conversion itself is not checked");
        return;
    }
    let o = csgpix(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csg = dir.path().join("t.csg");
    let ok = std::process::Command::new("openscad")
        .arg("-o")
        .arg(&csg)
        .arg(&scad)
        .output()
        .unwrap()
        .status
        .success();
    assert!(ok);
    let out2 = dir.path().join("u.nrrd");
    let o = csgpix(&[
        "voxelize",
        csg.to_str().unwrap(),
        "--res",
        "16x16x16",
        "-o",
        out2.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let read = |p: &std::path::Path| {
        csgpix::scene::nrrd::read(&std::fs::read(p).unwrap())
            .unwrap()
            .1
    };
    assert_eq!(read(&out), read(&out2));
}
