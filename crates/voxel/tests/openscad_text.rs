//! `text()` against OpenSCAD's own geometry: each case of `vectors/openscad/text/cases.txt`
//! is `linear_extrude(height = 2) text(...)`; its committed CSG export is read by csgpix and
//! voxelized on a 256×64×4 grid over the text's bounds (centre sampling, float route), and so
//! is OpenSCAD's committed mesh of the same file (`NAME.off`, a closed triangle mesh). The
//! voxels must agree with IoU ≥ 0.99, and the outline areas (each mesh's volume / height) to
//! within 0.5 %. The figures are printed for docs/volume-scenes.md
//! (`cargo test --release -p csgpix-voxel --test openscad_text -- --nocapture`).
//!
//! Fonts: the reader looks in `CSGPIX_FONT_PATH`, then the bundled `vectors/fonts` (the same
//! Liberation 2.1.5 files OpenSCAD used), then the system fonts; set here to `vectors/fonts`
//! so the bundled files are the ones drawn even where the system has other versions.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use csgpix_openscad::extrude::signed_area;
use csgpix_openscad::parse_csg;
use csgpix_openscad::text::{render, segments, Fonts, TextSpec};
use csgpix_scene::solid::{CsgNode, CsgScene, Import};
use csgpix_voxel::blist::BlistEval;
use csgpix_voxel::sampled::load_imports;
use csgpix_voxel::{voxelize, Grid, Route, Slicer, SlicerOptions};
use glam::DVec3;
use rtl_model::Equations;

type Tri = [[f64; 3]; 3];

/// The workspace's root, where `vectors/` and `fuzz/` are: two levels above this crate.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn dir() -> PathBuf {
    Path::new(ROOT).join("vectors/openscad/text")
}

/// OpenSCAD's OFF export: a header, vertices, then faces (triangles, fanned if larger).
fn read_off(path: &Path) -> Vec<Tri> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut words = text
        .lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .flat_map(str::split_whitespace);
    assert_eq!(words.next(), Some("OFF"));
    let mut num = || words.next().unwrap().parse::<f64>().unwrap();
    let (nv, nf, _) = (num() as usize, num() as usize, num());
    let v: Vec<[f64; 3]> = (0..nv).map(|_| [num(), num(), num()]).collect();
    let mut tris = vec![];
    for _ in 0..nf {
        let k = num() as usize;
        let f: Vec<usize> = (0..k).map(|_| num() as usize).collect();
        for i in 1..k - 1 {
            tris.push([v[f[0]], v[f[i]], v[f[i + 1]]]);
        }
    }
    tris
}

/// The volume a closed, outward-wound triangle mesh encloses.
fn volume(tris: &[Tri]) -> f64 {
    let v = |p: [f64; 3]| DVec3::from(p);
    tris.iter()
        .map(|t| v(t[0]).dot(v(t[1]).cross(v(t[2]))) / 6.0)
        .sum()
}

fn occupancy(scene: &CsgScene, grid: &Grid) -> Vec<bool> {
    let sampled = load_imports(scene, "t.csg", &dir()).unwrap();
    let opts = SlicerOptions {
        sampled,
        ..SlicerOptions::default()
    };
    let slicer = Slicer::new(scene, *grid, opts).unwrap();
    let eval = BlistEval::new(&scene.root);
    let (vol, _) = voxelize(
        &slicer,
        Route::Float,
        Equations::Derived.set(),
        &eval,
        &|| {},
    )
    .unwrap();
    vol.voxels.iter().map(|&c| c != 0).collect()
}

/// A scene of one closed mesh.
fn mesh_scene(tris: Vec<Tri>) -> CsgScene {
    CsgScene {
        solids: vec![],
        imports: vec![Import {
            file: "openscad.off".into(),
            threshold: None,
            matrix: None,
            colour: None,
            line: 1,
            col: 1,
            footprint: None,
            mesh: Some(Arc::new(tris)),
        }],
        root: CsgNode::Solid(0),
        warnings: vec![],
        reading_bytes: 0,
    }
}

/// The value of `key = …` in the `text(…)` statement of a CSG export (a string unquoted).
fn arg(csg: &str, key: &str) -> String {
    let line = csg
        .lines()
        .find(|l| l.trim_start().starts_with("text("))
        .unwrap();
    let at = [format!("({key} = "), format!(" {key} = ")]
        .iter()
        .find_map(|k| line.find(k.as_str()))
        .unwrap()
        + key.len()
        + 4;
    let rest = &line[at..];
    if let Some(r) = rest.strip_prefix('"') {
        r[..r.find('"').unwrap()].to_string()
    } else {
        rest[..rest.find([',', ')']).unwrap()].to_string()
    }
}

/// The area of csgpix's outline of the case's `text(…)` (the extruded mesh's caps are fans
/// filled by parity, so its signed volume is not the solid's).
fn outline_area(csg: &str) -> f64 {
    let num = |k: &str| arg(csg, k).parse::<f64>().unwrap();
    let spec = TextSpec {
        text: arg(csg, "text"),
        size: num("size"),
        spacing: num("spacing"),
        font: arg(csg, "font"),
        direction: arg(csg, "direction"),
        language: arg(csg, "language"),
        script: arg(csg, "script"),
        halign: arg(csg, "halign"),
        valign: arg(csg, "valign"),
        segments: segments(num("size"), num("$fn"), num("$fa"), num("$fs")),
    };
    let poly = render(&spec, Fonts::standard(), 1_000_000).unwrap();
    poly.paths.iter().map(|c| signed_area(c)).sum::<f64>().abs()
}

/// (IoU, csgpix's outline area, OpenSCAD's outline area) of one case.
fn compare(name: &str) -> (f64, f64, f64) {
    let csg = std::fs::read_to_string(dir().join(format!("{name}.csg"))).unwrap();
    let ours = parse_csg(&csg, &format!("{name}.csg")).unwrap_or_else(|e| panic!("{e}"));
    let theirs = read_off(&dir().join(format!("{name}.off")));
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in theirs.iter().flatten() {
        lo = lo.min(DVec3::from(*p));
        hi = hi.max(DVec3::from(*p));
    }
    let pad = (hi - lo).truncate().max_element() * 0.02;
    let lo = DVec3::new(lo.x - pad, lo.y - pad, 0.0);
    let hi = DVec3::new(hi.x + pad, hi.y + pad, 2.0);
    let grid = Grid::new([256, 64, 4], lo, hi).unwrap();
    let a = occupancy(&ours, &grid);
    let b = occupancy(&mesh_scene(theirs.clone()), &grid);
    let both = a.iter().zip(&b).filter(|(x, y)| **x && **y).count();
    let either = a.iter().zip(&b).filter(|(x, y)| **x || **y).count();
    let iou = both as f64 / either as f64;
    if iou < 0.99 {
        let ours_lo = ours
            .imports
            .iter()
            .flat_map(|i| i.mesh.as_ref().unwrap().iter().flatten())
            .fold(DVec3::splat(f64::INFINITY), |a, p| a.min(DVec3::from(*p)));
        println!(
            "{name}: csgpix's lowest corner {ours_lo:?}, OpenSCAD's bounds {lo:?} {hi:?} (padded)"
        );
    }
    (iou, outline_area(&csg), volume(&theirs) / 2.0)
}

fn cases() -> Vec<String> {
    std::fs::read_to_string(dir().join("cases.txt"))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| l.split('\t').next().unwrap().to_string())
        .collect()
}

#[test]
fn text_agrees_with_openscad() {
    // Before the first text() is read: the font set is loaded once per process.
    std::env::set_var("CSGPIX_FONT_PATH", Path::new(ROOT).join("vectors/fonts"));
    let mut bad = vec![];
    for name in cases() {
        let (iou, ours, theirs) = compare(&name);
        let rel = (ours - theirs).abs() / theirs;
        println!(
            "{name:22} IoU {iou:.5}  area csgpix {ours:.4}  OpenSCAD {theirs:.4}  differ {:.4} %",
            rel * 100.0
        );
        if iou < 0.99 || rel > 0.005 {
            bad.push(name);
        }
    }
    assert!(bad.is_empty(), "disagreeing with OpenSCAD: {bad:?}");
}

/// HarfBuzz's advances are scaled by FreeType's unrounded `x_scale` (hb-ft loads them
/// unhinted), the outlines by the whole-pixel one of a TrueType font asking for an integer
/// ppem: 40 "o"s end where OpenSCAD's do (the rounded scale put the last one 0.02 short).
#[test]
fn advances_accumulate_as_openscad() {
    std::env::set_var("CSGPIX_FONT_PATH", Path::new(ROOT).join("vectors/fonts"));
    let name = "sans-advances-long";
    let csg = std::fs::read_to_string(dir().join(format!("{name}.csg"))).unwrap();
    let theirs = read_off(&dir().join(format!("{name}.off")));
    let their_right = theirs
        .iter()
        .flatten()
        .map(|p| p[0])
        .fold(f64::NEG_INFINITY, f64::max);
    let spec = TextSpec {
        text: arg(&csg, "text"),
        size: 10.0,
        spacing: 1.0,
        font: arg(&csg, "font"),
        direction: arg(&csg, "direction"),
        language: arg(&csg, "language"),
        script: arg(&csg, "script"),
        halign: arg(&csg, "halign"),
        valign: arg(&csg, "valign"),
        segments: segments(10.0, 0.0, 12.0, 2.0),
    };
    let poly = render(&spec, Fonts::standard(), 1_000_000).unwrap();
    let our_right = poly
        .paths
        .iter()
        .flatten()
        .map(|p| p[0])
        .fold(f64::NEG_INFINITY, f64::max);
    println!("right edge: csgpix {our_right:.5}, OpenSCAD {their_right:.5}");
    assert!(
        (our_right - their_right).abs() < 2e-3,
        "{our_right} {their_right}"
    );
}
