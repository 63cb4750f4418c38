//! `csgpix study`: the re-tessellation, what a small sweep must show, the CSV and the charts,
//! bad input.
//!
//! Expected values come from the scene and the docs' formulas worked by hand, never from the
//! code under test.

mod common;
use common::csgpix;

use std::path::Path;

use csgpix::openscad::parse_csg;
use csgpix::run::sweep::{prepare, with_fragments, Model, Point, Sweep, CSV_HEADER};

fn scene_text(name: &str) -> String {
    let path = format!("{}/vectors/scenes/{name}.csg", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).unwrap()
}

fn vertices(text: &str) -> Vec<usize> {
    let s = parse_csg(text, "t").unwrap();
    s.solids.iter().map(|s| s.vertices.len()).collect()
}

#[test]
fn fragments_are_rewritten_or_added_and_comments_left_alone() {
    // A cylinder with two non-zero radii has 2n vertices; a sphere ceil(n/2) rings of n
    // (OpenSCAD's CylinderNode/SphereNode layout, docs in crates/openscad/src).
    let text = "// sphere($fn = 3) in a comment\n\
                union() { cylinder($fn=24, $fa = 12, h = 2, r = 1);\n\
                sphere(r = 2); sphere ( ); cube(1); }";
    // As read: $fn = 24 → 48; r = 2 with $fa = 12, $fs = 2 → ceil(max(min(30, 2π), 5)) = 7
    // fragments, 4 rings → 28; r = 1 → 5 fragments, 3 rings → 15; the cube 8.
    assert_eq!(vertices(text), vec![48, 28, 15, 8]);
    let out = with_fragments(text, 10);
    assert!(
        out.starts_with("// sphere($fn = 3) in a comment\n"),
        "{out}"
    );
    assert_eq!(out.lines().count(), text.lines().count());
    // 10 fragments: cylinder 20 vertices, sphere 5 rings × 10, cube untouched.
    assert_eq!(vertices(&out), vec![20, 50, 50, 8]);
}

fn small_sweep() -> Vec<Point> {
    let sweep = Sweep {
        bits: vec![12, 4, 8],
        fragments: vec![16, 8],
        slabs: vec![16, 8],
        models: vec![Model::Float, Model::Word, Model::Cycle],
        res: 16,
        int_bits: 10,
        ovf_bits: 11,
        sampling: csgpix::voxel::Sampling::Centre,
    };
    let text = scene_text("cube-minus-cylinder");
    prepare(&text, "cube-minus-cylinder.csg", sweep)
        .unwrap()
        .run(&|| {})
        .unwrap()
}

fn at(points: &[Point], m: Model, bits: u32, frags: u32, slabs: usize) -> &Point {
    points
        .iter()
        .find(|p| (p.model, p.frac_bits, p.fragments, p.slabs) == (m, bits, frags, slabs))
        .unwrap()
}

#[test]
fn a_small_sweep_keeps_what_must_hold() {
    let pts = small_sweep();
    assert_eq!(pts.len(), 3 * 2 * 2 * 3);
    for slabs in [8, 16] {
        // The reference is float at the finest tessellation and most bits: that point is
        // the reference itself.
        assert_eq!(at(&pts, Model::Float, 12, 16, slabs).diff_ref, 0);
        for frags in [8, 16] {
            let mut last_cycles = 0;
            for bits in [4, 8, 12] {
                let (c, w) = (
                    at(&pts, Model::Cycle, bits, frags, slabs),
                    at(&pts, Model::Word, bits, frags, slabs),
                );
                let f = at(&pts, Model::Float, bits, frags, slabs);
                // cycle and word are the same hardware (crates/voxel/tests/voxelize.rs, crates/voxel/tests/slices.rs).
                assert_eq!(
                    (&c.digest, c.cycles, c.depth_err),
                    (&w.digest, w.cycles, w.depth_err)
                );
                assert_eq!(w.voxels, 16 * 16 * slabs);
                // Float is no hardware and the truth the word is measured against.
                assert_eq!((f.cycles, f.diff_float, f.depth_err), (None, 0, 0.0));
                // Every plane window takes N_D = F + 21 clocks and F changes neither the
                // planes nor the frames, so more bits cost strictly more clocks.
                assert_eq!(w.n_d, bits + 10 + 11 + 1);
                let cycles = w.cycles.unwrap();
                assert!(
                    cycles > last_cycles,
                    "{bits} bits: {cycles} <= {last_cycles}"
                );
                last_cycles = cycles;
                assert_eq!(w.hardware_s, Some(cycles as f64 / 1e7));
                assert_bound(w, bits, slabs);
            }
        }
    }
}

/// The depth bound 2^-(F+1)·(1 + x + y) at the far pixel (15, 15), converted to scene units:
/// the grid spans z = -15..15 (the cylinder reaches ±15), so a voxel is 30/slabs deep and a
/// slab q = floor(1016·2^F/slabs)/2^F depth units (docs/voxelization.md). Every interval end
/// is a max or min of planes each within the bound, so the measured error is too.
fn assert_bound(p: &Point, bits: u32, slabs: usize) {
    let bound = 0.5f64.powi(bits as i32 + 1) * 31.0 * scale(bits, slabs);
    assert!((p.depth_bound - bound).abs() <= 1e-12 * bound, "{p:?}");
    assert!(p.depth_err <= bound * (1.0 + 1e-9), "{p:?}");
}

fn scale(bits: u32, slabs: usize) -> f64 {
    let one = f64::from(1u32 << bits);
    let q = (1016.0 * one / slabs as f64).floor() / one;
    30.0 / slabs as f64 / q
}

#[test]
fn the_finest_bits_beat_the_coarsest_in_depth_on_this_scene() {
    // Why this holds here (not in general: rounding errors of different widths can cancel
    // differently, and the voxel counts are not monotone in F; see docs/tradeoffs.md): the
    // cube's front face z = -10 is a constant plane at depth 4 + (5/30·16)·q, q = 63.5 for 16
    // slabs at F = 4 and F = 12. That is 173.333…, which 4 fraction bits round to 173.3125:
    // an error of exactly 1/48 depth units at every pixel, so the measured error at F = 4 is
    // at least that; at F = 12 it is at most the bound 2^-13·31 ≈ 0.0038 < 1/48.
    let pts = small_sweep();
    let coarse = at(&pts, Model::Word, 4, 16, 16);
    let fine = at(&pts, Model::Word, 12, 16, 16);
    assert!(
        coarse.depth_err >= scale(4, 16) / 48.0 * (1.0 - 1e-9),
        "{coarse:?}"
    );
    assert!(fine.depth_err <= 0.5f64.powi(13) * 31.0 * scale(12, 16) * (1.0 + 1e-9));
    assert!(fine.depth_err < coarse.depth_err);
}

const SMALL: [&str; 10] = [
    "--bits",
    "4,8",
    "--fragments",
    "8,16",
    "--slabs",
    "8",
    "--models",
    "word,float",
    "--res",
    "12",
];

fn run_study(dir: &Path) -> String {
    let mut args = vec!["study", "vectors/scenes/figure-5.2.csg", "-o"];
    args.push(dir.to_str().unwrap());
    args.extend(SMALL);
    let out = csgpix(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::read_to_string(dir.join("study.csv")).unwrap()
}

fn without_wall(csv: &str) -> Vec<String> {
    csv.lines()
        .map(|l| l.rsplit_once(',').unwrap().0.to_string())
        .collect()
}

#[test]
fn the_csv_is_well_formed_and_the_same_every_run() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let (x, y) = (run_study(a.path()), run_study(b.path()));
    let lines: Vec<&str> = x.lines().collect();
    assert_eq!(lines[0], CSV_HEADER);
    assert_eq!(lines.len(), 1 + 2 * 2 * 2);
    let columns = CSV_HEADER.split(',').count();
    for l in &lines[1..] {
        let f: Vec<&str> = l.split(',').collect();
        assert_eq!(f.len(), columns, "{l}");
        assert!(f.last().unwrap().parse::<f64>().unwrap() >= 0.0, "{l}");
        // 12×12×8 voxels on every row.
        assert_eq!(f[6], "1152", "{l}");
    }
    assert_eq!(without_wall(&x), without_wall(&y));
    for png in ["bits.png", "fragments.png", "depth.png", "wall.png"] {
        let img = image::open(a.path().join(png)).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (800, 560), "{png}");
        let dark = img
            .pixels()
            .filter(|p| p.0.iter().all(|&c| c < 100))
            .count();
        assert!(dark > 500, "{png}: {dark} dark pixels");
    }
    let files = std::fs::read_dir(a.path()).unwrap().count();
    assert_eq!(files, 5, "study.csv and four charts, no temporary left");
}

#[test]
fn json_has_every_point() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["study", "vectors/scenes/figure-5.2.csg", "--json", "-o"];
    args.push(dir.path().to_str().unwrap());
    args.extend(SMALL);
    let out = csgpix(&args);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 8);
    assert!(points
        .iter()
        .all(|p| p["model"] == "word" || p["cycles"].is_null()));
}

#[test]
fn bad_input_is_one_line_exit_2_and_no_files() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csg");
    std::fs::write(&bad, "union() {\n  cube(size = [1, 2);\n}\n").unwrap();
    let out_dir = dir.path().join("out");
    let o = out_dir.to_str().unwrap();
    let cases: [(&[&str], &str); 6] = [
        (&["study", bad.to_str().unwrap(), "-o", o], "bad.csg:2:"),
        (&["study", "no/such.csg", "-o", o], "no/such.csg"),
        (
            &[
                "study",
                "vectors/scenes/figure-5.2.csg",
                "--fragments",
                "2",
                "-o",
                o,
            ],
            "at least 3",
        ),
        (
            &[
                "study",
                "vectors/scenes/figure-5.2.csg",
                "--slabs",
                "0",
                "-o",
                o,
            ],
            "at least 1",
        ),
        (
            &[
                "study",
                "vectors/scenes/figure-5.2.csg",
                "--bits",
                "60",
                "-o",
                o,
            ],
            "--bits 60",
        ),
        (
            &[
                "study",
                "vectors/scenes/figure-5.2.csg",
                "--models",
                "fast",
                "-o",
                o,
            ],
            "fast",
        ),
    ];
    for (args, what) in cases {
        let out = csgpix(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(what), "{args:?}: {err}");
        assert!(!out_dir.exists(), "{args:?} left {}", out_dir.display());
    }
}
