//! The `csgpix` binary end to end.

mod common;
use common::csgpix;

use std::path::{Path, PathBuf};

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn checked_in_vectors_are_what_the_generator_writes() {
    let out = csgpix(&["gen-vectors", "--check"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn derived_equations_pass_the_verifier() {
    let out = csgpix(&["verify-select", "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let sigs = v.as_array().unwrap();
    assert_eq!(sigs.len(), 9);
    for s in sigs {
        assert!(s["rows"].as_u64().unwrap() > 0);
        assert_eq!(s["mismatches"].as_array().unwrap().len(), 0, "{s}");
    }
}

#[test]
fn printed_equations_fail_the_verifier_with_rows_named() {
    let out = csgpix(&["verify-select", "--equations", "printed", "--json"]);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let bad: Vec<&serde_json::Value> = v
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| !s["mismatches"].as_array().unwrap().is_empty())
        .collect();
    assert!(!bad.is_empty());
    let m = &bad[0]["mismatches"][0];
    assert!(m["inputs"].as_str().unwrap().contains("N="));
    assert_ne!(m["expected"], m["got"]);
}

#[test]
fn verify_select_reports_a_broken_vector_file_with_line_and_column() {
    let d = tmp();
    for t in ["front", "back", "close", "clip", "second"] {
        let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("vectors/select/{t}.pla"));
        std::fs::copy(src, d.path().join(format!("{t}.pla"))).unwrap();
    }
    let p = d.path().join("back.pla");
    let text = std::fs::read_to_string(&p)
        .unwrap()
        .replacen("\n000000 ", "\n0x0000 ", 1);
    std::fs::write(&p, text).unwrap();
    let out = csgpix(&["verify-select", "--vectors", s(d.path())]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("back.pla:") && err.contains(":2:"), "{err}");
}

/// A copy of the golden vectors in a temporary directory, `second.pla` edited by `edit`.
fn vectors_with_second(edit: impl Fn(String) -> String) -> tempfile::TempDir {
    let d = tmp();
    for t in ["front", "back", "close", "clip", "second"] {
        let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("vectors/select/{t}.pla"));
        std::fs::copy(src, d.path().join(format!("{t}.pla"))).unwrap();
    }
    let p = d.path().join("second.pla");
    std::fs::write(&p, edit(std::fs::read_to_string(&p).unwrap())).unwrap();
    d
}

#[test]
fn verify_select_locates_names_the_select_logic_does_not_know() {
    let cases: [(&dyn Fn(String) -> String, &str); 3] = [
        // An input that is no variable: at its name in `.ilb`.
        (
            &|t| t.replace(".ilb P N J T M", ".ilb P N J  x0 M"),
            "second.pla:7:13: unknown input \"x0\"",
        ),
        // No `.ilb`: the default names, at the `.i` count.
        (
            &|t| t.replace(".ilb P N J T M\n", ""),
            "second.pla:5:4: unknown input \"x0\"",
        ),
        // An output of the table missing: at `.ob`.
        (
            &|t| t.replace(".ob S3 S4", ".ob S3 Q"),
            "second.pla:8:1: no output S4",
        ),
    ];
    for (edit, want) in cases {
        let d = vectors_with_second(edit);
        let out = csgpix(&["verify-select", "--vectors", s(d.path())]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        let want = format!("csgpix: {}\n", d.path().join(want).display());
        assert_eq!(err, want);
    }
}

#[test]
fn render_cube_in_both_models_gives_the_same_image_and_cycles() {
    let d = tmp();
    let (a, b) = (d.path().join("c.png"), d.path().join("w.png"));
    let mut reports = vec![];
    for (model, out) in [("cycle", &a), ("word", &b)] {
        let o = csgpix(&[
            "render",
            "vectors/thesis/cube.dl",
            "--model",
            model,
            "--json",
            "-o",
            s(out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        reports.push(serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap());
    }
    let (ia, ib) = (
        image::open(&a).unwrap().to_rgb8(),
        image::open(&b).unwrap().to_rgb8(),
    );
    assert_eq!(ia, ib);
    assert_eq!(reports[0]["cycles"], reports[1]["cycles"]);
    // The cube covers part of the window and leaves background elsewhere.
    let lit = ia.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    assert!(lit > 1000 && lit < 250 * 250, "lit pixels {lit}");
}

#[test]
fn bad_display_list_gives_file_line_col_exit_2_and_no_output() {
    let d = tmp();
    let bad = d.path().join("bad.dl");
    std::fs::write(&bad, "1 2 3 4\n1 0 x\n0 0 0 1234\n").unwrap();
    let out_png = d.path().join("out.png");
    let o = csgpix(&["render", s(&bad), "-o", s(&out_png)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.dl:2:5"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(!out_png.exists());
}

#[test]
fn vcd_probe_records_the_first_plane_arriving_in_a() {
    let d = tmp();
    let vcd_path = d.path().join("cube.vcd");
    let (x, y) = (120usize, 100usize);
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--vcd",
        s(&vcd_path),
        "--probe",
        &format!("{x},{y};3,4"),
        "-o",
        s(&d.path().join("c.png")),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let f = std::fs::File::open(&vcd_path).unwrap();
    let mut parser = vcd::Parser::new(std::io::BufReader::new(f));
    let header = parser.parse_header().unwrap();
    let a = header
        .find_var(&[format!("px_{x}_{y}"), "A".to_string()])
        .unwrap()
        .code;
    // The first plane of the cube (§5.2): 46.06 - 1.0·x + 1.18·y, coefficients rounded to
    // 1/1024. DEPGEN's fill on a 250x250 array is 8 + 1 clocks; A holds the whole word after
    // the 32nd clock of the first window.
    let q = |v: f64| (v * 1024.0).round() as i64;
    let want = q(46.06) + x as i64 * q(-1.0) + y as i64 * q(1.18);
    let t_full = 9 + 32;
    let mut now = 0u64;
    let mut changes = vec![];
    for cmd in parser {
        match cmd.unwrap() {
            vcd::Command::Timestamp(t) => now = t,
            vcd::Command::ChangeVector(id, v) if id == a && now <= t_full => {
                let raw = v
                    .iter()
                    .fold(0i64, |acc, b| acc << 1 | (b == vcd::Value::V1) as i64);
                changes.push((now, (raw << 32) >> 32));
            }
            _ => {}
        }
    }
    // Bit-serial arrival: A changes clock by clock, starting after DEPGEN's fill, and holds
    // the plane's depth once the window's last bit is in.
    assert!(changes.len() > 2, "{changes:?}");
    assert!(changes[0].0 > 9, "{changes:?}");
    assert_eq!(changes.last().unwrap().1, want, "{changes:?}");
}

#[test]
fn coefficient_outside_the_word_is_located_and_refused() {
    let d = tmp();
    let dl = d.path().join("far.dl");
    std::fs::write(
        &dl,
        "# far plane\n1 2 3 4\n1 0 0\n\n5 1 5e7 2\n0 0 0\n0 0 0 1234\n",
    )
    .unwrap();
    let png = d.path().join("far.png");
    let o = csgpix(&["render", s(&dl), "-o", s(&png)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("far.dl:5:5: dZy"), "{err}");
    assert!(!png.exists());
}

#[test]
fn arrays_over_the_memory_limit_are_refused_before_allocation() {
    let d = tmp();
    let png = d.path().join("big.png");
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--size",
        "40000x40000",
        "-o",
        s(&png),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--max-memory"));
    assert!(!png.exists());
}

#[test]
fn probes_outside_the_array_are_refused() {
    let d = tmp();
    let png = d.path().join("p.png");
    let vcd = d.path().join("p.vcd");
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--vcd",
        s(&vcd),
        "--probe",
        "250,0",
        "-o",
        s(&png),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!png.exists() && !vcd.exists());
}

#[test]
fn tie_policy_changes_which_plane_colour_wins_on_an_exact_tie() {
    // Two coincident convex front planes of different colours, closed by one back plane: at
    // every pixel A = F on the second plane, so the tie policy alone picks the colour.
    let d = tmp();
    let dl = d.path().join("tie.dl");
    std::fs::write(
        &dl,
        "10 0 0 2\n1 0 0\n10 0 0 4\n1 0 0\n500 0 0 1\n0 0 0\n0 0 0 1234\n",
    )
    .unwrap();
    let mut colours = vec![];
    for ties in ["keep", "put"] {
        let png = d.path().join(format!("{ties}.png"));
        let o = csgpix(&[
            "render",
            s(&dl),
            "--ties",
            ties,
            "--size",
            "8x8",
            "-o",
            s(&png),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        colours.push(image::open(&png).unwrap().to_rgb8().get_pixel(3, 3).0);
    }
    assert_eq!(
        colours,
        vec![[0, 170, 0], [170, 0, 0]],
        "keep: first plane (2, green); put: second (4, red)"
    );
}

#[test]
fn clip_function_renders_and_bad_ones_are_located() {
    let d = tmp();
    let png = d.path().join("amb.png");
    let args = [
        "render",
        "vectors/thesis/box1-corrected.dl",
        "vectors/thesis/box2.dl",
        "--clip",
    ];
    let o = csgpix(&[&args[..], &["A.!B", "-o", s(&png)]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let plain = d.path().join("plain.png");
    let o = csgpix(&[
        "render",
        "vectors/thesis/box1-corrected.dl",
        "-o",
        s(&plain),
    ]);
    assert!(o.status.success());
    // Clipping by the complement of box2 cuts box1: the images differ.
    assert_ne!(
        image::open(&png).unwrap().to_rgb8(),
        image::open(&plain).unwrap().to_rgb8()
    );
    let bad = d.path().join("bad.png");
    let o = csgpix(&[&args[..], &["A.!(B", "-o", s(&bad)]].concat());
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--clip:1:6"), "{err}");
    assert!(!bad.exists());
}

#[test]
fn float_model_renders_without_clocks() {
    let d = tmp();
    let png = d.path().join("f.png");
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--model",
        "float",
        "--json",
        "-o",
        s(&png),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["cycles"], 0);
    assert_eq!(v["model"], "float");
    let vcd = d.path().join("f.vcd");
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--model",
        "float",
        "--vcd",
        s(&vcd),
        "--probe",
        "1,1",
        "-o",
        s(&png),
    ]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn csg_scene_renders_in_every_view_and_model() {
    let d = tmp();
    let mut images = vec![];
    for view in ["top", "front", "iso"] {
        for model in ["cycle", "word"] {
            let out = d.path().join(format!("{view}-{model}.png"));
            let o = csgpix(&[
                "render",
                "vectors/scenes/cube-minus-cylinder.csg",
                "--view",
                view,
                "--model",
                model,
                "--size",
                "96x96",
                "-o",
                s(&out),
            ]);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            images.push(image::open(&out).unwrap().to_rgb8());
        }
    }
    for pair in images.chunks(2) {
        assert_eq!(pair[0], pair[1], "cycle and word images differ");
    }
    // Seen from the top the bore is a hole through the cube: background shows through it.
    let top = &images[0];
    assert_eq!(top.get_pixel(48, 48).0, [0, 0, 0]);
    assert_ne!(top.get_pixel(3, 3).0, [0, 0, 0]);
    // From the front the cylinder is hidden inside the cube: one colour fills the square.
    assert_ne!(images[2].get_pixel(48, 48).0, [0, 0, 0]);
    assert_ne!(images[0], images[4], "views differ");
}

/// Run `render` on a `.csg` text; (exit status, stderr, whether the output file exists).
fn render_csg(text: &str, extra: &[&str]) -> (Option<i32>, String, bool) {
    let d = tmp();
    let scene = d.path().join("scene.csg");
    std::fs::write(&scene, text).unwrap();
    let out = d.path().join("out.png");
    let mut args = vec!["render", s(&scene)];
    args.extend_from_slice(extra);
    args.extend(["--size", "32x32", "-o", s(&out)]);
    let o = csgpix(&args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    (o.status.code(), err, out.exists())
}

#[test]
fn unsupported_csg_nodes_are_named_with_line_and_column() {
    // `roof`: a node of OpenSCAD releases after 2021.01.
    let text = "group() {\n  cube(size = [1, 1, 1]);\n  roof(method = \"straight\");\n}\n";
    let (code, err, written) = render_csg(text, &[]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("scene.csg:3:3") && err.contains("roof"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(!written);
    let (code, err, written) = render_csg("cube(size = [1, 1, 1]", &[]);
    assert_eq!((code, written), (Some(2), false));
    assert!(err.contains("scene.csg:1:"), "{err}");
}

#[test]
fn csg_scenes_refuse_clip_and_other_scenes_and_too_deep_arrays() {
    let cube = "cube(size = [1, 1, 1]);\n";
    let (code, err, written) = render_csg(cube, &["--clip", "A"]);
    assert_eq!((code, written), (Some(2), false));
    assert!(err.contains("--clip"), "{err}");
    let (code, err, written) = render_csg(cube, &["vectors/thesis/cube.dl"]);
    assert_eq!((code, written), (Some(2), false));
    assert!(err.contains("only SCENE"), "{err}");
    // A rod seen end-on fills the array across and is 100 times as deep: 3100 depth units.
    let rod = "cube(size = [1, 1, 100]);\n";
    let (code, err, written) = render_csg(rod, &["--view", "top"]);
    assert_eq!((code, written), (Some(2), false));
    // A whole-scene error: no line and column, the fix named (2^12 > 3100).
    assert!(
        err.contains("scene.csg: the scene is") && err.contains("use --word 10/12/11"),
        "{err}"
    );
}

#[test]
fn an_empty_csg_scene_renders_background() {
    let text = "difference() {\n  group();\n  cube(size = [1, 1, 1]);\n}\n";
    let (code, err, written) = render_csg(text, &[]);
    assert_eq!(code, Some(0), "{err}");
    assert!(written);
}

#[test]
fn voxelize_writes_the_same_nrrd_for_any_thread_count() {
    let d = tmp();
    let mut outs = vec![];
    for threads in ["1", "2", "5"] {
        let out = d.path().join(format!("v{threads}.nrrd"));
        let o = csgpix(&[
            "voxelize",
            "vectors/scenes/figure-5.2.csg",
            "--res",
            "24x20x16",
            "--threads",
            threads,
            "--json",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["dims"], serde_json::json!([24, 20, 16]));
        assert!(v["filled"].as_u64().unwrap() > 0 && v["cycles"].as_u64().unwrap() > 0);
        outs.push(std::fs::read(&out).unwrap());
    }
    assert!(outs.iter().all(|o| *o == outs[0]));
    let (dims, voxels) = csgpix::scene::nrrd::read(&outs[0]).unwrap();
    assert_eq!(dims, [24, 20, 16]);
    assert!(voxels.iter().any(|&v| v != 0) && voxels.contains(&0));
    let head = String::from_utf8_lossy(&outs[0][..400]);
    assert!(
        head.contains("space origin: (") && head.contains("space directions: ("),
        "{head}"
    );
}

#[test]
fn voxelize_routes_and_models_agree_and_slices_are_written() {
    let d = tmp();
    let mut volumes = vec![];
    for (model, route) in [("word", "intervals"), ("word", "array"), ("cycle", "array")] {
        let out = d.path().join(format!("{model}-{route}.nrrd"));
        let slices = d.path().join(format!("{model}-{route}"));
        let o = csgpix(&[
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--res",
            "10x10x10",
            "--model",
            model,
            "--route",
            route,
            "--eval",
            "stack",
            "--slices",
            s(&slices),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        volumes.push(std::fs::read(&out).unwrap());
        assert!(slices.join("slice-0009.png").exists());
    }
    assert!(volumes.iter().all(|v| *v == volumes[0]));
    // Every slice's pixel indices are the volume's label codes (an indexed PNG), z by z.
    let nrrd = &volumes[0];
    let data = &nrrd[nrrd.len() - 1000..];
    assert!(
        data.iter().any(|&c| c > 1),
        "the hollow cube has a colour code"
    );
    for k in 0..10 {
        let png = d.path().join(format!("word-intervals/slice-{k:04}.png"));
        let (size, indices, palette) = indexed_png(&png);
        assert_eq!(size, (10, 10));
        assert_eq!(indices, data[k * 100..(k + 1) * 100], "slice {k}");
        // The colours shown are the palette's, an entry for every code up to the largest.
        let top = *data.iter().max().unwrap() as usize;
        assert_eq!(palette.len(), (top + 1) * 3);
    }
}

/// An indexed PNG's size, pixel indices and palette (RGB triples, flattened).
fn indexed_png(path: &std::path::Path) -> ((u32, u32), Vec<u8>, Vec<u8>) {
    let file = std::io::BufReader::new(std::fs::File::open(path).unwrap());
    let mut dec = png::Decoder::new(file);
    dec.set_transformations(png::Transformations::IDENTITY);
    let mut reader = dec.read_info().unwrap();
    let info = reader.info();
    assert_eq!(info.color_type, png::ColorType::Indexed);
    let palette = info.palette.as_ref().unwrap().to_vec();
    let size = (info.width, info.height);
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut buf).unwrap();
    buf.truncate(frame.buffer_size());
    (size, buf, palette)
}

/// `--eval blist` is the Blist of `csgpix blist`: its label width is reported, its counts are
/// §4.5's (one comparison and one label write per classifying row, no stack), and it fills the
/// voxels the stack fills.
#[test]
fn voxelize_eval_blist_reports_the_label_register() {
    let d = tmp();
    let mut filled = vec![];
    for eval in ["blist", "stack"] {
        let out = d.path().join(format!("{eval}.nrrd"));
        let o = csgpix(&[
            "voxelize",
            "vectors/scenes/figure-5.2.csg",
            "--res",
            "20x20x20",
            "--eval",
            eval,
            // Counts per voxel (§5.5) are the slab route's; the run route counts per run.
            "--route",
            "intervals",
            "--json",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["eval"], eval);
        assert_eq!(v["route"], "intervals");
        // (Cube1 + Cube2) - (Cylinder1 + Cylinder2): two names besides 0, so two bits.
        assert_eq!(v["label_bits"], 2, "{v}");
        if eval == "blist" {
            assert_eq!(v["state_bits_per_voxel"], 2);
            assert_eq!(v["ops"]["comparisons"], v["ops"]["label_writes"]);
            assert_eq!(
                (v["ops"]["pushes"].as_u64(), v["ops"]["pops"].as_u64()),
                (Some(0), Some(0))
            );
            let c = v["ops"]["comparisons"].as_u64().unwrap();
            // At least one row per voxel, at most one per row (4 rows).
            assert!((8000..=4 * 8000).contains(&c), "{c}");
        }
        let (_, voxels) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
        filled.push(voxels.iter().map(|&c| c != 0).collect::<Vec<_>>());
    }
    assert_eq!(filled[0], filled[1]);
}

#[test]
fn voxelize_refuses_bad_input_without_output() {
    let d = tmp();
    let out = d.path().join("v.nrrd");
    let bad = d.path().join("bad.csg");
    std::fs::write(
        &bad,
        "cube(size = [1, 1, 1]);\nroof(method = \"straight\");\n",
    )
    .unwrap();
    for args in [
        vec!["voxelize", s(&bad), "--res", "8x8x8", "-o", s(&out)],
        vec![
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--res",
            "0",
            "-o",
            s(&out),
        ],
        vec![
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--res",
            "8x8x8",
            "--bounds",
            "1,1,1,0,2,2",
            "-o",
            s(&out),
        ],
        vec![
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--res",
            "4096x4096x4096",
            "--max-memory",
            "64",
            "-o",
            s(&out),
        ],
    ] {
        let o = csgpix(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!out.exists(), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&o.stderr).lines().count(),
            1,
            "{args:?}"
        );
    }
    let o = csgpix(&["voxelize", s(&bad), "--res", "8x8x8", "-o", s(&out)]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("bad.csg:2:1"));
}

fn json_of(args: &[&str]) -> serde_json::Value {
    let o = csgpix(args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// `requirements` predicts what the simulator then does: the pixel-clocks the pruned cycle
/// route simulates, the clocks of every frame, the stack the render program uses, the label
/// width `blist` reports.
#[test]
fn requirements_predict_the_simulators_work() {
    let d = tmp();
    let out = d.path().join("v.nrrd");
    let scene = "vectors/scenes/figure-5.2.csg";
    let req = json_of(&[
        "requirements",
        scene,
        "--res",
        "24x20x12",
        "--panel",
        "8x8",
        "--json",
    ]);
    let vox = json_of(&[
        "voxelize",
        scene,
        "--res",
        "24x20x12",
        "--panel",
        "8x8",
        "--model",
        "cycle",
        "--json",
        "-o",
        s(&out),
    ]);
    assert_eq!(req["simulated_pixel_clocks"], vox["simulated_pixel_clocks"]);
    assert_eq!(req["full_pixel_clocks"], vox["full_pixel_clocks"]);
    assert_eq!(req["cycles_all_frames"], vox["cycles"]);
    assert_eq!(req["label_bits"], vox["label_bits"]);
    let png = d.path().join("r.png");
    let render = json_of(&["render", scene, "--json", "-o", s(&png)]);
    assert_eq!(req["stack_levels_render"], render["stack_levels"]);
    assert_eq!(req["cycles_render"], render["cycles"]);
    let (touched, total) = (
        req["panels_touched"].as_u64().unwrap(),
        req["panels_total"].as_u64().unwrap(),
    );
    // 24x20 in 8x8 panels: 3x3; Figure 5.2's L leaves one corner panel empty.
    assert_eq!(total, 9);
    assert!(touched < total, "{req}");
    assert!(req["cycles_needed_frames"].as_u64() <= req["cycles_all_frames"].as_u64());
}

/// The render array models only the clipping-stack levels the program uses: the same image
/// as a deeper stack, and a program deeper than `--stack-depth` is refused.
#[test]
fn render_models_only_the_stack_it_needs() {
    let d = tmp();
    let scene = "vectors/scenes/cube-minus-cylinder.csg";
    let (a, b) = (d.path().join("a.png"), d.path().join("b.png"));
    let deep = json_of(&["render", scene, "--size", "64x64", "--json", "-o", s(&a)]);
    let need = deep["stack_levels"].as_u64().unwrap();
    assert!(need >= 1 && need < deep["stack_depth"].as_u64().unwrap());
    let need_s = need.to_string();
    let exact = json_of(&[
        "render",
        scene,
        "--size",
        "64x64",
        "--stack-depth",
        &need_s,
        "--json",
        "-o",
        s(&b),
    ]);
    assert_eq!(exact["stack_levels"], need);
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    let less = (need - 1).to_string();
    let c = d.path().join("c.png");
    let o = csgpix(&[
        "render",
        scene,
        "--size",
        "64x64",
        "--stack-depth",
        &less,
        "-o",
        s(&c),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!c.exists());
}

/// `render --panel` draws a `.csg` scene on panels: the same PNG, fewer pixel-clocks; display
/// lists are refused (they have no footprint to bin by).
#[test]
fn render_on_panels_is_the_same_image() {
    let d = tmp();
    let (a, b) = (d.path().join("a.png"), d.path().join("b.png"));
    let scene = "vectors/scenes/figure-5.2.csg";
    let whole = json_of(&["render", scene, "--size", "64x48", "--json", "-o", s(&a)]);
    let panels = json_of(&[
        "render",
        scene,
        "--size",
        "64x48",
        "--panel",
        "16x16",
        "--json",
        "-o",
        s(&b),
    ]);
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    assert_eq!(whole["cycles"], panels["cycles"]);
    assert!(panels["simulated_pixel_clocks"].as_u64() < whole["simulated_pixel_clocks"].as_u64());
    let c = d.path().join("c.png");
    let o = csgpix(&[
        "render",
        "vectors/thesis/cube.dl",
        "--panel",
        "16x16",
        "-o",
        s(&c),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!c.exists());
}

/// `--voxel` fits cubic voxels to the bounds, `--pad` adds empty voxels of the same size,
/// `--sampling` is reported; the hollow cube's cavity is exactly 16³ under centre sampling
/// and one layer deeper under the thesis's slab.
#[test]
fn voxelize_grid_options_and_sampling() {
    let d = tmp();
    let out = d.path().join("v.nrrd");
    let run = |extra: &[&str]| -> serde_json::Value {
        let mut args = vec![
            "voxelize",
            "vectors/scenes/hollow-cube.csg",
            "--json",
            "-o",
            s(&out),
        ];
        args.extend_from_slice(extra);
        let o = csgpix(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let r = run(&["--res", "32x32x32"]);
    assert_eq!(r["sampling"], "centre");
    assert_eq!(r["filled"], 32 * 32 * 32 - 16 * 16 * 16);
    let r = run(&["--res", "32x32x32", "--sampling", "slab"]);
    assert_eq!(r["sampling"], "slab");
    assert_eq!(r["filled"], 32 * 32 * 32 - 16 * 16 * 17);
    // The hollow cube is 20 units wide: 0.5-unit voxels, 40 a side, and 2 of padding.
    let r = run(&["--voxel", "0.5", "--pad", "2"]);
    assert_eq!(r["dims"], serde_json::json!([44, 44, 44]));
    assert_eq!(r["voxel"], serde_json::json!([0.5, 0.5, 0.5]));
    assert_eq!(r["min"], serde_json::json!([-11.0, -11.0, -11.0]));
    assert_eq!(r["filled"], 40 * 40 * 40 - 20 * 20 * 20);
    let (dims, v) = csgpix::scene::nrrd::read(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(dims, [44; 3]);
    assert_eq!(v[0], 0, "padding is empty");
    for bad in [
        &["--voxel", "0"][..],
        &["--voxel", "-1"],
        &["--voxel", "1e-9"],
        &["--voxel", "1", "--res", "8x8x8"],
    ] {
        std::fs::remove_file(&out).ok();
        let mut args = vec!["voxelize", "vectors/scenes/hollow-cube.csg", "-o", s(&out)];
        args.extend_from_slice(bad);
        let o = csgpix(&args);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
        assert!(!out.exists(), "{bad:?} left an output");
    }
}

/// `--compress` writes the same voxels gzip-encoded, on the streamed run route and on the
/// held volume's path alike; `space` is neutral unless an imported dataset declares its own.
#[test]
fn voxelize_compress_writes_gzip_nrrd_in_the_scenes_space() {
    let d = tmp();
    let run = |scene: &str, extra: &[&str], out: &Path| {
        let args = [
            &["voxelize", scene, "--res", "24x24x24", "-o", s(out)][..],
            extra,
        ]
        .concat();
        let o = csgpix(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read(out).unwrap()
    };
    let split = |bytes: &[u8]| {
        let at = bytes.windows(2).position(|w| w == b"\n\n").unwrap();
        let head = String::from_utf8(bytes[..at].to_vec()).unwrap();
        (head, bytes[at + 2..].to_vec())
    };
    let gunzip = |data: &[u8]| {
        let mut out = vec![];
        std::io::Read::read_to_end(&mut flate2::read::GzDecoder::new(data), &mut out).unwrap();
        out
    };
    let twelve = "vectors/scenes/twelve.csg";
    let (raw_head, raw) = split(&run(twelve, &[], &d.path().join("raw.nrrd")));
    assert!(
        raw_head.contains("\nspace: 3D-right-handed\n"),
        "{raw_head}"
    );
    assert!(raw_head.contains("\nencoding: raw\n"), "{raw_head}");
    // Streamed (the run route alone) and held (with --preview) both compress the same bytes.
    let preview = d.path().join("p.png");
    for extra in [vec![], vec!["--preview", s(&preview)]] {
        let args = [vec!["--compress"], extra].concat();
        let bytes = run(twelve, &args, &d.path().join("gz.nrrd"));
        let (head, data) = split(&bytes);
        assert!(head.contains("\nencoding: gzip\n"), "{head}");
        assert_eq!(head.replace("encoding: gzip", "encoding: raw"), raw_head);
        assert!(
            data.len() < raw.len() / 4,
            "{} of {} bytes",
            data.len(),
            raw.len()
        );
        assert_eq!(gunzip(&data), raw);
    }
    // A dataset's declared space is the volume's.
    let (head, _) = split(&run(
        "vectors/scenes/figure-5.6.csg",
        &[],
        &d.path().join("h.nrrd"),
    ));
    assert!(
        head.contains("\nspace: right-anterior-superior\n"),
        "{head}"
    );
}

/// `--res N` lays N cubic voxels on the longest side (as binvox, OpenVDB and trimesh count a
/// resolution); `--res NXxNYxNZ` that many per axis; a cube's bounds get N×N×N either way.
#[test]
fn res_n_is_the_longest_side_in_cubic_voxels() {
    let d = tmp();
    let json = |scene: &str, res: &str| {
        let out = d.path().join("v.nrrd");
        let o = csgpix(&["voxelize", scene, "--res", res, "--json", "-o", s(&out)]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()
    };
    let dims = |v: &serde_json::Value| -> Vec<u64> {
        v["dims"]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| d.as_u64().unwrap())
            .collect()
    };
    let voxel = |v: &serde_json::Value| -> Vec<f64> {
        v["voxel"]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| d.as_f64().unwrap())
            .collect()
    };
    // twelve.csg is 22.83 × 22.83 × 28 units: 64 along Z, ⌈22.83 / (28/64)⌉ = 53 across.
    let twelve = json("vectors/scenes/twelve.csg", "64");
    assert_eq!(dims(&twelve), [53, 53, 64]);
    let v = voxel(&twelve);
    assert!(v.iter().all(|&x| (x - 28.0 / 64.0).abs() < 1e-12), "{v:?}");
    assert_eq!(
        dims(&json("vectors/scenes/twelve.csg", "64x64x64")),
        [64, 64, 64]
    );
    // A cube's bounds: the same grid, byte for byte, as the per-axis form.
    let logo = |res: &str| {
        let out = d.path().join(format!("logo-{res}.nrrd"));
        let o = csgpix(&[
            "voxelize",
            "vectors/scenes/csg-logo.csg",
            "--res",
            res,
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read(out).unwrap()
    };
    assert_eq!(logo("32"), logo("32x32x32"));
}

/// `completions` and `man` come from the parser's own definition: every subcommand is in
/// them, so neither can fall behind a new command.
#[test]
fn completions_and_man_page_name_the_subcommands() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = csgpix(&["completions", shell]);
        assert_eq!(out.status.code(), Some(0), "{shell}");
        let text = String::from_utf8(out.stdout).unwrap();
        for sub in ["voxelize", "render", "sculpt", "completions", "man"] {
            assert!(text.contains(sub), "{shell} completion lacks {sub}");
        }
    }
    let bash = String::from_utf8(csgpix(&["completions", "bash"]).stdout).unwrap();
    assert!(bash.contains("complete -F _csgpix"), "{bash}");
    let out = csgpix(&["man"]);
    assert_eq!(out.status.code(), Some(0));
    let page = String::from_utf8(out.stdout).unwrap();
    assert!(page.contains(".TH csgpix 1"), "{page}");
    for sub in ["voxelize", "render", "gen\\-vectors", "completions"] {
        assert!(page.contains(sub), "man page lacks {sub}");
    }
    // A shell that clap_complete does not know is a usage error, exit status 2.
    let out = csgpix(&["completions", "tcsh"]);
    assert_eq!(out.status.code(), Some(2));
}
