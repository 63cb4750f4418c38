//! `csgpix print`: resin-printer layers (docs/printer.md). The archives read back with a
//! standard zip reader and PNG decoder; the layers compared with PrusaSlicer 2.5's own
//! (`vectors/printer/prusaslicer-*-sl1-layer10.png`, layer 10 of `prusa-slicer --export-sla`
//! of the same part's STL on its SL1 profile, supports and pad off).

use std::io::Read;
use std::path::Path;
use std::process::Command;

fn csgpix(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_csgpix"))
        .args(args)
        .output()
        .expect("csgpix runs")
}

fn member(archive: &Path, name: &str) -> Vec<u8> {
    let f = std::fs::File::open(archive).unwrap();
    let mut z = zip::ZipArchive::new(f).unwrap();
    let mut m = z.by_name(name).unwrap();
    let mut v = vec![];
    m.read_to_end(&mut v).unwrap();
    v
}

fn grey(png: &[u8]) -> image::GrayImage {
    image::load_from_memory(png).unwrap().to_luma8()
}

/// `csgpix print SCENE -o OUT --aa AA --json`, which must succeed: its report.
fn print_aa(scene: &Path, out: &Path, aa: &str) -> serde_json::Value {
    let r = csgpix(&[
        "print",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--aa",
        aa,
        "--json",
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    serde_json::from_slice(&r.stdout).unwrap()
}

/// A `.csg` cube of `size` with its lowest corner at `at`, one tab in.
fn cube_at(at: [f64; 3], size: [f64; 3]) -> String {
    format!(
        "\tmultmatrix([[1, 0, 0, {}], [0, 1, 0, {}], [0, 0, 1, {}], [0, 0, 0, 1]]) \
         {{\n\t\tcube(size = [{}, {}, {}], center = false);\n\t}}\n",
        at[0], at[1], at[2], size[0], size[1], size[2]
    )
}

/// Prints `cut` and `solid` into archives at `--aa AA` and asserts they are the same
/// print: the same layer count, the part at the same pixels, every layer's greys equal.
/// The layer count.
fn prints_alike(cut: &Path, solid: &Path, aa: &str) -> usize {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("p.sl1"), dir.path().join("q.sl1"));
    let (ra, rb) = (print_aa(cut, &a, aa), print_aa(solid, &b, aa));
    assert_eq!(ra["layers"], rb["layers"], "--aa {aa}: layer counts");
    assert_eq!(
        ra["part_origin"], rb["part_origin"],
        "--aa {aa}: part origins"
    );
    let layers = ra["layers"].as_u64().unwrap() as usize;
    for l in 0..layers {
        let (x, y) = (
            member(&a, &format!("p{l:05}.png")),
            member(&b, &format!("q{l:05}.png")),
        );
        assert!(grey(&x) == grey(&y), "--aa {aa}: layer {l} differs");
    }
    layers
}

/// Intersection over union of the pixels at or above 128.
fn iou(a: &image::GrayImage, b: &image::GrayImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions());
    let (mut both, mut any) = (0u64, 0u64);
    for (p, q) in a.pixels().zip(b.pixels()) {
        let (x, y) = (p.0[0] >= 128, q.0[0] >= 128);
        both += u64::from(x && y);
        any += u64::from(x || y);
    }
    both as f64 / any.max(1) as f64
}

#[test]
fn layers_match_prusaslicers_on_its_sl1() {
    let dir = tempfile::tempdir().unwrap();
    for (scene, reference, min_iou) in [
        ("box", "box", 1.0),
        ("l-shape", "l", 1.0),
        ("wedge", "wedge", 0.99),
    ] {
        let out = dir.path().join(format!("{scene}.sl1"));
        let csg = format!("vectors/printer/{scene}.csg");
        let r = csgpix(&["print", &csg, "-o", out.to_str().unwrap()]);
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
        let ours = grey(&member(&out, &format!("{scene}00010.png")));
        let path = format!("vectors/printer/prusaslicer-{reference}-sl1-layer10.png");
        let theirs = image::open(path).unwrap().to_luma8();
        let v = iou(&ours, &theirs);
        assert!(
            v >= min_iou,
            "{scene}: IoU {v} against PrusaSlicer's layer 10"
        );
    }
}

#[test]
fn an_archive_states_its_layers_and_material() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("part.sl1");
    let r = csgpix(&[
        "print",
        "vectors/printer/box.csg",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(r.status.success());
    let config = String::from_utf8(member(&out, "config.ini")).unwrap();
    // 3 mm at 0.05 mm: 60 layers; 10 × 6 × 3 mm = 0.18 ml to within the pixels' snapping.
    assert!(config.contains("numFast = 60\n"), "{config}");
    assert!(config.contains("jobDir = part\n"), "{config}");
    let ml: f64 = config
        .lines()
        .find_map(|l| l.strip_prefix("usedMaterial = "))
        .unwrap()
        .parse()
        .unwrap();
    assert!((ml - 0.18).abs() < 0.005, "usedMaterial {ml}");
    let thumb = grey(&member(&out, "thumbnail/thumbnail400x400.png"));
    assert_eq!(thumb.dimensions(), (400, 400));
    // The last layer is lit; there is no layer past it.
    let last = grey(&member(&out, "part00059.png"));
    assert!(last.pixels().any(|p| p.0[0] == 255));
    let f = std::fs::File::open(&out).unwrap();
    assert!(zip::ZipArchive::new(f)
        .unwrap()
        .by_name("part00060.png")
        .is_err());
}

/// A 10 mm cube on a made-up 100 × 100 mm display of 10 × 10 pixels, placed so that its
/// edges cut pixels in half: those pixels are grey 128 with --aa 4 (8 of 16 samples), 255
/// inside, and thresholded away or kept whole without anti-aliasing.
#[test]
fn anti_aliasing_gives_the_covered_share() {
    let dir = tempfile::tempdir().unwrap();
    let stack = dir.path().join("stack");
    let args = [
        "print",
        "vectors/printer/box.csg",
        "--display",
        "100x100",
        "--pixels",
        "100x100",
        "--orientation",
        "landscape",
        "--mirror",
        "none",
        "--position",
        "0.5,0",
        "--aa",
        "4",
        "-o",
        stack.to_str().unwrap(),
    ];
    let r = csgpix(&args);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let img = image::open(stack.join("layer-00000.png"))
        .unwrap()
        .to_luma8();
    // 10 × 6 mm centred at (50.5, 50) on 1 mm pixels: x 45.5..55.5, y 47..53.
    let row = 100 - 1 - 50; // a pixel row inside the part (y 50..51)
    let at = |x: u32| img.get_pixel(x, row).0[0];
    assert_eq!(
        (at(44), at(45), at(46), at(54), at(55), at(56)),
        (0, 128, 255, 255, 128, 0)
    );
    let info: serde_json::Value =
        serde_json::from_slice(&std::fs::read(stack.join("print.json")).unwrap()).unwrap();
    assert_eq!(info["layers"], 60);
}

#[test]
fn bad_printer_settings_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.sl1");
    let o = out.to_str().unwrap();
    for (args, says) in [
        (vec!["--layer-height", "0"], "--layer-height"),
        (vec!["--aa", "0"], "--aa"),
        (vec!["--pixels", "0x10"], "--pixels"),
        (vec!["--display", "5x5"], "does not fit"),
    ] {
        let mut all = vec!["print", "vectors/printer/box.csg", "-o", o];
        all.extend(args);
        let r = csgpix(&all);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(2), "{all:?}: {err}");
        assert!(
            err.contains(says) && err.trim().lines().count() == 1,
            "{err}"
        );
        assert!(!out.exists(), "no partial output");
    }
}

/// A difference that cuts the top and a side away: the part is 10 × 6 × 5 mm, not the
/// first child's 10 × 6 × 10, and sits where PrusaSlicer would put that part: 100 layers
/// in an archive and in a stack alike, each layer the 10 × 6 mm footprint below z = 5.
#[test]
fn a_part_cut_by_a_difference_is_placed_by_what_remains() {
    let dir = tempfile::tempdir().unwrap();
    let archive = dir.path().join("cut.sl1");
    let stack = dir.path().join("cut");
    for out in [&archive, &stack] {
        let r = csgpix(&[
            "print",
            "vectors/printer/cut-top.csg",
            "-o",
            out.to_str().unwrap(),
            "--json",
        ]);
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
        let report: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap();
        assert_eq!(report["layers"], 100, "{out:?}");
        // 10 mm over 0.04725 mm pixels: 212 columns of part, as for the uncut box.
        assert_eq!(report["part_pixels"][0], 212, "{out:?}");
    }
    let box_layer = {
        let r = csgpix(&[
            "print",
            "vectors/printer/box.csg",
            "-o",
            dir.path().join("box.sl1").to_str().unwrap(),
        ]);
        assert!(r.status.success());
        grey(&member(&dir.path().join("box.sl1"), "box00010.png"))
    };
    let cut_layer = grey(&member(&archive, "cut00010.png"));
    assert_eq!(iou(&box_layer, &cut_layer), 1.0);
    let stacked = image::open(stack.join("layer-00010.png"))
        .unwrap()
        .to_luma8();
    assert_eq!(iou(&box_layer, &stacked), 1.0);
}

/// A box cut out of a larger cube by a difference on all four sides and at the floor and
/// the top, at places that fall inside pixels and layers, against the same box as a cube of its own
/// (whose box is exact): a slicer centres the part on the mesh's box, so the cut sides
/// must be found to well under a pixel for the two to light the same pixels. The same
/// layer count (131: 6.5986 mm over 0.05 mm layers) and every layer's greys equal, with
/// and without anti-aliasing, in an archive and in a stack.
#[test]
fn a_part_cut_on_every_side_is_placed_as_the_same_part_uncut() {
    let dir = tempfile::tempdir().unwrap();
    let cut = dir.path().join("cut.csg");
    let solid = dir.path().join("solid.csg");
    let slab = cube_at;
    let slabs = [
        slab([-1.0, -1.0, -1.0], [2.37, 8.0, 12.0]),
        slab([8.911, -1.0, -1.0], [5.0, 8.0, 12.0]),
        slab([-1.0, -1.0, -1.0], [12.0, 1.613, 12.0]),
        slab([-1.0, 5.0417, -1.0], [12.0, 5.0, 12.0]),
        slab([-1.0, -1.0, -1.0], [12.0, 8.0, 1.4137]),
        slab([-1.0, -1.0, 7.0123], [12.0, 8.0, 5.0]),
    ];
    std::fs::write(
        &cut,
        format!(
            "difference() {{\n\tcube(size = [10, 6, 10], center = false);\n{}}}\n",
            slabs.concat()
        ),
    )
    .unwrap();
    std::fs::write(
        &solid,
        "multmatrix([[1, 0, 0, 1.37], [0, 1, 0, 0.613], [0, 0, 1, 0.4137], [0, 0, 0, 1]]) \
         {\n\tcube(size = [7.541, 4.4287, 6.5986], center = false);\n}\n",
    )
    .unwrap();
    for aa in ["1", "4"] {
        assert_eq!(prints_alike(&cut, &solid, aa), 131);
    }
    let (a, b) = (dir.path().join("sa"), dir.path().join("sb"));
    assert_eq!(print_aa(&cut, &a, "1")["layers"], 131);
    print_aa(&solid, &b, "1");
    for l in [0, 1, 65, 130] {
        let name = format!("layer-{l:05}.png");
        let x = image::open(a.join(&name)).unwrap().to_luma8();
        let y = image::open(b.join(&name)).unwrap().to_luma8();
        assert!(x == y, "stack layer {l} differs");
    }
}

/// A diamond cut by a difference so that the part's highest and lowest points are
/// corners where the cut meets its 45° edges, at different heights on either side: along
/// a column of samples the lit extent falls short of such a corner by up to half a
/// sample, so finding those sides needs the second, finer look around where the first
/// saw them. Printed as the same outline extruded (whose box is exact): the same greys on
/// every layer, at `--aa 1` and `--aa 4`.
#[test]
fn a_part_whose_cut_sides_are_corners_is_placed_as_the_same_part_uncut() {
    let dir = tempfile::tempdir().unwrap();
    let cut = dir.path().join("cut.csg");
    let solid = dir.path().join("solid.csg");
    let (c, s) = (
        std::f64::consts::FRAC_1_SQRT_2,
        2.5 * std::f64::consts::SQRT_2,
    );
    std::fs::write(
        &cut,
        format!(
            "difference() {{\n\tmultmatrix([[{c}, -{c}, 0, 0], [{c}, {c}, 0, 0], [0, 0, 1, 1.5], \
             [0, 0, 0, 1]]) {{\n\t\tcube(size = [5, 5, 3], center = true);\n\t}}\n\t\
             multmatrix([[1, 0, 0, -1], [0, 1, 0, 0], [0, 0, 1, -5], [0, 0, 0, 1]]) {{\n\t\t\
             cube(size = [10, 10, 10], center = false);\n\t}}\n\tmultmatrix([[1, 0, 0, -1.7], \
             [0, 1, 0, -10], [0, 0, 1, -5], [0, 0, 0, 1]]) {{\n\t\t\
             cube(size = [10, 10, 10], center = false);\n\t}}\n}}\n"
        ),
    )
    .unwrap();
    let outline = [
        (-s, 0.0),
        (-1.7, 1.7 - s),
        (-1.7, 0.0),
        (-1.0, 0.0),
        (-1.0, s - 1.0),
    ];
    let points: Vec<String> = outline.iter().map(|(x, y)| format!("[{x}, {y}]")).collect();
    std::fs::write(
        &solid,
        format!(
            "linear_extrude(height = 3, center = false, convexity = 1, scale = [1, 1]) {{\n\t\
             polygon(points = [{}], paths = undef, convexity = 1);\n}}\n",
            points.join(", ")
        ),
    )
    .unwrap();
    for aa in ["1", "4"] {
        assert_eq!(prints_alike(&cut, &solid, aa), 60);
    }
}

/// A part whose box a difference cuts on four sides, beyond which two fins and two pillars
/// stick out, each 0.06 mm thick (1.3 pixels on the SL1): the print's box is found before
/// the print by a first look at every eighth sample along X and Y, which steps over such a
/// fin or pillar, and then by every sample between the box's sides and what that look lit
/// (along Z, in the layers it lit none of). Printed as the same part uncut (the cube, the
/// fins and the pillars, whose box is exact): the same layers and greys.
#[test]
fn thin_features_between_the_first_looks_samples_still_place_the_part() {
    let dir = tempfile::tempdir().unwrap();
    let (cut, solid) = (dir.path().join("cut.csg"), dir.path().join("solid.csg"));
    let cube = cube_at;
    let part = [
        cube([0.0, 0.0, 0.0], [6.0, 4.0, 2.0]),
        cube([6.0, 2.013, 0.0], [1.317, 0.06, 2.0]),
        cube([3.021, -1.139, 0.0], [0.06, 1.139, 2.0]),
        cube([1.5, 1.0, 0.0], [0.06, 0.06, 2.8]),
        cube([4.5, 3.0, -0.4], [0.06, 0.06, 0.4]),
    ]
    .concat();
    let far = [
        cube([9.0, 0.0, 0.0], [2.0, 4.0, 2.0]),
        cube([0.0, -4.0, 0.0], [6.0, 1.5, 2.0]),
        cube([0.0, 0.0, 3.5], [6.0, 4.0, 1.0]),
        cube([0.0, 0.0, -2.0], [6.0, 4.0, 0.5]),
    ]
    .concat();
    let cutters = [
        cube([8.1, -10.0, -5.0], [10.0, 20.0, 15.0]),
        cube([-10.0, -10.0, -5.0], [20.0, 8.3, 15.0]),
        cube([-10.0, -10.0, 3.3], [30.0, 30.0, 5.0]),
        cube([-10.0, -10.0, -10.0], [30.0, 30.0, 9.5]),
    ]
    .concat();
    std::fs::write(
        &cut,
        format!("difference() {{\n\tunion() {{\n{part}{far}\t}}\n{cutters}}}\n"),
    )
    .unwrap();
    std::fs::write(&solid, format!("union() {{\n{part}}}\n")).unwrap();
    for aa in ["1", "4"] {
        assert_eq!(prints_alike(&cut, &solid, aa), 64);
    }
}

/// A cut part so thin (a pillar 0.06 mm square, beside a block the cut removes) that the
/// first look at every eighth sample lights none of it: then every sample is looked at, and
/// the pillar is placed as the pillar alone (at `--aa 1` that is the fallback's path).
#[test]
fn a_part_the_first_look_misses_altogether_is_still_placed() {
    let dir = tempfile::tempdir().unwrap();
    let (cut, solid) = (dir.path().join("cut.csg"), dir.path().join("solid.csg"));
    let pillar = cube_at([3.021, 1.013, 0.0], [0.06, 0.06, 1.0]);
    let far = cube_at([9.0, -2.0, 0.0], [2.0, 6.0, 1.0]);
    let cutter = cube_at([8.0, -10.0, -5.0], [10.0, 20.0, 15.0]);
    std::fs::write(
        &cut,
        format!("difference() {{\n\tunion() {{\n{pillar}{far}\t}}\n{cutter}}}\n"),
    )
    .unwrap();
    std::fs::write(&solid, format!("union() {{\n{pillar}}}\n")).unwrap();
    for aa in ["1", "4"] {
        assert_eq!(prints_alike(&cut, &solid, aa), 20);
    }
}

/// Text and other concave outlines are footprints in a print (their 2D tree sampled, not
/// meshed); where the tree subtracts, its box is not the part's and the print finds the
/// part's as it does for a difference of solids: an L less a strip along its foot prints as
/// the L's remaining outline does, at the same place.
#[test]
fn a_footprint_that_subtracts_is_placed_by_what_it_lights() {
    let dir = tempfile::tempdir().unwrap();
    let (cut, solid) = (dir.path().join("cut.csg"), dir.path().join("solid.csg"));
    let extrude = |s: &str| format!("linear_extrude(height = 1.2) {{\n{s}\n}}\n");
    let ell = "polygon(points = [[0, 0], [6, 0], [6, 1], [1, 1], [1, 4], [0, 4]]);";
    let strip = "square(size = [7, 0.513]);";
    let rest = "polygon(points = [[0, 0.513], [6, 0.513], [6, 1], [1, 1], [1, 4], [0, 4]]);";
    let cut_text = extrude(&format!("difference() {{ {ell} {strip} }}"));
    std::fs::write(&cut, cut_text).unwrap();
    std::fs::write(&solid, extrude(rest)).unwrap();
    for aa in ["1", "4"] {
        assert_eq!(prints_alike(&cut, &solid, aa), 24);
    }
}

/// A scene of two colours: besides the part's stack, one stack per colour code, each the
/// pixels of its own cube, the two together the part.
#[test]
fn each_material_has_its_own_stack() {
    let dir = tempfile::tempdir().unwrap();
    let stack = dir.path().join("two");
    let r = csgpix(&[
        "print",
        "vectors/printer/two-colours.csg",
        "-o",
        stack.to_str().unwrap(),
        "--json",
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let report: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap();
    let codes: Vec<u64> = report["materials"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_u64().unwrap())
        .collect();
    assert_eq!(codes.len(), 2, "{report}");
    // Layer 50 (z = 2.525) is above the 2 mm cube: only the 3 mm one is lit there.
    for layer in [0, 50] {
        let all = image::open(stack.join(format!("layer-{layer:05}.png")))
            .unwrap()
            .to_luma8();
        let lit = |img: &image::GrayImage| img.pixels().filter(|p| p.0[0] > 0).count();
        let parts: Vec<usize> = codes
            .iter()
            .map(|c| {
                lit(
                    &image::open(stack.join(format!("material-{c}-layer-{layer:05}.png")))
                        .unwrap()
                        .to_luma8(),
                )
            })
            .collect();
        assert_eq!(
            parts.iter().sum::<usize>(),
            lit(&all),
            "layer {layer}: {parts:?}"
        );
        assert_eq!(
            parts.iter().filter(|&&n| n > 0).count(),
            if layer == 0 { 2 } else { 1 }
        );
    }
}

/// Material stacks come from `color()` and only in a PNG stack: solids without a colour
/// (which `voxelize` codes 1..6 in turn) are one material, and an archive (one resin) holds
/// the part's layers alone.
#[test]
fn materials_only_where_the_scene_has_colours() {
    let dir = tempfile::tempdir().unwrap();
    let plain = dir.path().join("plain.csg");
    std::fs::write(
        &plain,
        "cube(size = [10, 6, 3]);\nmultmatrix([[1, 0, 0, 12], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = [4, 6, 2]);\n",
    )
    .unwrap();
    let report = |scene: &str, out: &Path| {
        let r = csgpix(&["print", scene, "-o", out.to_str().unwrap(), "--json"]);
        assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
        serde_json::from_slice::<serde_json::Value>(&r.stdout).unwrap()
    };
    let stack = dir.path().join("plain");
    assert_eq!(
        report(plain.to_str().unwrap(), &stack)["materials"],
        serde_json::json!([])
    );
    let names: Vec<String> = std::fs::read_dir(&stack)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names.iter().all(|n| !n.starts_with("material-")),
        "{names:?}"
    );
    let archive = dir.path().join("two.sl1");
    let r = report("vectors/printer/two-colours.csg", &archive);
    assert_eq!(r["materials"], serde_json::json!([]), "{r}");
    let f = std::fs::File::open(&archive).unwrap();
    let z = zip::ZipArchive::new(f).unwrap();
    assert!(z.file_names().all(|n| !n.contains("material")));
}

/// A scene's warnings reach stderr once: told as the scene is read, not again with the
/// summary (an open polyhedron's, which the print voxelizes by its winding number).
#[test]
fn a_warning_is_told_once() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("open.sl1");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("vectors/openmesh/open-box.csg");
    let r = csgpix(&[
        "print",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let stderr = String::from_utf8_lossy(&r.stderr);
    let told: Vec<&str> = stderr.lines().filter(|l| l.contains("warning")).collect();
    assert_eq!(told.len(), 1, "{stderr}");
    assert!(told[0].contains("polyhedron is not closed"), "{stderr}");
}
