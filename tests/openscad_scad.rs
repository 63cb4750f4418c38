//! `.scad` files as OpenSCAD users write them, through the command line: errors placed at the
//! line and column of the `.scad` (or said to be in openscad's export), OpenSCAD's warnings
//! for empty primitives and ignored children, `surface()` checked against OpenSCAD's own mesh
//! of the design, and `--fallback openscad` for what csgpix does not draw.
//!
//! Needs `openscad` on PATH (skipped without it unless `CSGPIX_OPENSCAD=require`).

mod common;

use common::have_openscad;

use std::path::Path;

use common::csgpix;

fn run(dir: &Path, scad: &str, extra: &[&str]) -> (Option<i32>, String, String) {
    let file = dir.join("p.scad");
    std::fs::write(&file, scad).unwrap();
    let out = dir.join("p.nrrd");
    let mut args = vec![
        "voxelize",
        file.to_str().unwrap(),
        "--res",
        "16x16x16",
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    let o = csgpix(&args);
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    (o.status.code(), stdout, stderr)
}

fn occupancy(path: &Path) -> Vec<bool> {
    let (_, v) = csgpix::scene::nrrd::read(&std::fs::read(path).unwrap()).unwrap();
    v.iter().map(|&c| c != 0).collect()
}

/// OpenSCAD's own mesh of `dir/p.scad`, voxelized by csgpix at 16³ on `bounds`.
fn openscads_voxels(dir: &Path, bounds: &[&str]) -> Vec<bool> {
    let stl = dir.join("whole.stl");
    let ok = std::process::Command::new("openscad")
        .arg("-o")
        .arg(&stl)
        .arg(dir.join("p.scad"))
        .output()
        .unwrap()
        .status
        .success();
    assert!(ok);
    let csg = dir.join("whole.csg");
    std::fs::write(&csg, "import(\"whole.stl\");\n").unwrap();
    let out = dir.join("whole.nrrd");
    let mut a = vec!["voxelize", csg.to_str().unwrap(), "--res", "16x16x16"];
    a.extend(bounds);
    a.extend(["-o", out.to_str().unwrap()]);
    let o = csgpix(&a);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    occupancy(&out)
}

#[test]
fn errors_are_placed_in_the_scad_file() {
    if !have_openscad() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // surface() is called at one place (line 5, column 3), its file has a height csgpix
    // refuses: the error is put there.
    let scad = "// a part\nh = 2;\n\nmodule bump() {\n  surface(file = \"bump.dat\");\n}\n\
                translate([1, 0, 0]) cube(h);\nbump();\n";
    std::fs::write(dir.path().join("bump.dat"), "1 2\n3 inf\n").unwrap();
    let refused = "bump.dat:2:3: `surface(\"bump.dat\")`: a height of `inf`";
    let (code, _, e) = run(dir.path(), scad, &[]);
    assert_eq!(code, Some(2), "{e}");
    assert_eq!(e.trim().lines().count(), 1, "{e}");
    assert!(e.contains("p.scad:5:3: ") && e.contains(refused), "{e}");
    assert!(!dir.path().join("p.nrrd").exists());
    // A module called twice still has one call site of `surface`: the error is put there.
    let twice = format!("{scad}translate([5, 0, 0]) bump();\n");
    let (code, _, e) = run(dir.path(), &twice, &[]);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("p.scad:5:3: ") && e.contains(refused), "{e}");
    // Written at two places: no line of the .scad is claimed.
    let twice = format!("{scad}surface(file = \"bump.dat\");\n");
    let (code, _, e) = run(dir.path(), &twice, &[]);
    assert_eq!(code, Some(2), "{e}");
    assert!(
        e.contains("p.scad: in the CSG openscad exported from it (line 5, `surface(…)`)"),
        "{e}"
    );
}

#[test]
fn empty_primitives_and_other_dimensions_warn_and_go_on() {
    if !have_openscad() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scad = "cube(4);\ncylinder(r1 = 0, r2 = 0, h = 3);\ngroup();\nsquare(9);\n";
    let (code, out, e) = run(dir.path(), scad, &["--json"]);
    assert_eq!(code, Some(0), "{e}");
    assert!(
        e.starts_with("csgpix: warning: ")
            && e.contains("p.scad:2:1: `cylinder` has a zero, negative or non-finite size"),
        "{e}"
    );
    assert!(
        e.contains("Ignoring 2D child object for 3D operation"),
        "{e}"
    );
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["warnings"].as_array().map(Vec::len), Some(2), "{out}");
    assert_eq!(json["solids"], 1);
    // The cube alone, as OpenSCAD draws it.
    let only = occupancy(&dir.path().join("p.nrrd"));
    assert!(only.iter().all(|&f| f), "the cube fills its own bounds");
}

/// `surface()`, read by csgpix (crates/openscad/src/surface.rs), gives the voxels of
/// OpenSCAD's own mesh of the design; `--fallback openscad` leaves it to csgpix, as a node
/// csgpix reads.
#[test]
fn surface_gives_the_voxels_of_openscads_mesh() {
    if !have_openscad() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let heights: String = (0..6)
        .map(|y| {
            let row: Vec<String> = (0..6).map(|x| format!("{}", 1 + (x * y) % 4)).collect();
            row.join(" ") + "\n"
        })
        .collect();
    std::fs::write(dir.path().join("bump.dat"), heights).unwrap();
    let scad =
        "difference() {\n  translate([0, 0, -1]) surface(file = \"bump.dat\", center = true);\n  \
                cylinder(r = 1.2, h = 10, center = true, $fn = 24);\n}\n";
    let bounds = ["--bounds", "-3,-3,-2,3,3,4"];
    let mut args = vec!["--fallback", "openscad"];
    args.extend(bounds);
    let (code, _, e) = run(dir.path(), scad, &args);
    assert_eq!(code, Some(0), "{e}");
    assert!(!e.contains("meshed by openscad"), "{e}");
    let fallback = occupancy(&dir.path().join("p.nrrd"));
    let (code, _, e) = run(dir.path(), scad, &bounds);
    assert_eq!(code, Some(0), "{e}");
    let ours = occupancy(&dir.path().join("p.nrrd"));
    assert_eq!(ours, fallback);
    let theirs = openscads_voxels(dir.path(), &bounds);
    let both = ours.iter().zip(&theirs).filter(|(a, b)| **a && **b).count();
    let either = ours.iter().zip(&theirs).filter(|(a, b)| **a || **b).count();
    let iou = both as f64 / either.max(1) as f64;
    assert!(iou >= 0.99, "IoU {iou}");
    assert!(both > 100, "a real solid: {both} voxels");
    // Nothing left beside the scene.
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with(".csgpix"))
        .collect();
    assert!(left.is_empty());
}

/// A DXF import csgpix refuses (a comment line over 64 KiB, which OpenSCAD reads) is outlined
/// by openscad under `--fallback openscad`: extruded by csgpix, it gives the voxels of
/// OpenSCAD's own mesh. DXF and SVG imports csgpix reads (crates/openscad/src/dxf.rs, svg.rs)
/// are read by it, by default and under the fallback alike, also one with a value that is not
/// a number, which csgpix skips with OpenSCAD's warning.
#[test]
fn fallback_outlines_a_2d_import() {
    if !have_openscad() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let lwpolyline = |pts: &[(i32, i32)]| {
        let mut s = format!("0\nLWPOLYLINE\n8\n0\n90\n{}\n70\n1\n", pts.len());
        for (x, y) in pts {
            s += &format!("10\n{x}\n20\n{y}\n");
        }
        s
    };
    let dxf = format!(
        "0\nSECTION\n2\nENTITIES\n{}{}0\nENDSEC\n0\nEOF\n",
        lwpolyline(&[(2, 2), (18, 2), (18, 18), (2, 18)]),
        lwpolyline(&[(6, 6), (6, 14), (14, 14), (14, 6)])
    );
    std::fs::write(dir.path().join("frame.dxf"), &dxf).unwrap();
    let odd = dxf.replacen(
        "70\n1\n",
        &format!("70\n1\n999\n{}\n", "x".repeat(70_000)),
        1,
    );
    std::fs::write(dir.path().join("odd.dxf"), odd).unwrap();
    let comma = dxf.replacen("70\n1\n", "70\n1\n40\n1,5\n", 1);
    std::fs::write(dir.path().join("comma.dxf"), comma).unwrap();
    let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20mm\" height=\"20mm\" \
               viewBox=\"0 0 20 20\"><path d=\"M 2 2 L 18 2 L 18 18 L 2 18 Z M 6 6 L 6 14 \
               L 14 14 L 14 6 Z\"/></svg>\n";
    std::fs::write(dir.path().join("frame.svg"), svg).unwrap();
    let bounds = ["--bounds", "0,-1,-1,22,21,4"];
    for (file, fallback) in [
        ("frame.dxf", false),
        ("frame.dxf", true),
        ("odd.dxf", true),
        ("comma.dxf", false),
        ("frame.svg", false),
        ("frame.svg", true),
    ] {
        let scad = format!("translate([1, 0, 0]) linear_extrude(height = 3) import(\"{file}\");\n");
        if file == "odd.dxf" {
            let (code, _, e) = run(dir.path(), &scad, &[]);
            assert_eq!(code, Some(2), "refused by default: {e}");
            assert!(e.contains("p.scad:1:") && e.contains(file), "{e}");
        }
        let mut args = if fallback {
            vec!["--fallback", "openscad"]
        } else {
            vec![]
        };
        args.extend(bounds);
        let (code, _, e) = run(dir.path(), &scad, &args);
        assert_eq!(code, Some(0), "{file}: {e}");
        assert_eq!(e.contains("outlined by openscad"), file == "odd.dxf", "{e}");
        let skipped = "Illegal value \"1,5\" for group code 40";
        assert_eq!(e.contains(skipped), file == "comma.dxf", "{e}");
        let ours = occupancy(&dir.path().join("p.nrrd"));
        let theirs = openscads_voxels(dir.path(), &bounds);
        let both = ours.iter().zip(&theirs).filter(|(a, b)| **a && **b).count();
        let either = ours.iter().zip(&theirs).filter(|(a, b)| **a || **b).count();
        assert!(both > 100, "{file}: a real solid: {both} voxels");
        assert_eq!(both, either, "{file}: the same voxels");
    }
}

/// A `.scad` file is read as OpenSCAD renders it (F6, STL export: `$preview` false), not as it
/// previews it: the parts to print, not an `if ($preview)` assembly view.
#[test]
fn a_scad_file_is_read_as_rendered_not_previewed() {
    if !have_openscad() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scad = "if ($preview) translate([10, 0, 0]) cube(2); else cube(4);\n";
    let (code, out, e) = run(dir.path(), scad, &["--json"]);
    assert_eq!(code, Some(0), "{e}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["solids"], 1, "{out}");
    assert_eq!(
        json["max"],
        serde_json::json!([4.0, 4.0, 4.0]),
        "the rendered cube(4): {out}"
    );
}
